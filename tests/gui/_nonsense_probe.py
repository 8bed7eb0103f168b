"""A nonsense-typing new user: every FabGuide command on wrong selections, nonsense in every property of every
FabGuide object, nonsense typed in every task panel field, deleted dependencies, undo/redo/rename/save/reopen, and
exports into bad folders. Exploratory (not run by ctest): it records what each mistake produced and passes as long
as the session itself runs; the findings are in the log (markers "NONSENSE:") and /tmp/nonsense/results-*.txt.

NONSENSE_PART=1..5 runs one part (the default runs all, which takes longer than run_in_freecad.py's timeout).
"""
import math
import os
import stat
import tempfile
import traceback

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import guitest

PART = os.environ.get("NONSENSE_PART", "all")
OUT = "/tmp/nonsense"
os.makedirs(OUT, exist_ok=True)
RESULTS = []
V = FreeCAD.Vector
state = {}


# --- recording ---------------------------------------------------------------------------------------------------
def note(text):
    FreeCAD.Console.PrintMessage("NONSENSE: " + text.replace("\n", " | ")[:3000] + "\n")
    RESULTS.append(text)


class Modals:
    """Closes every modal dialog (message boxes OK, input dialogs answered nonsense, anything else Cancel) and keeps
    what each said."""

    def __init__(self):
        self.told = []
        self.input_answer = ("\n\n", True)
        self.timer = QtCore.QTimer()
        self.timer.timeout.connect(self.answer)
        self.timer.start(40)

    def answer(self):
        box = QtGui.QApplication.activeModalWidget()
        if box is None:
            return
        if isinstance(box, QtGui.QMessageBox):
            self.told.append(box.text())
            box.accept()
        elif isinstance(box, QtGui.QDialog):
            self.told.append("<dialog {} '{}'>".format(type(box).__name__, box.windowTitle()))
            box.reject()

    def take(self):
        said, self.told[:] = list(self.told), []
        return said


modals = None
FILE_ANSWER = {"path": ""}


def patch_dialogs():
    """File dialogs answer FILE_ANSWER['path'] ('' = cancelled); input dialogs answer nonsense."""
    for name in ("getOpenFileName", "getSaveFileName"):
        setattr(QtGui.QFileDialog, name, staticmethod(lambda *a, **k: (FILE_ANSWER["path"], "")))
    QtGui.QFileDialog.getExistingDirectory = staticmethod(lambda *a, **k: FILE_ANSWER["path"])
    QtGui.QInputDialog.getText = staticmethod(lambda *a, **k: modals.input_answer)


def attempt(label, fn, *args):
    """Runs one mistake; records an exception escaping it and what message boxes said."""
    FreeCAD.Console.PrintMessage("NONSENSE-STEP: {}\n".format(label))
    result = None
    try:
        result = fn(*args)
        guitest.settle(0.05)
    except Exception as error:  # noqa
        note("EXCEPTION in {}: {}: {}\n{}".format(label, type(error).__name__, error, traceback.format_exc()[-1500:]))
    said = modals.take()
    if said:
        note("{} -> told {}".format(label, said))
        for s in said:
            if "did not finish" in s or "Traceback" in s or "report this" in s:
                note("BUG-BOX in {}: {}".format(label, s))
    return result


def save_results():
    with open(os.path.join(OUT, "results-{}.txt".format(PART)), "w") as f:
        f.write("\n".join(RESULTS))


def pick(*picked):
    Gui.Selection.clearSelection()
    for p in picked:
        obj, sub = p if isinstance(p, tuple) else (p, None)
        if sub:
            Gui.Selection.addSelection(obj.Document.Name, obj.Name, sub)
        else:
            Gui.Selection.addSelection(obj)


def close_panel():
    dialog = Gui.Control.activeDialog()
    if dialog:
        try:
            for d in FreeCAD.listDocuments().values():
                g = Gui.getDocument(d.Name)
                if g and g.getInEdit():
                    g.resetEdit()
            if Gui.Control.activeDialog():
                Gui.Control.closeDialog()
        except Exception as error:  # noqa
            note("EXCEPTION closing panel: {}".format(error))
        guitest.settle(0.1)


# --- models ------------------------------------------------------------------------------------------------------
def box(doc, label, low, high):
    from freecad.fabguide import cuboids

    b = doc.addObject("Part::Box", "Box")
    b.Label = label
    cuboids.set_coordinates(b, [v for a in range(3) for v in (low[a], high[a])])
    return b


def bookcase(doc, name="Bookcase", x=0):
    made = []
    for label, size, at in (("side", (18, 300, 800), (0, 0, 0)), ("side", (18, 300, 800), (582, 0, 0)),
                            ("shelf", (564, 300, 18), (18, 0, 100)), ("shelf", (564, 300, 18), (18, 0, 400)),
                            ("top", (600, 300, 18), (0, 0, 800))):
        b = doc.addObject("Part::Box", "Box")
        b.Label = "{} {}".format(name, label)
        b.Length, b.Width, b.Height = size
        b.Placement.Base = V(at[0] + x, at[1], at[2])
        made.append(b)
    doc.recompute()
    return made


def commands():
    from freecad.fabguide.gui import commands as c

    return c


def is_fab(o):
    return str(getattr(getattr(o, "Proxy", None), "TYPE", "")).startswith("FabGuide::")


def fab_objects(doc):
    return [o for o in doc.Objects if is_fab(o)]


