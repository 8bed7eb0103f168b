"""Function toolbar in the real FreeCAD GUI: the Cabinet imported and shown in a configuration; a clamshell
made from plain boxes with the commands (mechanism, hinge, configuration panel, cover), its faces coloured in
the relationship panel, a conflict shown in red, undo, a box renamed and deleted, and export; screenshots of
the 3-D view and panels."""
# expects error: Part 'Lid part' has no boxes: add a Part::Box to its Cuboids
# expects error: Joint 'Lid hinge': choose the Edge it turns about
# expects error: Making the bodies of 'cabinet printable': cancelled; it keeps its last result
import json
import os
import tempfile
import threading
import time

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

from freecad.fabguide.core import fabguide_core
import guitest
from freecad.fabguide import cuboids
from freecad.fabguide.function import configuration, joints, mechanism, relationships

state = {}
SOURCE = os.environ["FABGUIDE_SOURCE_DIR"]


def import_the_cabinet():
    Gui.activateWorkbench("FabGuideWorkbench")
    doc = guitest.new_document("Cabinet")
    state["cabinet"] = doc
    guitest.with_file_dialog("getOpenFileName", os.path.join(SOURCE, "examples", "cabinet.workslike.json"),
                     "FabGuide_ImportWorkslike")
    mech = [o for o in doc.Objects if mechanism.is_mechanism(o)][0]
    assert mech.Status == "Solved", mech.Status
    rels = [o for o in mech.Group if relationships.is_relationship(o)]
    assert len(rels) == 8 and {r.Status for r in rels} == {"Satisfied"}
    hinge = doc.getObjectsByLabel("left door hinge")[0]
    assert hinge.ViewObject.Proxy.coordinates.point.getNum() == 4  # its edge and its slide axis drawn
    assert doc.getObjectsByLabel("upper compartment")[0].ViewObject.Transparency == 75
    guitest.isometric()
    print("3-D view: " + guitest.view_image("function_cabinet"))
    state["mech"] = mech


def the_configurations_panel_shows_the_doors_stowed():
    mech = state["mech"]
    door = state["cabinet"].getObjectsByLabel("left door")[0]
    children = door.ViewObject.RootNode.getNumChildren()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    Gui.runCommand("FabGuide_Configurations")
    QtGui.QApplication.processEvents()
    panel = mech.ViewObject.Proxy.panel
    assert panel.choice.count() == 5, "4 configurations and 'New configuration'"
    panel.choice.setCurrentIndex(0)  # doors stowed
    QtGui.QApplication.processEvents()
    node = door.ViewObject.RootNode.getChild(0)
    assert abs(node.rotation.getValue().getValue()[3]) < 0.99, "the door is shown turned"
    guitest.isometric()
    print("screenshot: " + guitest.screenshot("function_configurations_panel"))
    print("3-D view: " + guitest.view_image("function_cabinet_doors_stowed"))
    Gui.ActiveDocument.resetEdit()
    QtGui.QApplication.processEvents()
    assert door.ViewObject.RootNode.getNumChildren() == children, "the preview's transforms are gone"


def a_long_print_shows_its_progress_and_cancel_keeps_the_last_bodies():
    """The cabinet takes seconds to print: FreeCAD keeps drawing, shows what runs, and Cancel leaves the bodies
    of the last print (nothing freezes FreeCAD)."""
    doc, mech = state["cabinet"], state["mech"]
    FreeCAD.setActiveDocument(doc.Name)
    seen = []

    def on_the_dialog(cancel):
        def look():  # runs from FreeCAD's event loop while the print runs: FreeCAD is not frozen
            dialogs = [w for w in QtGui.QApplication.topLevelWidgets()
                       if isinstance(w, QtGui.QProgressDialog) and w.isVisible()]
            if not dialogs:
                return QtCore.QTimer.singleShot(100, look)
            seen.append(dialogs[0].labelText())
            if cancel:
                print("screenshot: " + guitest.screenshot("function_print_progress", dialogs[0]))
                dialogs[0].cancel()
        QtCore.QTimer.singleShot(100, look)

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    on_the_dialog(cancel=False)
    Gui.runCommand("FabGuide_MakePrintable")
    made = [o for o in doc.Objects if o.Label == mech.Label + " printable"][0]
    assert seen and seen[0].startswith("Making the bodies of 'cabinet printable'"), seen
    assert not made.Error, made.Error
    volumes = {c.BodyName: c.Shape.Volume for c in made.Group if not c.Shape.isNull()}
    assert sum(volumes.values()) > 0
    made.Gap = 0.5
    on_the_dialog(cancel=True)
    started = time.monotonic()
    doc.recompute()
    assert time.monotonic() - started < 5, "Cancel returns at once; the print goes on unused on its thread"
    assert len(seen) == 2 and made.Error.startswith("Making the bodies of 'cabinet printable': cancelled"), made.Error
    assert {c.BodyName: c.Shape.Volume for c in made.Group if not c.Shape.isNull()} == volumes, "the last print's bodies stay"
    while len(threading.enumerate()) > 1 and time.monotonic() - started < 60:  # the abandoned print ends
        guitest.settle(0.2)
    assert len(threading.enumerate()) == 1, threading.enumerate()


