"""Zero-waste toolbar in the real FreeCAD GUI: a coffee table of Part boxes becomes a flat-pack design with
live usage and a Grain per box in the property editor; constraints are added from picked edges, faces and boxes;
Suggest runs in the background with a progress bar, shows three thumbnails, slides the design along a path and
applies the choice as one undo step, the grain kept; screenshots of the panel and the 3-D view."""
import json
import os
import re
import tempfile

import FreeCAD
import FreeCADGui as Gui
from freecad.fabguide.core import fabguide_core
from PySide import QtGui

import guitest
from freecad.fabguide import cuboids, references
from freecad.fabguide.material import design

state = {}


def box(label, size, at):
    b = state["doc"].addObject("Part::Box", label)
    b.Label = label
    b.Length, b.Width, b.Height = size
    b.Placement.Base = FreeCAD.Vector(*at)
    return b


def property_rows(obj):
    """{group: [(property, value)]} as the property editor shows `obj` selected (the tab with a FabGuide group,
    shown "Fab Guide")."""
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(obj)
    guitest.settle()
    for editor in Gui.getMainWindow().findChildren(QtGui.QTreeView):
        if editor.metaObject().className() != "Gui::PropertyEditor::PropertyEditor":
            continue
        model, rows = editor.model(), {}
        for g in range(model.rowCount()):
            group = model.index(g, 0)
            names = [model.index(r, 0, group) for r in range(model.rowCount(group))]
            rows[group.data().replace(" ", "")] = [(n.data(), n.sibling(n.row(), 1).data()) for n in names]
        if "FabGuide" in rows:
            return rows
    return {}


def shelf_along_the_grain(d):
    """Whether the layout lays the shelf with its length (x) along the sheet's grain (its width)."""
    laid = json.loads(d.LayoutJson)
    shelf = next(p for p in laid["layout"]["placements"] if p["part"] == "shelf")
    return shelf["rotation"] in (0, 180) and shelf["width"] == state["parts"]["shelf"].Length.Value


def places(parts):
    """Parts as a suggestion's path gives them: where they are and their sizes (no grain)."""
    return [{key: p[key] for key in ("id", "min", "max")} for p in parts]


def boxes_become_a_design_with_live_usage():
    Gui.activateWorkbench("FabGuideWorkbench")
    state["doc"] = doc = guitest.new_document("Table")
    parts = [box("top", (720, 450, 12), (0, 0, 400)), box("left", (12, 450, 400), (0, 0, 0)),
             box("right", (12, 450, 400), (708, 0, 0)), box("shelf", (696, 260, 12), (12, 95, 140))]
    doc.recompute()
    Gui.Selection.clearSelection()
    for p in parts:
        Gui.Selection.addSelection(p)
    Gui.runCommand("FabGuide_DesignFromBoxes")
    designs = [o for o in doc.Objects if design.is_design(o)]
    assert len(designs) == 1, [o.Label for o in doc.Objects]
    d = state["design"] = designs[0]
    d.MasterBoards[0].Width, d.MasterBoards[0].Height = 1220, 915
    doc.recompute()
    assert d.MasterBoards[0].Thickness.Value == 12
    assert 0.5 < d.Usage <= 1 and d.Status.startswith("Usage"), d.Status
    drawn = [c.Label for c in d.Group if design.is_constraint(c)]  # the sides drawn alike stay so, deletably
    assert drawn == ["drawn equal: size.y of left, right", "drawn equal: size.z of left, right"], drawn
    state["parts"] = {p.Label: p for p in parts}
    rows = property_rows(parts[3])
    assert rows["FabGuide"] == [("Grain", "Free")], rows
    d.MasterBoards[0].Grain = "Along width"
    parts[3].Grain = "X"  # the shelf's length along the sheet's grain, from here on
    parts[1].Grain = parts[2].Grain = "Z"
    doc.recompute()
    assert property_rows(parts[3])["FabGuide"] == [("Grain", "X")]
    print("screenshot: " + guitest.screenshot("flatpack_grain_property"))
    assert shelf_along_the_grain(d) and not d.Error, d.Status


