"""A new user's bookcase session, full of mistakes: two designs side by side, a master board resized for
one of them, a seed of -1, exports of a layout in error, panels opened over panels, "1e9" typed as a kerf, Enter
pressed in a field, the pages made twice, the document saved. Every mistake is one sentence (the runner fails on
any traceback or unexpected red line), nothing is changed the user did not ask for, nothing stale is written.
"""
# expects error: Design 'Cabinet': the design does not fit on the master boards: part 'Cabinet side' is left over
# expects error: Layout 'Layout': Seed must be 0 or more; kept 1
# expects error: Design 'Bookcase': the design does not fit on the master boards: part 'Bookcase side' is left over
# expects error: Layout 'Layout': not enough master boards: part 'Bookcase side001 board' does not fit
import os
import tempfile

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import guitest

state = {}
boxes = None  # guitest.MessageBoxes, from the first step: what message boxes said, in order


def bookcase(doc, name, x):
    made = []
    for label, size, at in (("side", (18, 300, 800), (0, 0, 0)), ("side", (18, 300, 800), (582, 0, 0)),
                            ("shelf", (564, 300, 18), (18, 0, 100)), ("shelf", (564, 300, 18), (18, 0, 400))):
        box = doc.addObject("Part::Box", "Box")
        box.Label = "{} {}".format(name, label)
        box.Length, box.Width, box.Height = size
        box.Placement.Base = FreeCAD.Vector(at[0] + x, at[1], at[2])
        made.append(box)
    doc.recompute()
    return made


def design_from(boxes):
    Gui.Selection.clearSelection()
    for box in boxes:
        Gui.Selection.addSelection(box)
    Gui.runCommand("FabGuide_DesignFromBoxes")
    guitest.settle(0.5)
    return next(o for o in reversed(boxes[0].Document.Objects) if o.TypeId == "App::DocumentObjectGroupPython")


def two_designs_get_a_master_board_each():
    global boxes
    doc, boxes = guitest.session("Bookcases")
    state["doc"] = doc
    bookcase_design = design_from(bookcase(doc, "Bookcase", 0))
    cabinet = design_from(bookcase(doc, "Cabinet", 1500))
    bookcase_design.Label, cabinet.Label = "Bookcase", "Cabinet"
    doc.recompute()
    (mine,), (theirs,) = bookcase_design.MasterBoards, cabinet.MasterBoards
    assert mine != theirs, "a new design takes a master board of its own"
    assert list(mine.UsedBy) == ["Bookcase"] and list(theirs.UsedBy) == ["Cabinet"], (mine.UsedBy, theirs.UsedBy)
    state.update(bookcase=bookcase_design, cabinet=cabinet)


def a_master_board_too_small_for_its_design_is_said_once():
    doc, cabinet, bookcase_design = state["doc"], state["cabinet"], state["bookcase"]
    before = [b.Length.Value for b in cabinet.Group if b.TypeId == "Part::Box"]
    doc.openTransaction("Resize")
    cabinet.MasterBoards[0].Width = 400
    doc.commitTransaction()
    doc.recompute()
    assert cabinet.Error.startswith("Design 'Cabinet': the design does not fit"), cabinet.Error
    assert cabinet.Status in cabinet.Error, "its Status says it too, not the old usage"
    assert [b.Length.Value for b in cabinet.Group if b.TypeId == "Part::Box"] == before, "no box changed"
    assert not bookcase_design.Error and bookcase_design.Status.startswith("Usage"), bookcase_design.Status
    doc.undo()
    doc.recompute()
    assert not cabinet.Error, cabinet.Error


def a_layout_refuses_a_negative_seed():
    doc = state["doc"]
    Gui.Selection.clearSelection()
    for box in state["bookcase"].Group:
        if box.TypeId == "Part::Box":
            Gui.Selection.addSelection(box)
    Gui.runCommand("FabGuide_BoardsFromSolids")
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_Layout")
    guitest.settle(0.5)
    lay = state["layout"] = next(o for o in doc.Objects if hasattr(o, "Seed"))
    assert Gui.Control.activeDialog(), "the layout panel is open"
    lay.Seed = -1
    assert lay.Seed == 1, "refused as typed"


def a_second_panel_is_refused_in_one_sentence():
    lay = state["layout"]
    del boxes.told[:]
    assert not lay.ViewObject.Proxy.setEdit(lay.ViewObject, 0), "no second panel over the first (a double-click)"
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(state["cabinet"])
    Gui.runCommand("FabGuide_Suggest")
    guitest.settle(0.3)
    assert boxes.told == ["Another task panel is open: finish it with OK or Cancel first."] * 2, boxes.told