def a_clamshell_from_plain_boxes_with_the_commands():
    doc = guitest.new_document("Clamshell")
    state["doc"] = doc
    doc.UndoMode = 1
    body, lid = doc.addObject("Part::Box", "Body"), doc.addObject("Part::Box", "Lid")
    cuboids.set_coordinates(body, [0, 60, 0, 120, 0, 10])
    cuboids.set_coordinates(lid, [3, 57, 122, 230, 0, 7])
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(body)
    Gui.Selection.addSelection(lid)
    Gui.runCommand("FabGuide_NewMechanism")
    mech = [o for o in doc.Objects if mechanism.is_mechanism(o)][0]
    assert len(mech.Group) == 2 and mech.Status == "Solved"
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(lid, cuboids.edge_element(lid, ("near", "top")))
    Gui.runCommand("FabGuide_AddHinge")
    hinge = [o for o in mech.Group if joints.is_joint(o)][0]
    assert joints.as_dict(hinge)["edge"] == ["Lid.near", "Lid.top"]
    # The configurations panel: a new configuration with the hinge at 180°.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    Gui.runCommand("FabGuide_Configurations")
    QtGui.QApplication.processEvents()
    panel = mech.ViewObject.Proxy.panel
    assert Gui.Control.activeDialog() and panel.choice.currentText() == "New configuration"
    panel.moves[0].setChecked(True)
    panel.angles[0].lineEdit().setText("360/2 °")  # typed as a quantity
    QtGui.QApplication.processEvents()
    assert abs(panel.angles[0].property("rawValue") - 180) < 1e-9, panel.angles[0].property("rawValue")
    panel.name.setText("Closed")
    assert not panel.offsets[0].isEnabled(), "a hinge has no offset"
    guitest.task_button("OK").click()
    QtGui.QApplication.processEvents()
    closed = doc.getObjectsByLabel("Closed")[0]
    assert mech.ShownConfiguration == closed and [a for _, a, _ in configuration.poses(closed)] == [180.0]
    # Cover: pick the lid, then the body (picked last: covered); it holds in the shown configuration.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(lid)
    Gui.Selection.addSelection(body)
    Gui.runCommand("FabGuide_AddCover")
    cover = [o for o in mech.Group if relationships.is_relationship(o)][0]
    assert cover.Configuration == closed and cover.Status == "Satisfied", cover.Status
    assert lid.Length.Value == body.Length.Value, "just cover: as wide as the body"
    guitest.isometric()
    print("3-D view: " + guitest.view_image("function_clamshell"))
    state.update(mech=mech, cover=cover, body=body, lid=lid)


