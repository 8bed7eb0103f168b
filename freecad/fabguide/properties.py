"""Adding FeaturePython properties idempotently, so documents saved by an older FabGuide gain new
properties when they are opened (call `add` again from onDocumentRestored); the recompute of every FabGuide
object, which says a mistake in the model in one plain sentence."""
import FreeCAD

from freecad import fabguide
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

READ_ONLY, HIDDEN, OUTPUT = 1, 4, 8  # App::PropertyType flags

NUMBERS = ("App::PropertyFloat", "App::PropertyLength", "App::PropertyDistance", "App::PropertyAngle")
TYPED = NUMBERS + ("App::PropertyFloatList",)  # what typed_in judges finite


def add(obj, kind, name, group, doc, value=None, mode=0):
    """Adds property `name` if missing and sets `value` on creation (for an enumeration, the list of choices);
    mode 1 = read-only, 2 = hidden. A number an older FabGuide saved as another kind of number (a Float now a
    Distance) becomes `kind`, keeping its value (migration 2: lengths in units)."""
    if name in obj.PropertiesList:
        was = obj.getTypeIdOfProperty(name)
        if was == kind or was not in NUMBERS or kind not in NUMBERS:
            return
        kept = number(getattr(obj, name))
        obj.removeProperty(name)
        add(obj, kind, name, group, doc, kept, mode)
        return
    obj.addProperty(kind, name, group, doc)
    if value is not None:
        setattr(obj, name, value)
    if mode:
        obj.setEditorMode(name, mode)


def stamp(obj):
    """The FabGuide version that wrote the object, made or opened (and migrated) by this one: hidden, and an
    output, so stamping an opened document changes nothing a recompute depends on."""
    if "FabGuideVersion" not in obj.PropertiesList:
        obj.addProperty("App::PropertyString", "FabGuideVersion", "Base",
                        QT_TRANSLATE_NOOP("App::Property", "The FabGuide version that wrote this"),
                        HIDDEN | OUTPUT)
    obj.FabGuideVersion = fabguide.__version__


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


def number(v):
    """A property's number, whether a Quantity or a plain number."""
    return getattr(v, "Value", v)


def more_than(limit):
    return lambda obj, v: number(v) > limit, lambda: translate("FabGuide", "greater than {:g}").format(limit)


def at_least(limit, meaning=""):
    """`meaning`: marked with QT_TRANSLATE_NOOP("FabGuide", ...) by the caller."""
    return lambda obj, v: number(v) >= limit, lambda: translate("FabGuide", "{:g}{} or more").format(
        limit, translate("FabGuide", meaning) if meaning else "")


def shown(value):
    """A property's value as the user knows it: a quantity with its unit, objects by their labels."""
    if isinstance(value, list) and value and hasattr(value[0], "Label"):
        return ", ".join(shown(v) for v in value)
    if hasattr(value, "Label"):
        return "'{}'".format(value.Label)
    return getattr(value, "UserString", value)


def links(test, what):
    """A link or link list to objects that pass `test`, never to the object itself (a part among its own boxes
    is a cycle, which crashed FreeCAD); `what` marked with QT_TRANSLATE_NOOP("FabGuide", ...) by the caller."""
    def valid(obj, value):
        return all(o is None or (o != obj and test(o)) for o in (value if isinstance(value, list) else [value]))
    return valid, what


