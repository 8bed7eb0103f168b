"""Joints (thesis 4.1.2): a hinge turns its part about an edge of one of its boxes, a slide moves it along an
axis, a sliding hinge does both; a double pivot links a point on a face of the part to a point on a coplanar face
of its Base by a rigid link (the solve places both pivots, 4.3.6); a fixed joint holds the part rigidly to its Base
(no poses; print-in-place fuses the two). A joint may hang on another moving part (its Base), which carries it."""
from freecad.fabguide.core import fabguide_core
from freecad.fabguide import properties
from freecad.fabguide import cuboids
from freecad.fabguide.function import parts
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

MOTIONS = {k["name"]: k for k in fabguide_core.joint_kinds()}  # how each kind moves, as the core says

AXES = ["x", "y", "z"]


class Joint(properties.Proxy):
    KIND, NOUN = None, QT_TRANSLATE_NOOP("FabGuide", "Joint")  # KIND as *.workslike.json names it
    VALID = dict(Part=properties.links(parts.is_part, QT_TRANSLATE_NOOP("FabGuide", "a FabGuide part")),
                 Base=properties.links(parts.is_part,
                                       QT_TRANSLATE_NOOP("FabGuide", "a FabGuide part (empty: the ground)")))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLink", "Part", "Joint", QT_TRANSLATE_NOOP("App::Property", "The part the joint moves"))
        add(obj, "App::PropertyLink", "Base", "Joint",
            QT_TRANSLATE_NOOP("App::Property", "The part it hangs on, which carries it along when it moves; empty: the "
                                               "ground"))
        if MOTIONS[self.KIND]["turns"]:
            add(obj, "App::PropertyLinkSub", "Edge", "Joint",
                QT_TRANSLATE_NOOP("App::Property", "The edge of one of the part's boxes it turns about"))
        if MOTIONS[self.KIND]["slides"]:
            add(obj, "App::PropertyEnumeration", "Axis", "Joint",
                QT_TRANSLATE_NOOP("App::Property", "The direction it slides along"), AXES)
        if self.KIND == "double_pivot":
            add(obj, "App::PropertyLinkSub", "PivotFace", "Double pivot",
                QT_TRANSLATE_NOOP("App::Property", "The face of the part's box with the pivot"))
            add(obj, "App::PropertyVector", "Pivot", "Double pivot",
                QT_TRANSLATE_NOOP("App::Property", "The pivot on the part (placed by the solve)"))
            add(obj, "App::PropertyLinkSub", "BasePivotFace", "Double pivot",
                QT_TRANSLATE_NOOP("App::Property", "The face of the base's box, in the same plane, with the other "
                                                   "pivot"))
            add(obj, "App::PropertyVector", "BasePivot", "Double pivot",
                QT_TRANSLATE_NOOP("App::Property", "The pivot on the base (placed by the solve)"))

    def recompute(self, obj):
        as_dict(obj)


class Hinge(Joint):
    TYPE, KIND = "FabGuide::Hinge", "hinge"


class Slide(Joint):
    TYPE, KIND = "FabGuide::Slide", "slide"


class SlidingHinge(Joint):
    TYPE, KIND = "FabGuide::SlidingHinge", "sliding_hinge"


class DoublePivot(Joint):
    TYPE, KIND = "FabGuide::DoublePivot", "double_pivot"


class Fixed(Joint):
    TYPE, KIND = "FabGuide::Fixed", "fixed"


KINDS = {cls.KIND: cls for cls in (Hinge, Slide, SlidingHinge, DoublePivot, Fixed)}


class JointError(ValueError):
    """A joint that names nothing it can move; the message names the joint."""


def create(doc, kind, part, edge=None, axis=None, base=None, label=None, pivots=None):
    """kind: "hinge", "slide", "sliding_hinge", "double_pivot" or "fixed"; edge: (box, "EdgeN"); axis: "x", "y" or "z";
    pivots: ((box, "FaceN", Vector) on the part, (box, "FaceN", Vector) on the base)."""
    cls = KINDS[kind]
    obj = doc.addObject("App::FeaturePython", cls.__name__)
    cls(obj)
    name = part.Label[:-len(" part")] if part.Label.endswith(" part") else part.Label
    obj.Label = label or "{} {}".format(name, kind.replace("_", " "))  # "Lid hinge"
    obj.Part, obj.Base = part, base
    if edge is not None:
        obj.Edge = edge
    if axis is not None:
        obj.Axis = axis
    if pivots is not None:
        (obj.PivotFace, obj.Pivot), (obj.BasePivotFace, obj.BasePivot) = [((box, [face]), point)
                                                                         for box, face, point in pivots]
    return obj


def is_joint(obj):
    return any(properties.is_a(obj, cls) for cls in KINDS.values())


def kind(obj):
    return obj.Proxy.KIND


def turns(obj):
    """Turns about an edge (hinges)."""
    return MOTIONS[kind(obj)]["turns"]


def slides(obj):
    return MOTIONS[kind(obj)]["slides"]


def angled(obj):
    """Posed by an angle: it turns about an edge, or (a double pivot) about its pole."""
    return turns(obj) or kind(obj) == "double_pivot"


def moves(obj):
    """Configurations can pose it (a fixed joint never moves its part against its base)."""
    return kind(obj) != "fixed"


def as_dict(obj):
    if obj.Part is None:
        raise JointError(translate("FabGuide", "Joint '{}': choose the Part it moves").format(obj.Label))
    out = {"name": obj.Label, "type": kind(obj), "part": obj.Part.Label}
    if obj.Base is not None:
        out["base"] = obj.Base.Label
    if turns(obj):
        if obj.Edge is None or not obj.Edge[1]:
            raise JointError(translate("FabGuide", "Joint '{}': choose the Edge it turns about").format(obj.Label))
        box, elements = obj.Edge
        if box not in obj.Part.Cuboids:
            raise JointError(translate("FabGuide", "Joint '{}': its edge is on '{}', which is not a box of part '{}'")
                             .format(obj.Label, box.Label, obj.Part.Label))
        try:
            out["edge"] = ["{}.{}".format(box.Label, side) for side in cuboids.edge_sides(box, elements[0])]
        except cuboids.CuboidError as error:
            raise JointError(translate("FabGuide", "Joint '{}': {}").format(obj.Label, error))
    if slides(obj):
        out["axis"] = obj.Axis
    if kind(obj) == "fixed" and obj.Base is None:
        raise JointError(translate("FabGuide", "Fixed joint '{}': choose the Base part it holds '{}' to").format(
            obj.Label, obj.Part.Label))
    if kind(obj) == "double_pivot":
        if obj.Base is None:
            raise JointError(translate("FabGuide", "Double pivot '{}': choose the Base part it links to").format(
                obj.Label))
        for key, face, point, part in (("pivot", obj.PivotFace, obj.Pivot, obj.Part),
                                       ("base_pivot", obj.BasePivotFace, obj.BasePivot, obj.Base)):
            if face is None or not face[1] or face[0] not in part.Cuboids:
                raise JointError(translate("FabGuide", "Double pivot '{}': choose a face of a box of '{}' for its "
                                                       "{}").format(
                    obj.Label, part.Label, key.replace("_", " ")))
            out[key] = [cuboids.face_name(face[0], face[1][0]), list(point)]
    return out