def works_like(doc):
    """Box with a lid (hinge, cover) and a drawer in a carcass (cavity, slide, fit inside)."""
    from freecad.fabguide.function import mechanism

    body = box(doc, "Body", (0, 0, 0), (100, 80, 50))
    lid = box(doc, "Lid", (0, 0, 50), (100, 80, 55))
    carcass = box(doc, "Carcass", (200, 0, 0), (500, 300, 300))
    drawer = box(doc, "Drawer", (210, 0, 10), (490, 290, 140))
    opening = box(doc, "Opening", (205, 0, 5), (495, 295, 145))
    doc.recompute()
    pick(body, lid)
    attempt("NewMechanism body+lid", Gui.runCommand, "FabGuide_NewMechanism")
    pick(carcass, opening)
    attempt("Cavity carcass/opening", Gui.runCommand, "FabGuide_MakeCavity")
    pick(drawer)
    attempt("MakePart drawer", Gui.runCommand, "FabGuide_MakePart")
    pick((lid, edge_of(lid, "y", 0, 80)))
    attempt("AddHinge lid", Gui.runCommand, "FabGuide_AddHinge")
    pick((drawer, face_of(drawer, "y", "min")))
    attempt("AddSlide drawer", Gui.runCommand, "FabGuide_AddSlide")
    pick(lid, body)
    attempt("AddCover lid/body", Gui.runCommand, "FabGuide_AddCover")
    pick(drawer, opening)
    attempt("AddFitInside drawer/opening", Gui.runCommand, "FabGuide_AddFitInside")
    pick((lid, face_of(lid, "x", "min")), (body, face_of(body, "x", "min")))
    attempt("AddFlush", Gui.runCommand, "FabGuide_AddFlush")
    pick((lid, edge_of(lid, "y", 0, 80)), (body, edge_of(body, "y", 0, 80)))
    attempt("AddGeometric", Gui.runCommand, "FabGuide_AddGeometric")
    mech = next(o for o in doc.Objects if mechanism.is_mechanism(o))
    # a configuration, as the panel's OK makes it
    from freecad.fabguide.function import configuration, joints
    from freecad.fabguide.gui import function_viewproviders as vp

    js = mechanism.members(mech, joints.is_joint)

    def config():
        c = vp.attach(configuration.create(doc, "open", []))
        mech.Group = mech.Group + [c]
        configuration.set_poses(c, [(j, 90.0 if joints.kind(j) == "hinge" else 0.0,
                                     100.0 if joints.kind(j) == "slide" else 0.0) for j in js],
                                [FreeCAD.Vector() for j in js])
        doc.recompute()
    attempt("configuration", config)
    Gui.Selection.clearSelection()
    attempt("MakePrintable", Gui.runCommand, "FabGuide_MakePrintable")
    doc.recompute()
    state.update(body=body, lid=lid, carcass=carcass, drawer=drawer, opening=opening, mech=mech)
    note("works-like made: " + ", ".join("{}({})".format(o.Label, o.Proxy.TYPE) for o in fab_objects(doc)))
    note("mechanism status: " + mech.Status)
    return mech


def edge_of(b, axis, a0=None, a1=None):
    """An edge of box b running along `axis`."""
    i = "xyz".index(axis)
    for k, e in enumerate(b.Shape.Edges):
        d = e.Vertexes[1].Point - e.Vertexes[0].Point
        if abs(d[i]) > 1e-9:
            return "Edge{}".format(k + 1)
    return "Edge1"


def face_of(b, axis, side):
    i = "xyz".index(axis)
    bb = b.Shape.BoundBox
    want = (bb.XMin, bb.YMin, bb.ZMin)[i] if side == "min" else (bb.XMax, bb.YMax, bb.ZMax)[i]
    for k, f in enumerate(b.Shape.Faces):
        c = f.CenterOfMass
        if abs(c[i] - want) < 1e-6:
            return "Face{}".format(k + 1)
    return "Face1"


def flatpack(doc):
    from freecad.fabguide.material import design

    boxes = bookcase(doc, "Bookcase", 1000)
    pick(*boxes)
    attempt("DesignFromBoxes", Gui.runCommand, "FabGuide_DesignFromBoxes")
    des = next(o for o in doc.Objects if design.is_design(o))
    side1, side2, shelf1, shelf2, top = boxes
    pick((shelf1, edge_of(shelf1, "x")), (shelf2, edge_of(shelf2, "x")))
    attempt("EqualLengths", Gui.runCommand, "FabGuide_EqualLengths")
    pick((side1, edge_of(side1, "z")))
    attempt("FixedLength", Gui.runCommand, "FabGuide_FixedLength")
    pick((top, edge_of(top, "x")))
    attempt("LengthRange", Gui.runCommand, "FabGuide_LengthRange")
    pick((shelf1, edge_of(shelf1, "x")), (top, edge_of(top, "x")))
    attempt("SumOfLengths", Gui.runCommand, "FabGuide_SumOfLengths")
    pick((shelf1, face_of(shelf1, "z", "max")), (shelf2, face_of(shelf2, "z", "max")))
    attempt("EqualPosition", Gui.runCommand, "FabGuide_EqualPosition")
    pick(side1, side2)
    for c in ("FabGuide_Ground", "FabGuide_Coplanar", "FabGuide_Snap", "FabGuide_Symmetric"):
        attempt(c, Gui.runCommand, c)
    pick(shelf1)
    attempt("InnerVolume", Gui.runCommand, "FabGuide_InnerVolume")
    Gui.Selection.clearSelection()
    attempt("OuterVolume", Gui.runCommand, "FabGuide_OuterVolume")
    pick(*boxes)
    attempt("BoardsFromSolids", Gui.runCommand, "FabGuide_BoardsFromSolids")
    Gui.Selection.clearSelection()
    attempt("Layout", Gui.runCommand, "FabGuide_Layout")
    guitest.settle(0.3)
    close_panel()
    doc.recompute()
    state.update(design=des, shelves=boxes)
    note("flat-pack made: " + ", ".join("{}({})".format(o.Label, o.Proxy.TYPE) for o in fab_objects(doc)
                                       if o.Proxy.TYPE not in ("FabGuide::Part",)))
    note("design status: " + des.Status)
    return des


