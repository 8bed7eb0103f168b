"""A bookcase bound to a spreadsheet, as a furniture designer models one: Part boxes whose sizes and
places are expressions of a spreadsheet's aliases; boards and a layout made from them, a flat-pack design with the
aliases as Parameters, Suggest, undo, save and reopen; with the mistakes people make on the way (a word typed
into a size cell, a misspelt or out-of-range parameter, a negative height, the spreadsheet deleted). Each mistake
is said in one sentence naming what to mend, nothing is changed that was not asked for, and the report view
holds no traceback and no red line that is not such a sentence."""
# FreeCAD's own lines while a size cell holds a word (its expressions cannot be evaluated):
# expects error: Failed to convert to Quantity
# expects error: unsupported operand type(s)
# expects error: Recompute failed! Please check report view.
# FreeCAD 1.0's own line for a box of negative height:
# expects error: Height of box too small
# expects error: not found in 'Dims.
# FreeCAD 0.20's undo of Suggest's cell values, at times, once the height cell has held a word (std::bad_cast on the
# height's cell B2 or the width's B1, whichever Suggest changed; the values come back, checked below):
# expects error: exception while restoring Bookcase#Dims.B
# FabGuide's sentences for the user's mistakes:
# expects error: Design 'FlatpackDesign': parameter 'Dims.heigth 1500 2000': no spreadsheet 'Dims' with an alias
# expects error: Design 'FlatpackDesign': parameter 'Dims.height 100 200' is 1800 now, outside its range
import os
import tempfile

import FreeCAD
import FreeCADGui as Gui

import guitest
from freecad.fabguide import properties
from freecad.fabguide.material import board, design, layout

state = {}

# (label, length, width, height, x, y, z) in the spreadsheet's aliases: sides "thick", top, bottom and two shelves
BOXES = (("Left side", "Dims.thick", "Dims.depth", "Dims.height", "0", "0", "0"),
         ("Right side", "Dims.thick", "Dims.depth", "Dims.height", "Dims.width - Dims.thick", "0", "0"),
         ("Bottom", "Dims.width - 2 * Dims.thick", "Dims.depth", "Dims.thick", "Dims.thick", "0", "0"),
         ("Top", "Dims.width - 2 * Dims.thick", "Dims.depth", "Dims.thick", "Dims.thick", "0", "Dims.height - Dims.thick"),
         ("Shelf 1", "Dims.width - 2 * Dims.thick", "Dims.depth - 20", "Dims.thick", "Dims.thick", "0", "Dims.height / 3"),
         ("Shelf 2", "Dims.width - 2 * Dims.thick", "Dims.depth - 20", "Dims.thick", "Dims.thick", "0", "2 * Dims.height / 3"))


def sizes():
    return {b.Label: (round(b.Length.Value, 3), round(b.Width.Value, 3), round(b.Height.Value, 3))
            for b in state["boxes"]}


def a_bookcase_bound_to_a_spreadsheet():
    doc, state["told"] = guitest.session("Bookcase")
    state["doc"] = doc
    sheet = doc.addObject("Spreadsheet::Sheet", "Dims")
    for row, (alias, value) in enumerate((("width", "800"), ("height", "1800"), ("depth", "300"), ("thick", "18")), 1):
        sheet.set("A{}".format(row), alias)
        sheet.set("B{}".format(row), value)
        sheet.setAlias("B{}".format(row), alias)
    boxes = []
    for label, length, width, height, x, y, z in BOXES:
        b = doc.addObject("Part::Box", "Box")
        b.Label = label
        for prop, expression in (("Length", length), ("Width", width), ("Height", height), (".Placement.Base.x", x),
                                 (".Placement.Base.y", y), (".Placement.Base.z", z)):
            b.setExpression(prop, expression)
        boxes.append(b)
    doc.recompute()
    state["boxes"], state["sheet"] = boxes, sheet
    assert sizes()["Top"] == (764, 300, 18), sizes()
    assert boxes[3].Placement.Base.z == 1782


def boards_and_a_layout_follow_the_spreadsheet():
    doc = state["doc"]
    guitest.pick(*[(b, None) for b in state["boxes"]])
    Gui.runCommand("FabGuide_BoardsFromSolids")
    boards = [o for o in doc.Objects if board.is_board(o)]
    assert len(boards) == 6, [o.Label for o in doc.Objects]
    guitest.pick(*[(b, None) for b in boards])
    Gui.runCommand("FabGuide_Layout")
    Gui.Control.closeDialog()
    lay = next(o for o in doc.Objects if layout.is_layout(o))
    assert not lay.Error and lay.SheetCount == 1, lay.Error
    area = lay.WasteArea.Value
    state["sheet"].set("width", "1000")  # the alias cell: the whole bookcase wider
    doc.recompute()
    assert sizes()["Top"] == (964, 300, 18), sizes()
    assert not lay.Error and lay.WasteArea.Value < area, (lay.Error, lay.WasteArea.Value, area)
    state["layout"] = lay


def a_word_in_a_size_cell_is_said_and_mended():
    doc, sheet, lay = state["doc"], state["sheet"], state["layout"]
    before = sizes()
    sheet.set("B2", "eighteen hundred")
    doc.recompute()
    assert sizes() == before, "the boxes keep their sizes while the cell holds no number"
    sheet.set("B2", "1800")
    doc.recompute()
    assert not lay.Error, lay.Error
    assert not [o.Label for o in doc.Objects if "Invalid" in o.State], [(o.Label, o.State) for o in doc.Objects]


