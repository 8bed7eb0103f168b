"""Joints (thesis 4.1.2): a hinge turns its part about an edge of one of its boxes, a slide moves it along an
axis, a sliding hinge does both. A joint may hang on another moving part (its Base), which carries it."""
from fabguide import properties
from fabguide.function import cuboids

AXES = ["x", "y", "z"]


class Joint(properties.Proxy):
    KIND = None  # as *.workslike.json names it

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLink", "Part", "Joint", "The part the joint moves")
        add(obj, "App::PropertyLink", "Base", "Joint",
            "The part it hangs on, which carries it along when it moves; empty: the ground")
        if self.KIND != "slide":
            add(obj, "App::PropertyLinkSub", "Edge", "Joint", "The edge of one of the part's boxes it turns about")
        if self.KIND != "hinge":
            add(obj, "App::PropertyEnumeration", "Axis", "Joint", "The direction it slides along", AXES)

    def execute(self, obj):
        as_dict(obj)


class Hinge(Joint):
    TYPE, KIND = "FabGuide::Hinge", "hinge"


class Slide(Joint):
    TYPE, KIND = "FabGuide::Slide", "slide"


class SlidingHinge(Joint):
    TYPE, KIND = "FabGuide::SlidingHinge", "sliding_hinge"


KINDS = {cls.KIND: cls for cls in (Hinge, Slide, SlidingHinge)}


class JointError(ValueError):
    """A joint that names nothing it can move; the message names the joint."""


def create(doc, kind, part, edge=None, axis=None, base=None, label=None):
    """kind: "hinge", "slide" or "sliding_hinge"; edge: (box, "EdgeN"); axis: "x", "y" or "z"."""
    cls = KINDS[kind]
    obj = doc.addObject("App::FeaturePython", cls.__name__)
    cls(obj)
    obj.Label = label or "{} {}".format(part.Label, kind.replace("_", " "))
    obj.Part, obj.Base = part, base
    if edge is not None:
        obj.Edge = edge
    if axis is not None:
        obj.Axis = axis
    return obj


def is_joint(obj):
    return any(properties.is_a(obj, cls) for cls in KINDS.values())


def kind(obj):
    return obj.Proxy.KIND


def turns(obj):
    return kind(obj) != "slide"


def slides(obj):
    return kind(obj) != "hinge"


def as_dict(obj):
    if obj.Part is None:
        raise JointError("Joint '{}': choose the Part it moves".format(obj.Label))
    out = {"name": obj.Label, "type": kind(obj), "part": obj.Part.Label}
    if obj.Base is not None:
        out["base"] = obj.Base.Label
    if turns(obj):
        if obj.Edge is None or not obj.Edge[1]:
            raise JointError("Joint '{}': choose the Edge it turns about".format(obj.Label))
        box, elements = obj.Edge
        if box not in obj.Part.Cuboids:
            raise JointError("Joint '{}': its edge is on '{}', which is not a box of part '{}'"
                             .format(obj.Label, box.Label, obj.Part.Label))
        out["edge"] = ["{}.{}".format(box.Label, side) for side in cuboids.edge_sides(box, elements[0])]
    if slides(obj):
        out["axis"] = obj.Axis
    return out