# --- part 1: every command on wrong selections ---------------------------------------------------------------------
def wrong_things(doc):
    import Part  # noqa

    b1 = box(doc, "Lonely box", (-500, 0, 0), (-400, 100, 100))
    b2 = box(doc, "Other box", (-300, 0, 0), (-250, 50, 50))
    sk = doc.addObject("Sketcher::SketchObject", "Sketch")
    sk.addGeometry(Part.LineSegment(V(0, 0, 0), V(10, 10, 0)))
    sheet = doc.addObject("Spreadsheet::Sheet", "Spreadsheet")
    sheet.set("A1", "12")
    group = doc.addObject("App::DocumentObjectGroup", "Group")
    group.addObject(b2)
    page = None
    try:
        page = doc.addObject("TechDraw::DrawPage", "Page")
        template = doc.addObject("TechDraw::DrawSVGTemplate", "Template")
        template.Template = "/usr/share/freecad/Mod/TechDraw/Templates/A4_LandscapeTD.svg"
        page.Template = template
    except Exception as error:  # noqa
        note("no TechDraw page: {}".format(error))
    body = doc.addObject("PartDesign::Body", "Body")
    psk = body.newObject("Sketcher::SketchObject", "PadSketch")
    for a, b in ((V(0, 0, 0), V(50, 0, 0)), (V(50, 0, 0), V(50, 30, 0)), (V(50, 30, 0), V(0, 30, 0)),
                 (V(0, 30, 0), V(0, 0, 0))):
        psk.addGeometry(Part.LineSegment(a, b))
    pad = body.newObject("PartDesign::Pad", "Pad")
    pad.Profile = psk
    pad.Length = 18
    doc.recompute()
    return dict(b1=b1, b2=b2, sketch=sk, sheet=sheet, group=group, page=page, body=body, pad=pad)


ALL = None


def all_commands():
    c = commands()
    return [n for n in c.COMMANDS if n not in c.GROUPS and n != "FabGuide_About"]


def run_everything(label, doc, sel=()):
    """Every command with the selection `sel`; whatever it made is undone."""
    for name in all_commands():
        cmd = commands().COMMANDS[name]
        try:
            pick(*sel)
        except Exception as error:  # noqa
            note("cannot pick again [{}]: {}".format(label, error))
        active = attempt("{} IsActive [{}]".format(name, label), cmd.IsActive)
        if not active:
            continue
        before = {o.Name for o in doc.Objects}
        n_undo = doc.UndoCount
        FILE_ANSWER["path"] = ""
        attempt("{} [{}]".format(name, label), Gui.runCommand, name)
        guitest.settle(0.2)
        made = [o.Label for o in doc.Objects if o.Name not in before]
        dialog = Gui.Control.activeDialog()
        note("{} [{}]: active; made {}{}".format(name, label, made, "; PANEL OPEN" if dialog else ""))
        close_panel()
        if doc.UndoCount > n_undo:
            attempt("undo after {} [{}]".format(name, label), doc.undo)
        doc.recompute()


def part1():
    doc = guitest.new_document("Wrong")
    things = wrong_things(doc)
    flat = flatpack(doc)  # a design group to pick
    state["doc1"] = doc
    Gui.Selection.clearSelection()
    run_everything("nothing", doc)
    b1, b2 = things["b1"], things["b2"]
    selections = [
        ("sketch", [things["sketch"]]),
        ("sketch edge", [(things["sketch"], "Edge1")]),
        ("spreadsheet", [things["sheet"]]),
        ("face of box", [(b1, "Face1")]),
        ("edge of box", [(b1, "Edge1")]),
        ("vertex of box", [(b1, "Vertex1")]),
        ("two faces of one box", [(b1, "Face1"), (b1, "Face2")]),
        ("box + spreadsheet", [b1, things["sheet"]]),
        ("two unrelated boxes", [b1, b2]),
        ("group", [things["group"]]),
        ("page", [things["page"]] if things["page"] else []),
        ("design group", [flat]),
        ("body + pad", [things["body"], things["pad"]]),
        ("pad face", [(things["pad"], "Face1")]),
        ("design + lonely box", [flat, b1]),
        ("board (FabGuide)", [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "TYPE", "") ==
                              "FabGuide::Board"][:1]),
        ("master board", [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "TYPE", "") ==
                          "FabGuide::MasterBoard"][:1]),
        ("layout", [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "TYPE", "") == "FabGuide::Layout"]),
        ("constraint", [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "TYPE", "") ==
                        "FabGuide::DesignConstraint"][:1]),
    ]
    for label, sel in selections:
        try:
            pick(*sel)
        except Exception as error:  # noqa
            note("cannot pick {}: {}".format(label, error))
            continue
        run_everything(label, doc, sel)
    # a second document with a works-like product, picked wrongly
    doc2 = guitest.new_document("WrongFunction")
    mech = works_like(doc2)
    for label, sel in (("mechanism", [mech]), ("printable", [o for o in doc2.Objects if getattr(
            getattr(o, "Proxy", None), "TYPE", "") == "FabGuide::Printable"]),
            ("part", [o for o in doc2.Objects if getattr(getattr(o, "Proxy", None), "TYPE", "") == "FabGuide::Part"][:2]),
            ("joint", [o for o in doc2.Objects if "Hinge" in getattr(getattr(o, "Proxy", None), "TYPE", "")][:1]),
            ("lid twice edge+face", [(state["lid"], "Edge1"), (state["lid"], "Face1")]),
            ("body edge + lid face", [(state["body"], "Edge1"), (state["lid"], "Face2")]),
            ("cavity box", [state["opening"]]),
            ("cavity + drawer", [state["opening"], state["drawer"]]),
            ("lid face + carcass face (double pivot, non-coplanar)", [(state["lid"], "Face1"), (state["carcass"], "Face3")]),
            ("nothing", [])):
        run_everything(label, doc2, sel)


# --- part 2: nonsense in every property ------------------------------------------------------------------------------
LONG = "x" * 10000


