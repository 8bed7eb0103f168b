"""The FabGuide workbench: a Function toolbar and menu (works-like prototypes, thesis ch. 4), Material and Zero
waste toolbars and a Material menu (zero-waste flat-pack furniture, thesis ch. 5)."""
import FreeCAD
import FreeCADGui as Gui

from freecad.fabguide.gui import resources
from freecad.fabguide.i18n import translate


class FabGuideWorkbench(Gui.Workbench):
    MenuText = "FabGuide"
    ToolTip = translate("FabGuide", "Design things that work and waste nothing: functional relationships and "
                                    "zero-waste layouts")
    Icon = resources.icon("FabGuide.svg")

    def Initialize(self):
        """All the commands, or, where the compiled core is missing, the one that builds it and one sentence."""
        from freecad.fabguide import CoreMissing

        try:
            from freecad.fabguide.gui import commands
        except CoreMissing as missing:
            from freecad.fabguide.gui import build_core

            FreeCAD.Console.PrintWarning(str(missing) + "\n")
            Gui.addCommand("FabGuide_BuildCore", build_core.BuildCoreCommand())
            self.appendToolbar("FabGuide", ["FabGuide_BuildCore"])
            self.appendMenu("FabGuide", ["FabGuide_BuildCore"])
            return
        commands.register()
        for title, names in commands.TOOLBARS.items():
            self.appendToolbar(title, names)
        for path, names in commands.MENUS:
            self.appendMenu(path, names)

    def Activated(self):
        """FabGuide's toolbars start a row of their own, where the three fit a 1366 px screen; FreeCAD's own fill
        the rows above. The user may move them: a row break already there is left alone."""
        from PySide import QtCore, QtGui

        window = Gui.getMainWindow()
        first = [bar for bar in window.findChildren(QtGui.QToolBar) if bar.objectName() == "Function"]
        if first and window.toolBarArea(first[0]) == QtCore.Qt.TopToolBarArea and not window.toolBarBreak(first[0]):
            window.insertToolBarBreak(first[0])

    def GetClassName(self):
        return "Gui::PythonWorkbench"
