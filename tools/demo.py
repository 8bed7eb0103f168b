"""`make demo`, run by freecadcmd: proves FreeCAD loads the installed workbench, then runs the
bundled examples through it: the Cabinet (thesis Table 4.1) is built as a FreeCAD document from its
works-like model, solved and saved; the bookshelf is laid out on its master boards and cut sheets are
written; the coffee table's flat-pack design is optimised to waste less and the best suggestion applied.
tools/demo_view.py then renders the saved cabinet in FreeCAD's GUI."""
import os
import sys

import FreeCAD
from freecad.fabguide.core import fabguide_core

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "demo")

mod_dir = os.path.dirname(os.path.realpath(fabguide_core.__file__))
assert os.path.isfile(os.path.join(mod_dir, "init_gui.py")), "fabguide_core is not inside a workbench folder"
print("FabGuide {} loaded by FreeCAD {} from {}".format(
    fabguide_core.__version__, ".".join(FreeCAD.Version()[:3]), mod_dir))

from freecad.fabguide.function import (joints, mechanism, parts, printable, relationships,  # noqa: E402
                                       workslike_file)
from freecad.fabguide.material import layout  # noqa: E402

# Function: the Cabinet as parts, joints, configurations and relationships; solved on recompute (thesis ch. 4).
os.makedirs(os.path.join(OUT, "cabinet"), exist_ok=True)
doc = FreeCAD.newDocument("Cabinet")
cabinet = workslike_file.read(doc, os.path.join(ROOT, "examples", "cabinet.workslike.json"))
modelled = {b.Label: b.Shape.BoundBox for b in mechanism.boxes(cabinet)}
doc.recompute()
print("Cabinet: {} parts, {} joints, {} relationships: {}".format(
    len(mechanism.members(cabinet, parts.is_part)), len(mechanism.members(cabinet, joints.is_joint)),
    len(mechanism.members(cabinet, relationships.is_relationship)), cabinet.Status))
for rel in mechanism.members(cabinet, relationships.is_relationship):
    print("  {:<11} {:<44} {}".format(rel.Proxy.KIND.replace("_", " "), rel.Label, rel.Status))
for box in mechanism.boxes(cabinet):
    was, now = modelled[box.Label], box.Shape.BoundBox
    corners = (was.XMin, was.YMin, was.ZMin, was.XMax, was.YMax, was.ZMax), (
        now.XMin, now.YMin, now.ZMin, now.XMax, now.YMax, now.ZMax)
    if max(abs(a - b) for a, b in zip(*corners)) > 1e-4:
        print("  {:<20} {:.0f} x {:.0f} x {:.0f} -> {:.0f} x {:.0f} x {:.0f} mm".format(
            box.Label, was.XLength, was.YLength, was.ZLength, now.XLength, now.YLength, now.ZLength))
if cabinet.Status != "Solved":
    sys.exit("the cabinet did not solve: " + cabinet.Status)
# Print in place (thesis 4.5): gaps, cavities, hinge pins and yokes; STL, 3MF and STEP; the clearance checked.
made = printable.create(doc, cabinet)
doc.recompute()
if "Invalid" in made.State:
    sys.exit("the cabinet could not be made printable: see the messages above")
print("Cabinet printable: {} bodies, least clearance {:.3f} mm (gap {} mm), at {}".format(
    len(made.Group) - 1, made.MinimumClearance.Value, made.Gap.Value, made.ClearanceAt))
for note in made.Notes:
    print("  note: " + note)
for path in printable.export(made, os.path.join(OUT, "cabinet", "print")):
    if "assembly" in path:
        print("  wrote " + os.path.relpath(path, ROOT))
doc.saveAs(os.path.join(OUT, "cabinet", "cabinet.FCStd"))
print("  wrote " + os.path.relpath(doc.FileName, ROOT))
# The same print fitted to a desktop printer's build volume (the saved document keeps it at 1:1).
made.FitToBuildVolume = True
doc.recompute()
if "Invalid" in made.State:
    sys.exit("the cabinet could not be fitted to the printer: see the messages above")
print("Cabinet fitted to a {:g} x {:g} x {:g} mm printer: scale {:.3f}, {}, least clearance {:.3f} mm".format(
    *made.BuildVolume, made.Scale, made.PrintSize, made.MinimumClearance.Value))
for path in printable.export(made, os.path.join(OUT, "cabinet", "print-desktop")):
    if path.endswith("assembly.3mf"):
        print("  wrote " + os.path.relpath(path, ROOT))
FreeCAD.closeDocument(doc.Name)


# Material: lay the bookshelf out on its master boards and write its cut sheets (thesis ch. 5).
doc = FreeCAD.openDocument(os.path.join(ROOT, "examples", "bookshelf.FCStd"))
for obj in doc.Objects:
    obj.touch()
doc.recompute()
shelf_layout = next(obj for obj in doc.Objects if layout.is_layout(obj))
if "Invalid" in shelf_layout.State:
    sys.exit("bookshelf layout failed: see the messages above")
print("Bookshelf: {} boards on {} master board(s) of {}; usage {:.1%}, sheet utilisation {:.1%}, waste {:.2f} m²"
      .format(sum(b.Quantity for b in shelf_layout.Boards), shelf_layout.SheetCount,
              shelf_layout.MasterBoards[0].Material, shelf_layout.Usage, shelf_layout.SheetUtilisation,
              shelf_layout.WasteArea.Value / 1e6))
for path in layout.export_cut_sheets(shelf_layout, os.path.join(OUT, "bookshelf")):
    print("  wrote " + os.path.relpath(path, ROOT))
FreeCAD.closeDocument(doc.Name)


# Zero waste: the coffee table's design changed within its constraints to waste less (thesis 5.4, Table 5.1).
from freecad.fabguide.material import design  # noqa: E402

os.makedirs(os.path.join(OUT, "coffee-table"), exist_ok=True)
doc = FreeCAD.newDocument("CoffeeTable")
table = design.from_file(doc, os.path.join(ROOT, "examples", "coffee-table.flatpack.json"))
doc.recompute()
result = fabguide_core.optimise(design.flatpack(table), seed=1, threads=2)
best = result["suggestions"][0]
print("Coffee table: usage {:.3f} -> {:.3f} ({} suggestions in {:.1f} s; the design's constraints all hold)".format(
    table.Usage, best["usage"], len(result["suggestions"]), result["seconds"]))
before = {p["id"]: design.sizes(p) for p in design.parts_of(table)}
doc.openTransaction("Accept suggestion")
design.apply_parts(table, best["design"]["parts"])
doc.recompute()
doc.commitTransaction()
for p in design.parts_of(table):
    if design.sizes(p) != before[p["id"]]:
        print("  {:<6} {:.1f} x {:.1f} x {:.1f} -> {:.1f} x {:.1f} x {:.1f} mm".format(p["id"], *before[p["id"]],
                                                                                      *design.sizes(p)))
if abs(table.Usage - best["usage"]) > 0.02 or "Broken" in "".join(c.Status for c in table.Group
                                                                  if design.is_constraint(c)):
    sys.exit("the accepted coffee table does not lay out as suggested: " + table.Status)
for path in fabguide_core.write_layout_files(best["problem"], best["layout"],
                                             svg_folder=os.path.join(OUT, "coffee-table")):
    print("  wrote " + os.path.relpath(path, ROOT))
doc.saveAs(os.path.join(OUT, "coffee-table", "coffee-table.FCStd"))
print("  wrote " + os.path.relpath(doc.FileName, ROOT))
FreeCAD.closeDocument(doc.Name)
