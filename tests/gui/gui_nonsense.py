"""Nonsense everywhere: what a tester typed and picked in a session that found tracebacks, a crash and
a change undo could not take back. A part among its own boxes, links to the wrong kind of object, a minimum size of
1e-300, nan in a list of angles or a box's Length, an edge picked for a slide, two faces of one box made flush,
boxes already in parts made a mechanism, an edge that does not exist, a folder picked as a file, an envelope round
no boxes, a spreadsheet cell holding words. Each is one sentence; the runner fails on any traceback or other red
line.
"""
# expects error: Part 'Body part': Cuboids must be Part::Box objects; kept 'Body'
# expects error: Mechanism 'Mechanism': MinimumSize must be 0.01 mm or more; kept
# expects error: Joint 'Lid hinge': Part must be a FabGuide part; kept 'Lid part'
# expects error: Configuration 'Open': Joints must be joints; kept 'Lid hinge'
# expects error: Configuration 'Open': HingeAngle must be a finite number; kept -90.00 °
# expects error: Printable 'Mechanism printable': Mechanism must be a Mechanism; kept 'Mechanism'
# expects error: Design 'Bookshelf': MasterBoards must be master boards; kept 'MasterBoard'
# expects error: Design 'Bookshelf': no boxes to lay out (drag the furniture's Part boxes into the design)
# expects error: Joint 'Lid hinge': 'Lid.Face99' is not an edge of the box
# expects error: 'Shelf side': its Length, Width, Height and Placement must be finite numbers
import math
import os
import tempfile

import FreeCAD
import FreeCADGui as Gui

import guitest
from freecad.fabguide import cuboids
from freecad.fabguide.function import configuration, joints, mechanism, parts, printable
from freecad.fabguide.material import design

state = {}
boxes = None  # guitest.MessageBoxes: what message boxes said, in order


def box(label, low, high):
    return guitest.box(state["doc"], label, low, high)


pick = guitest.pick


def typed(obj, prop, value):
    """A value set as a script or the property editor sets it, in one undo step; then a recompute."""
    doc = obj.Document
    doc.openTransaction("Nonsense")
    try:
        setattr(obj, prop, value)
    finally:
        doc.commitTransaction()
    doc.recompute()
    guitest.settle(0.2)


def told(command, *picked):
    pick(*picked)
    said = len(boxes.told)
    Gui.runCommand(command)
    guitest.settle(0.3)
    return boxes.told[said:]


def a_clamshell():
    global boxes
    doc, boxes = guitest.session("Nonsense")
    state["doc"] = doc
    body, lid = box("Body", (0, 0, 0), (100, 60, 40)), box("Lid", (0, 0, 40), (100, 60, 50))
    doc.recompute()
    pick((body, None), (lid, None))
    Gui.runCommand("FabGuide_NewMechanism")
    pick((lid, "Edge2"))
    Gui.runCommand("FabGuide_AddHinge")
    mech = next(o for o in doc.Objects if mechanism.is_mechanism(o))
    state.update(body=body, lid=lid, mech=mech, hinge=next(o for o in doc.Objects if joints.is_joint(o)))
    assert mech.Status == "Solved", mech.Status


def links_to_the_wrong_objects_are_refused_as_typed():
    doc, mech = state["doc"], state["mech"]
    body_part = parts.part_of(doc.Objects, state["body"])
    sheet = doc.addObject("Spreadsheet::Sheet", "Sheet")
    typed(body_part, "Cuboids", [body_part, sheet, state["body"]])  # crashed FreeCAD: a part among its boxes
    assert list(body_part.Cuboids) == [state["body"]]
    typed(state["hinge"], "Part", mech)
    assert parts.is_part(state["hinge"].Part)
    made = configuration.create(doc, "Open", [(state["hinge"], -90, 0)])
    mech.Group = mech.Group + [made]
    typed(made, "Joints", [made])
    assert list(made.Joints) == [state["hinge"]]
    angle = state["hinge"].Name + "Angle"
    typed(made, angle, math.nan)
    assert getattr(made, angle).Value == -90
    print_it = printable.create(doc, mech)
    group = doc.addObject("App::DocumentObjectGroup", "Group")
    typed(print_it, "Mechanism", group)
    assert print_it.Mechanism == mech
    doc.removeObject(print_it.Name)
    doc.recompute()


