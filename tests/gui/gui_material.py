"""Material toolbar in the real FreeCAD GUI: a shelf unit made of Part boxes becomes boards, is laid out
(task panel with the usage), edited live, undone, and exported; screenshots of the 3-D view and panel. Mistakes
are refused or said in one sentence.
"""
# expects error: Master board 'MasterBoard': Count must be 0 (as many as needed) or more; kept 1
# expects error: Layout 'Layout': part 'Back board' is 6 mm thick: no master board is (add one that thick)
import json
import os
import sys
import tempfile

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import guitest

state = {}


def model_and_workbench():
    Gui.activateWorkbench("FabGuideWorkbench")
    doc = guitest.new_document("Shelf")
    sizes = [("Side", (18, 300, 800), (0, 0, 0)), ("Side", (18, 300, 800), (582, 0, 0))]
    sizes += [("Shelf", (564, 300, 18), (18, 0, 100 + 300 * i)) for i in range(3)]
    for label, (x, y, z), at in sizes:
        box = doc.addObject("Part::Box", label)
        box.Length, box.Width, box.Height = x, y, z
        box.Placement.Base = FreeCAD.Vector(*at)
    doc.recompute()
    state["doc"] = doc
    state["solids"] = list(doc.Objects)


def boards_from_solids_makes_one_board_per_solid():
    doc = state["doc"]
    Gui.Selection.clearSelection()
    for solid in state["solids"]:
        Gui.Selection.addSelection(solid)
    Gui.runCommand("FabGuide_BoardsFromSolids")
    boards = [o for o in doc.Objects if o.TypeId == "Part::FeaturePython" and hasattr(o, "Thickness")]
    assert len(boards) == 5, [o.Label for o in doc.Objects]
    assert all(b.Thickness.Value == 18 and "Invalid" not in b.State for b in boards)
    assert not any(s.Visibility for s in state["solids"])
    state["boards"] = boards


def master_board_and_layout_open_the_usage_panel():
    doc = state["doc"]
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_NewMasterBoard")
    master = doc.ActiveObject
    master.Width, master.Height = 1220, 1220
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_Layout")
    layouts = [o for o in doc.Objects if hasattr(o, "LayoutJson")]
    assert len(layouts) == 1
    layout = layouts[0]
    assert "Invalid" not in layout.State and layout.SheetCount == 1 and 0.5 < layout.Usage <= 1
    QtGui.QApplication.processEvents()
    panels = [w for w in QtGui.QApplication.allWidgets() if w.objectName() == "LayoutPanel" and w.isVisible()]
    assert len(panels) == 1, "the layout task panel is open"
    state["layout"] = layout
    guitest.isometric()
    QtGui.QApplication.processEvents()
    colours = layout.ViewObject.DiffuseColor
    assert len(colours) == len(layout.Shape.Faces) and colours[0] != colours[-1], "sheets and parts coloured"
    print("screenshot: " + guitest.screenshot("material_layout_panel"))
    for path in guitest.screenshots_at_screen_sizes("material_layout"):
        print("screenshot: " + path)
    print("3-D view: " + guitest.view_image("material_layout_3d"))


def editing_the_kerf_in_the_panel_relays_out_when_typing_pauses():
    layout = state["layout"]
    form = [w for w in Gui.getMainWindow().findChildren(QtGui.QAbstractSpinBox) if w.objectName() == "kerf"]
    assert form, "kerf field in the panel"
    assert form[0].property("unit") == "mm" or "mm" in form[0].text(), form[0].text()
    before = layout.LayoutJson
    for typed in (7.0, 7.5, 8.0):  # keystrokes: the setting follows each, the layout waits for the pause
        form[0].setProperty("rawValue", typed)
        assert layout.Kerf.Value == typed and layout.LayoutJson == before
    guitest.settle(1.2)
    assert layout.LayoutJson != before and json.loads(layout.ProblemJson)["settings"]["kerf"] == 8.0
    usage = [w for w in Gui.getMainWindow().findChildren(QtGui.QLabel) if w.objectName() == "usage"][0]
    assert usage.text() == "{:.1%}".format(layout.Usage)