def the_relationship_panel_colours_the_faces():
    cover, lid = state["cover"], state["lid"]
    cover.ViewObject.doubleClicked()
    QtGui.QApplication.processEvents()
    lists = [w for w in Gui.getMainWindow().findChildren(QtGui.QListWidget) if w.isVisible()]
    assert [lists[0].item(i).text() for i in range(lists[0].count())] == ["Lid.bottom -> Body.top"]
    assert lid.ViewObject.DiffuseColor[4][:3] != lid.ViewObject.DiffuseColor[5][:3], "the covering face coloured"
    print("screenshot: " + guitest.screenshot("function_relationship_panel"))
    body = state["body"]
    form = [w for w in Gui.getMainWindow().findChildren(QtGui.QWidget) if w.objectName() == "RelationshipPanel"][0]
    Gui.Selection.clearSelection()
    form.findChild(QtGui.QPushButton, "add").click()  # nothing picked: it says what to do
    status = form.findChild(QtGui.QLabel, "status").text()
    assert "Pick two faces" in status and lists[0].count() == 1, status
    Gui.Selection.addSelection(lid)  # the panel's selection gate: faces of boxes only
    Gui.Selection.addSelection(lid, "Edge1")
    assert not Gui.Selection.getSelectionEx(), "only faces of boxes can be picked while pairs are edited"
    Gui.Selection.addSelection(lid, "Face1")
    Gui.Selection.addSelection(body, "Face1")
    form.findChild(QtGui.QPushButton, "add").click()  # the two picked faces, first to second
    assert lists[0].item(1).text() == "Lid.left -> Body.left", lists[0].item(1).text()
    lists[0].item(1).setText("Lid.left Body.left")  # mistyped: OK keeps the panel open and says why
    guitest.task_button("OK").click()
    QtGui.QApplication.processEvents()
    status = form.findChild(QtGui.QLabel, "status").text()
    assert Gui.Control.activeDialog() and "must read 'Box.side -> Box.side'" in status, status
    guitest.task_button("Cancel").click()
    QtGui.QApplication.processEvents()
    assert len({c[:3] for c in lid.ViewObject.DiffuseColor}) == 1, "colours restored"
    Gui.Selection.addSelection(lid)
    assert Gui.Selection.getSelection() == [lid], "the gate goes with the panel"
    Gui.Selection.clearSelection()


def a_conflict_turns_the_parts_red_and_undo_takes_it_back():
    doc, mech, lid = state["doc"], state["mech"], state["lid"]
    doc.openTransaction("Narrow lid")
    body = state["body"]
    narrow = relationships.create(doc, "geometric", "Lid 40 wide", Left=[(lid, "width")], Offset=40)
    mech.Group = mech.Group + [narrow]
    mech.Locks = [(body, "left"), (body, "right")]
    doc.recompute()
    doc.commitTransaction()
    assert mech.Status.startswith("Conflict: Lid 40 wide"), mech.Status
    red = lid.ViewObject.DiffuseColor[0]
    assert abs(red[0] - 0.85) < 0.01 and red[1] < 0.25, red
    print("3-D view: " + guitest.view_image("function_conflict"))
    name = narrow.Name
    doc.undo()
    doc.recompute()
    assert doc.getObject(name) is None and mech.Status == "Solved", mech.Status


def a_box_renamed_keeps_the_mechanism_and_a_box_deleted_marks_it():
    doc, mech, lid, cover = state["doc"], state["mech"], state["lid"], state["cover"]
    doc.openTransaction("Rename")
    lid.Label = "Cap"
    mech.touch()
    doc.recompute()
    doc.commitTransaction()
    assert mech.Status == "Solved" and cover.Status == "Satisfied", (mech.Status, cover.Status)
    assert relationships.pair_texts(cover) == ["Cap.bottom -> Body.top"], relationships.pair_texts(cover)
    doc.openTransaction("Delete")
    doc.removeObject(lid.Name)
    doc.recompute()
    doc.commitTransaction()
    assert mech.Error == mech.Status == "Mechanism 'Mechanism': Part 'Lid part' has no boxes: add a Part::Box to " \
        "its Cuboids", mech.Status
    assert cover.Status == mechanism.STALE and mech.ViewObject.Proxy.getIcon().endswith("FabGuide_Error.svg")
    print("window: " + guitest.screenshot("function_box_deleted"))
    doc.undo()
    doc.undo()
    state["lid"] = lid = doc.getObjectsByLabel("Lid")[0]
    mech.touch()
    doc.recompute()
    assert mech.Status == "Solved" and not mech.Error and cover.Status == "Satisfied", mech.Status
    assert mech.ViewObject.Proxy.getIcon().endswith("FabGuide_Mechanism.svg")