def a_kerf_typed_out_of_range_is_refused_whole_and_enter_keeps_the_panel():
    lay = state["layout"]
    kerf = next(w for w in QtGui.QApplication.allWidgets() if w.objectName() == "kerf" and w.isVisible())
    was = lay.Kerf.Value
    kerf.setFocus()
    kerf.selectAll()
    guitest.keys(kerf, "1e9")
    guitest.settle(1.2)  # past the pause
    assert lay.Kerf.Value == was, "kept, not cut to 1 mm on the way: {}".format(lay.Kerf)
    message = next(w for w in QtGui.QApplication.allWidgets() if w.objectName() == "message" and w.isVisible())
    assert '"1e9" is not a length from 0 to 50 mm; it stays 0.2 mm' in message.text(), message.text()
    kerf.selectAll()
    guitest.keys(kerf, "0.3")
    guitest.keys(kerf, key=QtCore.Qt.Key_Return)
    guitest.settle(0.3)
    assert Gui.Control.activeDialog(), "Enter in a field does not accept the panel"
    assert abs(lay.Kerf.Value - 0.3) < 1e-9 and not lay.Error, (lay.Kerf, lay.Error)
    lay.ViewObject.Proxy.panel.accept()
    guitest.settle(0.3)


def nothing_is_made_from_a_layout_in_error():
    doc, lay = state["doc"], state["layout"]
    masters = list(lay.MasterBoards)
    for m in masters:
        m.Width = 500
    doc.recompute()
    assert lay.Error.startswith("Layout 'Layout': not enough master boards") and "is shared with 'Bookcase'" in lay.Error
    folder = tempfile.mkdtemp()
    original = QtGui.QFileDialog.getExistingDirectory
    QtGui.QFileDialog.getExistingDirectory = staticmethod(lambda *args, **kwargs: folder)
    del boxes.told[:]
    try:
        for command in ("FabGuide_ExportCutSheets", "FabGuide_TechDrawPages", "FabGuide_MakeCamJob"):
            Gui.runCommand(command)
            guitest.settle(0.2)
    finally:
        QtGui.QFileDialog.getExistingDirectory = original
    assert os.listdir(folder) == [], "no files of the last good layout"
    assert len(boxes.told) == 3 and all("Mend that first" in t for t in boxes.told), boxes.told
    assert not [o for o in doc.Objects if o.TypeId == "TechDraw::DrawPage"]
    for m in masters:
        m.Width = 2440
    doc.recompute()
    assert not lay.Error, lay.Error


def no_board_is_made_from_a_layout():
    """Make Board on the layout (its sheets are faces): refused by name, nothing made, no undo step."""
    doc, lay = state["doc"], state["layout"]
    objects, undo_steps = [o.Name for o in doc.Objects], doc.UndoCount
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(lay)
    del boxes.told[:]
    Gui.runCommand("FabGuide_MakeBoard")
    guitest.settle(0.3)
    assert boxes.told == ["Nothing made: 'Layout': is FabGuide's Layout, not a part of your model (pick a sketch, a "
                          "planar face or a thin solid)."], boxes.told
    assert [o.Name for o in doc.Objects] == objects and doc.UndoCount == undo_steps
    Gui.Selection.clearSelection()


def pages_made_twice_are_redrawn_one_for_one():
    doc = state["doc"]
    mdi = Gui.getMainWindow().findChild(QtGui.QMdiArea)
    Gui.runCommand("FabGuide_TechDrawPages")
    guitest.settle(0.5)
    first = [o.Name for o in doc.Objects if o.TypeId == "TechDraw::DrawPage"]
    tabs = [w.windowTitle() for w in mdi.subWindowList()]
    Gui.runCommand("FabGuide_TechDrawPages")
    guitest.settle(0.5)
    assert [o.Name for o in doc.Objects if o.TypeId == "TechDraw::DrawPage"] == first
    assert [w.windowTitle() for w in mdi.subWindowList()] == tabs, "no second tab of the same page"
    print("window: " + guitest.screenshot("mistakes_material_pages"))
    mdi.activateNextSubWindow()


def saved_is_unmodified():
    """Saved with Ctrl+S from the model's 3-D view (a TechDraw page's view keeps 0.20's Save to itself)."""
    doc = state["doc"]
    doc.saveAs(os.path.join(tempfile.mkdtemp(), "bookcases.FCStd"))
    doc.Objects[0].touch()  # an edit since, saved as users save
    mdi = Gui.getMainWindow().findChild(QtGui.QMdiArea)
    mdi.setActiveSubWindow(next(w for w in mdi.subWindowList() if w.windowTitle().startswith(doc.Label)))
    Gui.runCommand("Std_Save")
    guitest.settle(0.5)
    assert not Gui.getDocument(doc.Name).Modified, [o.Name for o in doc.Objects if "Touched" in o.State]
    boxes.timer.stop()


guitest.run([
    two_designs_get_a_master_board_each,
    a_master_board_too_small_for_its_design_is_said_once,
    a_layout_refuses_a_negative_seed,
    a_second_panel_is_refused_in_one_sentence,
    a_kerf_typed_out_of_range_is_refused_whole_and_enter_keeps_the_panel,
    nothing_is_made_from_a_layout_in_error,
    no_board_is_made_from_a_layout,
    pages_made_twice_are_redrawn_one_for_one,
    saved_is_unmodified,
])