def guillotine_cuts_chosen_in_the_panel_give_the_saw_cuts():
    layout = state["layout"]
    window = Gui.getMainWindow()
    cuts = [w for w in window.findChildren(QtGui.QComboBox) if w.objectName() == "cuts"][0]
    stages = [w for w in window.findChildren(QtGui.QSpinBox) if w.objectName() == "stages"][0]
    assert not stages.isEnabled(), "stages mean nothing for free cuts"
    cuts.setCurrentText("Guillotine (panel saw)")
    stages.setValue(2)
    guitest.settle(1.2)
    assert layout.Cuts == "Guillotine (panel saw)" and layout.Stages == 2 and stages.isEnabled()
    assert layout.SawCuts > 0 and layout.SawCutLength.Value > 0 and not layout.Error, layout.Error
    shown = [w for w in window.findChildren(QtGui.QLabel) if w.objectName() == "sawCuts"][0].text()
    assert shown.startswith("{}, ".format(layout.SawCuts)), shown
    QtGui.QApplication.processEvents()
    print("screenshot: " + guitest.screenshot("material_layout_guillotine"))
    cuts.setCurrentText("Free (CNC router, laser)")
    guitest.settle(1.2)
    assert layout.Cuts.startswith("Free") and layout.SawCuts == 0
    # Common-line cutting: a line two boards share cut once, the cut length said in the panel.
    common = [w for w in window.findChildren(QtGui.QCheckBox) if w.objectName() == "commonLine"][0]
    assert common.isEnabled() and not common.isChecked()
    whole = layout.CutLength.Value
    layout.Spacing = 0
    common.setChecked(True)
    guitest.settle(1.2)
    assert layout.CommonLine and json.loads(layout.ProblemJson)["settings"]["common_line"] is True
    assert 0 < layout.CommonLineLength.Value and layout.CutLength.Value < whole, (layout.CutLength, whole)
    shown = [w for w in window.findChildren(QtGui.QLabel) if w.objectName() == "cutLength"][0].text()
    assert "shared, cut once" in shown and shown.startswith("{:.1f} m".format(layout.CutLength.Value / 1000)), shown
    Gui.Control.activeDialog() and Gui.ActiveDocument.resetEdit()
    Gui.Control.closeDialog()
    state["doc"].commitTransaction()


def a_long_layout_shows_its_progress_and_stops_with_the_best_so_far():
    doc, layout = state["doc"], state["layout"]
    layout.Iterations, layout.TimeLimit = 10 ** 9, 300  # a search that would run for five minutes
    master = [o for o in doc.Objects if hasattr(o, "Count")][0]
    master.Count = 0  # as many as needed
    for board in state["boards"]:
        board.Quantity = 12  # 60 boards, as the layout that froze FreeCAD for 60 s
    seen = {}

    def press_stop():  # runs from FreeCAD's event loop while the search runs: FreeCAD is not frozen
        dialogs = [w for w in QtGui.QApplication.topLevelWidgets()
                   if isinstance(w, QtGui.QProgressDialog) and w.isVisible()]
        if not dialogs:
            return QtCore.QTimer.singleShot(100, press_stop)
        seen["label"] = dialogs[0].labelText()
        print("screenshot: " + guitest.screenshot("material_layout_progress", dialogs[0]))
        dialogs[0].cancel()

    QtCore.QTimer.singleShot(1000, press_stop)
    doc.recompute()
    assert "(60 boards)" in seen.get("label", "") and "at most 300 s" in seen["label"], seen
    assert not layout.Error and layout.SheetCount >= 6 and 0.5 < layout.Usage <= 1, layout.Error
    assert len(json.loads(layout.LayoutJson)["placements"]) == 60
    layout.Iterations, layout.TimeLimit = -1, 60
    master.Count = 1
    for board in state["boards"]:
        board.Quantity = 1
    doc.recompute()


