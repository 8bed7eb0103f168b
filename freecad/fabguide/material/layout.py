"""Layout: the boards laid out on the master boards by docking (thesis 5.3.1, 5.4.3), shown as 2-D sheets
beside the model, with the material usage. Cut sheets are written from exactly the layout shown."""
import json
import os
import re

import FreeCAD
import Part

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import background, messages, preferences, properties
from freecad.fabguide.material import board, master_board
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

GAP = 100  # mm between the model and the sheets, and between sheets
JOINTS = {"Auto (dowels for thick boards)": "Auto", "Finger joints": "Fingers", "None": "None"}
CUTS = {"Free (CNC router, laser)": "free", "Guillotine (panel saw)": "guillotine"}
FIRST_CUTS = {"Any": "any", "Along the sheet": "along", "Across the sheet": "across"}


class LayoutError(ValueError):
    """A layout that cannot be made; the message names the layout and the board at fault."""


class Layout(properties.Proxy):
    TYPE, NOUN = "FabGuide::Layout", QT_TRANSLATE_NOOP("FabGuide", "Layout")
    VALID = dict(Resolution=properties.more_than(0),
                 Iterations=properties.at_least(-1, QT_TRANSLATE_NOOP("FabGuide", " (parts squared)")),
                 RotationStep=(lambda obj, v: v == 0 or (0 < v <= 90 and 90 % v == 0),
                               QT_TRANSLATE_NOOP("FabGuide", "0 or a divisor of 90 (e.g. 15, 30, 45)")),
                 Stages=properties.at_least(0, QT_TRANSLATE_NOOP("FabGuide", " (0: unlimited)")),
                 LabelWidth=properties.at_least(20),
                 Seed=(lambda obj, v: 0 <= v < 2 ** 63, QT_TRANSLATE_NOOP("FabGuide", "0 or more")),
                 TimeLimit=properties.more_than(0),
                 LabelHeight=properties.at_least(10))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLinkList", "Boards", "Layout", QT_TRANSLATE_NOOP("App::Property", "Boards to lay out"))
        add(obj, "App::PropertyLinkList", "MasterBoards", "Layout",
            QT_TRANSLATE_NOOP("App::Property", "Master boards to cut them from, opened in this order"))
        add(obj, "App::PropertyLength", "Kerf", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Width of the cut (laser beam, router bit)"),
            preferences.get("Kerf"))
        add(obj, "App::PropertyLength", "Spacing", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Material left between parts besides the kerf"),
            preferences.get("Spacing"))
        add(obj, "App::PropertyLength", "Trim", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Margin kept along every master board edge"),
            preferences.get("Trim"))
        add(obj, "App::PropertyLength", "Dogbone", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Router bit diameter: the cut sheets relieve inside corners (slots, "
                                               "notches) so the bit cuts them square; 0 for none (a laser)"), 0)
        add(obj, "App::PropertyLength", "TabWidth", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Holding tabs left in the outer cut of small parts so they stay in the "
                                               "sheet; 0 for none"), 0)
        add(obj, "App::PropertyLength", "TabBelow", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Parts whose longer side is shorter get holding tabs"),
            300)
        add(obj, "App::PropertyBool", "CommonLine", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Common-line cutting: a line two boards a kerf apart share is cut once, "
                                               "by the board cut first (Spacing 0 lays boards so); the machine's "
                                               "paths only, not AsDesigned"), False)
        add(obj, "App::PropertyBool", "AsDesigned", "Cut sheets",
            QT_TRANSLATE_NOOP("App::Property", "Export the parts' outlines as designed (no kerf offset, no dogbones, "
                                               "closed, holding tabs on a layer of their own) for CAM software that "
                                               "offsets by its tool itself; off: tool paths as a laser or the machine "
                                               "cuts them"), False)
        add(obj, "App::PropertyBool", "TextLabels", "Cut sheets",
            QT_TRANSLATE_NOOP("App::Property", "Labels as text in a font; off: as single strokes to engrave, which "
                                               "laser software, CAM and FreeCAD's DXF import take as they are"), False)
        add(obj, "App::PropertyLength", "LabelWidth", "Cut sheets",
            QT_TRANSLATE_NOOP("App::Property", "Width of the label printer's labels"), 62)
        add(obj, "App::PropertyLength", "LabelHeight", "Cut sheets",
            QT_TRANSLATE_NOOP("App::Property", "Height of the label printer's labels"), 29)
        add(obj, "App::PropertyEnumeration", "Joints", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Connectors where boards meet: finger joints or cross slots; dowels for "
                                               "boards of 18 mm or more under Auto"), list(JOINTS))
        add(obj, "App::PropertyEnumeration", "Cuts", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Free: any outline (a CNC router or laser follows it); Guillotine: "
                                               "straight cuts from edge to edge only (a panel, track or table saw), "
                                               "with the cut sequence on the cut sheets"), list(CUTS))
        add(obj, "App::PropertyInteger", "Stages", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Guillotine cuts: at most this many changes of direction (2, 3, ...); 0 "
                                               "= unlimited"), 0)
        add(obj, "App::PropertyEnumeration", "FirstCut", "Cutting",
            QT_TRANSLATE_NOOP("App::Property", "Guillotine cuts: the first cuts along the sheet's length (x), across "
                                               "it, or whichever wastes less"),
            list(FIRST_CUTS))
        add(obj, "App::PropertyStringList", "Connectors", "Result",
            QT_TRANSLATE_NOOP("App::Property", "The connectors made"), mode=1)
        add(obj, "App::PropertyInteger", "SawCuts", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Guillotine cuts: the saw cuts to make"), mode=1)
        add(obj, "App::PropertyLength", "SawCutLength", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Guillotine cuts: their total length"), mode=1)
        add(obj, "App::PropertyLength", "CutLength", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Length of all cuts: the saw's for guillotine cuts, else every outline "
                                               "and hole, a line two boards share counted once with CommonLine"),
            mode=1)
        add(obj, "App::PropertyLength", "CommonLineLength", "Result",
            QT_TRANSLATE_NOOP("App::Property", "CommonLine: the length of the lines two boards share, cut once"),
            mode=1)
        add(obj, "App::PropertyLength", "Resolution", "Search",
            QT_TRANSLATE_NOOP("App::Property", "Cell size of the layout grid (thesis 5.4.1)"), 0.5)
        add(obj, "App::PropertyInteger", "RotationStep", "Search",
            QT_TRANSLATE_NOOP("App::Property", "Free rotation: boards without grain may turn by every multiple of this "
                                               "many degrees (a divisor of 90, e.g. 15); 0 = quarter turns only"), 0)
        add(obj, "App::PropertyInteger", "Iterations", "Search",
            QT_TRANSLATE_NOOP("App::Property", "Ordering swaps tried; -1 = parts squared (thesis 5.4.3)"), -1)
        add(obj, "App::PropertyInteger", "Seed", "Search",
            QT_TRANSLATE_NOOP("App::Property", "Seed of the ordering search"), 1)
        add(obj, "App::PropertyFloat", "TimeLimit", "Search",
            QT_TRANSLATE_NOOP("App::Property", "Seconds the search may take at most; in FreeCAD a dialog shows it and "
                                               "Stop keeps the best layout so far"),
            preferences.get("LayoutTimeLimit"))
        add(obj, "App::PropertyFloat", "Usage", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Part area / bounding rectangle of the layout"), mode=1)
        add(obj, "App::PropertyFloat", "SheetUtilisation", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Part area / area of the master boards used"),
            mode=1)
        add(obj, "App::PropertyArea", "WasteArea", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Area of the master boards used minus part area"), mode=1)
        add(obj, "App::PropertyInteger", "SheetCount", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Master boards used"), mode=1)
        add(obj, "App::PropertyString", "ProblemJson", "Data",
            QT_TRANSLATE_NOOP("App::Property", "The problem laid out (*.pack.json)"), mode=2)
        add(obj, "App::PropertyString", "LayoutJson", "Data",
            QT_TRANSLATE_NOOP("App::Property", "The layout (layout JSON)"), mode=2)

    def onChanged(self, obj, prop):
        super().onChanged(obj, prop)
        master_board.users_changed(obj, prop)

    def recompute(self, obj):
        master_board.note_users(obj.Document)
        problem, boards = make_problem(obj)
        try:
            joined = join(obj, boards)
            problem["parts"] = pieces(obj, joined, boards)
            # The search runs on a thread of its own (background.py): it is given values, never FreeCAD objects.
            search = dict(iterations=obj.Iterations, seed=obj.Seed, time_limit=obj.TimeLimit)
            count = sum(p.get("quantity", 1) for p in problem["parts"])
            result = background.run(
                translate("FabGuide", "Laying out '{}' ({} boards)").format(obj.Label, count),
                lambda cancel: fabguide_core.pack(problem, cancel=cancel, **search), seconds=obj.TimeLimit)
        except (fabguide_core.FormatError, fabguide_core.PackingError, RuntimeError) as error:
            said = messages.in_words(str(error), problem, messages.PACK)
            raise LayoutError(translate("FabGuide", "Layout '{}': {}{}").format(
                obj.Label, said, master_board.shared(obj.MasterBoards, obj)))
        obj.ProblemJson = json.dumps(problem)
        obj.LayoutJson = json.dumps(result)
        obj.Usage = result["usage"]
        obj.SheetUtilisation = result["sheet_utilisation"]
        obj.WasteArea = result["waste_area"]
        obj.SheetCount = len(result["boards"])
        saw_cuts = [c for sheet in result.get("saw_cuts", []) for c in sheet]
        obj.SawCuts = len(saw_cuts)
        obj.SawCutLength = sum(c["length"] for c in saw_cuts)
        obj.CutLength = result["cut_length"]
        obj.CommonLineLength = result.get("common_line", 0)
        obj.Connectors = [connector_text(c) for c in joined["connectors"]]
        for note in joined["notes"]:
            FreeCAD.Console.PrintWarning("{}: {}\n".format(obj.Label, note))
        obj.Shape = sheets_shape(problem, result, beside(boards))
        FreeCAD.Console.PrintMessage(translate("FabGuide", "{}: {} parts on {} master board(s), usage {:.1%}, sheet "
                                                           "utilisation {:.1%}\n")
                                     .format(obj.Label, len(result["placements"]), obj.SheetCount, obj.Usage,
                                             obj.SheetUtilisation))


def create(doc, boards, master_boards, label="Layout"):
    obj = doc.addObject("Part::FeaturePython", "Layout")
    obj.Label = label
    Layout(obj)
    obj.Boards = list(boards)
    obj.MasterBoards = list(master_boards)
    return obj


def is_layout(obj):
    return properties.is_a(obj, Layout)


def part_ids(boards):
    """Each board's name on the cut sheets: its label, made unique with its internal name if needed."""
    labels = [b.Label for b in boards]
    return [b.Label if labels.count(b.Label) == 1 else "{} ({})".format(b.Label, b.Name) for b in boards]


def make_problem(obj):
    """(the *.pack.json problem of the layout without its parts, which come from the joined pieces, and its
    boards), or LayoutError naming the fault."""
    boards = [b for b in obj.Boards if board.is_board(b)]
    masters = [m for m in obj.MasterBoards if master_board.is_master_board(m)]
    if not boards:
        raise LayoutError(translate("FabGuide", "Layout '{}': no boards to lay out (add FabGuide boards to "
                                                "Boards)").format(obj.Label))
    if not masters:
        raise LayoutError(translate("FabGuide", "Layout '{}': no master boards (add one to MasterBoards)").format(
            obj.Label))
    for b in boards:
        if b.Shape.isNull():
            raise LayoutError(translate("FabGuide", "Layout '{}': board '{}' has no shape; recompute it first").format(
                obj.Label, b.Label))
    problem = {
        "format": "fabguide.pack", "version": 1,
        "settings": {"resolution": obj.Resolution.Value, "kerf": obj.Kerf.Value, "spacing": obj.Spacing.Value,
                     "trim": obj.Trim.Value, "dogbone": obj.Dogbone.Value, "tab_width": obj.TabWidth.Value,
                     "tab_below": obj.TabBelow.Value, "rotation_step": obj.RotationStep,
                     "cuts": CUTS[obj.Cuts], "stages": obj.Stages, "first_cut": FIRST_CUTS[obj.FirstCut],
                     "common_line": obj.CommonLine},
        "boards": [master_board.as_problem_board(m) for m in masters],
    }
    return problem, boards


def join(obj, boards):
    """The boards' outlines with the connectors where they meet (thesis 5.1), from their 3-D placement."""
    boards3 = [board.as_board3(b, part_id) for b, part_id in zip(boards, part_ids(boards))]
    return fabguide_core.join_boards(boards3, style=JOINTS[obj.Joints])


def pieces(obj, joined, boards):
    """The parts to pack: one per piece of the joined design, each with the quantity, turns and grain of its
    first board; coplanar boards in contact are one piece (thesis 5.3.4) and must be made once each."""
    by_id = dict(zip(part_ids(boards), boards))
    result = []
    for piece in joined["parts"]:
        members = [by_id[i] for i in piece.pop("boards")]
        if len(members) > 1 and any(b.Quantity != 1 for b in members):
            raise LayoutError(translate("FabGuide", "Layout '{}': {} lie in one plane and touch, so they are cut as "
                                                    "one piece; set their Quantity to 1").format(
                obj.Label, ", ".join("'{}'".format(b.Label) for b in members)))
        result.append(dict(piece, **board.packing_of(members[0])))  # the first board's quantity, turns, grain
    return result


def connector_text(c):
    """'Shelf board into Left side board: 3 dowels', one line of the Connectors list."""
    what = {"fingers": "finger tabs", "dowels": "dowels", "cross slots": "cross slots"}[c["kind"]]
    return "{} into {}: {} {}".format(c["a"], c["b"], c["count"], what)


def beside(boards):
    """Where the sheets go: to the right of the boards' bounding box, level with its bottom."""
    box = boards[0].Shape.BoundBox
    for b in boards[1:]:
        box.add(b.Shape.BoundBox)
    return FreeCAD.Vector(box.XMax + GAP, box.YMin, 0)


def polygon_face(points, holes=(), at=FreeCAD.Vector()):
    """A planar face in z = 0 from a polygon [(x, y)...] and its holes, moved by `at`."""
    def wire(polygon):
        vectors = [at + FreeCAD.Vector(x, y, 0) for x, y in polygon]
        return Part.makePolygon(vectors + vectors[:1])
    return Part.makeFace([wire(points)] + [wire(h) for h in holes], "Part::FaceMakerBullseye")


def sheets_shape(problem, result, origin):
    """A compound: one face per master board used (1 mm below), then one face per placed part."""
    def face(points, holes=(), z=0.0, dx=0.0):
        return polygon_face(points, holes, origin + FreeCAD.Vector(dx, 0, z))

    offsets, x = [], 0.0
    for sheet in result["boards"]:
        offsets.append(x)
        x += sheet["width"] + GAP
    sheets = [face([(0, 0), (s["width"], 0), (s["width"], s["height"]), (0, s["height"])], z=-1.0, dx=dx)
              for s, dx in zip(result["boards"], offsets)]
    parts = [face(p["outline"], p["holes"], dx=offsets[p["board"]])
             for p in fabguide_core.placed_outlines(problem, result)]
    return Part.makeCompound(sheets + parts)


def file_stem(label):
    """A label as a file name: letters, digits, '-', '_' and '.', the rest '-' ("Shelf unit" -> "Shelf-unit")."""
    return re.sub(r"[^A-Za-z0-9._-]+", "-", label).strip("-.") or "layout"


def current(obj):
    """Refuses a layout whose result is not the layout of its boards as they are: never computed, or its last
    recompute failed (files or pages made from it would show the last layout that could be made)."""
    if not obj.LayoutJson:
        raise LayoutError(translate("FabGuide", "Layout '{}' has not been computed yet: recompute it first").format(
            obj.Label))
    broken = properties.failed_inputs(obj)
    if properties.failed(obj) or broken:
        said = (obj.Error.rstrip(".") + "." if obj.Error else
                translate("FabGuide", "Layout '{}': {} could not be recomputed (see the report view).").format(
                    obj.Label, ", ".join(broken)) if broken else
                translate("FabGuide", "Layout '{}' is in error.").format(obj.Label))
        raise LayoutError(translate("FabGuide", "{} Mend that first: what was made now would show the last layout that "
                                                "could be made, not the boards as they are.").format(said))


def export_cut_sheets(obj, folder):
    """LABEL-sheet-N.svg and .dxf per master board, LABEL-cutlist.csv, LABEL-report.pdf, LABEL-labels.pdf and
    LABEL-opticutter.csv (optiCutter's import) into `folder`, for the layout as last computed: two layouts share a
    folder, and a re-export replaces its own set whole."""
    current(obj)
    os.makedirs(folder, exist_ok=True)
    stem = file_stem(obj.Label)
    problem, result = json.loads(obj.ProblemJson), json.loads(obj.LayoutJson)
    def file(what):
        return os.path.join(folder, stem + what)
    return fabguide_core.write_layout_files(
        problem, result, svg_folder=folder, dxf_folder=folder, csv_file=file("-cutlist.csv"),
        report_file=file("-report.pdf"), labels_file=file("-labels.pdf"), opticutter_file=file("-opticutter.csv"),
        name=stem, title=obj.Label, label_size=(obj.LabelWidth.Value, obj.LabelHeight.Value),
        as_designed=obj.AsDesigned, text_labels=obj.TextLabels)
