"""A new user's drawer session, full of mistakes: a carcass with a top, a drawer front and a tray drawn
inside the carcass, made parts before the cavity; a Geometric picked from a face and an edge; an angle typed out of
range and Enter pressed in a Configurations field. Nothing changes that no relationship asks for, every mistake is
a sentence (the runner fails on any traceback or unexpected red line).
"""
import FreeCADGui as Gui
from PySide import QtCore

import guitest
from freecad.fabguide import cuboids
from freecad.fabguide.function import configuration, mechanism

state = {}
boxes = None  # guitest.MessageBoxes, from the first step: what message boxes said, in order


def box(label, low, high):
    return guitest.box(state["doc"], label, low, high)


pick = guitest.pick


def heights():
    return {b.Label: (round(cuboids.coordinates(b)[4], 6), round(cuboids.coordinates(b)[5], 6))
            for b in state["doc"].Objects if cuboids.is_box(b)}


def a_part_made_before_its_cavity_changes_nothing():
    global boxes
    doc, boxes = guitest.session("Drawer")
    state["doc"] = doc
    carcass, top = box("Carcass", (0, 0, 0), (600, 400, 800)), box("Top", (0, 0, 800), (600, 400, 830))
    front, tray = box("Front", (20, -20, 600), (580, 0, 780)), box("Tray", (30, 0, 610), (570, 380, 770))
    doc.recompute()
    drawn = heights()
    pick((front, None), (tray, None))
    Gui.runCommand("FabGuide_MakePart")
    pick((carcass, None))
    Gui.runCommand("FabGuide_MakePart")
    pick((top, None))
    Gui.runCommand("FabGuide_MakePart")
    mech = state["mech"] = next(o for o in doc.Objects if mechanism.is_mechanism(o))
    assert heights() == drawn, "no box moved or shrank: {}".format(heights())
    assert mech.Status == "Conflict: drawn inside: Tray in Carcass", mech.Status
    state.update(carcass=carcass, tray=tray, top=top)


def the_cavity_made_the_mechanism_solves_as_drawn():
    doc, carcass = state["doc"], state["carcass"]
    space = box("Drawer space", (20, 0, 600), (580, 390, 780))
    doc.recompute()
    pick((carcass, None), (space, None))
    Gui.runCommand("FabGuide_MakeCavity")
    doc.recompute()
    assert state["mech"].Status == "Solved", state["mech"].Status
    assert heights()["Carcass"] == (0, 800) and heights()["Top"] == (800, 830), heights()


def fit_inside_picked_on_the_tray_takes_the_tray_not_the_front():
    doc, tray, carcass = state["doc"], state["tray"], state["carcass"]
    front = doc.getObjectsByLabel("Front")[0]
    before = {b.Label: cuboids.coordinates(b) for b in (front, tray, carcass)}
    pick((tray, None), (carcass, None))
    Gui.runCommand("FabGuide_AddFitInside")
    fit = next(o for o in doc.Objects if getattr(o, "Portion", None) is not None)
    assert [b.Label for b in fit.Portion] == ["Tray"], [b.Label for b in fit.Portion]
    assert state["mech"].Status == "Solved", state["mech"].Status
    after = {b.Label: cuboids.coordinates(b) for b in (front, tray, carcass)}
    assert after == before, "the drawer already fits: nothing moves ({})".format(after)


def a_geometric_from_a_face_and_an_edge_is_refused():
    doc, tray = state["doc"], state["tray"]
    objects = len(doc.Objects)
    del boxes.told[:]
    pick((tray, "Face1"), (tray, "Edge1"))
    Gui.runCommand("FabGuide_AddGeometric")
    guitest.settle(0.2)
    assert boxes.told and boxes.told[0].startswith("Pick one or two edges of boxes, and nothing else"), boxes.told
    assert len(doc.Objects) == objects


def an_angle_typed_out_of_range_keeps_the_panel_open_and_enter_does_not_accept():
    mech, tray = state["mech"], state["tray"]
    pick((tray, "Edge1"))
    Gui.runCommand("FabGuide_AddHinge")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    Gui.runCommand("FabGuide_Configurations")
    guitest.settle(0.3)
    panel = mech.ViewObject.Proxy.panel
    configurations = len([o for o in mech.Group if hasattr(o, "Angles")])
    panel.moves[-1].setChecked(True)
    angle = panel.angles[-1]
    angle.setFocus()
    angle.selectAll()
    guitest.keys(angle, "-400", QtCore.Qt.Key_Return)
    guitest.settle(0.3)
    assert angle.text().startswith("-400"), "every keystroke kept: {}".format(angle.text())
    assert Gui.Control.activeDialog(), "Enter in a field does not accept the panel"
    assert not panel.accept(), "OK refused while the angle does not read"
    assert "is not an angle from -360 to 360" in panel.status.text(), panel.status.text()
    assert len([o for o in mech.Group if configuration.is_configuration(o)]) == configurations, "nothing stored"
    angle.selectAll()
    guitest.keys(angle, "-40")
    panel.name.setText("Drawer pulled out all the way for cleaning behind it, as the manual shows on page twelve")
    assert panel.accept()
    guitest.settle(0.3)
    shown = mech.ShownConfiguration
    assert shown is not None and [a for _, a, _ in configuration.poses(shown)] == [-40.0], shown
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    Gui.runCommand("FabGuide_Configurations")
    guitest.settle(0.3)
    panel = mech.ViewObject.Proxy.panel
    assert panel.choice.currentText() == shown.Label + " (current)", panel.choice.currentText()
    assert panel.form.minimumSizeHint().width() <= 260, "a long name does not widen the panel: {}".format(panel.form.minimumSizeHint().width())
    for path in guitest.screenshots_at_screen_sizes("mistakes_function_configurations"):
        print("window: " + path)
    panel.reject()
    boxes.timer.stop()


guitest.run([
    a_part_made_before_its_cavity_changes_nothing,
    the_cavity_made_the_mechanism_solves_as_drawn,
    fit_inside_picked_on_the_tray_takes_the_tray_not_the_front,
    a_geometric_from_a_face_and_an_edge_is_refused,
    an_angle_typed_out_of_range_keeps_the_panel_open_and_enter_does_not_accept,
])
