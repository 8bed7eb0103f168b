"""Configurations task panel (thesis 4.1.2): name a configuration, pose its joints, and move the mechanism
between the base pose and that configuration with a slider; OK stores it (one undo step) and makes it the one
new relationships hold in."""
import os

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from freecad.fabguide.function import configuration, joints, mechanism
from freecad.fabguide.gui import editing, function_viewproviders as vp, resources
from freecad.fabguide.gui.posing import Poser
from freecad.fabguide.i18n import translate


def quantity_box(loader, unit, largest, parent):
    """A unit-aware spin box: it takes what FreeCAD's quantities take, "1 in", "90/2 °", and shows the value in
    the user's units; a value beyond ±`largest` is refused whole on OK (editing.widened). Made by a `loader` the
    panel keeps, as a child of `parent` at once: under PySide6 (FreeCAD 1.1) a box made by a loader that was
    then collected could be deleted before its signals were connected."""
    box = loader.createWidget("Gui::QuantitySpinBox", parent)
    box.setProperty("unit", unit)
    box.setProperty("minimum", -largest)
    box.setProperty("maximum", largest)
    box.setButtonSymbols(QtGui.QAbstractSpinBox.NoButtons)  # room for "-180.00 °" in a narrow combo view
    return editing.widened(box)


def value(box):
    """A quantity spin box's value in mm or degrees."""
    return float(box.property("rawValue"))


