"""FabGuide's GUI commands and where the workbench shows them."""
import FreeCADGui as Gui

from fabguide_gui import about, design_commands, function_commands, material_commands

# Toolbar and menu contents: Function (thesis ch. 4), Material and Zero waste (ch. 5).
TOOLBARS = {
    "Function": list(function_commands.COMMANDS),
    "Material": list(material_commands.COMMANDS),
    "Zero waste": list(design_commands.COMMANDS),
}
HELP = ["FabGuide_About"]

COMMANDS = dict(function_commands.COMMANDS, **material_commands.COMMANDS, **design_commands.COMMANDS,
                FabGuide_About=about.AboutCommand())


def register():
    """Add every FabGuide command to FreeCAD's command registry (idempotent)."""
    for name, command in COMMANDS.items():
        Gui.addCommand(name, command)