def nonsense_values(obj, prop, kind, doc, others):
    wrong = others.get("wrong")
    box_ = others.get("box")
    if kind in ("App::PropertyLength", "App::PropertyDistance", "App::PropertyFloat", "App::PropertyArea",
                "App::PropertyAngle", "App::PropertyPercent", "App::PropertySpeed"):
        return [-5, 0, 1e300, float("nan"), float("inf"), 1e-300, "12 kg"]
    if kind == "App::PropertyInteger":
        return [-5, 0, 2 ** 31 - 1, -(2 ** 31)]
    if kind == "App::PropertyString":
        return ["", LONG, "a\nb\r\nc", "ünï€😀\u202e", "{not json", "null"]
    if kind == "App::PropertyStringList":
        return [[], [""], [LONG], ["a\nb"], ["nonsense", "=", "A1"], ["{", "]"]]
    if kind == "App::PropertyEnumeration":
        return ["nonsense", 99, -1]
    if kind == "App::PropertyBool":
        return [not getattr(obj, prop)]
    if kind == "App::PropertyLink":
        return [obj, wrong, box_, None]
    if kind in ("App::PropertyLinkList",):
        return [[], [obj], [wrong], [box_, box_], [wrong, box_]]  # [obj, wrong, box_] crashes: _nonsense_crash.py
    if kind == "App::PropertyLinkSub":
        return [(obj, []), (box_, ["Face99"]), (box_, ["Edge999"]), (box_, ["Vertex1"]), (wrong, ["Edge1"]), None]
    if kind == "App::PropertyLinkSubList":
        return [[], [(box_, "Face99")], [(box_, "Face1")], [(box_, "Face1"), (box_, "Face1"), (box_, "Face2")],
                [(wrong, "Edge1"), (box_, "Vertex1")]]
    if kind == "App::PropertyFloatList":
        return [[], [float("nan")], [1e300] * 7, [-1.0]]
    if kind == "App::PropertyVectorList":
        return [[], [V(float("nan"), 0, 0)], [V(1e300, 0, 0)] * 7]
    if kind == "App::PropertyVector":
        return [V(float("nan"), 0, 0), V(1e300, 1e300, 1e300), V(-1, -1, -1), V(0, 0, 0)]
    if kind == "App::PropertyPlacement":
        return [FreeCAD.Placement(V(1e300, 0, 0), FreeCAD.Rotation(V(1, 1, 0), 33))]
    return []


def boxes_now(doc):
    return {b.Label: (round(b.Length.Value, 6), round(b.Width.Value, 6), round(b.Height.Value, 6),
                      tuple(round(c, 6) for c in b.Placement.Base)) for b in doc.Objects if b.TypeId == "Part::Box"}


def restore_boxes(doc, snap):
    for b in doc.Objects:
        if b.TypeId == "Part::Box" and b.Label in snap:
            l, w, h, base = snap[b.Label]
            b.Length, b.Width, b.Height = l, w, h
            b.Placement.Base = V(*base)
    doc.recompute()


SKIP = {"Proxy", "ExpressionEngine", "Visibility", "Label2", "Group", "FabGuideVersion", "Error"}


def short(v):
    r = repr(v)
    return r if len(r) < 60 else r[:40] + "...({} chars)".format(len(r))


def torture(doc, objs, others, skip=()):
    for obj in objs:
        try:
            props = list(obj.PropertiesList)
            label = obj.Label
        except Exception:  # deleted meanwhile
            continue
        for prop in props:
            if prop in SKIP or prop in skip:
                continue
            kind = obj.getTypeIdOfProperty(prop)
            mode = obj.getEditorMode(prop)
            for value in nonsense_values(obj, prop, kind, doc, others):
                step = "{}.{} ({}{}) = {}".format(label, prop, kind.split("::")[-1],
                                                   "," + "/".join(mode) if mode else "", short(value))

                def go(obj=obj, prop=prop, value=value):
                    doc.openTransaction("nonsense")
                    try:
                        setattr(obj, prop, value)
                    except Exception as error:  # noqa  the property itself refused it: FreeCAD's type check
                        doc.abortTransaction()
                        return "refused by FreeCAD: {}: {}".format(type(error).__name__, str(error)[:120])
                    doc.commitTransaction()
                    now = getattr(obj, prop)
                    doc.recompute()
                    err = getattr(obj, "Error", "")
                    return "kept={} err={}".format(short(now), short(err))
                snap = boxes_now(doc)
                r = attempt(step, go)
                FreeCAD.Console.PrintMessage("NONSENSE-RESULT: {}\n".format(r))
                if r and not r.startswith("refused"):
                    attempt("undo " + step, doc.undo)
                    doc.recompute()
                if boxes_now(doc) != snap:
                    changed = {k: (snap.get(k), v) for k, v in boxes_now(doc).items() if snap.get(k) != v}
                    note("BOXES NOT RESTORED after {} and undo: {}".format(step, changed))
                    restore_boxes(doc, snap)
            attempt("recompute after {}".format(label), doc.recompute)


