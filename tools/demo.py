"""`make demo`, run by freecadcmd: proves FreeCAD loads the installed workbench, then runs the
bundled examples through it: the bookshelf is laid out on its master boards and cut sheets are written."""
import os
import sys

import FreeCAD
import fabguide_core

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "demo")

mod_dir = os.path.dirname(os.path.realpath(fabguide_core.__file__))
assert os.path.isfile(os.path.join(mod_dir, "InitGui.py")), "fabguide_core is not inside a workbench folder"
print("FabGuide {} loaded by FreeCAD {} from {}".format(
    fabguide_core.__version__, ".".join(FreeCAD.Version()[:3]), mod_dir))

from fabguide.material import layout  # noqa: E402  (needs the workbench found above)

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
