"""Printable: a mechanism turned into print-in-place bodies (thesis 4.5): one Part::Feature per part (and per
double-pivot link) in a group, remade on recompute when the mechanism changes; the clearance found along every
motion is shown, and the bodies export as STL, 3MF and STEP."""
import FreeCAD
import Part

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import background, messages, preferences, properties
from freecad.fabguide.function import mechanism
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

PRINTERS = dict([(p["name"], p["gap"]) for p in fabguide_core.printer_profiles()] + [("Custom", None)])


class PrintableError(ValueError):
    """A mechanism that cannot be made printable; the message names the printable and the reason."""


class Printable(properties.Proxy):
    TYPE = "FabGuide::Printable"
    NOUN, VALID = QT_TRANSLATE_NOOP("FabGuide", "Printable"), dict(Scale=properties.more_than(0),
                                    Mechanism=properties.links(mechanism.is_mechanism, "a Mechanism"))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLink", "Mechanism", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "The mechanism to print in place"))
        add(obj, "App::PropertyEnumeration", "Printer", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "Printer profile: the gap it needs"), list(PRINTERS))
        add(obj, "App::PropertyLength", "Gap", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "Clearance between parts (set by the printer profile)"),
            preferences.get("Gap"))
        add(obj, "App::PropertyFloat", "Scale", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "Print at this scale (0.2 for 1:5); the gap stays as it is"), 1.0)
        add(obj, "App::PropertyBool", "FitToBuildVolume", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "Print at the largest scale (at most 1) that fits the build volume; "
                                               "sets Scale"), False)
        add(obj, "App::PropertyVector", "BuildVolume", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "The printer's build volume in mm: width (x), depth (y), height (z); "
                                               "the print may turn a quarter about z"),
            FreeCAD.Vector(*(preferences.get("BuildVolume" + axis) for axis in "XYZ")))
        add(obj, "App::PropertyString", "PrintSize", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Width x depth x height of the print"), mode=1)
        add(obj, "App::PropertyBool", "TurnedOnBed", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Fitted turned a quarter about z: exported so, shown as "
                                               "modelled"), False, mode=1)
        add(obj, "App::PropertyBool", "ShowCavities", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "Show the volumes swept into cavities"), False)
        add(obj, "App::PropertyBool", "CheckMotion", "Printable",
            QT_TRANSLATE_NOOP("App::Property", "Measure the clearance at 32 poses along every configuration's "
                                               "motion"), True)
        add(obj, "App::PropertyLength", "MinimumClearance", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Least distance between two bodies"), mode=1)
        add(obj, "App::PropertyString", "ClearanceAt", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Where the least distance is"), mode=1)
        add(obj, "App::PropertyStringList", "Notes", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Joints made without geometry, and why"), mode=1)

    def onChanged(self, obj, prop):
        super().onChanged(obj, prop)
        if prop == "Printer" and PRINTERS.get(obj.Printer) is not None and "Gap" in obj.PropertiesList:
            obj.Gap = PRINTERS[obj.Printer]
        if prop == "FitToBuildVolume" and "Scale" in obj.PropertiesList:
            obj.setEditorMode("Scale", 1 if obj.FitToBuildVolume else 0)

    def recompute(self, obj):
        data = bodies(obj)
        by_name = {child.BodyName: child for child in obj.Group if hasattr(child, "BodyName")}
        missing = [b["name"] for b in data["bodies"] if b["name"] not in by_name]
        if missing:
            raise PrintableError(translate("FabGuide", "Printable '{}': the mechanism has new parts ({}); run Make "
                                                       "Printable again")
                                 .format(obj.Label, ", ".join(missing)))
        for b in data["bodies"]:
            shape = Part.Shape()
            shape.importBrepFromString(b["brep"])
            by_name[b["name"]].Shape = shape
            by_name[b["name"]].purgeTouched()  # made here, within this recompute
        cavities = [c for c in obj.Group if getattr(c, "BodyName", None) == CAVITIES]
        for c in cavities:
            shapes = []
            for text in data["sweeps"] if obj.ShowCavities else []:
                s = Part.Shape()
                s.importBrepFromString(text)
                shapes.append(s)
            c.Shape = Part.makeCompound(shapes) if shapes else Part.Shape()
            c.purgeTouched()
        if obj.CheckMotion:
            obj.MinimumClearance = data["clearance"]
            obj.ClearanceAt = data["where"]
            if data["invalid"]:
                raise PrintableError(translate("FabGuide", "Printable '{}': invalid solids: {}").format(
                    obj.Label, ", ".join(data["invalid"])))
            if data["loose"]:
                raise PrintableError(translate("FabGuide", "Printable '{}': bodies that print in pieces ({}): a cut "
                                                           "went through them, a joint turning the wrong way round or "
                                                           "a part in the way").format(
                    obj.Label, "; ".join(data["loose"])))
            if data["too_close"]:
                FreeCAD.Console.PrintWarning(translate("FabGuide", "{}: parts come within {:.3f} mm of each other "
                                                                   "({}), less than the {} mm gap\n").format(
                    obj.Label, data["clearance"], data["where"], obj.Gap.Value))
        obj.Notes = data["notes"]
        if obj.FitToBuildVolume:
            obj.Scale = data["scale"]
        obj.TurnedOnBed = data["turned"]
        obj.PrintSize = "{:.1f} x {:.1f} x {:.1f} mm".format(*data["size"]) + (
            ", turned a quarter on the bed" if data["turned"] else "")


CAVITIES = "cavities swept"


def bodies(obj):
    if obj.Mechanism is None:
        raise PrintableError(translate("FabGuide", "Printable '{}': choose the Mechanism to print").format(obj.Label))
    try:
        arguments = mechanism.model(obj.Mechanism), obj.Gap.Value, obj.CheckMotion, obj.Scale, fit(obj)
        return background.run(translate("FabGuide", "Making the bodies of '{}'").format(obj.Label),
                              lambda cancel: fabguide_core.printable(*arguments), stoppable=False)
    except (fabguide_core.FormatError, RuntimeError) as error:
        raise PrintableError(translate("FabGuide", "Printable '{}': {}").format(
            obj.Label, messages.in_words(str(error), arguments[0], messages.WORKSLIKE)))


def fit(obj):
    """The build volume to fit the print to, or None to print at Scale."""
    if not obj.FitToBuildVolume:
        return None
    volume = tuple(obj.BuildVolume)
    if min(volume) <= 0:
        raise PrintableError(translate("FabGuide", "Printable '{}': BuildVolume must be greater than 0 in x, y and z "
                                                   "(is {:g} x {:g} x {:g})")
                             .format(obj.Label, *volume))
    return volume


def create(doc, mech, label=None):
    """The Printable group and one body per part and link of the mechanism."""
    obj = doc.addObject("App::DocumentObjectGroupPython", "Printable")
    Printable(obj)
    gap = preferences.get("Gap")  # the printer profile of the preferences' gap, else Custom
    obj.Printer = next((name for name, value in PRINTERS.items() if value == gap), "Custom")
    obj.Gap = gap
    obj.Label = label or mech.Label + " printable"
    obj.Mechanism = mech
    sync(obj)
    return obj


def sync(obj):
    """One Part::Feature per body (named by BodyName), plus one for the swept cavities; returns those added."""
    names = fabguide_core.printable_body_names(mechanism.model(obj.Mechanism))
    have = {getattr(c, "BodyName", None) for c in obj.Group}
    added = []
    for name in [n for n in names + [CAVITIES] if n not in have]:
        child = obj.Document.addObject("Part::Feature", "Body")
        child.addProperty("App::PropertyString", "BodyName", "Printable",
                          QT_TRANSLATE_NOOP("App::Property", "The body this shape is"))
        child.BodyName = name
        child.setEditorMode("BodyName", 1)
        child.Label = name + " printed"
        added.append(child)
    obj.Group = obj.Group + added
    return added


def is_printable(obj):
    return properties.is_a(obj, Printable)


def export(obj, folder):
    """assembly.stl/.3mf/.step and one of each per body into folder, the bodies as made (turned a quarter on the
    bed when the fit says so); the paths written."""
    failed = [o for o in [obj] + obj.OutListRecursive if properties.failed(o)]
    if failed:  # recomputing does not mend it
        raise PrintableError(translate("FabGuide", "Printable '{}': {}; mend that first").format(
            obj.Label, getattr(failed[0], "Error", "") or "'{}' is in error".format(failed[0].Label)))
    stale = [o.Label for o in [obj] + obj.OutListRecursive if "Touched" in o.State]
    if stale:
        raise PrintableError(translate("FabGuide", "Printable '{}': not made from the mechanism as it stands ({} "
                                                   "changed); recompute first")
                             .format(obj.Label, ", ".join(stale)))
    made = [c for c in obj.Group if getattr(c, "BodyName", CAVITIES) != CAVITIES]
    empty = [c.Label for c in made if c.Shape.isNull()]
    if empty:
        raise PrintableError(translate("FabGuide", "Printable '{}': {} not made yet; recompute it first").format(
            obj.Label, ", ".join(empty)))
    bodies = [{"name": c.BodyName, "brep": c.Shape.exportBrepToString()} for c in made]
    return fabguide_core.write_printable(bodies, folder, obj.TurnedOnBed)
