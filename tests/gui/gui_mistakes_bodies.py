"""A new user's bedside cabinet from PartDesign Bodies and a Part Extrude, with their mistakes: the Pad
picked in the 3-D view rather than its Body, a block and an empty Body picked as boards, a Pad made thicker than any
master board, the document saved and reopened. Each mistake is one sentence; the board follows the Body.
"""
# expects error: Layout 'Layout': part 'Side L board' is 25 mm thick: no master board is (add one that thick)
import json
import os
import tempfile

import FreeCAD
import FreeCADGui as Gui
import Part

from freecad.fabguide.gui import editing
from freecad.fabguide.material import board, layout

import guitest

state = {}


def rectangle(width, depth):
    corners = [FreeCAD.Vector(x, y, 0) for x, y in ((0, 0), (width, 0), (width, depth), (0, depth))]
    return [Part.LineSegment(a, b) for a, b in zip(corners, corners[1:] + corners[:1])]


def padded(doc, label, width, depth, thickness):
    """A Body of one Pad on an unattached sketch: what a PartDesign user draws for a panel."""
    body = doc.addObject("PartDesign::Body", "Body")
    body.Label = label
    sketch = body.newObject("Sketcher::SketchObject", "Sketch")
    for line in rectangle(width, depth):
        sketch.addGeometry(line)
    pad = body.newObject("PartDesign::Pad", "Pad")
    pad.Profile = sketch
    pad.Length = thickness
    return body, pad


def extruded(doc, label, width, depth, thickness):
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    for line in rectangle(width, depth):
        sketch.addGeometry(line)
    extrusion = doc.addObject("Part::Extrusion", "Extrude")
    extrusion.Base, extrusion.Solid, extrusion.LengthFwd = sketch, True, thickness
    extrusion.Label = label
    return extrusion


def boards_from(objects, says=None):
    Gui.Selection.clearSelection()
    for obj in objects:
        Gui.Selection.addSelection(obj)
    told = guitest.told("FabGuide_BoardsFromSolids")
    assert told == says, told
    guitest.settle(0.3)


def boards(doc):
    return [o for o in doc.Objects if board.is_board(o)]


def a_pad_picked_in_the_3d_view_makes_a_board_of_its_body():
    Gui.activateWorkbench("FabGuideWorkbench")
    doc = state["doc"] = guitest.new_document("Bedside")
    side_l, pad_l = padded(doc, "Side L", 400, 600, 18)
    side_r, pad_r = padded(doc, "Side R", 400, 600, 18)
    top = extruded(doc, "Top", 450, 400, 18)
    state.update(pad=pad_l, side=side_l)
    doc.recompute()
    Gui.runCommand("FabGuide_NewMasterBoard")
    boards_from([pad_l, side_r, top])  # the Pad, as a click on the solid picks it
    made = boards(doc)
    assert sorted(b.Label for b in made) == ["Side L board", "Side R board", "Top board"], [b.Label for b in made]
    sources = {b.Label: b.Source[0] for b in made}
    assert sources["Side L board"] == side_l, "a Pad stands for its Body, not a link into it from outside"
    assert all(not b.Error for b in made), [b.Error for b in made]
    assert [round(b.Thickness.Value, 6) for b in made] == [18.0] * 3


def a_block_and_an_empty_body_are_said_not_made():
    doc = state["doc"]
    block, _ = padded(doc, "Drawer block", 300, 300, 300)
    empty = doc.addObject("PartDesign::Body", "Body")
    empty.Label = "Empty body"
    doc.recompute()
    before = len(boards(doc))
    boards_from([empty], says="Select the solids of your furniture model (flat boxes, pads, extrusions) first.")
    assert len(boards(doc)) == before, "nothing made from an empty Body"
    boards_from([block, state["side"]], says="Nothing made: 'Drawer block': is 300 mm thick and 300 mm wide, a "
                "block or a post rather than a board (a board is thinner than it is wide).")
    assert len(boards(doc)) == before, "nothing made when a pick is no board: the user picks again"


def a_layout_follows_the_pad_and_says_when_no_master_board_is_thick_enough():
    doc = state["doc"]
    Gui.Selection.clearSelection()
    Gui.runCommand("FabGuide_Layout")
    guitest.settle(0.5)
    editing.close_panel(doc)
    lay = state["layout"] = next(o for o in doc.Objects if layout.is_layout(o))
    doc.recompute()
    assert not lay.Error and lay.SheetCount >= 1, (lay.Error, lay.SheetCount)
    placed = json.loads(lay.LayoutJson)["placements"]
    assert len(placed) == 3, "panels drawn on top of each other at the origin are three parts, not one piece"
    doc.openTransaction("Thicker side")
    state["pad"].Length = 25
    doc.commitTransaction()
    doc.recompute()
    side_board = next(b for b in boards(doc) if b.Source[0] == state["side"])
    assert abs(side_board.Thickness.Value - 25) < 1e-6, side_board.Thickness
    assert "part 'Side L board' is 25 mm thick: no master board is (add one that thick)" in lay.Error, lay.Error
    doc.undo()
    doc.recompute()
    assert abs(side_board.Thickness.Value - 18) < 1e-6 and not lay.Error, (side_board.Thickness, lay.Error)


def saved_and_reopened_it_is_the_same():
    doc = state["doc"]
    path = os.path.join(tempfile.mkdtemp(), "bedside.FCStd")
    sheets = state["layout"].SheetCount
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    again = FreeCAD.openDocument(path)
    again.recompute()
    lay = next(o for o in again.Objects if layout.is_layout(o))
    assert lay.SheetCount == sheets and not lay.Error, (lay.SheetCount, lay.Error)
    assert next(b for b in boards(again) if b.Label == "Side L board").Source[0].TypeId == "PartDesign::Body"
    guitest.screenshots_at_screen_sizes("bodies_reopened")


guitest.run([a_pad_picked_in_the_3d_view_makes_a_board_of_its_body, a_block_and_an_empty_body_are_said_not_made,
             a_layout_follows_the_pad_and_says_when_no_master_board_is_thick_enough, saved_and_reopened_it_is_the_same])
