"""FreeCAD's GUI start-up imports this (FreeCAD's `freecad` namespace packages): registers the workbench."""
import FreeCADGui

from freecad.fabguide.gui.workbench import FabGuideWorkbench

FreeCADGui.addWorkbench(FabGuideWorkbench())
