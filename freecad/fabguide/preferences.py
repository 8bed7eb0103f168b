"""FabGuide's preferences (Edit > Preferences > FabGuide, Resources/ui/Preferences.ui): the values new objects
start with. FreeCAD keeps them with every module's preferences; until set, each is the default below. A file
read by the command-line tool carries its own settings, so these never change what a file gives."""
import FreeCAD

PATH = "User parameter:BaseApp/Preferences/Mod/FabGuide"

# The defaults, by the page's prefEntry names.
DEFAULTS = {
    "Kerf": 0.2,  # a new Layout's, mm
    "Spacing": 2.0,
    "Trim": 5.0,
    "LayoutTimeLimit": 60.0,  # s
    "SheetWidth": 2440.0,  # a new master board's, mm
    "SheetHeight": 1220.0,
    "SheetThickness": 18.0,  # when no board gives it
    "Gap": 0.4,  # a new Printable's, mm
    "BuildVolumeX": 250.0,  # the printer's, mm
    "BuildVolumeY": 210.0,
    "BuildVolumeZ": 210.0,
}


def get(name):
    """The user's value of preference `name`, or its default; a value that cannot be right (not above 0) is not
    used."""
    default = DEFAULTS[name]
    value = FreeCAD.ParamGet(PATH).GetFloat(name, default)
    return value if value > 0 else default


def cam_speeds(material, defaults):
    """(feed mm/min, spindle rpm) Make CAM Job last used for `material`, or `defaults`."""
    group = FreeCAD.ParamGet(PATH + "/CamSpeeds")
    return group.GetFloat(material + " feed", defaults[0]), group.GetFloat(material + " spindle", defaults[1])


def remember_cam_speeds(material, feed, spindle):
    group = FreeCAD.ParamGet(PATH + "/CamSpeeds")
    group.SetFloat(material + " feed", feed)
    group.SetFloat(material + " spindle", spindle)
