"""FabGuide's GUI commands and where the workbench shows them: a toolbar per half that fits a 1366 px screen,
related commands in drop-down buttons, and one menu per half with submenus."""
import FreeCADGui as Gui

from freecad.fabguide.gui import about, design_commands, function_commands, material_commands
from freecad.fabguide.gui.command_base import Group
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP

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

GROUPS = {  # drop-down buttons, each also a submenu: its name is translated as the menus' are
    "FabGuide_Parts": Group(QT_TRANSLATE_NOOP("Workbench", "Parts"),
                            QT_TRANSLATE_NOOP("FabGuide", "Make a mechanism, a part or a cavity from boxes"), PARTS),
    "FabGuide_Joints": Group(QT_TRANSLATE_NOOP("Workbench", "Joints"), QT_TRANSLATE_NOOP(
        "FabGuide", "Add a joint: hinge, slide, sliding hinge, double pivot or fixed"), JOINTS),
    "FabGuide_Relationships": Group(QT_TRANSLATE_NOOP("Workbench", "Relationships"), QT_TRANSLATE_NOOP(
        "FabGuide", "Add a relationship: cover, fit inside, support, flush or geometric"), RELATIONSHIPS),
    "FabGuide_Print": Group(QT_TRANSLATE_NOOP("Workbench", "Print in place"), QT_TRANSLATE_NOOP(
        "FabGuide", "Make the mechanism printable in place, or export the print"), PRINT),
    "FabGuide_WorkslikeFile": Group(QT_TRANSLATE_NOOP("Workbench", "Works-like file"), QT_TRANSLATE_NOOP(
        "FabGuide", "Import or export a *.workslike.json model"), WORKSLIKE_FILE),
    "FabGuide_Boards": Group(QT_TRANSLATE_NOOP("Workbench", "Boards"), QT_TRANSLATE_NOOP(
        "FabGuide", "Make boards from thin solids, or from a sketch or face; band their edges"), BOARDS),
    "FabGuide_CutSheets": Group(QT_TRANSLATE_NOOP("Workbench", "Cut sheets"), QT_TRANSLATE_NOOP(
        "FabGuide", "Export cut sheets, make TechDraw pages or CAM jobs"), CUT_SHEETS),
    "FabGuide_DesignConstraints": Group(QT_TRANSLATE_NOOP("Workbench", "Design constraints"), QT_TRANSLATE_NOOP(
        "FabGuide", "Add a design constraint on the picked boards"), CONSTRAINTS),
    "FabGuide_Volumes": Group(QT_TRANSLATE_NOOP("Workbench", "Volumes"), QT_TRANSLATE_NOOP(
        "FabGuide", "Add an inner (kept free) or the outer volume"), VOLUMES),
    "FabGuide_FlatpackFile": Group(QT_TRANSLATE_NOOP("Workbench", "Flat-pack file"), QT_TRANSLATE_NOOP(
        "FabGuide", "Import or export a *.flatpack.json design"), FLATPACK_FILE),
}

# Toolbar and menu names (FreeCAD translates them in the context "Workbench").
FUNCTION = QT_TRANSLATE_NOOP("Workbench", "Function")
MATERIAL = QT_TRANSLATE_NOOP("Workbench", "Material")
ZERO_WASTE = QT_TRANSLATE_NOOP("Workbench", "Zero waste")
ZERO_WASTE_DESIGN = QT_TRANSLATE_NOOP("Workbench", "Zero-waste design")

# The toolbars: Function (thesis ch. 4), Material and Zero waste (ch. 5).
TOOLBARS = {
    FUNCTION: ["FabGuide_Parts", "FabGuide_Joints", "FabGuide_Relationships", "FabGuide_Solve",
               "FabGuide_Configurations", "FabGuide_Print", "FabGuide_WorkslikeFile"],
    MATERIAL: ["FabGuide_NewMasterBoard", "FabGuide_Boards", "FabGuide_Layout", "FabGuide_CutSheets"],
    ZERO_WASTE: ["FabGuide_DesignFromBoxes", "FabGuide_DesignConstraints", "FabGuide_Volumes", "FabGuide_Suggest",
                 "FabGuide_FlatpackFile"],
}

# The menus, one per half: (menu path, commands); submenus are named as their drop-down buttons.
MENUS = [
    ([FUNCTION], PARTS),
    ([FUNCTION, GROUPS["FabGuide_Joints"].menu], JOINTS),
    ([FUNCTION, GROUPS["FabGuide_Relationships"].menu], RELATIONSHIPS),
    ([FUNCTION], ["FabGuide_Solve", "FabGuide_Configurations"]),
    ([FUNCTION, GROUPS["FabGuide_Print"].menu], PRINT),
    ([FUNCTION, GROUPS["FabGuide_WorkslikeFile"].menu], WORKSLIKE_FILE),
    ([MATERIAL], ["FabGuide_NewMasterBoard"] + BOARDS + ["FabGuide_Layout"]),
    ([MATERIAL, GROUPS["FabGuide_CutSheets"].menu], CUT_SHEETS),
    ([MATERIAL, ZERO_WASTE_DESIGN], ["FabGuide_DesignFromBoxes"]),
    ([MATERIAL, ZERO_WASTE_DESIGN, GROUPS["FabGuide_DesignConstraints"].menu], CONSTRAINTS),
    ([MATERIAL, ZERO_WASTE_DESIGN, GROUPS["FabGuide_Volumes"].menu], VOLUMES),
    ([MATERIAL, ZERO_WASTE_DESIGN], ["FabGuide_Suggest"]),
    ([MATERIAL, ZERO_WASTE_DESIGN, GROUPS["FabGuide_FlatpackFile"].menu], FLATPACK_FILE),
    (["&Help", "FabGuide"], ["FabGuide_About"]),
]

COMMANDS = dict(F, **M, **D, FabGuide_About=about.AboutCommand(), **GROUPS)


def register():
    """Add every FabGuide command to FreeCAD's command registry (idempotent)."""
    for name, command in COMMANDS.items():
        Gui.addCommand(name, command)
