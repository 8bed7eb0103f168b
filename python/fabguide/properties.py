"""Adding FeaturePython properties idempotently, so documents saved by an older FabGuide gain new
properties when they are opened (call `add` again from onDocumentRestored)."""


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
    `add`; restoring a document calls it again, so documents saved by an older FabGuide gain new properties."""

    def __init__(self, obj):
        obj.Proxy = self
        self.define(obj)

    def onDocumentRestored(self, obj):
        self.define(obj)


def is_a(obj, proxy_class):
    """Whether `obj` is a FabGuide object made by `proxy_class` (matched by its TYPE, not by identity, so
    objects restored from a file count too)."""
    return getattr(getattr(obj, "Proxy", None), "TYPE", None) == proxy_class.TYPE