def mistakes_are_told_in_a_sentence_and_change_nothing():
    doc = guitest.new_document("Mistakes")
    tilted = doc.addObject("Part::Box", "Tilted")
    tilted.Placement = FreeCAD.Placement(FreeCAD.Vector(), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 10))
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(tilted)
    said = guitest.told("FabGuide_NewMechanism")
    assert said and said.startswith("'Tilted' is rotated: FabGuide parts are axis-aligned boxes"), said
    assert [o.Label for o in doc.Objects] == ["Tilted"], "nothing made"
    assert active("FabGuide_NewMechanism") and not active("FabGuide_AddHinge"), "a box picked, no edge"
    assert FreeCAD.ActiveDocument is doc and not active("FabGuide_Solve"), "no mechanism to solve"
    Gui.Selection.clearSelection()
    assert not active("FabGuide_NewMechanism"), "greyed out until boxes are picked"
    assert guitest.told("FabGuide_AddHinge") is None and [o.Label for o in doc.Objects] == ["Tilted"], "inactive"
    Gui.Selection.addSelection(tilted, "Edge1")
    assert active("FabGuide_AddHinge") and not active("FabGuide_AddSlide")
    Gui.Selection.clearSelection()
    FreeCAD.closeDocument(doc.Name)


def active(name):
    """Whether the command is enabled (its IsActive) for the active document and selection."""
    return Gui.Command.get(name).isActive()


def the_crate_bed_folds_along_its_four_bar_motion():
    doc = guitest.new_document("CrateBed")
    guitest.with_file_dialog("getOpenFileName", os.path.join(SOURCE, "examples", "crate-bed.workslike.json"),
                     "FabGuide_ImportWorkslike")
    mech = [o for o in doc.Objects if mechanism.is_mechanism(o)][0]
    assert mech.Status == "Solved", mech.Status
    pivot = doc.getObjectsByLabel("head pivot left")[0]
    assert pivot.ViewObject.Proxy.coordinates.point.getNum() == 2, "the link is drawn"
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    Gui.runCommand("FabGuide_Configurations")
    QtGui.QApplication.processEvents()
    panel = mech.ViewObject.Proxy.panel
    panel.slider.setValue(25)  # turns take the first half of the way: a quarter in, the headboard is lifted over
    # the bed's end, turned less than 90° (as the print's sweeps and clearance check have it)
    head = doc.getObjectsByLabel("headboard")[0]
    q = head.ViewObject.RootNode.getChild(0).rotation.getValue().getValue()
    assert 0.2 < abs(q[0]) < 0.6, q
    modelled = (pivot.Pivot, pivot.BasePivot)

    def drawn():
        return [FreeCAD.Vector(pivot.ViewObject.Proxy.coordinates.point[k].getValue()) for k in (0, 1)]

    link = drawn()
    assert (link[0] - modelled[0]).Length > 1, "the link's end on the headboard moves with it"
    assert abs((link[0] - link[1]).Length - (modelled[0] - modelled[1]).Length) < 1e-3, "the link stays rigid"
    guitest.isometric("Right")
    print("3-D view: " + guitest.view_image("function_crate_bed_half_folded"))
    Gui.ActiveDocument.resetEdit()
    assert all((a - b).Length < 1e-3 for a, b in zip(drawn(), modelled)), "closed: the link is drawn as modelled"


def a_double_pivot_from_two_picked_points():
    doc = state["doc"]
    arm, post = doc.addObject("Part::Box", "Arm"), doc.addObject("Part::Box", "Post")
    cuboids.set_coordinates(arm, [0, 10, 0, 100, 200, 220])
    cuboids.set_coordinates(post, [0, 10, 0, 20, 0, 200])
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, arm.Name, "Face1", 0, 80, 210)  # on the arm's left face
    Gui.Selection.addSelection(doc.Name, post.Name, "Face1", 0, 10, 150)  # on the post's left face
    Gui.runCommand("FabGuide_AddDoublePivot")
    joint = [o for o in doc.Objects if joints.is_joint(o) and joints.kind(o) == "double_pivot"][0]
    assert joint.Part.Cuboids == [arm] and joint.Base.Cuboids == [post]
    face, point = joints.as_dict(joint)["pivot"]  # picked on the arm's left face, which stays under it
    assert face == "Arm.left" and abs(point[0] - arm.Placement.Base.x) < 1e-6, (face, point)


