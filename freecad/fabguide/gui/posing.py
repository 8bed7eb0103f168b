"""Showing a mechanism in a configuration without touching the document: each moved box's scene gets an extra
Coin transform. The motion is the core's (thesis 4.1.2, J(Θ): a part moves by its joint, then by its base's
joint, out to the ground), the one the print's sweeps and clearance check follow: part of the way there,
everything that turns does so in the first half and everything that slides in the second; a double pivot
follows its four-bar motion."""
import re

import FreeCAD

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import messages
from freecad.fabguide.function import configuration, joints, mechanism, parts

PREVIEW = "FabGuide preview"  # the configuration being shown, added to the model for the core


def part_motions(model, mech, poses, fraction=1.0):
    """{part name: Placement} `fraction` of the way to poses {joint Name: (angle, offset, pole)}, for the
    mechanism's `model` (mechanism.model); unposed joints stay as modelled."""
    by_name = {j.Name: j for j in mechanism.members(mech, joints.is_joint)}
    preview = {by_name[n].Label: configuration.pose_dict(by_name[n], *pose) for n, pose in poses.items()}
    shown = dict(model, configurations=model["configurations"] + [{"name": PREVIEW, "poses": preview}])
    try:
        rows = fabguide_core.part_motions(shown, PREVIEW, fraction)
    except fabguide_core.FormatError as error:  # "configuration 'FabGuide preview' poses.Lid hinge: ..."
        said = messages.in_words(str(error), shown, messages.WORKSLIKE)
        raise ValueError(re.sub(r"configuration '{}' poses[. ](.+?)(\.angle|\.offset|\.pole)?: ".format(PREVIEW),
                                lambda m: "joint '{}'{}: ".format(m.group(1), (m.group(2) or "").replace(".", " ")),
                                said))
    return {name: FreeCAD.Placement(FreeCAD.Matrix(*r[0], *r[1], *r[2], 0, 0, 0, 1)) for name, r in rows.items()}


class Poser:
    """Adds a transform node in front of each box's scene; `show` sets them and draws the joints posed; `clear`
    removes them and draws the joints as modelled."""

    def __init__(self, mech):
        from pivy import coin

        self.mech, self.nodes, self.model = mech, {}, None
        for part in mechanism.members(mech, parts.is_part):
            for box in parts.boxes(part):
                if box.ViewObject is not None:
                    node = coin.SoTransform()
                    box.ViewObject.RootNode.insertChild(node, 0)
                    self.nodes[box.Name] = (box, part, node)
        self.joints = [j.ViewObject.Proxy for j in mechanism.members(mech, joints.is_joint)
                       if j.ViewObject is not None and hasattr(j.ViewObject.Proxy, "redraw")]

    def show(self, poses, fraction=1.0):
        """Poses the boxes; a model the core cannot read stays as modelled, and the reason is returned."""
        try:
            self.model = self.model or mechanism.model(self.mech)
            motions = part_motions(self.model, self.mech, poses, fraction)
        except ValueError as error:
            motions = {}
            reason = str(error)
        else:
            reason = ""
        for box, part, node in self.nodes.values():
            m = motions.get(part.Label, FreeCAD.Placement())
            node.translation.setValue(tuple(m.Base))
            node.rotation.setValue(tuple(m.Rotation.Q))
        for joint in self.joints:
            joint.redraw(motions)
        return reason

    def clear(self):
        for box, _, node in self.nodes.values():
            try:
                box.ViewObject.RootNode.removeChild(node)
            except (ReferenceError, RuntimeError, AttributeError):  # deleted meanwhile
                pass
        for joint in self.joints:
            joint.redraw()
        self.nodes, self.joints = {}, []
