"""Exports the first Layout of a FreeCAD document into a folder, as the Export Cut Sheets command does: the kill
test's FreeCAD job (tests/gen/kills.py).
    python3 tests/gen/export_layout.py DOCUMENT.FCStd FOLDER"""
import os
import sys

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
for path in ("/usr/lib/freecad-python3/lib", "/usr/share/freecad/Mod/Part", os.environ.get(
        "FABGUIDE_MOD_DIR", os.path.join(SOURCE, "build", "test-home", ".local", "share", "FreeCAD", "Mod",
                                         "FabGuide"))):
    if path not in sys.path:
        sys.path.append(path)

import FreeCAD  # noqa: E402
from freecad.fabguide.material import layout  # noqa: E402

document = FreeCAD.openDocument(sys.argv[1])
layout.export_cut_sheets(next(o for o in document.Objects if layout.is_layout(o)), sys.argv[2])