def part2():
    doc = guitest.new_document("Nonsense")
    works_like(doc)
    flatpack(doc)
    sheet = doc.addObject("Spreadsheet::Sheet", "Spreadsheet")
    others = dict(wrong=sheet, box=state["body"])
    one_each = {}
    for o in fab_objects(doc):
        one_each.setdefault(o.Proxy.TYPE, o)
    note("tortured: {}".format(sorted(one_each)))
    torture(doc, list(one_each.values()), others)
    # the boxes FabGuide reads
    for b in (state["lid"], state["shelves"][0]):
        for prop, values in (("Length", [0, -5, 1e300, float("nan")]), ("Height", [1e-9]),
                             ("Placement", [FreeCAD.Placement(V(0, 0, 0), FreeCAD.Rotation(V(0, 0, 1), 30)),
                                            FreeCAD.Placement(V(1e300, 0, 0), FreeCAD.Rotation())])):
            for value in values:
                def go(b=b, prop=prop, value=value):
                    doc.openTransaction("box nonsense")
                    try:
                        setattr(b, prop, value)
                    except Exception as error:  # noqa
                        doc.abortTransaction()
                        return "refused: {}".format(error)
                    doc.commitTransaction()
                    doc.recompute()
                    return "errs: " + "; ".join("{}: {}".format(o.Label, o.Error) for o in fab_objects(doc)
                                                if getattr(o, "Error", ""))
                r = attempt("box {}.{} = {}".format(b.Label, prop, short(value)), go)
                FreeCAD.Console.PrintMessage("NONSENSE-RESULT: {}\n".format(r))
                attempt("undo box", doc.undo)
                doc.recompute()
    # a parametric design: Parameters naming nonsense with a spreadsheet
    des = state["design"]
    sheet.set("B1", "abc")
    sheet.setAlias("B1", "word")
    sheet.set("B2", "300")
    sheet.setAlias("B2", "width")
    sheet.setAlias("B3", "empty")
    sheet.set("B4", "=1/0")
    sheet.setAlias("B4", "broken")
    sheet.set("B5", "=2 kg")
    sheet.setAlias("B5", "mass")
    doc.recompute()
    for params in (["Spreadsheet.A1:0:100"], ["nonsense"], ["Spreadsheet.width"], ["Spreadsheet.word 0 100"],
                   ["Spreadsheet.empty 0 100"], ["Spreadsheet.broken 0 100"], ["Spreadsheet.mass 0 100"],
                   ["Spreadsheet.width 100 0"], ["Spreadsheet.width nan nan"], ["Spreadsheet.width -inf inf"],
                   ["Spreadsheet.width 300 300"], ["Bookcase side.width 0 100"], ["Spreadsheet.width 0 1e300"]):
        def go(params=params):
            doc.openTransaction("params")
            des.Parameters = params
            doc.commitTransaction()
            doc.recompute()
            return des.Error or des.Status
        r = attempt("design.Parameters = {}".format(params), go)
        FreeCAD.Console.PrintMessage("NONSENSE-RESULT: {}\n".format(r))
        Gui.Selection.clearSelection()
        attempt("Suggest with Parameters {}".format(params), Gui.runCommand, "FabGuide_Suggest")
        guitest.settle(0.5)
        close_panel()
        attempt("undo params", doc.undo)
    doc.recompute()


# --- part 3: nonsense typed in every panel field ---------------------------------------------------------------------
TYPED = ["abc", "-", "1e9", "1e-9", ",", "99999999999999999999", "", "=nonsense", "2 kg", "-0", "1,5,", "nan", "inf"]


def fields(panel):
    forms = panel.form if isinstance(panel.form, (list, tuple)) else [panel.form]
    found = []
    for form in forms:
        found += form.findChildren(QtGui.QAbstractSpinBox) + form.findChildren(QtGui.QLineEdit) + \
            form.findChildren(QtGui.QComboBox)
    # a spin box's own line edit is typed into through the spin box
    return [f for f in found if not (isinstance(f, QtGui.QLineEdit) and isinstance(f.parent(), (
        QtGui.QAbstractSpinBox, QtGui.QComboBox)))]


def press(which):
    """Presses the task view's OK or Cancel button, as a user does."""
    role = QtGui.QDialogButtonBox.Ok if which == "OK" else QtGui.QDialogButtonBox.Cancel
    for bb in Gui.getMainWindow().findChildren(QtGui.QDialogButtonBox):
        b = bb.button(role)
        if b is not None and b.isVisible():
            b.click()
            guitest.settle(0.3)
            return True
    note("no {} button found".format(which))
    return False


def type_into_panel(label, panel, texts=TYPED, finish="OK"):
    if panel is None:
        note("{}: no panel".format(label))
        return
    for i, f in enumerate(fields(panel)):
        name = f.objectName() or "{}#{}".format(type(f).__name__, i)
        for text in texts:
            if not Gui.Control.activeDialog():
                return
            def go(f=f, text=text):
                if isinstance(f, QtGui.QComboBox):
                    if f.isEditable():
                        f.lineEdit().selectAll()
                        guitest.keys(f.lineEdit(), text, QtCore.Qt.Key_Return)
                    else:
                        guitest.keys(f, text[:1])  # type-ahead
                        f.setCurrentIndex(f.count() - 1)
                    return
                f.setFocus()
                if isinstance(f, QtGui.QAbstractSpinBox):
                    f.selectAll()
                else:
                    f.selectAll()
                guitest.keys(f, text)
                guitest.settle(0.8)  # past the pause
                guitest.keys(f, key=QtCore.Qt.Key_Return)
                guitest.settle(0.2)
            before = watched(panel)
            attempt("{} field {} <- {!r}".format(label, name, text), go)
            after = watched(panel)
            if after != before:
                note("{} field {} <- {!r}: CHANGED {}".format(label, name, text, {k: (before.get(k), v) for k, v in
                                                                                 after.items() if before.get(k) != v}))
    if Gui.Control.activeDialog():
        msgs = [w.text() for w in panel_labels(panel)]
        note("{}: panel messages before {}: {}".format(label, finish, msgs))
        attempt("{} press {}".format(label, finish), press, finish)
        if Gui.Control.activeDialog():
            msgs = [w.text() for w in panel_labels(panel)]
            note("{}: panel still open after {} ({})".format(label, finish, msgs))
            attempt("{} press Cancel".format(label), press, "Cancel")
    close_panel()