def a_fixed_joint_from_two_picked_boxes():
    doc = guitest.new_document("Fixed")
    knob, door = doc.addObject("Part::Box", "Knob"), doc.addObject("Part::Box", "Door")
    cuboids.set_coordinates(door, [100, 110, 0, 100, 0, 200])
    cuboids.set_coordinates(knob, [110, 120, 40, 60, 90, 110])
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(knob)
    Gui.Selection.addSelection(door)
    Gui.runCommand("FabGuide_AddFixedJoint")
    joint = [o for o in doc.Objects if joints.is_joint(o) and joints.kind(o) == "fixed"][0]
    assert joint.Part.Cuboids == [knob] and joint.Base.Cuboids == [door]
    assert joints.as_dict(joint)["type"] == "fixed" and joint.ViewObject.Proxy.coordinates.point.getNum() == 2
    Gui.Selection.clearSelection()  # the same two picked the other way round: a loop, refused
    Gui.Selection.addSelection(door)
    Gui.Selection.addSelection(knob)
    said = guitest.told("FabGuide_AddFixedJoint")
    assert said == ("'Knob part' already rides on 'Door part': pick the part to hold first, then the part it "
                    "rides on."), said
    assert len([o for o in doc.Objects if joints.is_joint(o)]) == 1
    # A part is moved by one joint: a hinge on the knob says where it belongs; the door takes it.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(knob, cuboids.edge_element(knob, ("near", "top")))
    said = guitest.told("FabGuide_AddHinge")
    assert said == ("'Knob part' rides on 'Door part' by the fixed joint 'Knob part on Door part', and a part is "
                    "moved by one joint: add this joint to 'Door part' (they move together), or delete the fixed "
                    "joint and hold 'Door part' on 'Knob part' instead."), said
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(door, cuboids.edge_element(door, ("near", "left")))
    Gui.runCommand("FabGuide_AddHinge")
    hinge = next(o for o in doc.Objects if joints.is_joint(o) and joints.kind(o) == "hinge")
    assert hinge.Part.Cuboids == [door]
    plate = doc.addObject("Part::Box", "Plate")
    cuboids.set_coordinates(plate, [110, 112, 20, 80, 20, 40])
    doc.recompute()
    Gui.Selection.clearSelection()  # the door picked first, to be held on the plate: backwards
    Gui.Selection.addSelection(door)
    Gui.Selection.addSelection(plate)
    said = guitest.told("FabGuide_AddFixedJoint")
    assert said == ("'Door part' is already moved by joint '{}' (a part is moved by one joint): pick the part to "
                    "hold first, then the part it rides on.".format(hinge.Label)), said
    assert len([o for o in doc.Objects if joints.is_joint(o)]) == 2


def the_cellphone_made_printable_in_its_colours():
    doc = guitest.new_document("Phone")
    guitest.with_file_dialog("getOpenFileName", os.path.join(SOURCE, "examples", "cellphone.workslike.json"),
                     "FabGuide_ImportWorkslike")
    mech = [o for o in doc.Objects if mechanism.is_mechanism(o)][0]
    doc.getObjectsByLabel("screen")[0].ViewObject.ShapeColor = (0.2, 0.5, 0.8)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(mech)
    Gui.runCommand("FabGuide_MakePrintable")
    made = [o for o in doc.Objects if o.Label == mech.Label + " printable"][0]
    assert "Invalid" not in made.State and abs(made.MinimumClearance.Value - 0.4) < 0.01
    screen = [c for c in made.Group if c.BodyName == "screen part"][0]
    assert abs(screen.ViewObject.ShapeColor[2] - 0.8) < 0.01, "printed in its part's colour"
    assert not [o.Label for o in doc.Objects if "Touched" in o.State]
    guitest.isometric()
    print("3-D view: " + guitest.view_image("function_cellphone_printable"))
    folder = tempfile.mkdtemp()
    original = QtGui.QFileDialog.getExistingDirectory
    QtGui.QFileDialog.getExistingDirectory = staticmethod(lambda *args, **kwargs: folder)
    try:
        Gui.runCommand("FabGuide_ExportPrintable")
    finally:
        QtGui.QFileDialog.getExistingDirectory = original
    assert "assembly.3mf" in os.listdir(folder)
    # Fitted to a small printer (100 mm cube): the 190 mm phone prints at about half size, Scale follows.
    made.BuildVolume = FreeCAD.Vector(100, 100, 100)
    made.FitToBuildVolume = True
    doc.recompute()
    assert "Invalid" not in made.State and abs(made.Scale - 100 / 190) < 0.01, made.Scale
    assert made.PrintSize.startswith("26.3 x 100.0 x") and abs(made.MinimumClearance.Value - 0.4) < 0.01
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(made)
    print("window: " + guitest.screenshot("function_cellphone_fitted"))