def constraints_from_picked_edges_faces_and_boxes():
    parts = state["parts"]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(parts["left"], "Edge1")   # along z
    Gui.Selection.addSelection(parts["right"], "Edge1")
    Gui.runCommand("FabGuide_EqualLengths")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(parts["left"])
    Gui.Selection.addSelection(parts["right"])
    Gui.runCommand("FabGuide_Ground")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(parts["left"])
    Gui.Selection.addSelection(parts["right"])
    Gui.runCommand("FabGuide_Symmetric")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(parts["top"], "Edge2")
    Gui.runCommand("FabGuide_LengthRange")
    constraints = [o for o in state["design"].Group if design.is_constraint(o) and "drawn" not in o.Label]
    kinds = sorted(c.Kind for c in constraints)
    assert kinds == ["equal", "ground", "range", "symmetric"], kinds
    assert references.names(constraints[0].Refs) == ["left.size.z", "right.size.z"], constraints[0].Refs
    assert all(c.Status == design.SATISFIED for c in constraints), [c.Status for c in constraints]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(parts["shelf"])
    Gui.runCommand("FabGuide_InnerVolume")
    volumes = [o for o in state["design"].Group if design.is_volume(o)]
    assert len(volumes) == 1 and volumes[0].On == parts["shelf"]
    volumes[0].ViewObject.doubleClicked()  # drags in place
    assert Gui.ActiveDocument.getInEdit() == volumes[0].ViewObject
    Gui.ActiveDocument.resetEdit()


def an_edit_keeps_the_constraints():
    doc, parts = state["doc"], state["parts"]
    doc.openTransaction("taller")
    parts["left"].Height = 420
    doc.recompute()
    doc.commitTransaction()
    assert parts["right"].Height.Value == 420  # equal lengths
    QtGui.QApplication.processEvents()
    message = Gui.getMainWindow().statusBar().currentMessage()
    assert message.startswith(state["design"].Label + ": Usage 0."), message
    assert cuboids.coordinates(parts["top"])[4] == 420  # the top still rests on the legs
    doc.undo()
    doc.recompute()
    assert parts["right"].Height.Value == 400


def suggest_shows_three_suggestions_and_applies_one_as_one_step():
    doc, d = state["doc"], state["design"]
    before = design.parts_of(d)
    space = design.inner_volumes(d)[0].Placement.Base
    guitest.isometric()
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_Suggest")
    from freecad.fabguide.gui import design_commands

    panel = design_commands.COMMANDS["FabGuide_Suggest"].panel
    QtGui.QApplication.processEvents()
    assert panel.form.isVisible(), "the Suggest panel is open"
    panel.wait()
    QtGui.QApplication.processEvents()
    assert panel.bar.value() == 100
    cards = panel.cards.buttons()
    assert 1 <= len(cards) <= 3, panel.message.text()
    assert re.match(r"1: 1 sheet\(s\), waste 0\.\d\d m² \(-\d+%\)$", cards[0].text()), cards[0].text()
    # The slider moves the design along the path, live, without an undo step.
    panel.slider.setValue(0)
    assert places(design.parts_of(d)) == panel.result["suggestions"][0]["design"]["path"][0]["parts"]
    panel.slider.setValue(panel.slider.maximum())
    QtGui.QApplication.processEvents()
    print("screenshot: " + guitest.screenshot("suggest_panel"))
    for path in guitest.screenshots_at_screen_sizes("suggest"):
        print("screenshot: " + path)
    print("3-D view: " + guitest.view_image("suggest_3d", compared=False))
    undo_steps = doc.UndoCount
    panel.accept()
    doc.recompute()
    assert doc.UndoCount == undo_steps + 1
    chosen = panel.result["suggestions"][0]
    assert design.parts_of(d) == chosen["design"]["parts"]  # applied as suggested
    assert chosen["waste_m2"] < panel.result["before"]["waste_m2"]
    assert all(c.Status == design.SATISFIED for c in d.Group if design.is_constraint(c))
    assert state["parts"]["shelf"].Grain == "X" and shelf_along_the_grain(d)
    doc.undo()
    doc.recompute()
    assert design.parts_of(d) == before
    assert design.inner_volumes(d)[0].Placement.Base == space  # back on the shelf exactly, after the previews


def import_and_export_a_flatpack_design():
    Gui.Control.closeDialog()
    doc = guitest.new_document("Shelf")
    source = os.path.join(os.environ["FABGUIDE_SOURCE_DIR"], "examples", "parrot-shelf.flatpack.json")
    guitest.with_file_dialog("getOpenFileName", source, "FabGuide_ImportFlatpack")
    designs = [o for o in doc.Objects if design.is_design(o)]
    assert len(designs) == 1 and "Invalid" not in designs[0].State, designs[0].Status
    shelf = designs[0]
    assert len(design.boxes(shelf)) == 7 and shelf.Usage > 0.8
    constraints = [o for o in shelf.Group if design.is_constraint(o)]
    assert len(constraints) == 7 and all(c.Status == design.SATISFIED for c in constraints)
    assert [o.ViewObject.Proxy.getIcon().endswith("FabGuide_Ground.svg") for o in constraints][0]
    guitest.isometric()
    print("3-D view: " + guitest.view_image("flatpack_parrot_shelf", compared=False))
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "shelf.flatpack.json")
        Gui.Selection.clearSelection()
        guitest.with_file_dialog("getSaveFileName", path, "FabGuide_ExportFlatpack")
        with open(path) as f:
            assert fabguide_core.lay_out_design(json.load(f))["usage"] == shelf.Usage


