"""Showing a mechanism in a configuration without touching the document: each moved box's scene gets an extra
Coin transform (thesis 4.1.2, J(Θ): a part moves by its joint, then by its base's joint, out to the ground)."""
import FreeCAD

from fabguide.function import joints, mechanism, parts


def joint_motion(joint, angle, offset):
    """The rigid motion of a joint at a pose: a turn about its edge, then a slide along its axis."""
    motion = FreeCAD.Placement()
    if joints.turns(joint) and angle:
        box, elements = joint.Edge
        edge = box.Shape.getElement(elements[0])
        direction = edge.Vertexes[-1].Point - edge.Vertexes[0].Point
        axis = FreeCAD.Vector(*[1 if abs(c) > 1e-9 else 0 for c in direction])  # +x, +y or +z
        motion = FreeCAD.Placement(FreeCAD.Vector(), FreeCAD.Rotation(axis, angle), edge.Vertexes[0].Point)
    if joints.slides(joint) and offset:
        slide = FreeCAD.Vector(*[offset if joint.Axis == a else 0 for a in "xyz"])
        motion = FreeCAD.Placement(slide, FreeCAD.Rotation()).multiply(motion)
    return motion


def part_motions(mech, poses):
    """{part name: Placement} for poses {joint name: (angle, offset)}; unposed joints stay as modelled."""
    moving = {j.Part.Name: j for j in mechanism.members(mech, joints.is_joint) if j.Part is not None}
    motions = {}
    for part in mechanism.members(mech, parts.is_part):
        total, joint, seen = FreeCAD.Placement(), moving.get(part.Name), set()
        while joint is not None and joint.Name not in seen:
            seen.add(joint.Name)
            angle, offset = poses.get(joint.Name, (0.0, 0.0))
            total = joint_motion(joint, angle, offset).multiply(total)
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

    def show(self, poses):
        motions = part_motions(self.mech, poses)
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