def watched(panel):
    """The document values a panel edits, and its message, to see what a typed value did."""
    out = {}
    for attr in ("layout", "mech", "rel", "design"):
        obj = getattr(panel, attr, None)
        if obj is None:
            continue
        try:
            for prop in ("Kerf", "Spacing", "Trim", "Stages", "Cuts", "FirstCut", "Status", "Pairs", "Error"):
                if prop in obj.PropertiesList:
                    v = getattr(obj, prop)
                    out[prop] = str(getattr(v, "UserString", v))[:120]
        except Exception:  # noqa  deleted
            pass
    for name in ("message", "status"):
        w = getattr(getattr(panel, "form", None), name, None)
        try:
            if w is not None:
                out["form." + name] = w.text()[:200]
        except RuntimeError:
            pass
    return out


def panel_labels(panel):
    try:
        forms = panel.form if isinstance(panel.form, (list, tuple)) else [panel.form]
        return [w for form in forms for w in form.findChildren(QtGui.QLabel) if w.text()]
    except RuntimeError:
        return []


def current_panel():
    d = Gui.Control.activeDialog()
    if not d:
        return None
    if LAST_PANEL[0] is not None and editing_showing(LAST_PANEL[0]):
        return LAST_PANEL[0]
    # the panel object: FreeCAD gives no handle to a Python dialog; find it through the view providers / commands
    for doc in FreeCAD.listDocuments().values():
        for o in doc.Objects:
            p = getattr(getattr(o, "ViewObject", None), "Proxy", None)
            panel = getattr(p, "panel", None)
            if panel is not None and getattr(panel, "form", None) is not None and editing_showing(panel):
                return panel
    for name, cmd in commands().COMMANDS.items():
        panel = getattr(cmd, "panel", None)
        if panel is not None and editing_showing(panel):
            return panel
    return None


def editing_showing(panel):
    from freecad.fabguide.gui import editing

    return editing.showing(panel)


class FakePanel:
    def __init__(self):
        tv = [w for w in Gui.getMainWindow().findChildren(QtGui.QWidget) if type(w).__name__ == "TaskView"] or \
            [w for w in QtGui.QApplication.allWidgets() if w.metaObject().className() == "Gui::TaskView::TaskView"]
        self.form = tv[:1]


def part3():
    from freecad.fabguide.function import mechanism, relationships
    from freecad.fabguide.material import design, layout

    doc = guitest.new_document("Panels")
    mech = works_like(doc)
    des = flatpack(doc)
    lay = next(o for o in doc.Objects if layout.is_layout(o))
    opens = [
        ("Layout panel", lambda: Gui.getDocument(doc.Name).setEdit(lay.Name)),
        ("Configurations panel", lambda: Gui.getDocument(doc.Name).setEdit(mech.Name)),
    ]
    for rel in [o for o in doc.Objects if relationships.is_relationship(o)] if hasattr(relationships, "is_relationship") \
            else [o for o in doc.Objects if "Relationship" in str(getattr(getattr(o, "Proxy", None), "TYPE", ""))]:
        opens.append(("Relationship panel {}".format(rel.Label), lambda rel=rel: rel.ViewObject.doubleClicked()))
    opens.append(("Suggest panel", lambda: (pick(des), Gui.runCommand("FabGuide_Suggest"))))
    opens.append(("CAM panel", lambda: (Gui.Selection.clearSelection(), Gui.runCommand("FabGuide_MakeCamJob"))))
    for finish in ("OK", "Cancel"):
        for label, opener in opens:
            attempt("open " + label, opener)
            guitest.settle(0.5)
            panel = current_panel()
            note("{}: opened {} ({})".format(label, bool(Gui.Control.activeDialog()), type(panel).__name__))
            if label.startswith("Suggest"):
                guitest.settle(3)
            type_into_panel("{} ({})".format(label, finish), panel, finish=finish)
            doc.recompute()
    # relationship pairs typed nonsense
    for rel in [o for o in doc.Objects if "Pairs" in o.PropertiesList]:
        attempt("open pairs " + rel.Label, rel.ViewObject.doubleClicked)
        guitest.settle(0.3)
        panel = current_panel()
        if panel is not None and getattr(panel, "pairs", None) is not None:
            for text in ("nonsense", "", "Lid.left -> ", " → ", "Body.top → Body.top", "Lid.Face99 → Body.Face1"):
                def go(text=text):
                    if panel.pairs.count() == 0:
                        panel.pairs.addItem(QtGui.QListWidgetItem("x"))
                    panel.pairs.item(0).setText(text)
                    guitest.settle(0.2)
                attempt("pair <- {!r}".format(text), go)
            attempt("pairs OK", press, "OK")
            note("pairs after OK: {} {}".format(list(getattr(rel, "Pairs", [])), rel.Status))
        close_panel()
    # a panel and the document closes under it; a panel and undo
    for label, opener in opens[:2] + opens[-2:]:
        attempt("open {} then undo".format(label), opener)
        guitest.settle(0.5)
        attempt("undo with {} open".format(label), doc.undo)
        guitest.settle(0.3)
        note("{}: panel open after undo: {}".format(label, bool(Gui.Control.activeDialog())))
        attempt("redo after {}".format(label), doc.redo)
        close_panel()
    for label, index in (("Layout panel", 0), ("Configurations panel", 1), ("Suggest panel", -2), ("CAM panel", -1)):
        d = guitest.new_document("Closing")
        try:
            m = works_like(d)
            ds = flatpack(d)
        except Exception as error:  # noqa
            note("could not build the Closing document for {}: {!r}".format(label, error))
            FreeCAD.closeDocument(d.Name)
            continue
        ly = next(o for o in d.Objects if layout.is_layout(o))
        opener = {0: lambda: Gui.getDocument(d.Name).setEdit(ly.Name), 1: lambda: Gui.getDocument(d.Name).setEdit(m.Name),
                  -2: lambda: (pick(ds), Gui.runCommand("FabGuide_Suggest")),
                  -1: lambda: (Gui.Selection.clearSelection(), Gui.runCommand("FabGuide_MakeCamJob"))}[index]
        attempt("open {} then close doc".format(label), opener)
        guitest.settle(0.5)
        attempt("close doc with {} open".format(label), FreeCAD.closeDocument, d.Name)
        guitest.settle(1.0)
        note("{}: panel open after closing: {}".format(label, bool(Gui.Control.activeDialog())))
        close_panel()
    # a second panel over a first, double-clicks
    Gui.setActiveDocument(doc.Name)
    FreeCAD.setActiveDocument(doc.Name)
    attempt("layout panel", lambda: Gui.getDocument(doc.Name).setEdit(lay.Name))
    guitest.settle(0.3)
    for label, fn in (("config over layout", lambda: Gui.getDocument(doc.Name).setEdit(mech.Name)),
                      ("double-click volume", lambda: [o.ViewObject.doubleClicked() for o in doc.Objects
                                                       if design.is_volume(o)][:1]),
                      ("double-click configuration", lambda: [o.ViewObject.doubleClicked() for o in doc.Objects
                                                              if "Configuration" == getattr(getattr(o, "Proxy", None),
                                                                                            "TYPE", "")[10:]]),
                      ("command Configurations", lambda: Gui.runCommand("FabGuide_Configurations")),
                      ("command Layout", lambda: Gui.runCommand("FabGuide_Layout"))):
        attempt(label, fn)
        guitest.settle(0.3)
    close_panel()