def a_flatpack_design_with_the_aliases_as_parameters():
    doc = state["doc"]
    guitest.pick(*[(b, None) for b in state["boxes"]])
    Gui.runCommand("FabGuide_DesignFromBoxes")
    d = next(o for o in doc.Objects if design.is_design(o))
    state["design"] = d
    assert d.Status and not d.Error, d.Error
    d.Parameters = ["Dims.heigth 1500 2000"]  # misspelt
    doc.recompute()
    assert "parameter 'Dims.heigth 1500 2000': no spreadsheet 'Dims' with an alias 'heigth'" in d.Error, d.Error
    d.Parameters = ["Dims.height 100 200"]  # the value is outside its range
    doc.recompute()
    assert "is 1800 now, outside its range" in d.Error, d.Error
    d.Parameters = ["Dims.height 1500 2000", "Dims.width 800 1100"]
    doc.recompute()
    assert not d.Error, d.Error
    guitest.pick((d, None))
    guitest.isometric()
    for path in guitest.screenshots_at_screen_sizes("bookcase"):
        print("screenshot: " + path)
    print("3-D view: " + guitest.view_image("bookcase_3d", compared=False))


def suggest_changes_the_aliases_and_undo_brings_them_back():
    doc, d, sheet = state["doc"], state["design"], state["sheet"]
    was = (sheet.get("height"), sheet.get("width"))
    Gui.runCommand("FabGuide_Suggest")
    from freecad.fabguide.gui import design_commands

    panel = design_commands.COMMANDS["FabGuide_Suggest"].panel
    panel.seconds.setValue(3)
    panel.wait()
    if not panel.cards.buttons():  # nothing wastes less: said, and nothing changes
        assert "No variation" in panel.message.text() or "No suggestions" in panel.message.text(), \
            panel.message.text()
        panel.reject()
        assert (sheet.get("height"), sheet.get("width")) == was
        return
    panel.accept()
    now = (sheet.get("height"), sheet.get("width"))
    assert now != was and 1500 <= now[0] <= 2000 and 800 <= now[1] <= 1100, now
    assert sizes()["Top"][0] == round(now[1] - 36, 3), (sizes(), now)
    doc.undo()
    doc.recompute()
    assert (sheet.get("height"), sheet.get("width")) == was


def a_negative_height_is_refused_by_name():
    # FreeCAD refuses the boxes (a Part::Box of negative height) and leaves what is made from them touched: the
    # layout's files and Suggest refuse to start from their last shapes, naming the boxes.
    doc, sheet, d, lay, boxes = state["doc"], state["sheet"], state["design"], state["layout"], state["told"]
    sheet.set("height", "-5")
    doc.recompute()
    guitest.pick((lay, None))
    guitest.with_file_dialog("getExistingDirectory", tempfile.mkdtemp(), "FabGuide_ExportCutSheets")
    guitest.pick((d, None))
    Gui.runCommand("FabGuide_Suggest")
    guitest.settle(0.3)
    assert not Gui.Control.activeDialog()
    assert len(boxes.told) == 2, boxes.told
    assert boxes.told[0].startswith("Layout 'Layout': 'Left side', 'Right side' could not be recomputed"), boxes.told
    assert boxes.told[1].startswith("Design 'FlatpackDesign': 'Left side', 'Right side' could not be recomputed"), \
        boxes.told
    boxes.told.clear()
    sheet.set("height", "1800")
    doc.recompute()
    assert not d.Error and not lay.Error and not properties.failed_inputs(lay), (d.Error, lay.Error)


def deleting_the_spreadsheet_is_said_and_undone():
    doc, d, lay, boxes = state["doc"], state["design"], state["layout"], state["told"]
    doc.openTransaction("Delete")
    doc.removeObject("Dims")
    doc.commitTransaction()
    doc.recompute()
    guitest.pick((lay, None))
    guitest.with_file_dialog("getExistingDirectory", tempfile.mkdtemp(), "FabGuide_ExportCutSheets")
    assert len(boxes.told) == 1 and "could not be recomputed" in boxes.told[0], boxes.told
    boxes.told.clear()
    doc.undo()
    doc.recompute()
    assert doc.getObject("Dims") and not d.Error and not properties.failed_inputs(lay), d.Error


def saved_and_reopened_it_is_as_it_was():
    doc, lay = state["doc"], state["layout"]
    path = os.path.join(tempfile.mkdtemp(), "bookcase.FCStd")
    before = (sizes(), lay.SheetCount, round(lay.WasteArea.Value), state["design"].Status)
    doc.saveAs(path)
    assert not [o.Label for o in doc.Objects if "Touched" in o.State], [(o.Label, o.State) for o in doc.Objects]
    FreeCAD.closeDocument(doc.Name)
    doc = FreeCAD.openDocument(path)
    state["doc"] = doc
    state["boxes"] = [next(o for o in doc.Objects if o.Label == label) for label, *_ in BOXES]
    lay = next(o for o in doc.Objects if layout.is_layout(o))
    d = next(o for o in doc.Objects if design.is_design(o))
    assert (sizes(), lay.SheetCount, round(lay.WasteArea.Value), d.Status) == before
    doc.recompute()
    assert (sizes(), lay.SheetCount, round(lay.WasteArea.Value), d.Status) == before
    assert state["told"].told == [], state["told"].told
    FreeCAD.closeDocument(doc.Name)


guitest.run([
    a_bookcase_bound_to_a_spreadsheet,
    boards_and_a_layout_follow_the_spreadsheet,
    a_word_in_a_size_cell_is_said_and_mended,
    a_flatpack_design_with_the_aliases_as_parameters,
    suggest_changes_the_aliases_and_undo_brings_them_back,
    a_negative_height_is_refused_by_name,
    deleting_the_spreadsheet_is_said_and_undone,
    saved_and_reopened_it_is_as_it_was,
])