class Proxy(Stateless):
    """Base of FabGuide's FeaturePython proxies. Subclasses list their properties in `define(obj)` with
    `add`; restoring a document calls it again, so documents saved by an older FabGuide gain new properties.
    They recompute in `recompute(obj)`. VALID lists what a property's value must be, {name: (test(obj, value),
    what it must be)}: a value that fails is refused as it is typed (the old one stays, the report view says
    why), and a document that holds one anyway does not recompute."""

    VALID, NOUN = {}, QT_TRANSLATE_NOOP("FabGuide", "Object")

    def __init__(self, obj):
        obj.Proxy = self
        self.define_all(obj)

    def onDocumentRestored(self, obj):
        self.define_all(obj)

    def define_all(self, obj):
        self.define(obj)
        add(obj, "App::PropertyString", "Error", "Base",
            QT_TRANSLATE_NOOP("App::Property", "Why the last recompute failed; empty when it did not"),
            mode=2)
        stamp(obj)

    def onBeforeChange(self, obj, prop):
        if prop in self.VALID or typed_in(obj, prop):
            self.before = prop, getattr(obj, prop)  # on the proxy only: never saved

    def onChanged(self, obj, prop):
        before = getattr(self, "before", (None, None))
        problem = self.invalid(obj, prop)
        if problem and before[0] == prop and not obj.Document.Restoring:
            FreeCAD.Console.PrintError(translate("FabGuide", "{}; kept {}\n").format(problem, shown(before[1])))
            setattr(obj, prop, before[1])

    def invalid(self, obj, prop):
        """What is wrong with property `prop`'s value, as a sentence; "" when it is valid. Every number must be
        finite (a script can set inf or nan, which no spin box types)."""
        if prop not in obj.PropertiesList:
            return ""
        value = getattr(obj, prop)
        numbers = value if isinstance(value, list) else [value]
        if typed_in(obj, prop) and not all(abs(number(v)) < 1e100 for v in numbers):  # a length keeps inf as 1e308
            return translate("FabGuide", "{} '{}': {} must be a finite number").format(
                translate("FabGuide", self.NOUN), obj.Label, prop)
        test, must = self.VALID.get(prop, (None, ""))
        if test is None or test(obj, value):
            return ""
        return translate("FabGuide", "{} '{}': {} must be {}").format(
            translate("FabGuide", self.NOUN), obj.Label, prop,
            must() if callable(must) else translate("FabGuide", must))

    def execute(self, obj):
        """A mistake in the model (a ValueError: FabGuide's own errors, the core's FormatError; or the core's
        PackingError: it does not fit) is one plain sentence in the report view and in the object's Error (its
        tree icon is marked), never a traceback; `recompute` says it in the object's Status too, and clears the
        statuses it can no longer vouch for."""
        try:
            problem = next(filter(None, (self.invalid(obj, prop) for prop in self.VALID)), "")
            if problem:
                raise ValueError(problem)
            self.recompute(obj)
        except mistakes() as error:
            fail(obj, str(error), getattr(error, "source", None))
        else:
            fail(obj, "")

    def recompute(self, obj):
        pass


def mistakes():
    """The exceptions that are a mistake in the model, said as they are: ValueError, and the core's PackingError
    when the core is there (a clone without it still opens documents)."""
    try:
        from freecad.fabguide.core import fabguide_core
    except ImportError:
        return (ValueError,)
    return (ValueError, fabguide_core.PackingError)


def typed_in(obj, prop):
    """Whether `prop` is a number the user (or a script) sets: not a result FabGuide writes (read-only, hidden)."""
    return (prop in obj.PropertiesList and obj.getTypeIdOfProperty(prop) in TYPED and
            not {"ReadOnly", "Hidden"} & set(obj.getEditorMode(prop)))


def failed(obj):
    """Whether the last recompute of `obj` failed (said by FabGuide, or by FreeCAD for others' objects)."""
    return bool(getattr(obj, "Error", "")) or "Invalid" in obj.State


def failed_inputs(obj):
    """The labels of the objects `obj` is made from (at any depth) whose last recompute failed: FreeCAD then
    leaves `obj` touched, showing what it made from their last shapes."""
    return ["'{}'".format(label) for label in sorted(o.Label for o in obj.OutListRecursive if failed(o))]


def fail(obj, message, source=None):
    """Marks `obj` failed with `message` (said in the report view once), or not failed when it is empty. A failure
    that is another object's (`source`: a mechanism failing for its joint's missing edge) is not said again when
    that object has said it (its own Error)."""
    if obj.Error != message:
        if message and not (source not in (None, obj) and getattr(source, "Error", "")):
            FreeCAD.Console.PrintError(message + "\n")
        obj.Error = message


def is_a(obj, proxy_class):
    """Whether `obj` is a FabGuide object made by `proxy_class` (matched by its TYPE, not by identity, so
    objects restored from a file count too)."""
    return getattr(getattr(obj, "Proxy", None), "TYPE", None) == proxy_class.TYPE
