"""FreeCAD's GUI start-up imports this (FreeCAD's `freecad` namespace packages): registers FabGuide's
translations, the workbench and its preferences page (Edit > Preferences > FabGuide)."""
import os

import FreeCADGui

from freecad.fabguide.gui import resources

FreeCADGui.addLanguagePath(os.path.join(resources.RESOURCES, "translations"))  # FabGuide_<language>.qm
FreeCADGui.updateLocale()

from freecad.fabguide.gui import busy  # noqa: E402,F401  (long core calls run off FreeCAD's thread)
from freecad.fabguide.gui import documents  # noqa: E402,F401  (opened documents get FabGuide's view providers)
from freecad.fabguide.gui.workbench import FabGuideWorkbench  # noqa: E402  (its tip translated)

FreeCADGui.addWorkbench(FabGuideWorkbench())
FreeCADGui.addPreferencePage(os.path.join(resources.RESOURCES, "ui", "Preferences.ui"), "FabGuide")
FreeCADGui.addIconPath(os.path.dirname(resources.icon("FabGuide.svg")))  # holds the page's preferences-fabguide.svg
