"""Builds examples/bookshelf.FCStd and examples/coffee-table.FCStd: furniture modelled from plain Part
boxes, as a FreeCAD user would, turned into FabGuide boards with a master board and a layout.
Run with the workbench installed: freecadcmd -c "import runpy; runpy.run_path('tools/make_examples.py')"
The same parts are in examples/*.pack.json for the command line."""
import os

import FreeCAD

from freecad.fabguide.material import board, layout, master_board

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def furniture(name, thickness, panels, sheet, cutting):
    """panels: (label, (dx, dy, dz), (x, y, z)) boxes; sheet: (width, height, count, material)."""
    doc = FreeCAD.newDocument(name)
    solids = []
    for label, size, at in panels:
        box = doc.addObject("Part::Box", "Box")
        box.Label = label
        box.Length, box.Width, box.Height = size
        box.Placement.Base = FreeCAD.Vector(*at)
        solids.append(box)
    doc.recompute()
    boards = [board.create(doc, solid, label=solid.Label + " board") for solid in solids]
    for solid in solids:
        solid.Visibility = False
    width, height, count, material = sheet
    master = master_board.create(doc, width, height, thickness, count, material, label=material)
    lay = layout.create(doc, boards, [master])
    lay.Kerf, lay.Spacing, lay.Trim = cutting
    doc.recompute()
    path = os.path.join(ROOT, "examples", name + ".FCStd")
    doc.saveAs(path)
    print("{}: {} boards, usage {:.1%} on {} sheet(s)".format(path, len(boards), lay.Usage, lay.SheetCount))
    FreeCAD.closeDocument(doc.Name)


t = 18  # bookshelf: 800 wide, 1800 tall, 300 deep, five shelves, plinth and top rail, for a CNC router
shelves = [("Shelf {}".format(i + 1), (764, 300, t), (t, 0, 80 + i * 420)) for i in range(5)]
furniture("bookshelf", t,
          [("Left side", (t, 300, 1800), (0, 0, 0)), ("Right side", (t, 300, 1800), (764 + t, 0, 0))] + shelves +
          [("Plinth", (764, t, 80), (t, 0, 0)), ("Top rail", (764, t, 60), (t, 0, 1740))],
          (2440, 1220, 2, "birch plywood"), (6, 4, 10))

t = 12  # coffee table: a top on two legs with a shelf between them, for a laser cutter
furniture("coffee-table", t,
          [("Top", (700, 420, t), (0, 0, 400)), ("Left leg", (t, 380, 400), (30, 20, 0)),
           ("Right leg", (t, 380, 400), (700 - 30 - t, 20, 0)), ("Shelf", (616, 150, t), (30 + t, 135, 120))],
          (1220, 915, 1, "poplar plywood"), (0.2, 3, 5))