def mistakes_are_refused_or_said_in_one_sentence():
    doc, layout = state["doc"], state["layout"]
    master = [o for o in doc.Objects if hasattr(o, "Count")][0]
    master.Count = -5
    assert master.Count == 1, "refused as typed"
    thin = doc.addObject("Part::Box", "Back")
    thin.Length, thin.Width, thin.Height = 600, 6, 800
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(thin)
    Gui.runCommand("FabGuide_BoardsFromSolids")
    back = doc.ActiveObject
    doc.openTransaction("Add a 6 mm board")
    layout.Boards = layout.Boards + [back]
    doc.recompute()
    doc.commitTransaction()
    assert layout.Error.startswith("Layout 'Layout': ") and "\n" not in layout.Error, layout.Error
    assert layout.ViewObject.Proxy.getIcon().endswith("FabGuide_Error.svg")
    print("window: " + guitest.screenshot("material_two_thicknesses"))
    doc.undo()  # the 6 mm board out of the layout
    doc.undo()  # and made no more, so the next steps undo what they expect
    doc.removeObject(thin.Name)
    doc.recompute()
    assert not layout.Error, layout.Error


def top_view_of_the_sheet():
    guitest.isometric("Top")
    print("3-D view: " + guitest.view_image("material_layout_top"))


def export_writes_svg_dxf_and_csv():
    folder = tempfile.mkdtemp()
    original = QtGui.QFileDialog.getExistingDirectory
    QtGui.QFileDialog.getExistingDirectory = staticmethod(lambda *args, **kwargs: folder)
    try:
        Gui.Selection.clearSelection()
        Gui.runCommand("FabGuide_ExportCutSheets")
    finally:
        QtGui.QFileDialog.getExistingDirectory = original
    assert sorted(os.listdir(folder)) == ["Layout-cutlist.csv", "Layout-labels.pdf", "Layout-opticutter.csv", "Layout-report.pdf",
                                          "Layout-sheet-1.dxf", "Layout-sheet-1.svg"], os.listdir(folder)


def techdraw_page_opens_with_the_cut_sheet():
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_TechDrawPages")
    pages = [o for o in state["doc"].Objects if o.TypeId == "TechDraw::DrawPage"]
    assert len(pages) == state["layout"].SheetCount + 1  # and the cut list with the totals
    QtGui.QApplication.processEvents()
    Gui.SendMsgToActiveView("ViewFit")
    print("screenshot: " + guitest.screenshot("material_techdraw_page"))
    state["doc"].undo()  # the pages, in one step
    assert not [o for o in state["doc"].Objects if o.TypeId == "TechDraw::DrawPage"]
    Gui.getMainWindow().centralWidget().activateNextSubWindow()


