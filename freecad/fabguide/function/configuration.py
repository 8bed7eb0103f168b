"""A configuration (thesis 4.1.2): named poses of joints, in which relationships must hold."""
import FreeCAD

from freecad.fabguide import properties
from freecad.fabguide.function import joints
from freecad.fabguide.i18n import translate


class Configuration(properties.Proxy):
    TYPE, NOUN = "FabGuide::Configuration", "Configuration"
    VALID = dict(Joints=properties.links(joints.is_joint, "joints"))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLinkList", "Joints", "Configuration", "The joints it moves")
        add(obj, "App::PropertyFloatList", "Angles", "Configuration",
            "Per joint: the hinge angle in degrees (right-handed about the edge's +x/+y/+z direction)")
        add(obj, "App::PropertyFloatList", "Offsets", "Configuration", "Per joint: the slide offset in mm")
        add(obj, "App::PropertyVectorList", "Poles", "Configuration",
            "Per joint: for a double pivot, the point its part turns about (with Angles) to get here")

    def recompute(self, obj):
        as_dict(obj)


def create(doc, label, poses, poles=None):
    """poses: [(joint, angle, offset)]; poles: a Vector per pose (used by double pivots)."""
    obj = doc.addObject("App::FeaturePython", "Configuration")
    Configuration(obj)
    obj.Label = label
    set_poses(obj, poses, poles)
    return obj


def set_poses(obj, poses, poles=None):
    """poses: [(joint, angle, offset)]; poles: a Vector per pose (double pivots), else kept where they were."""
    kept = dict(zip([j.Name for j in obj.Joints], obj.Poles))
    obj.Joints = [j for j, _, _ in poses]
    obj.Angles = [float(a) for _, a, _ in poses]
    obj.Offsets = [float(o) for _, _, o in poses]
    obj.Poles = list(poles) if poles is not None else [kept.get(j.Name, FreeCAD.Vector()) for j, _, _ in poses]


def poses(obj):
    """[(joint, angle, offset)], missing list entries read as 0."""
    angles, offsets = list(obj.Angles), list(obj.Offsets)
    return [(j, angles[k] if k < len(angles) else 0.0, offsets[k] if k < len(offsets) else 0.0)
            for k, j in enumerate(obj.Joints)]


def pole(obj, joint):
    """The pole a configuration turns a double pivot's part about."""
    names = [j.Name for j in obj.Joints]
    poles = list(obj.Poles)
    k = names.index(joint.Name) if joint.Name in names else len(poles)
    return poles[k] if k < len(poles) else FreeCAD.Vector()


def is_configuration(obj):
    return properties.is_a(obj, Configuration)


def as_dict(obj):
    out = {}
    for joint, angle, offset in poses(obj):
        if not joints.is_joint(joint):
            raise ValueError(translate("FabGuide", "Configuration '{}': '{}' is not a joint").format(
                obj.Label, joint.Label))
        out[joint.Label] = pose_dict(joint, angle, offset, pole(obj, joint))
    return {"name": obj.Label, "poses": out}


def pose_dict(joint, angle, offset, pole):
    """A joint's pose as *.workslike.json writes it."""
    kind = joints.kind(joint)
    return ({"angle": angle, "offset": offset} if kind == "sliding_hinge"
            else {"angle": angle, "pole": list(pole)} if kind == "double_pivot"
            else angle if kind == "hinge" else offset)