# --- part 4: deleted dependencies, undo, redo, rename, save and reopen --------------------------------------------
def part4():
    from freecad.fabguide.function import joints, parts
    from freecad.fabguide.material import board, master_board

    doc = guitest.new_document("Deleting")
    mech = works_like(doc)
    des = flatpack(doc)

    def errors():
        return ["{}: {}".format(o.Label, o.Error) for o in fab_objects(doc) if getattr(o, "Error", "")]

    def delete(getter, what):
        targets = getter()
        if not targets:
            note("nothing to delete for " + what)
            return
        t = targets[0]
        name = t.Label

        def go():
            doc.openTransaction("Delete")
            doc.removeObject(t.Name)
            doc.commitTransaction()
            doc.recompute()
            return errors()
        r = attempt("delete {} '{}'".format(what, name), go)
        note("after deleting {} '{}': {}".format(what, name, r))
        deleted_at = doc.UndoCount
        attempt("Solve after delete", lambda: (Gui.Selection.clearSelection(), Gui.runCommand("FabGuide_Solve")))
        for c in ("FabGuide_Layout", "FabGuide_ExportWorkslike", "FabGuide_MakePrintable", "FabGuide_Configurations"):
            attempt("{} after deleting {}".format(c, what), Gui.runCommand, c)
            guitest.settle(0.3)
            close_panel()
        for _ in range(doc.UndoCount - deleted_at + 1):  # the commands' own steps, then the deletion
            attempt("undo delete", doc.undo)
        attempt("recompute after undo", doc.recompute)
        note("after undo: {}".format(errors()))
        attempt("redo delete", doc.redo)
        attempt("recompute after redo", doc.recompute)
        note("after redo: {}".format(errors()))
        attempt("undo again", doc.undo)
        doc.recompute()

    delete(lambda: [o for o in doc.Objects if master_board.is_master_board(o)], "master board")
    delete(lambda: [state["lid"]], "part's box (Lid)")
    delete(lambda: [state["opening"]], "cavity box")
    delete(lambda: [o for o in doc.Objects if parts.is_part(o)], "joint's part")
    delete(lambda: [o for o in doc.Objects if joints.is_joint(o)], "joint")
    delete(lambda: [o for o in doc.Objects if board.is_board(o)], "board")
    delete(lambda: [state["shelves"][2]], "design's box")
    delete(lambda: [o for o in doc.Objects if "Configuration" == str(getattr(getattr(o, "Proxy", None), "TYPE", ""))[10:]],
           "shown configuration")
    delete(lambda: [mech], "mechanism")
    delete(lambda: [des], "design")
    # renames
    for obj in [mech, des, state["lid"], state["shelves"][0]] + fab_objects(doc)[:12]:
        try:
            obj.Name
        except Exception:  # noqa  gone with an undo
            continue
        for label in ("", " ", "a\nb", "x" * 1000, "'\"<>&", "ünï😀", "Lid", "Body.size.x", "=A1"):
            def go(obj=obj, label=label):
                doc.openTransaction("Rename")
                obj.Label = label
                doc.commitTransaction()
                doc.recompute()
                return errors()
            r = attempt("rename {} -> {!r}".format(obj.Name, label[:20]), go)
            if r:
                note("rename {} -> {!r}: {}".format(obj.Name, label[:20], r))
            attempt("undo rename", doc.undo)
        doc.recompute()
    # save, close, reopen, recompute, undo/redo runs
    folder = tempfile.mkdtemp(dir=OUT)
    path = os.path.join(folder, "nonsense ünï.FCStd")

    def cycle():
        doc.saveAs(path)
        FreeCAD.closeDocument(doc.Name)
        guitest.settle(0.3)
        d = FreeCAD.openDocument(path)
        guitest.settle(0.3)
        d.recompute()
        return d
    d = attempt("save/close/reopen", cycle)
    if d is not None:
        note("reopened: errors {}".format(["{}: {}".format(o.Label, o.Error) for o in fab_objects(d)
                                            if getattr(o, "Error", "")]))
        note("reopened: touched after recompute {}".format([o.Label for o in d.Objects if "Touched" in o.State]))
        for c in ("FabGuide_Solve", "FabGuide_Layout", "FabGuide_Configurations", "FabGuide_MakePrintable"):
            Gui.Selection.clearSelection()
            attempt(c + " on reopened", Gui.runCommand, c)
            guitest.settle(0.3)
            close_panel()
        for i in range(6):
            attempt("undo #{} on reopened".format(i), d.undo)
        d.recompute()
        for i in range(6):
            attempt("redo #{} on reopened".format(i), d.redo)
        d.recompute()


