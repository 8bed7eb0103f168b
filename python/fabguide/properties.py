"""Adding FeaturePython properties idempotently, so documents saved by an older FabGuide gain new
properties when they are opened (call `add` again from onDocumentRestored); the recompute of every FabGuide
object, which says a mistake in the model in one plain sentence."""
import FreeCAD


def add(obj, kind, name, group, doc, value=None, mode=0):
    """Adds property `name` if missing and sets `value` on creation (for an enumeration, the list of choices);
    mode 1 = read-only, 2 = hidden."""
    if name in obj.PropertiesList:
        return
    obj.addProperty(kind, name, group, doc)
    if value is not None:
        setattr(obj, name, value)
    if mode:
        obj.setEditorMode(name, mode)


class Stateless:
    """Saved with no state of its own: FreeCAD 0.20 calls __getstate__/__setstate__, 0.21+ dumps/loads.
    Everything FabGuide keeps lives in properties, never a reference to the object."""

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None


class Proxy(Stateless):
    """Base of FabGuide's FeaturePython proxies. Subclasses list their properties in `define(obj)` with
    `add`; restoring a document calls it again, so documents saved by an older FabGuide gain new properties.
    They recompute in `recompute(obj)`."""

    def __init__(self, obj):
        obj.Proxy = self
        self.define_all(obj)

    def onDocumentRestored(self, obj):
        self.define_all(obj)

    def define_all(self, obj):
        self.define(obj)
        add(obj, "App::PropertyString", "Error", "Base", "Why the last recompute failed; empty when it did not",
            mode=2)

    def execute(self, obj):
        """A mistake in the model (a ValueError: FabGuide's own errors, the core's FormatError) is one plain
        sentence in the report view and in the object's Error (its tree icon is marked), never a traceback;
        `recompute` says it in the object's Status too, and clears the statuses it can no longer vouch for."""
        try:
            self.recompute(obj)
        except ValueError as error:
            fail(obj, str(error))
        else:
            fail(obj, "")

    def recompute(self, obj):
        pass


def failed(obj):
    """Whether the last recompute of `obj` failed (said by FabGuide, or by FreeCAD for others' objects)."""
    return bool(getattr(obj, "Error", "")) or "Invalid" in obj.State


def fail(obj, message):
    """Marks `obj` failed with `message` (said in the report view once), or not failed when it is empty."""
    if obj.Error != message:
        if message:
            FreeCAD.Console.PrintError(message + "\n")
        obj.Error = message


def is_a(obj, proxy_class):
    """Whether `obj` is a FabGuide object made by `proxy_class` (matched by its TYPE, not by identity, so
    objects restored from a file count too)."""
    return getattr(getattr(obj, "Proxy", None), "TYPE", None) == proxy_class.TYPE
