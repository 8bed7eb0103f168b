"""The FabGuide workbench: a Function toolbar and menu (works-like prototypes, thesis ch. 4), Material and Zero
waste toolbars and a Material menu (zero-waste flat-pack furniture, thesis ch. 5)."""
import FreeCADGui as Gui

from fabguide_gui import resources


class FabGuideWorkbench(Gui.Workbench):
    MenuText = "FabGuide"
    ToolTip = "Design things that work and waste nothing: functional relationships and zero-waste layouts"
    Icon = resources.icon("FabGuide.svg")

    def Initialize(self):
        from fabguide_gui import commands

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