def suggest_changes_the_spreadsheet_of_a_parametric_design():
    Gui.Control.closeDialog()
    state["doc"] = doc = guitest.new_document("Box")
    sheet = doc.addObject("Spreadsheet::Sheet", "Params")
    for cell, alias, v in (("A1", "side", "300"), ("A2", "height", "170")):
        sheet.set(cell, v)
        sheet.setAlias(cell, alias)
    boards = []
    for name, length, width in (("side", "Params.side", "Params.height"), ("end", "Params.side - 24", "Params.height"),
                                ("bottom", "Params.side - 24", "Params.side - 24")):
        b = box(name, (1, 1, 12), (500 * len(boards), 0, 0))
        b.setExpression("Length", length)
        b.setExpression("Width", width)
        boards.append(b)
    doc.recompute()
    Gui.Selection.clearSelection()
    for b in boards:
        Gui.Selection.addSelection(b)
    Gui.runCommand("FabGuide_DesignFromBoxes")
    d = next(o for o in doc.Objects if design.is_design(o))
    d.MasterBoards[0].Width, d.MasterBoards[0].Height = 900, 600
    doc.recompute()
    said = guitest.told("FabGuide_Suggest")  # without Parameters it could change nothing: said before searching
    assert said.startswith("Suggest cannot change 'side', 'end', 'bottom': their sizes or places are set by "
                           "expressions"), said
    assert not Gui.Control.activeDialog()
    d.Parameters = ["Params.side 200 400", "Params.height 100 300"]
    doc.recompute()
    Gui.runCommand("FabGuide_Suggest")
    from freecad.fabguide.gui import design_commands

    panel = design_commands.COMMANDS["FabGuide_Suggest"].panel
    panel.seconds.setValue(4)
    panel.wait()
    assert panel.cards.buttons(), panel.message.text()
    assert "stopped" not in panel.message.text(), "its time limit ended it; the user did not stop it"
    assert not panel.locks.isVisible()
    steps = doc.UndoCount
    panel.accept()
    assert doc.UndoCount == steps + 1
    assert sheet.get("side") != 300 or sheet.get("height") != 170
    assert all(abs(sheet.get(a) * 10 - round(sheet.get(a) * 10)) < 1e-6 for a in ("side", "height")), \
        "written to 0.1 mm: {} {}".format(sheet.get("side"), sheet.get("height"))
    assert boards[2].Length.Value == sheet.get("side") - 24


def a_design_the_search_refuses_is_said_with_the_boxes_labels():
    """A box thinner than every master board: the search refuses it as the design's Status would, by the box's
    label, not by its place in the core's document ("parts[1].size")."""
    doc, shelf = state["doc"], state["parts"]["shelf"]
    thickness = shelf.Height.Value
    shelf.Height = 0.5
    Gui.runCommand("FabGuide_Suggest")
    from freecad.fabguide.gui import design_commands

    panel = design_commands.COMMANDS["FabGuide_Suggest"].panel
    panel.wait()
    said = panel.message.text()
    assert "box 'shelf': its thinnest side 0.5" in said and "parts[" not in said, said
    panel.reject()
    guitest.settle(0.3)
    shelf.Height = thickness
    doc.recompute()


def cancel_while_searching_leaves_nothing_running():
    doc = state["doc"]
    Gui.runCommand("FabGuide_Suggest")
    from freecad.fabguide.gui import design_commands

    panel = design_commands.COMMANDS["FabGuide_Suggest"].panel
    guitest.settle(0.3)
    panel.reject()
    assert not panel.timer.isActive() and not Gui.Control.activeDialog()
    guitest.settle(0.5)  # a poll timer left on the deleted form would raise here
    FreeCAD.closeDocument(doc.Name)


guitest.run([
    boxes_become_a_design_with_live_usage,
    constraints_from_picked_edges_faces_and_boxes,
    an_edit_keeps_the_constraints,
    suggest_shows_three_suggestions_and_applies_one_as_one_step,
    a_design_the_search_refuses_is_said_with_the_boxes_labels,
    import_and_export_a_flatpack_design,
    suggest_changes_the_spreadsheet_of_a_parametric_design,
    cancel_while_searching_leaves_nothing_running,
])