def export_writes_a_model_the_core_solves():
    path = os.path.join(tempfile.mkdtemp(), "clamshell.workslike.json")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(state["mech"])
    guitest.with_file_dialog("getSaveFileName", path, "FabGuide_ExportWorkslike")
    with open(path) as f:
        assert fabguide_core.solve(json.load(f))["report"]["solved"]


def a_sloppy_kitchen_cabinet_solves_with_its_notes_and_overlaps_in_red():
    """A user's rough model (tests/data): the right door drawn 7 mm off its opening takes part and says so;
    then a panel pushed into the locked carcass, and held there, is a conflict that turns both red."""
    doc = guitest.new_document("Kitchen")
    guitest.with_file_dialog("getOpenFileName",
                             os.path.join(SOURCE, "tests", "data", "workslike", "kitchen-wall-cabinet.workslike.json"),
                             "FabGuide_ImportWorkslike")
    mech = [o for o in doc.Objects if mechanism.is_mechanism(o)][0]
    assert mech.Status == "Solved", mech.Status
    cover = doc.getObjectsByLabel("doors close the cabinet")[0]
    assert cover.Status == ("Satisfied; right door part: 7 mm from right compartment.near, beyond the 5 mm face "
                            "distance; linked to it"), cover.Status
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(cover)
    guitest.isometric()
    print("window: " + guitest.screenshot("function_sloppy_kitchen"))
    door, carcass = doc.getObjectsByLabel("left door")[0], doc.getObjectsByLabel("carcass")[0]
    doc.openTransaction("Push the door in")
    mech.Group = [o for o in mech.Group if o != cover]  # no longer a door that covers: a panel in front
    door.Placement.Base.y += 10  # 10 mm into the carcass, whose front is locked
    mech.Locks = list(mech.Locks) + [(door, "near"), (door, "far")]
    doc.recompute()
    doc.commitTransaction()
    assert "no overlap: carcass part, left door part" in mech.Status, mech.Status
    assert set(mech.Blamed) == {"carcass part", "left door part"}, mech.Blamed
    red = door.ViewObject.DiffuseColor[0]
    assert abs(red[0] - 0.85) < 0.01 and red[1] < 0.25, red
    print("3-D view: " + guitest.view_image("function_overlap_conflict"))
    doc.undo()
    doc.recompute()
    assert mech.Status == "Solved", mech.Status


guitest.run([
    import_the_cabinet,
    the_configurations_panel_shows_the_doors_stowed,
    a_long_print_shows_its_progress_and_cancel_keeps_the_last_bodies,
    a_clamshell_from_plain_boxes_with_the_commands,
    the_relationship_panel_colours_the_faces,
    a_conflict_turns_the_parts_red_and_undo_takes_it_back,
    a_box_renamed_keeps_the_mechanism_and_a_box_deleted_marks_it,
    mistakes_are_told_in_a_sentence_and_change_nothing,
    a_double_pivot_from_two_picked_points,
    export_writes_a_model_the_core_solves,
    the_crate_bed_folds_along_its_four_bar_motion,
    a_fixed_joint_from_two_picked_boxes,
    the_cellphone_made_printable_in_its_colours,
    a_sloppy_kitchen_cabinet_solves_with_its_notes_and_overlaps_in_red,
])
