"""Flat-pack design (thesis 5.1): furniture modelled as native Part::Box boards of one thickness, with design
constraints, inner and outer volumes and the master boards to cut from. Its recompute keeps the constraints
holding as the user edits a box (thesis 5.3.5: the edit is kept, the rest adapts) and lays the boards out to
show the material usage live; an edit that no longer fits the master boards is absorbed by the dynamic packer
(5.3.2: the parts sharing its line across the board give way) or undone with the reason."""
import contextlib
import json

import FreeCAD
import Part

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import background, cuboids, messages, properties, references
from freecad.fabguide.material import master_board
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

SATISFIED = "Satisfied"
BROKEN = "Broken: "  # a constraint's or volume's Status begins so when the design breaks it
UNBOUNDED = 1e11  # a range's Min or Max beyond this is absent
KINDS = ("equal", "sum", "fixed", "symmetric", "ground", "coplanar", "snap", "range")
GRAINS = ("Free", "X", "Y", "Z")  # a box's Grain: none, or the model axis its wood's grain runs along
LIVE_SECONDS = 2.0  # the layout search of a recompute, as Suggest gives the design as drawn at its default 8 s


class DesignError(ValueError):
    """A design that cannot be read as modelled; the message names the design and the object."""


class FlatpackDesign(properties.Proxy):
    TYPE, NOUN = "FabGuide::FlatpackDesign", QT_TRANSLATE_NOOP("FabGuide", "Design")
    VALID = dict(Resolution=properties.more_than(0), MaxGrowth=properties.at_least(1),
                 MasterBoards=properties.links(master_board.is_master_board,
                                               QT_TRANSLATE_NOOP("FabGuide", "master boards")))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLinkList", "MasterBoards", "Design",
            QT_TRANSLATE_NOOP("App::Property", "Master boards to cut the boards from"))
        add(obj, "App::PropertyLength", "Resolution", "Layout",
            QT_TRANSLATE_NOOP("App::Property", "Grid cell size tau (thesis 5.4.1)"), 0.5)
        add(obj, "App::PropertyLength", "Kerf", "Layout", QT_TRANSLATE_NOOP("App::Property", "Width of the cut"), 0.2)
        add(obj, "App::PropertyLength", "Spacing", "Layout",
            QT_TRANSLATE_NOOP("App::Property", "Extra material between parts"), 3)
        add(obj, "App::PropertyLength", "Trim", "Layout",
            QT_TRANSLATE_NOOP("App::Property", "Margin cut off every master board edge"), 5)
        add(obj, "App::PropertyLength", "MinimumLength", "Design",
            QT_TRANSLATE_NOOP("App::Property", "Shortest side a board may shrink to; 0: twice each board's own "
                                               "thickness, as a file without min_length"), 60)
        add(obj, "App::PropertyBool", "Snap", "Design",
            QT_TRANSLATE_NOOP("App::Property", "Boards that touch stay touching (edge snapping)"), True)
        add(obj, "App::PropertyFloat", "MaxGrowth", "Design",
            QT_TRANSLATE_NOOP("App::Property", "How many times its length now Suggest may make a board's side (1.5: "
                                               "half as long again), so a batten stays a batten; your own edits are "
                                               "not held"), 1.5)
        add(obj, "App::PropertyBool", "KeepEdits", "Design",
            QT_TRANSLATE_NOOP("App::Property", "A box you edit keeps its new size and place while the rest adapts to "
                                               "the constraints"), True)
        add(obj, "App::PropertyStringList", "Parameters", "Parametric",
            QT_TRANSLATE_NOOP("App::Property", "Spreadsheet aliases that drive the boxes by expressions, as "
                                               "'Sheet.alias min max' (thesis 5.4.2.2); when given, Suggest changes "
                                               "these instead of the boxes"))
        add(obj, "App::PropertyFloat", "Usage", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Part area / layout bounding rectangle (thesis 5.2.3)"),
            mode=1)
        add(obj, "App::PropertyString", "Status", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Laid out, or what is wrong"), mode=1)
        add(obj, "App::PropertyStringList", "Changes", "Result",
            QT_TRANSLATE_NOOP("App::Property", "What the last recompute or accepted suggestion that moved boards did: "
                                               "size old → new, how far"),
            mode=1)
        add(obj, "App::PropertyString", "Valid", "Data",
            QT_TRANSLATE_NOOP("App::Property", "Boards after the last valid recompute (JSON)"), mode=2)
        add(obj, "App::PropertyString", "LayoutJson", "Data",
            QT_TRANSLATE_NOOP("App::Property", "The last layout, its problem and the design it was made from (JSON)"),
            mode=2)

    def recompute(self, obj):
        master_board.note_users(obj.Document)
        with saying_changes(obj):
            recompute(obj)

    def onChanged(self, obj, prop):
        super().onChanged(obj, prop)
        if prop == "Group" and not obj.Document.Restoring:
            add_grain(boxes(obj))
        master_board.users_changed(obj, prop)

    def onDocumentRestored(self, obj):
        super().onDocumentRestored(obj)
        add_grain(boxes(obj))


class DesignConstraint(properties.Proxy):
    """One design constraint of thesis 5.1 as docs/formats.md writes it; its references are links to boxes with
    what of them: size.x, centre.z, min.y or max.x (the format writes "Box.size.x" with the box's label)."""
    TYPE, NOUN = "FabGuide::DesignConstraint", QT_TRANSLATE_NOOP("FabGuide", "Constraint")

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyEnumeration", "Kind", "Constraint",
            QT_TRANSLATE_NOOP("App::Property", "What must hold"), list(KINDS))
        references.define(obj, "Refs", "Constraint",
                          QT_TRANSLATE_NOOP("App::Property", "Boxes and what of them (size.x, centre.z, min.y, "
                                                             "max.x): equal, symmetric (two), sum (left side), fixed "
                                                             "and range (one)"))
        references.define(obj, "Rhs", "Constraint", QT_TRANSLATE_NOOP("App::Property", "Right side of a sum"))
        add(obj, "App::PropertyLinkList", "Parts", "Constraint",
            QT_TRANSLATE_NOOP("App::Property", "Boxes for ground, coplanar and snap"))
        add(obj, "App::PropertyDistance", "Value", "Constraint",
            QT_TRANSLATE_NOOP("App::Property", "Fixed value or sum offset"))
        add(obj, "App::PropertyDistance", "Min", "Constraint",
            QT_TRANSLATE_NOOP("App::Property", "Range: smallest value (beyond ±10⁸ m: none)"),
            -10 * UNBOUNDED)
        add(obj, "App::PropertyDistance", "Max", "Constraint",
            QT_TRANSLATE_NOOP("App::Property", "Range: largest value (beyond ±10⁸ m: none)"),
            10 * UNBOUNDED)
        references.define(obj, "About", "Constraint",
                          QT_TRANSLATE_NOOP("App::Property", "Symmetric about this reference (empty: midway now)"))
        add(obj, "App::PropertyString", "Status", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Satisfied, or what breaks it"), mode=1)

    def recompute(self, obj):
        """Min and Max are checked together here, not as each is typed: "900" passes through 9 and 90 on its way
        past a Max of 500, and a refusal would keep 90."""
        if obj.Kind == "range" and obj.Min.Value > obj.Max.Value:
            raise ValueError(translate("FabGuide", "Constraint '{}': its Min ({}) is more than its Max ({})").format(
                obj.Label, obj.Min.UserString, obj.Max.UserString))


class Volume(properties.Proxy):
    """An inner volume (space kept free, resting on board On) or the outer volume (the envelope the design must
    fit), shown as a box (thesis 5.3.5.1)."""
    TYPE = "FabGuide::DesignVolume"

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyEnumeration", "Kind", "Volume",
            QT_TRANSLATE_NOOP("App::Property", "Inner: kept free; Outer: the design stays inside"),
            ["Inner", "Outer"])
        add(obj, "App::PropertyLink", "On", "Volume",
            QT_TRANSLATE_NOOP("App::Property", "Inner volume: the board it rests on and moves with"))
        add(obj, "App::PropertyLength", "Length", "Volume", QT_TRANSLATE_NOOP("App::Property", "Size along x"), 100)
        add(obj, "App::PropertyLength", "Width", "Volume", QT_TRANSLATE_NOOP("App::Property", "Size along y"), 100)
        add(obj, "App::PropertyLength", "Height", "Volume", QT_TRANSLATE_NOOP("App::Property", "Size along z"), 100)
        add(obj, "App::PropertyString", "Status", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Satisfied, or the boards that break it"), mode=1)

    def recompute(self, obj):
        obj.Shape = Part.makeBox(obj.Length.Value, obj.Width.Value, obj.Height.Value)


def create(doc, boxes, master_boards, label="FlatpackDesign"):
    """A design holding `boxes`; DesignError naming a box that is in a group already (FreeCAD keeps an object
    in one group, and the user's own grouping is not undone for them)."""
    for box in boxes:
        group = box.getParentGroup()
        if group is not None:
            raise DesignError(translate("FabGuide", "Box '{}' is in {} '{}' already, and a box belongs to one group: "
                                                    "take it out of '{}' first, or pick other boxes").format(
                                  box.Label, "design" if is_design(group) else "group", group.Label, group.Label))
    obj = doc.addObject("App::DocumentObjectGroupPython", "FlatpackDesign")
    FlatpackDesign(obj)
    obj.Label = label
    obj.Group = list(boxes)
    obj.MasterBoards = list(master_boards)
    return obj


def add_constraint(design, kind, label=None, named=None, **values):
    """A constraint in `design`: values are its properties (Refs, Rhs, Parts, Value, Min, Max, About), references
    given as the format writes them ("Box.size.x") linked to the boxes `named` (by default the design's boxes
    by label)."""
    doc = design.Document
    obj = doc.addObject("App::FeaturePython", "DesignConstraint")
    DesignConstraint(obj)
    obj.Kind = kind
    named = named or {box.Label: box for box in boxes(design)}
    for name, value in values.items():
        if name in ("Refs", "Rhs", "About"):
            value = references.links(named, [value] if isinstance(value, str) else value,
                                     "{} constraint {}".format(kind, name))
        setattr(obj, name, value)
    obj.Label = label or "{} {}".format(kind.capitalize(), ", ".join(references.names(obj.Refs)) or
                                        ", ".join(p.Label for p in values.get("Parts", [])))
    design.addObject(obj)
    return obj


def keep_drawn_equal(design):
    """Equal constraints on the design's boards drawn the same size (posts, legs, rails), as the core infers them:
    the search no longer grows one leg of four; the user sees them in the design and deletes one to
    free its boards."""
    return [add_constraint(design, "equal", c["name"], Refs=c["refs"])
            for c in fabguide_core.drawn_equal(flatpack(design))]


def add_volume(design, kind, at, size, on=None, label=None):
    obj = design.Document.addObject("Part::FeaturePython", "Volume")
    Volume(obj)
    obj.Kind = kind
    obj.On = on
    obj.Length, obj.Width, obj.Height = size
    obj.Placement = FreeCAD.Placement(FreeCAD.Vector(*at), FreeCAD.Rotation())
    obj.Label = label or ("Space on " + on.Label if on else "Outer volume")
    design.addObject(obj)
    return obj


def add_grain(boxes):
    """Gives each box its Grain (group FabGuide) if it has none yet."""
    for box in boxes:
        properties.add(box, "App::PropertyEnumeration", "Grain", "FabGuide",
                       QT_TRANSLATE_NOOP("App::Property", "The model axis the wood's grain runs along, one in the "
                                                          "board's face: the board is laid with it along the grain of "
                                                          "master boards that have one. Free: no grain"), list(GRAINS))


def is_design(obj):
    return properties.is_a(obj, FlatpackDesign)


def is_constraint(obj):
    return properties.is_a(obj, DesignConstraint)


def is_volume(obj):
    return properties.is_a(obj, Volume)


def boxes(obj):
    return [o for o in obj.Group if cuboids.is_box(o)]


def inner_volumes(obj):
    return [v for v in obj.Group if is_volume(v) and v.Kind == "Inner"]


def parts_of(obj):
    """The boards as the format's parts: {id, min, max, grain if set}, from the boxes as they are now."""
    parts = []
    for box in boxes(obj):
        c = cuboids.coordinates(box)
        part = {"id": box.Label, "min": list(c[0::2]), "max": list(c[1::2])}
        if getattr(box, "Grain", "Free") != "Free":
            part["grain"] = box.Grain.lower()  # one across the board is refused by the core, by name
        parts.append(part)
    return parts


def constraint_dict(c):
    d = {"kind": c.Kind, "name": c.Label}
    refs = references.names(c.Refs)
    if c.Kind in ("equal", "symmetric"):
        d["refs"] = refs
    if c.Kind == "symmetric" and c.About:
        d["about"] = references.names(c.About)[0]
    if c.Kind == "sum":
        d.update(lhs=refs, rhs=references.names(c.Rhs), offset=c.Value.Value)
    if c.Kind in ("fixed", "range"):
        if len(refs) != 1:
            raise DesignError(translate("FabGuide", "constraint '{}': a {} constraint takes one reference").format(
                c.Label, c.Kind))
        d["ref"] = refs[0]
    if c.Kind == "fixed":
        d["value"] = c.Value.Value
    if c.Kind == "range":
        DesignConstraint.recompute(None, c)
        d.update({key: value for key, value in (("min", c.Min.Value), ("max", c.Max.Value)) if abs(value) < UNBOUNDED})
    if c.Kind in ("ground", "coplanar", "snap"):
        d["parts"] = [p.Label for p in c.Parts]
    return d


def volume_dicts(obj):
    """(the inner volumes as the format's dicts, in the order of inner_volumes(obj); the outer one or None)."""
    inner, outer = [], None
    for v in obj.Group:
        if not is_volume(v):
            continue
        low = v.Placement.Base
        size = [v.Length.Value, v.Width.Value, v.Height.Value]
        box = {"min": [low.x, low.y, low.z], "max": [low.x + size[0], low.y + size[1], low.z + size[2]]}
        if v.Kind == "Inner":
            if v.On is None:
                raise DesignError(translate("FabGuide", "inner volume '{}': choose the board it rests on (On)").format(
                    v.Label))
            inner.append(dict(name=v.Label, on=v.On.Label, **box))
        else:
            outer = box
    return inner, outer


def kept_layout(obj):
    """Where the design's last layout (LayoutJson) laid each box, as the format's `layout`, when they are its boxes:
    the core slides that layout to the boxes' sizes besides its search, so a design stays on the sheets it was laid
    out on. None without one."""
    if not obj.LayoutJson:
        return None
    layout = json.loads(obj.LayoutJson)["layout"]
    if sorted(p["part"] for p in layout["placements"]) != sorted(box.Label for box in boxes(obj)):
        return None
    return {"boards": layout["boards"], "placements": layout["placements"]}


def snapshot(obj):
    """The boxes and inner volumes as they are now: {parts, inner_volumes}, a start for write_parts."""
    return {"parts": parts_of(obj), "inner_volumes": volume_dicts(obj)[0]}


def flatpack(obj, parts=None):
    """The design as a *.flatpack.json dict (docs/formats.md), with `parts` instead of the boxes if given."""
    try:
        if not obj.MasterBoards:
            raise DesignError(translate("FabGuide", "add a master board (MasterBoards)"))
        if parts is None and not boxes(obj):
            raise DesignError(translate("FabGuide", "no boxes to lay out (drag the furniture's Part boxes into the "
                                                    "design)"))
        inner, outer = volume_dicts(obj)
        doc = {"format": "fabguide.flatpack", "version": 2,
               "settings": {"resolution": obj.Resolution.Value, "kerf": obj.Kerf.Value, "spacing": obj.Spacing.Value,
                            "trim": obj.Trim.Value, "snap": obj.Snap, "max_growth": obj.MaxGrowth},
               "boards": [master_board.as_problem_board(m) for m in obj.MasterBoards],
               "parts": parts if parts is not None else parts_of(obj),
               "constraints": [constraint_dict(c) for c in obj.Group if is_constraint(c)],
               "inner_volumes": inner}
        if obj.MinimumLength.Value > 0:  # else the format's own: twice each board's thickness
            doc["settings"]["min_length"] = obj.MinimumLength.Value
        kept = kept_layout(obj)
        if kept:
            doc["layout"] = kept
        if outer:
            doc["outer_volume"] = outer
        return doc
    except (ValueError, cuboids.CuboidError) as error:
        raise DesignError(translate("FabGuide", "Design '{}': {}").format(obj.Label, error))


def recompute(obj):
    """Keep the constraints through the user's edit, then lay out; refuse (undo) an edit that does not fit: one
    core call (`edit_design`, App/Api/DesignEdit.h), none when the design is the one last laid out. A Parameters
    entry Suggest could not use is said now, when it is typed, not when Suggest is asked."""
    from freecad.fabguide.material import parametric  # it builds on this module

    try:
        edited = flatpack(obj)
        parametric.parameters(obj)
    except (DesignError, parametric.ParameterError) as error:
        obj.Status = str(error)
        raise DesignError(str(error))
    valid = json.loads(obj.Valid) if obj.Valid else None
    laid, note = (last_layout(obj, edited) if valid == edited["parts"] else None), ""
    if laid is None:
        laid, note = edited_and_laid_out(obj, edited, valid)
        if laid is None:
            return
    mark_constraints(obj, "")
    obj.Usage = laid["usage"]
    obj.LayoutJson = json.dumps({key: laid[key] for key in ("usage", "layout", "problem", "design")})
    status = "Usage {:.3f} on {} board(s){}".format(laid["usage"], len(laid["layout"]["boards"]), note)
    if not note and valid == edited["parts"] and obj.Status.startswith(status + ";"):
        status = obj.Status  # FreeCAD recomputes again after boxes moved: keep what the first pass said
    obj.Status = status
    obj.Valid = json.dumps(edited["parts"])


def without_layout(design):
    """A design dict without the layout it keeps: what a layout is made from (LayoutJson's `design` key)."""
    return {key: value for key, value in design.items() if key != "layout"}


def last_layout(obj, edited):
    """The last layout (LayoutJson) when it was made from this very design: FreeCAD recomputes a design again after
    its boxes moved, and that pass has nothing new to lay out. None otherwise."""
    last = json.loads(obj.LayoutJson) if obj.LayoutJson else {}
    return last if last.get("design") == without_layout(edited) else None


def edited_and_laid_out(obj, edited, valid):
    """The core's recompute of the design dict `edited` from the last valid parts, off FreeCAD's thread in its GUI
    (background.py): live, in LIVE_SECONDS of search besides its last layout (a design of 46 boards searched its
    10 s on every edit). The boxes are moved where it leaves them and `edited` taken from them; (layout dict with
    its design, status note), or (None, "") when the edit was undone."""
    keep = obj.KeepEdits and not obj.Parameters
    try:
        result = background.run(translate("FabGuide", "Laying out '{}'").format(obj.Label),
                                lambda cancel: fabguide_core.edit_design(edited, valid, keep_edits=keep,
                                                                         seconds=LIVE_SECONDS),
                                seconds=LIVE_SECONDS, stoppable=False)
    except fabguide_core.FormatError as error:
        said = messages.in_words(str(error), edited, messages.FLATPACK)
        mark_constraints(obj, said, concerned(error, edited))
        obj.Status = ("Constraints broken: {}" if isinstance(error, fabguide_core.ConstraintError)
                      else "Design '" + obj.Label + "': {}").format(said)
        raise DesignError(translate("FabGuide", "Design '{}': {}").format(obj.Label, said))
    except fabguide_core.PackingError as error:  # no edit of the boxes to absorb or undo
        said = "{}{}".format(error, master_board.shared(obj.MasterBoards, obj))
        obj.Status = said
        raise DesignError(translate("FabGuide", "Design '{}': {}").format(obj.Label, said))
    if result["warning"]:
        FreeCAD.Console.PrintWarning("{}: {}\n".format(obj.Label, result["warning"]))
    ended = result["design"]
    if ended["parts"] != edited["parts"]:
        write_parts(obj, ended["parts"], ended)  # the volumes where the core moved them
        edited.update(snapshot(obj))
    if result["undone"]:
        obj.Status = "Edit undone: {}".format(result["undone"])
        FreeCAD.Console.PrintError(translate("FabGuide", "{}: edit undone: {}\n").format(obj.Label, result["undone"]))
        return None, ""
    note = held(obj, result)
    if result["satisfied"]:
        note += "; boards moved so that every constraint holds"
    if result["absorbed"]:
        note += "; edit absorbed: " + ", ".join(result["snapped"])
    return dict(result["laid_out"], design=without_layout(edited)), note


def held(obj, result):
    """What the status says of an edit the constraints held: refused or how much was kept, and by what (each
    once, the design's own constraints and volumes first); nothing for an edit kept whole."""
    if result["kept"] >= 1:
        return ""
    own = tuple(o.Label for o in obj.Group if is_constraint(o) or is_volume(o))
    limits = sorted(dict.fromkeys(result["limits"]), key=lambda name: not name.startswith(own))
    kept = "kept {:.0%}".format(result["kept"]) if result["kept"] > 0 else "refused"
    return "; edit {}, held by {}".format(kept, ", ".join(limits))


def broken(c):
    """Whether the design breaks the constraint or volume `c`, as its last recompute found."""
    return c.Status.startswith(BROKEN)


def mark_constraints(obj, said, names=()):
    """The constraints and volumes named in `names` show `said`; the others are satisfied."""
    for c in obj.Group:
        if is_constraint(c) or is_volume(c):
            status = BROKEN + said if c.Label in names else SATISFIED
            if c.Status != status:
                c.Status = status


def concerned(error, edited):
    """The names of the constraints and inner volumes the core's FormatError `error` is about: a ConstraintError's
    own, or the one whose field it names (constraints[2].refs[0], inner_volumes[0].size)."""
    names = set(error.names)
    steps = messages.STEP.findall(error.field)
    if steps and steps[0][0] in ("constraints", "inner_volumes") and steps[0][1]:
        listed = edited.get(steps[0][0], [])
        if int(steps[0][1]) < len(listed):
            names.add(listed[int(steps[0][1])].get("name"))
    return names


def write_parts(obj, parts, start=None):
    """Moves and sizes the boxes to `parts`. An inner volume rests on its board as the core has it: where it was
    in design `start` (a dict with parts and inner_volumes; the design now if None), moved along each axis as far
    as the face of its board it is nearer to (the lower one on a tie: InnerVolume in App/Design/Design.h) moved
    from `start` to `parts`; so writing `start`'s own parts puts every volume back exactly."""
    start = start or snapshot(obj)
    by_id = {p["id"]: p for p in parts}
    for box in boxes(obj):
        p = by_id[box.Label]
        cuboids.place(box, [round(v, 9) for v in corners(p)])
    before, after = {p["id"]: corners(p) for p in start["parts"]}, {p["id"]: corners(p) for p in parts}
    for v, was in zip(inner_volumes(obj), start["inner_volumes"]):
        on, at = was["on"], []
        for a in range(3):
            low, high = before[on][2 * a], before[on][2 * a + 1]
            face = 2 * a + (was["min"][a] - low > high - was["max"][a])
            shift = after[on][face] - before[on][face]
            at.append(round(was["min"][a] + shift, 9) if shift else was["min"][a])  # exactly back
        at = FreeCAD.Vector(*at)
        if (v.Placement.Base - at).Length > 1e-9:
            v.Placement = FreeCAD.Placement(at, FreeCAD.Rotation())
            v.purgeTouched()


def corners(part):
    """A format part's [left, right, near, far, bottom, top], as cuboids.coordinates has a box's."""
    return [v for a in range(3) for v in (part["min"][a], part["max"][a])]


@contextlib.contextmanager
def saying_changes(obj, start=None):
    """What the block does to the boards (from `start`, the format's parts, if given), in the design's Changes
    and the report view (cuboids.change)."""
    try:
        before = ({p["id"]: corners(p) for p in start} if start
                  else {box.Label: cuboids.coordinates(box) for box in boxes(obj)})
    except cuboids.CuboidError:  # a rotated box: the recompute says so
        before = {}
    try:
        yield
    finally:
        changes = [cuboids.change(box.Label, before[box.Label], cuboids.coordinates(box))
                   for box in boxes(obj) if box.Label in before]
        changes = [c for c in changes if c]
        if changes:  # FreeCAD recomputes again after boxes moved: that pass changes nothing and says nothing
            obj.Changes = changes
        for change in changes:
            FreeCAD.Console.PrintMessage("{}: {}\n".format(obj.Label, change))


def apply_parts(obj, parts, start=None, laid=None):
    """Sets the boxes to a suggestion's parts and makes them the valid state (used by Accept); the changes are
    said from `start` (the design before the suggestions were previewed). `laid`: the suggestion's {layout,
    problem}, which the next layout keeps while the boxes fit where it laid them, so the design shows the sheets it
    was suggested on."""
    with saying_changes(obj, start):
        write_parts(obj, parts)
    if laid is not None:
        obj.LayoutJson = json.dumps({"layout": laid["layout"], "problem": laid["problem"]})
    obj.Valid = json.dumps(parts_of(obj))
    obj.touch()


def from_file(doc, path, label=None):
    """A design from a *.flatpack.json file: boxes, master boards, constraints and volumes, built from the
    file's normal form (the core's reading of it: every default filled in)."""
    with open(path) as f:
        data = fabguide_core.check_design(json.load(f))  # or refused with why
    masters = [master_board.create(doc, b["width"], b["height"], b["thickness"], b["count"], b["material"],
                                   b["name"], b["grain"], b["cost"])
               for b in data["boards"]]
    made = {}
    for p in data["parts"]:
        box = doc.addObject("Part::Box", "Box")
        box.Label = p["id"]
        box.Length, box.Width, box.Height = sizes(p)
        box.Placement.Base = FreeCAD.Vector(*p["min"])
        made[p["id"]] = box
    obj = create(doc, made.values(), masters, label or data["title"] or "FlatpackDesign")
    for p in data["parts"]:
        made[p["id"]].Grain = p["grain"].capitalize()
    s = data["settings"]
    obj.Resolution, obj.Kerf, obj.Spacing, obj.Trim = s["resolution"], s["kerf"], s["spacing"], s["trim"]
    obj.MinimumLength = s.get("min_length", 0)  # none: twice each board's thickness
    obj.Snap, obj.MaxGrowth = s["snap"], s["max_growth"]
    for c in data["constraints"]:
        values = {}
        if "refs" in c:
            values["Refs"] = c["refs"]
        if c["kind"] == "sum":
            values.update(Refs=c["lhs"], Rhs=c["rhs"], Value=c["offset"])
        if "ref" in c:
            values["Refs"] = [c["ref"]]
        if c["kind"] == "fixed":
            values["Value"] = c["value"]
        if c["kind"] == "range":  # an end not given is none
            values.update(Min=c.get("min", -10 * UNBOUNDED), Max=c.get("max", 10 * UNBOUNDED))
        if isinstance(c.get("about"), str):
            values["About"] = c["about"]
        if "parts" in c:
            values["Parts"] = [made[p] for p in c["parts"]]
        add_constraint(obj, c["kind"], c.get("name"), made, **values)
    for v in data["inner_volumes"]:
        add_volume(obj, "Inner", v["min"], sizes(v), made[v["on"]], v["name"])
    if "outer_volume" in data:
        add_volume(obj, "Outer", data["outer_volume"]["min"], sizes(data["outer_volume"]))
    return obj


def sizes(box):
    """A format box's sizes along x, y and z."""
    return [high - low for low, high in zip(box["min"], box["max"])]
