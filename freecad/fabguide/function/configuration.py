"""A configuration (thesis 4.1.2): named poses of joints, in which relationships must hold."""
import FreeCAD

from freecad.fabguide import properties
from freecad.fabguide.function import joints
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate


POSES = "Poses"  # the property group of each joint's angle and offset


class Configuration(properties.Proxy):
    TYPE, NOUN = "FabGuide::Configuration", QT_TRANSLATE_NOOP("FabGuide", "Configuration")
    VALID = dict(Joints=properties.links(joints.is_joint, QT_TRANSLATE_NOOP("FabGuide", "joints")))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLinkList", "Joints", "Configuration",
            QT_TRANSLATE_NOOP("App::Property", "The joints it moves"))
        add(obj, "App::PropertyVectorList", "Poles", "Configuration",
            QT_TRANSLATE_NOOP("App::Property", "Per joint: for a double pivot, the point its part turns about to get "
                                               "here"))
        if "Angles" in obj.PropertiesList:  # migration 4: up to 0.2.0, plain lists per joint
            angles, offsets = list(obj.Angles), list(getattr(obj, "Offsets", []))
            obj.removeProperty("Angles")
            if "Offsets" in obj.PropertiesList:
                obj.removeProperty("Offsets")
            set_poses(obj, [(j, angles[k] if k < len(angles) else 0.0, offsets[k] if k < len(offsets) else 0.0)
                            for k, j in enumerate(obj.Joints)])

    def recompute(self, obj):
        as_dict(obj)


def create(doc, label, poses, poles=None):
    """poses: [(joint, angle, offset)]; poles: a Vector per pose (used by double pivots)."""
    obj = doc.addObject("App::FeaturePython", "Configuration")
    Configuration(obj)
    obj.Label = label
    set_poses(obj, poses, poles)
    return obj


def pose_properties(joint):
    """{property: (type, tip)} of a joint's pose in a configuration: an angle (degrees) for what turns, an offset
    (mm) for what slides; properties of their own, so they take units and expressions (a spreadsheet's cell)."""
    posed = {}
    if joints.angled(joint):
        posed[joint.Name + "Angle"] = ("App::PropertyAngle", QT_TRANSLATE_NOOP(
            "App::Property", "How far the joint turns its part (right-handed about its edge's +x/+y/+z direction)"))
    if joints.slides(joint):
        posed[joint.Name + "Offset"] = ("App::PropertyDistance",
                                        QT_TRANSLATE_NOOP("App::Property", "How far the joint slides its part"))
    return posed


def set_poses(obj, poses, poles=None):
    """poses: [(joint, angle, offset)]; poles: a Vector per pose (double pivots), else kept where they were. The
    properties of joints no longer posed go."""
    kept = dict(zip([j.Name for j in obj.Joints], obj.Poles))
    obj.Joints = [j for j, _, _ in poses]
    wanted = {}
    for joint, angle, offset in poses:
        for name, (kind, tip) in pose_properties(joint).items():
            properties.add(obj, kind, name, POSES, tip)
            wanted[name] = angle if kind == "App::PropertyAngle" else offset
    for name in obj.PropertiesList:
        if obj.getGroupOfProperty(name) == POSES and name not in wanted:
            obj.removeProperty(name)
    for name, value in wanted.items():
        setattr(obj, name, float(value))
    obj.Poles = list(poles) if poles is not None else [kept.get(j.Name, FreeCAD.Vector()) for j, _, _ in poses]


def poses(obj):
    """[(joint, angle in degrees, offset in mm)]; what a joint does not do reads 0."""
    def value(name):
        return getattr(obj, name).Value if name in obj.PropertiesList else 0.0
    return [(j, value(j.Name + "Angle"), value(j.Name + "Offset")) for j in obj.Joints]


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
    if joints.kind(joint) == "double_pivot":
        return {"angle": angle, "pole": list(pole)}
    if joints.turns(joint) and joints.slides(joint):
        return {"angle": angle, "offset": offset}
    return angle if joints.turns(joint) else offset
