"""FabGuide's preferences (Edit > Preferences > FabGuide, Resources/ui/Preferences.ui): the values new objects
start with. FreeCAD keeps them with every module's preferences; until set, each is the default below. A file
read by the command-line tool carries its own settings, so these never change what a file gives."""
import FreeCAD

PATH = "User parameter:BaseApp/Preferences/Mod/FabGuide"

# name: (default, what it is); the names are the page's prefEntry names.
DEFAULTS = {
    "Kerf": (0.2, "a new Layout's kerf, mm"),
    "Spacing": (2.0, "a new Layout's spacing, mm"),
    "Trim": (5.0, "a new Layout's edge trim, mm"),
    "LayoutTimeLimit": (60.0, "a new Layout's time limit, s"),
    "SheetWidth": (2440.0, "a new master board's width, mm"),
    "SheetHeight": (1220.0, "a new master board's height, mm"),
    "SheetThickness": (18.0, "a new master board's thickness when no board says it, mm"),
    "Gap": (0.4, "a new Printable's gap, mm"),
    "BuildVolumeX": (250.0, "the printer's build volume, width, mm"),
    "BuildVolumeY": (210.0, "the printer's build volume, depth, mm"),
    "BuildVolumeZ": (210.0, "the printer's build volume, height, mm"),
}


def get(name):
    """The user's value of preference `name`, or its default; a value that cannot be right (not above 0) is not
    used."""
    default = DEFAULTS[name][0]
    value = FreeCAD.ParamGet(PATH).GetFloat(name, default)
    return value if value > 0 else default