# --- part 5: exports -----------------------------------------------------------------------------------------------
EXPORTS = ("FabGuide_ExportCutSheets", "FabGuide_TechDrawPages", "FabGuide_MakeCamJob", "FabGuide_ExportFlatpack",
           "FabGuide_ExportWorkslike", "FabGuide_ExportPrintable")


def exports(doc, label, paths):
    for name in EXPORTS:
        for p in paths:
            FILE_ANSWER["path"] = p
            Gui.Selection.clearSelection()
            if not commands().COMMANDS[name].IsActive():
                note("{} inactive [{}]".format(name, label))
                break
            attempt("{} [{}] -> {!r}".format(name, label, p[-40:]), Gui.runCommand, name)
            guitest.settle(0.3)
            if Gui.Control.activeDialog():
                panel = current_panel()
                if panel is not None and hasattr(panel.form, "folder"):
                    panel.form.folder.setText(p if p else "")
                    attempt("CAM OK -> {!r}".format(p[-40:]), press, "OK")
                    note("CAM panel message: {}".format(panel.form.message.text() if editing_showing(panel) else "closed"))
                close_panel()
    FILE_ANSWER["path"] = ""


def part5():
    from freecad.fabguide.material import layout

    ro = tempfile.mkdtemp(dir=OUT)
    os.chmod(ro, stat.S_IRUSR | stat.S_IXUSR)
    missing = os.path.join(OUT, "does", "not", "exist")
    a_file = os.path.join(OUT, "plain-file.txt")
    open(a_file, "w").write("x")
    paths = [missing, ro, a_file, os.path.join(missing, "x.json"), os.path.join(ro, "x.json"), os.path.join(a_file, "x")]
    doc = guitest.new_document("Exports")
    mech = works_like(doc)
    des = flatpack(doc)
    exports(doc, "good", paths)
    # designs in error
    lay = next(o for o in doc.Objects if layout.is_layout(o))
    for m in des.MasterBoards:
        m.Width = 100
    mech.MinimumWall = 1e5
    doc.recompute()
    note("in error: design {!r} layout {!r} mech {!r}".format(des.Error, lay.Error, mech.Status))
    good = tempfile.mkdtemp(dir=OUT)
    exports(doc, "in error", [good])
    note("written while in error: {}".format(os.listdir(good)))
    # no boards: a layout whose boards are all deleted
    doc2 = guitest.new_document("NoBoards")
    from freecad.fabguide.material import board as board_mod
    pick(*bookcase(doc2, "Lone"))
    attempt("BoardsFromSolids", Gui.runCommand, "FabGuide_BoardsFromSolids")
    Gui.Selection.clearSelection()
    attempt("Layout", Gui.runCommand, "FabGuide_Layout")
    guitest.settle(0.3)
    close_panel()
    for o in [o for o in doc2.Objects if board_mod.is_board(o)]:
        doc2.removeObject(o.Name)
    doc2.recompute()
    good2 = tempfile.mkdtemp(dir=OUT)
    exports(doc2, "no boards", [good2])
    note("written with no boards: {}".format(os.listdir(good2)))
    # an empty design: all its boxes deleted
    d3 = guitest.new_document("EmptyDesign")
    bs = bookcase(d3, "Gone")
    pick(*bs)
    attempt("DesignFromBoxes", Gui.runCommand, "FabGuide_DesignFromBoxes")
    for b in bs:
        d3.removeObject(b.Name)
    attempt("recompute empty design", d3.recompute)
    good3 = tempfile.mkdtemp(dir=OUT)
    exports(d3, "empty design", [good3])
    for c in ("FabGuide_Suggest", "FabGuide_OuterVolume"):
        attempt(c + " on empty design", Gui.runCommand, c)
        guitest.settle(1)
        close_panel()
    # imports of nonsense files
    bad = os.path.join(OUT, "bad.workslike.json")
    for content in ("", "{", "[]", '{"parts": 5}', '{"parts": [{"name": "a", "cuboids": [{"min": [0,0,0], "max": ["x",1,1]}]}]}',
                    "\x00\x01", '{"parts": [], "joints": [{"kind": "hinge"}]}'):
        for name, ext in (("FabGuide_ImportWorkslike", ".workslike.json"), ("FabGuide_ImportFlatpack", ".flatpack.json")):
            p = os.path.join(OUT, "bad" + ext)
            open(p, "w").write(content)
            FILE_ANSWER["path"] = p
            attempt("{} <- {!r}".format(name, content[:40]), Gui.runCommand, name)
    for p in (missing, ro, os.path.join(ro, "nothing.json")):
        FILE_ANSWER["path"] = p
        for name in ("FabGuide_ImportWorkslike", "FabGuide_ImportFlatpack"):
            attempt("{} <- {!r}".format(name, p[-30:]), Gui.runCommand, name)
    FILE_ANSWER["path"] = ""
    os.chmod(ro, stat.S_IRWXU)


LAST_PANEL = [None]


def setup():
    global modals
    modals = Modals()
    patch_dialogs()
    from freecad.fabguide.gui import editing
    original = editing.show

    def show(make, doc):
        panel = original(make, doc)
        if panel is not None:
            LAST_PANEL[0] = panel
        return panel
    editing.show = show
    Gui.activateWorkbench("FabGuideWorkbench")


def part_step(n, fn):
    def step():
        if PART not in ("all", str(n)):
            return
        try:
            fn()
        except Exception:  # noqa  the session goes on
            note("PROBE CRASHED in part {}: {}".format(n, traceback.format_exc()[-2000:]))
        save_results()
        close_panel()
    step.__name__ = "part{}".format(n)
    return step


guitest.run([setup] + [part_step(n, f) for n, f in enumerate((part1, part2, part3, part4, part5), 1)])
