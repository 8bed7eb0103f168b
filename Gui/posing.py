"""Showing a mechanism in a configuration without touching the document: each moved box's scene gets an extra
Coin transform (thesis 4.1.2, J(Θ): a part moves by its joint, then by its base's joint, out to the ground).
Part of the way there, hinges and slides move in proportion; a double pivot follows its four-bar motion."""
import FreeCAD

import fabguide_core
from fabguide.function import joints, mechanism, parts


def turn(axis, degrees, centre):
    return FreeCAD.Placement(FreeCAD.Vector(), FreeCAD.Rotation(axis, degrees), centre)


def normal_axis(box, element):
    """The +x, +y or +z direction of a box's face or edge."""
    shape = box.Shape.getElement(element)
    if element.startswith("Face"):
        n = shape.normalAt(0, 0)
    else:
        n = shape.Vertexes[-1].Point - shape.Vertexes[0].Point
    return FreeCAD.Vector(*[1 if abs(c) > 1e-9 else 0 for c in n])


def joint_motion(joint, angle, offset, pole, fraction):
    """The rigid motion of a joint `fraction` of the way to a pose (angle, offset, pole)."""
    if joints.kind(joint) == "double_pivot":
        axis = normal_axis(joint.PivotFace[0], joint.PivotFace[1][0])
        u, w = [a for a in range(3) if abs(axis[a]) < 0.5]
        plane = lambda v: (v[u], v[w])  # noqa: E731
        link, part = fabguide_core.four_bar_angles(plane(joint.Pivot), plane(joint.BasePivot), plane(pole), angle)
        return turn(axis, fraction * link, joint.BasePivot).multiply(turn(axis, fraction * part, joint.Pivot))
    motion = FreeCAD.Placement()
    if joints.turns(joint) and angle:
        box, elements = joint.Edge
        start = box.Shape.getElement(elements[0]).Vertexes[0].Point
        motion = turn(normal_axis(box, elements[0]), fraction * angle, start)
    if joints.slides(joint) and offset:
        slide = FreeCAD.Vector(*[fraction * offset if joint.Axis == a else 0 for a in "xyz"])
        motion = FreeCAD.Placement(slide, FreeCAD.Rotation()).multiply(motion)
    return motion


def part_motions(mech, poses, fraction=1.0):
    """{part name: Placement} for poses {joint name: (angle, offset, pole)}; unposed joints stay as modelled."""
    moving = {j.Part.Name: j for j in mechanism.members(mech, joints.is_joint) if j.Part is not None}
    motions = {}
    for part in mechanism.members(mech, parts.is_part):
        total, joint, seen = FreeCAD.Placement(), moving.get(part.Name), set()
        while joint is not None and joint.Name not in seen:
            seen.add(joint.Name)
            if joint.Name in poses:
                total = joint_motion(joint, *poses[joint.Name], fraction).multiply(total)
            joint = moving.get(joint.Base.Name) if joint.Base is not None else None
        motions[part.Name] = total
    return motions


class Poser:
    """Adds a transform node in front of each box's scene; `show` sets them; `clear` removes them."""

    def __init__(self, mech):
        from pivy import coin

        self.mech, self.nodes = mech, {}
        for part in mechanism.members(mech, parts.is_part):
            for box in parts.boxes(part):
                if box.ViewObject is not None:
                    node = coin.SoTransform()
                    box.ViewObject.RootNode.insertChild(node, 0)
                    self.nodes[box.Name] = (box, part, node)

    def show(self, poses, fraction=1.0):
        motions = part_motions(self.mech, poses, fraction)
        for box, part, node in self.nodes.values():
            m = motions.get(part.Name, FreeCAD.Placement())
            node.translation.setValue(tuple(m.Base))
            node.rotation.setValue(tuple(m.Rotation.Q))

    def clear(self):
        for box, _, node in self.nodes.values():
            try:
                box.ViewObject.RootNode.removeChild(node)
            except (ReferenceError, RuntimeError, AttributeError):  # deleted meanwhile
                pass
        self.nodes = {}