def cam_job_from_the_layout_writes_checked_gcode():
    """Make CAM Job: refused in its panel while the parts lie closer than the tool, then jobs and G-code that the
    independent checker passes; one undo step takes the jobs away."""
    sys.path.insert(0, os.path.join(os.environ["FABGUIDE_SOURCE_DIR"], "tests", "gen"))
    import gcode_checker
    from freecad.fabguide.core import fabguide_core
    from freecad.fabguide.gui import material_commands
    from freecad.fabguide.material import cam

    doc, lay = state["doc"], state["layout"]
    kerf, spacing = lay.Kerf.Value, lay.Spacing.Value
    set_cutting(doc, lay, 0.5, 1.0)  # a laser's kerf
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_MakeCamJob")
    QtGui.QApplication.processEvents()
    panel = [w for w in QtGui.QApplication.allWidgets()
             if w.objectName() == "CamJobPanel" and w.isVisible()]
    assert panel, "the CAM job panel is open"
    form = panel[0]
    folder = tempfile.mkdtemp()
    form.findChild(QtGui.QLineEdit, "folder").setText(folder)
    cam_panel = material_commands.COMMANDS["FabGuide_MakeCamJob"].panel
    speeds = form.findChild(QtGui.QTableWidget, "speeds")
    assert [speeds.verticalHeaderItem(r).text() for r in range(speeds.rowCount())] == cam.materials(lay) == \
        ["plywood"], "a row per material of the master boards"
    assert [box.value() for box in cam_panel.boxes[0]] == [cam.FEED, cam.SPINDLE]
    cam_panel.boxes[0][0].setValue(2100)
    print("screenshot: " + guitest.screenshot("material_cam_panel"))
    assert cam_panel.accept() is False  # parts 1.5 mm apart: too close for a 5 mm end mill
    assert "Kerf" in form.findChild(QtGui.QLabel, "message").text()
    set_cutting(doc, lay, 5.0, 1.0)  # the router's
    before = {o.Name for o in doc.Objects}
    assert cam_panel.accept() is True
    jobs = [o for o in doc.Objects if getattr(o, "FabGuideLayout", None) == lay and hasattr(o, "Operations")]
    assert len(jobs) == lay.SheetCount
    written = sorted(os.listdir(folder))
    assert written == ["Layout-sheet-{}.nc".format(n + 1) for n in range(lay.SheetCount)], written
    problem, result = json.loads(lay.ProblemJson), json.loads(lay.LayoutJson)
    placed = fabguide_core.placed_outlines(problem, result)
    for n, sheet in enumerate(fabguide_core.cut_sheets(problem, result)):
        with open(os.path.join(folder, written[n])) as gcode:
            found = gcode_checker.problems(gcode.read(), [dict(p, id=p["part"]) for p in placed if p["board"] == n],
                                           sheet["thickness"], 2.5, through=cam.THROUGH, feed=2100)
        assert not found, found
    Gui.runCommand("FabGuide_MakeCamJob")  # the plywood's feed remembered for the next job
    QtGui.QApplication.processEvents()
    again = material_commands.COMMANDS["FabGuide_MakeCamJob"].panel
    assert again.boxes[0][0].value() == 2100, "remembered"
    again.reject()
    QtGui.QApplication.processEvents()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(jobs[0])
    guitest.isometric()
    print("screenshot: " + guitest.screenshot("material_cam_job"))
    guitest.isometric("Top")
    print("3-D view: " + guitest.view_image("material_cam_job_paths", compared=False))
    undo = doc.UndoNames
    doc.undo()  # the jobs, in one step
    assert {o.Name for o in doc.Objects} == before, (undo, {o.Label for o in doc.Objects if o.Name not in before})
    assert not [o for o in doc.Objects if hasattr(o, "Operations")], [o.Label for o in doc.Objects]
    doc.undo()  # the kerfs
    doc.undo()
    doc.recompute()
    assert (lay.Kerf.Value, lay.Spacing.Value) == (kerf, spacing)


def set_cutting(doc, lay, kerf, spacing):
    doc.openTransaction("Cutting")
    lay.Kerf, lay.Spacing = kerf, spacing
    doc.recompute()
    doc.commitTransaction()


def undo_removes_the_layout_in_one_step():
    doc = state["doc"]
    name = state["layout"].Name
    doc.undo()
    assert doc.getObject(name) is None
    assert all(doc.getObject(b.Name) for b in state["boards"])


def make_board_from_a_selected_face():
    doc = state["doc"]
    panel = doc.addObject("Part::Box", "Panel")
    panel.Length, panel.Width, panel.Height = 200, 100, 30
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(panel, "Face6")  # the top face
    Gui.runCommand("FabGuide_MakeBoard")
    made = doc.ActiveObject
    assert made.Label == "Panel board" and "Invalid" not in made.State
    assert abs(made.Shape.Volume - 200 * 100 * 18) < 1e-6  # as thick as the master board
    assert abs(made.Shape.BoundBox.ZMin - 30) < 1e-9       # standing on the selected face
    name = made.Name
    doc.undo()
    assert doc.getObject(name) is None


guitest.run([
    model_and_workbench,
    boards_from_solids_makes_one_board_per_solid,
    master_board_and_layout_open_the_usage_panel,
    editing_the_kerf_in_the_panel_relays_out_when_typing_pauses,
    guillotine_cuts_chosen_in_the_panel_give_the_saw_cuts,
    a_long_layout_shows_its_progress_and_stops_with_the_best_so_far,
    mistakes_are_refused_or_said_in_one_sentence,
    top_view_of_the_sheet,
    export_writes_svg_dxf_and_csv,
    techdraw_page_opens_with_the_cut_sheet,
    cam_job_from_the_layout_writes_checked_gcode,
    undo_removes_the_layout_in_one_step,
    make_board_from_a_selected_face,
])
