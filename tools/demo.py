"""`make demo`, run by freecadcmd: proves FreeCAD loads the installed workbench, then runs the
bundled examples through it."""
import os

import FreeCAD
import fabguide_core

mod_dir = os.path.dirname(os.path.realpath(fabguide_core.__file__))
assert os.path.isfile(os.path.join(mod_dir, "InitGui.py")), "fabguide_core is not inside a workbench folder"
print("FabGuide {} loaded by FreeCAD {} from {}".format(
    fabguide_core.__version__, ".".join(FreeCAD.Version()[:3]), mod_dir))
