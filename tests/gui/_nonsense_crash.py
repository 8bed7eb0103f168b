"""Repro: a part's Cuboids linked to itself (a script's or property editor's nonsense) -> FreeCAD crash?"""
import os
import FreeCAD
import FreeCADGui as Gui
import guitest
from freecad.fabguide import cuboids

VARIANT = os.environ.get("NONSENSE_VARIANT", "a")


def go():
    Gui.activateWorkbench("FabGuideWorkbench")
    doc = guitest.new_document("Crash")
    boxes = guitest.MessageBoxes()
    a = doc.addObject("Part::Box", "Box")
    b = doc.addObject("Part::Box", "Box")
    b.Placement.Base = FreeCAD.Vector(0, 0, 10)
    sheet = doc.addObject("Spreadsheet::Sheet", "Spreadsheet")
    doc.recompute()
    Gui.Selection.addSelection(a)
    Gui.Selection.addSelection(b)
    Gui.runCommand("FabGuide_NewMechanism")
    part = [o for o in doc.Objects if o.Name.startswith("FunctionalPart")][1]
    print("part", part.Label, [c.Label for c in part.Cuboids])
    values = {"a": [part], "b": [part, sheet, a], "c": [part, a], "d": [sheet, a]}[VARIANT]
    doc.openTransaction("x")
    part.Cuboids = values
    doc.commitTransaction()
    print("set")
    doc.recompute()
    print("recomputed", part.Error)
    guitest.settle(0.5)
    print("settled")
    doc.undo()
    print("undone")
    doc.recompute()
    guitest.settle(0.5)
    print("ok", [c.Label for c in part.Cuboids])


guitest.run([go])
