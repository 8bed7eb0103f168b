"""FabGuide's GUI commands and where the workbench shows them: a toolbar per half that fits a 1366 px screen,
related commands in drop-down buttons, and one menu per half with submenus."""
import FreeCADGui as Gui

from freecad.fabguide.gui import about, design_commands, function_commands, material_commands
from freecad.fabguide.gui.command_base import Group

F, M, D = function_commands.COMMANDS, material_commands.COMMANDS, design_commands.COMMANDS


def names(commands, *keys):
    """The commands' registered names, each checked to be one of `commands`."""
    return [key for key in keys if commands[key]]


PARTS = names(F, "FabGuide_NewMechanism", "FabGuide_MakePart", "FabGuide_MakeCavity")
JOINTS = names(F, "FabGuide_AddHinge", "FabGuide_AddSlide", "FabGuide_AddSlidingHinge", "FabGuide_AddDoublePivot",
               "FabGuide_AddFixedJoint")
RELATIONSHIPS = names(F, "FabGuide_AddCover", "FabGuide_AddFitInside", "FabGuide_AddSupport", "FabGuide_AddFlush",
                      "FabGuide_AddGeometric")
WORKSLIKE_FILE = names(F, "FabGuide_ImportWorkslike", "FabGuide_ExportWorkslike")
PRINT = names(F, "FabGuide_MakePrintable", "FabGuide_ExportPrintable")
BOARDS = names(M, "FabGuide_BoardsFromSolids", "FabGuide_MakeBoard", "FabGuide_BandEdges")
CUT_SHEETS = names(M, "FabGuide_ExportCutSheets", "FabGuide_TechDrawPages", "FabGuide_MakeCamJob")
CONSTRAINTS = names(D, "FabGuide_EqualLengths", "FabGuide_SumOfLengths", "FabGuide_FixedLength", "FabGuide_LengthRange",
                    "FabGuide_EqualPosition", "FabGuide_Symmetric", "FabGuide_Ground", "FabGuide_Coplanar",
                    "FabGuide_Snap")
VOLUMES = names(D, "FabGuide_InnerVolume", "FabGuide_OuterVolume")
FLATPACK_FILE = names(D, "FabGuide_ImportFlatpack", "FabGuide_ExportFlatpack")

GROUPS = {
    "FabGuide_Parts": Group("Parts", "Make a mechanism, a part or a cavity from boxes", PARTS),
    "FabGuide_Joints": Group("Joints", "Add a joint: hinge, slide, sliding hinge, double pivot or fixed", JOINTS),
    "FabGuide_Relationships": Group("Relationships", "Add a relationship: cover, fit inside, support, flush or "
                                    "geometric", RELATIONSHIPS),
    "FabGuide_Print": Group("Print in place", "Make the mechanism printable in place, or export the print", PRINT),
    "FabGuide_WorkslikeFile": Group("Works-like file", "Import or export a *.workslike.json model", WORKSLIKE_FILE),
    "FabGuide_Boards": Group("Boards", "Make boards from thin solids, or from a sketch or face; band their edges",
                              BOARDS),
    "FabGuide_CutSheets": Group("Cut sheets", "Export cut sheets, make TechDraw pages or CAM jobs", CUT_SHEETS),
    "FabGuide_DesignConstraints": Group("Design constraints", "Add a design constraint on the picked boards",
                                        CONSTRAINTS),
    "FabGuide_Volumes": Group("Volumes", "Add an inner (kept free) or the outer volume", VOLUMES),
    "FabGuide_FlatpackFile": Group("Flat-pack file", "Import or export a *.flatpack.json design", FLATPACK_FILE),
}

# The toolbars: Function (thesis ch. 4), Material and Zero waste (ch. 5).
TOOLBARS = {
    "Function": ["FabGuide_Parts", "FabGuide_Joints", "FabGuide_Relationships", "FabGuide_Solve",
                 "FabGuide_Configurations", "FabGuide_Print", "FabGuide_WorkslikeFile"],
    "Material": ["FabGuide_NewMasterBoard", "FabGuide_Boards", "FabGuide_Layout", "FabGuide_CutSheets"],
    "Zero waste": ["FabGuide_DesignFromBoxes", "FabGuide_DesignConstraints", "FabGuide_Volumes", "FabGuide_Suggest",
                   "FabGuide_FlatpackFile"],
}

# The menus, one per half: (menu path, commands).
MENUS = [
    (["Function"], PARTS),
    (["Function", "Joints"], JOINTS),
    (["Function", "Relationships"], RELATIONSHIPS),
    (["Function"], ["FabGuide_Solve", "FabGuide_Configurations"]),
    (["Function", "Print in place"], PRINT),
    (["Function", "Works-like file"], WORKSLIKE_FILE),
    (["Material"], ["FabGuide_NewMasterBoard"] + BOARDS + ["FabGuide_Layout"]),
    (["Material", "Cut sheets"], CUT_SHEETS),
    (["Material", "Zero-waste design"], ["FabGuide_DesignFromBoxes"]),
    (["Material", "Zero-waste design", "Design constraints"], CONSTRAINTS),
    (["Material", "Zero-waste design", "Volumes"], VOLUMES),
    (["Material", "Zero-waste design"], ["FabGuide_Suggest"]),
    (["Material", "Zero-waste design", "Flat-pack file"], FLATPACK_FILE),
    (["&Help", "FabGuide"], ["FabGuide_About"]),
]

COMMANDS = dict(F, **M, **D, FabGuide_About=about.AboutCommand(), **GROUPS)


def register():
    """Add every FabGuide command to FreeCAD's command registry (idempotent)."""
    for name, command in COMMANDS.items():
        Gui.addCommand(name, command)