class ConfigurationsPanel:
    def __init__(self, mech, shown=None):
        self.mech = mech
        self.joints = mechanism.members(mech, joints.is_joint)
        self.configurations = mechanism.members(mech, configuration.is_configuration)
        self.poser = Poser(mech)
        self.form = FreeCADGui.PySideUic.loadUi(os.path.join(resources.RESOURCES, "ui", "ConfigurationsPanel.ui"))
        self.form.setWindowIcon(FreeCADGui.getIcon(resources.icon("FabGuide_Configurations.svg")))
        for name in ("choice", "name", "slider", "play", "status"):
            setattr(self, name, getattr(self.form, name))
        self.choice.addItems([translate("FabGuide", "{} (current)").format(c.Label) if c == mech.ShownConfiguration
                              else c.Label for c in self.configurations] + [translate("FabGuide", "New configuration")])
        # A long configuration name elides rather than widening the panel past the screen (and OK with it).
        self.choice.setSizeAdjustPolicy(QtGui.QComboBox.AdjustToMinimumContentsLengthWithIcon)
        self.choice.setMinimumContentsLength(10)
        grid = self.form.poses
        self.loader = FreeCADGui.UiLoader()
        self.moves, self.angles, self.offsets = [], [], []
        for row, joint in enumerate(self.joints):  # the joint's name on a line, its angle and offset below it
            moves = QtGui.QCheckBox(joint.Label)
            moves.setToolTip(joint.Label)
            angle = quantity_box(self.loader, "deg", 360, self.form)
            offset = quantity_box(self.loader, "mm", 1e5, self.form)
            angle.setToolTip(translate("FabGuide", "Angle: its sign is the way the part swings"))
            offset.setToolTip(translate("FabGuide", "Offset along the slide"))
            moves.setEnabled(joints.moves(joint))
            grid.addWidget(moves, 2 * row, 0, 1, 3)
            for column, box, used in ((1, angle, joints.angled(joint)),
                                      (2, offset, joints.slides(joint))):
                box.setEnabled(used)
                box.setVisible(used)
                grid.addWidget(box, 2 * row + 1, column)
                box.valueChanged.connect(self.preview)
            moves.toggled.connect(self.preview)
            self.moves.append(moves)
            self.angles.append(angle)
            self.offsets.append(offset)
        self.slider.valueChanged.connect(self.preview)
        editing.on_click(self.play, self.animate)
        self.timer = QtCore.QTimer()
        self.timer.timeout.connect(self.step)
        self.direction = -4
        self.choice.currentIndexChanged.connect(self.load)
        start = self.configurations.index(shown) if shown in self.configurations else (
            self.configurations.index(mech.ShownConfiguration) if mech.ShownConfiguration in self.configurations else 0)
        self.choice.setCurrentIndex(start)
        self.load(start)

    def load(self, index):
        chosen = self.configurations[index] if index < len(self.configurations) else None
        poses = {j.Name: (a, o) for j, a, o in configuration.poses(chosen)} if chosen else {}
        self.name.setText(chosen.Label if chosen else translate("FabGuide", "Configuration {}").format(
            len(self.configurations) + 1))
        for row, joint in enumerate(self.joints):
            angle, offset = poses.get(joint.Name, (0.0, 0.0))
            for widget, value in ((self.moves[row], joint.Name in poses), (self.angles[row], angle),
                                  (self.offsets[row], offset)):
                widget.blockSignals(True)
                if isinstance(widget, QtGui.QCheckBox):
                    widget.setChecked(value)
                else:
                    widget.setProperty("rawValue", value)
                widget.blockSignals(False)
        self.preview()

    def poses(self):
        """{joint name: (angle, offset, pole)} of the checked joints."""
        chosen = self.chosen()
        return {j.Name: (value(self.angles[r]), value(self.offsets[r]),
                         configuration.pole(chosen, j) if chosen else j.BasePivot if joints.kind(j) == "double_pivot"
                         else FreeCAD.Vector())
                for r, j in enumerate(self.joints) if self.moves[r].isChecked()}

    def chosen(self):
        index = self.choice.currentIndex()
        return self.configurations[index] if index < len(self.configurations) else None

    def preview(self, *args):
        reason = self.poser.show(self.poses(), self.slider.value() / 100.0)
        moved = ", ".join(self.joints[r].Label for r in range(len(self.joints)) if self.moves[r].isChecked())
        self.status.setText(translate("FabGuide", "Cannot show it: {}").format(reason) if reason else
                            translate("FabGuide", "Moves: {}").format(moved) if moved else
                            translate("FabGuide", "Moves: nothing yet: tick the joints this configuration poses"))
        FreeCADGui.updateGui()

    def animate(self):
        if self.timer.isActive():
            self.timer.stop()
            self.play.setText(translate("FabGuide", "Play"))
        else:
            self.timer.start(30)
            self.play.setText(translate("FabGuide", "Stop"))

    def step(self):
        position = self.slider.value() + self.direction
        if not 0 <= position <= 100:
            self.direction = -self.direction
            position = max(0, min(100, position))
        self.slider.setValue(position)

    def unreadable(self):
        """What is typed wrong in a used field, as a sentence; "" when every field reads."""
        said = {"Angle": translate("FabGuide", "The angle of {}: \"{}\" is not an angle from {:g} to {:g}; type it "
                                                "again."),
                "Length": translate("FabGuide", "The offset of {}: \"{}\" is not a length from {:g} to {:g}; type it "
                                                "again.")}
        for row, joint in enumerate(self.joints):
            for box, unit in ((self.angles[row], "Angle"), (self.offsets[row], "Length")):
                if self.moves[row].isChecked() and box.isVisible() and not editing.readable(box, unit):
                    return said[unit].format(joint.Label, box.text(), *editing.limits(box))
        return ""

    def accept(self):
        mistake = self.unreadable()
        if mistake:  # the panel stays open with what was typed: nothing half-typed is stored
            self.status.setText("<b>{}</b>".format(mistake))
            return False
        index, label, poses = self.choice.currentIndex(), self.name.text(), self.poses()  # before the form goes
        posed = [(j, value(self.angles[r]), value(self.offsets[r])) for r, j in enumerate(self.joints)
                 if self.moves[r].isChecked()]
        self.close()
        doc = self.mech.Document
        doc.openTransaction("Configuration")
        chosen = self.configurations[index] if index < len(self.configurations) else None
        if chosen is None:
            chosen = vp.attach(configuration.create(doc, label, []))
            self.mech.Group = self.mech.Group + [chosen]
        chosen.Label = label or chosen.Label
        configuration.set_poses(chosen, posed, [poses[j.Name][2] for j, _, _ in posed])
        self.mech.ShownConfiguration = chosen
        doc.recompute()
        doc.commitTransaction()
        FreeCAD.Console.PrintMessage("{}: {} ({})\n".format(self.mech.Label, chosen.Label, self.mech.Status))
        return True

    def reject(self):
        self.close()
        return True

    def close(self):
        self.abandon()
        editing.close_panel(self.mech.Document)

    def abandon(self):
        """Stops the animation and removes the preview from the 3-D view (idempotent)."""
        self.timer.stop()
        self.poser.clear()

    def getStandardButtons(self):
        return editing.OK_CANCEL
