"""FreeCAD GUI entry point: registers the FabGuide workbench."""
import FreeCADGui

from fabguide_gui.workbench import FabGuideWorkbench

FreeCADGui.addWorkbench(FabGuideWorkbench())
