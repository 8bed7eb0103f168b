"""FabGuide's GUI commands and where the workbench shows them."""
import FreeCADGui as Gui

from fabguide_gui import about

# Toolbar and menu contents, filled by the feature work: Function (thesis ch. 4), Material (ch. 5).
TOOLBARS = {
    "Function": [],
    "Material": [],
}
HELP = ["FabGuide_About"]

COMMANDS = {
    "FabGuide_About": about.AboutCommand(),
}


def register():
    """Add every FabGuide command to FreeCAD's command registry (idempotent)."""
    for name, command in COMMANDS.items():
        Gui.addCommand(name, command)
