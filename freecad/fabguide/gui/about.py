"""Help > FabGuide > About: the versions a bug report needs."""
import FreeCAD
from freecad.fabguide.core import fabguide_core

from freecad.fabguide.gui import resources
from freecad.fabguide.i18n import translate


def report():
    """FabGuide, FreeCAD and core-library versions, one per line."""
    lines = ["FabGuide " + fabguide_core.__version__, "FreeCAD " + ".".join(FreeCAD.Version()[:3])]
    lines += ["{} {}".format(library, version) for library, version in fabguide_core.dependency_versions()]
    return "\n".join(lines)


class AboutCommand:
    def GetResources(self):
        return {
            "Pixmap": resources.icon("FabGuide.svg"),
            "MenuText": translate("FabGuide", "About FabGuide"),
            "ToolTip": translate("FabGuide", "Show the FabGuide version and the libraries it was built with"),
        }

    def Activated(self):
        from PySide import QtGui

        QtGui.QMessageBox.about(None, translate("FabGuide", "About FabGuide"), report())

    def IsActive(self):
        return True
