"""FreeCAD's GUI start-up imports this (FreeCAD's `freecad` namespace packages): registers the workbench."""
import FreeCADGui

from freecad.fabguide.gui import busy  # noqa: F401  (long core calls run off FreeCAD's thread)
from freecad.fabguide.gui.workbench import FabGuideWorkbench

FreeCADGui.addWorkbench(FabGuideWorkbench())
