"""The FabGuide workbench: a Function toolbar (works-like prototypes, thesis ch. 4) and a
Material toolbar (zero-waste flat-pack furniture, thesis ch. 5)."""
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
            self.appendMenu(title, names)
        self.appendMenu(["&Help", "FabGuide"], commands.HELP)

    def GetClassName(self):
        return "Gui::PythonWorkbench"