def a_minimum_size_of_nothing_is_refused_and_nothing_collapses():
    mech, lid = state["mech"], state["lid"]
    before = cuboids.coordinates(lid)
    typed(mech, "MinimumSize", 1e-300)
    assert mech.MinimumSize.Value == 1 and cuboids.coordinates(lid) == before


def commands_on_wrong_picks_say_one_sentence():
    doc, body, lid = state["doc"], state["body"], state["lid"]
    said = told("FabGuide_AddFlush", (lid, "Face1"), (lid, "Face2"))
    assert said == ["Pick faces of two different boxes: two faces of one box never lie in one plane."], said
    said = told("FabGuide_NewMechanism", (lid, None))
    assert said == ["Every picked box is already in a part: pick boxes that are not."], said
    said = told("FabGuide_AddSlide", (body, "Edge1"), (body, "Face6"))  # an edge too: a slide has none
    assert said == [], said
    slide = next(o for o in doc.Objects if joints.is_joint(o) and joints.kind(o) == "slide")
    assert slide.Axis == "z" and not slide.Error, (slide.Axis, slide.Error)


def an_edge_that_does_not_exist_is_a_sentence():
    hinge, lid = state["hinge"], state["lid"]
    before = guitest.report_view().count("'Lid.Face99' is not an edge of the box")
    typed(hinge, "Edge", (lid, ["Face99"]))
    assert "'Lid.Face99' is not an edge of the box" in hinge.Error, hinge.Error
    mech = next(o for o in hinge.InList if mechanism.is_mechanism(o))
    assert hinge.Error in mech.Error, mech.Error  # the mechanism fails for it, and does not say it again
    assert guitest.report_view().count("'Lid.Face99' is not an edge of the box") == before + 1


def a_folder_picked_as_a_file_is_said():
    folder = tempfile.mkdtemp()
    said = len(boxes.told)
    guitest.with_file_dialog("getSaveFileName", folder, "FabGuide_ExportWorkslike")
    guitest.settle(0.3)
    assert boxes.told[said:] and "cannot use '{}'".format(folder) in boxes.told[-1], boxes.told[said:]
    FreeCAD.closeDocument(state["doc"].Name)


def a_design_of_nonsense():
    doc = state["doc"] = guitest.new_document("Shelf")
    sides = [box("Shelf side", (0, 0, 0), (18, 300, 800)), box("Shelf side", (582, 0, 0), (600, 300, 800)),
             box("Shelf", (18, 0, 400), (582, 300, 418))]
    doc.recompute()
    pick(*[(b, None) for b in sides])
    Gui.runCommand("FabGuide_DesignFromBoxes")
    shelf = next(o for o in doc.Objects if design.is_design(o))
    shelf.Label = "Bookshelf"
    group = doc.addObject("App::DocumentObjectGroup", "Group")
    typed(shelf, "MasterBoards", [group])
    assert len(shelf.MasterBoards) == 1 and shelf.MasterBoards[0] != group
    typed(sides[0], "Length", math.nan)
    assert "must be finite numbers" in shelf.Error, shelf.Error
    doc.undo()
    doc.recompute()
    assert not shelf.Error, shelf.Error
    sheet = doc.addObject("Spreadsheet::Sheet", "Params")
    sheet.set("A1", "abc")
    sheet.setAlias("A1", "word")
    doc.recompute()
    shelf.Parameters = ["Params.word 0 100"]
    said = told("FabGuide_Suggest")
    assert said == ["Spreadsheet 'Params': 'word' holds no number (could not convert string to float: 'abc')"], said
    shelf.Parameters = []
    for b in sides:
        doc.removeObject(b.Name)
    doc.recompute()
    said = told("FabGuide_OuterVolume", (shelf, None))
    assert said == ["Design 'Bookshelf' has no boxes to put an envelope round."], said
    for path in guitest.screenshots_at_screen_sizes("nonsense"):  # the report view: sentences, no traceback
        print("screenshot: " + path)


guitest.run([a_clamshell, links_to_the_wrong_objects_are_refused_as_typed,
             a_minimum_size_of_nothing_is_refused_and_nothing_collapses, commands_on_wrong_picks_say_one_sentence,
             an_edge_that_does_not_exist_is_a_sentence, a_folder_picked_as_a_file_is_said, a_design_of_nonsense])
