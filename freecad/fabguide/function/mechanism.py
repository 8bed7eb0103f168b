"""Mechanism: a group of parts, joints, configurations and relationships. Its recompute gathers them into a
*.workslike.json model, solves it once in the core (thesis 4.4) and writes the boxes' sizes and places back.
The user's latest edits are kept: a box coordinate changed since the last solve is locked for this one."""
import json

import FreeCAD

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import background, cuboids, messages, properties, references
from freecad.fabguide.function import configuration, joints, parts, relationships
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

SATISFIED = "Satisfied"
STALE = "Unknown: the mechanism did not solve (see its Status)"
CONFLICT = "Conflict: "  # a relationship's Status begins so when it takes part in a conflict
# The conflicts' kinds a refusal and the hints read (of the core's: fabguide_core.conflict_kinds()).
MENDED, LOCK, NO_OVERLAP = {"drawn_inside", "one_piece"}, "lock", "no_overlap"
HINTED = MENDED | {LOCK, NO_OVERLAP}




class MechanismError(ValueError):
    """A mechanism that cannot be solved as modelled; the message names the mechanism and the field."""


class Mechanism(properties.Proxy):
    TYPE, NOUN = "FabGuide::Mechanism", QT_TRANSLATE_NOOP("FabGuide", "Mechanism")
    VALID = dict(MinimumSize=properties.at_least(0.01, QT_TRANSLATE_NOOP("FabGuide", " mm")),
                 ShownConfiguration=properties.links(configuration.is_configuration,
                                                     QT_TRANSLATE_NOOP("FabGuide", "a configuration")))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLength", "MinimumSize", "Mechanism",
            QT_TRANSLATE_NOOP("App::Property", "Smallest size of a box along any axis"), 1)
        add(obj, "App::PropertyLength", "MinimumWall", "Mechanism",
            QT_TRANSLATE_NOOP("App::Property", "Least wall around a cavity on its sides that are not openings"), 1)
        references.define(obj, "Locks", "Mechanism",
                          QT_TRANSLATE_NOOP("App::Property", "Coordinates that keep their value: a box and its side"))
        add(obj, "App::PropertyBool", "KeepEdits", "Mechanism",
            QT_TRANSLATE_NOOP("App::Property", "Box coordinates you changed since the last solve keep their new value "
                                               "while the rest adapts"), True)
        add(obj, "App::PropertyLink", "ShownConfiguration", "Mechanism",
            QT_TRANSLATE_NOOP("App::Property", "The configuration the Configurations panel last showed; new "
                                               "relationships hold in it"))
        add(obj, "App::PropertyString", "Status", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Solved, or the relationships in conflict"), mode=1)
        add(obj, "App::PropertyFloat", "Violation", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Largest constraint violation after the solve, mm"),
            mode=1)
        add(obj, "App::PropertyStringList", "Blamed", "Result",
            QT_TRANSLATE_NOOP("App::Property", "Parts a conflict blames besides its relationships' (overlapping parts, "
                                               "thin walls)"), mode=1)
        add(obj, "App::PropertyStringList", "Changes", "Result",
            QT_TRANSLATE_NOOP("App::Property", "What the last solve changed: box, size old → new, how far it "
                                               "moved"), mode=1)
        add(obj, "App::PropertyString", "Solved", "Data",
            QT_TRANSLATE_NOOP("App::Property", "Box coordinates after the last solve (JSON)"), mode=2)
        add(obj, "App::PropertyString", "Drawn", "Data",
            QT_TRANSLATE_NOOP("App::Property", "Box sizes as you drew them, before solves (JSON)"), mode=2)

    def recompute(self, obj):
        try:
            solve(obj)
        except ValueError as error:
            unsolved(obj, str(error))
            raise


def create(doc, label="Mechanism"):
    obj = doc.addObject("App::DocumentObjectGroupPython", "Mechanism")
    Mechanism(obj)
    obj.Label = label
    return obj


def is_mechanism(obj):
    return properties.is_a(obj, Mechanism)


def members(obj, test):
    return [o for o in obj.Group if test(o)]


def boxes(obj):
    return [box for part in members(obj, parts.is_part) for box in parts.boxes(part) if cuboids.is_box(box)]


def remembered(text, size):
    """{box name: `size` numbers} from a hidden JSON property; what is not that (a script wrote nonsense) is
    forgotten, as in a new mechanism."""
    try:
        stored = json.loads(text) if text else {}
    except ValueError:
        return {}
    if not isinstance(stored, dict):
        return {}
    return {name: v for name, v in stored.items() if isinstance(v, list) and len(v) == size and
            all(isinstance(x, (int, float)) and abs(x) < 1e100 for x in v)}


def edits(obj):
    """Box coordinates changed since the last solve, as lock names ("Lid.top"): both sides along an axis the
    user changed, so a Length typed stays a length with the box's corner where it was, never becomes a move."""
    before = remembered(obj.Solved, 6)
    if not obj.KeepEdits or not before:
        return []
    return ["{}.{}".format(box.Label, cuboids.SIDES[2 * a + high]) for box in boxes(obj) if box.Name in before
            for a, now in enumerate(zip(*[iter(cuboids.coordinates(box))] * 2))
            if any(abs(w - n) > 1e-7 for w, n in zip(before[box.Name][2 * a:2 * a + 2], now)) for high in (0, 1)]


def sizes(coordinates):
    return [high - low for low, high in zip(coordinates[0::2], coordinates[1::2])]


def drawn(obj):
    """Each box's sizes as the user drew them, {box name: [x, y, z]}: a size as the last solve wrote it is the
    one drawn before that solve; a size changed since (or a box new to the mechanism) is drawn as it is now.
    The solve holds sizes against them, so that successive solves cannot thin a part again and again."""
    solved, before = remembered(obj.Solved, 6), remembered(obj.Drawn, 3)
    out = {}
    for box in boxes(obj):
        now = sizes(cuboids.coordinates(box))
        wrote = sizes(solved[box.Name]) if box.Name in solved else [None] * 3
        was = before.get(box.Name, now)
        out[box.Name] = [d if w is not None and abs(n - w) <= 1e-7 else n for n, w, d in zip(now, wrote, was)]
    return out


def model(obj, locks=(), drawn_sizes=None):
    """The mechanism as a *.workslike.json dict; a cuboid whose sizes differ from those the user drew
    (`drawn_sizes`, drawn(obj) by default) says them."""
    drawn_sizes = drawn(obj) if drawn_sizes is None else drawn_sizes
    names = {box.Label: box.Name for box in boxes(obj)}
    try:
        made = [read(p, parts.as_dict) for p in members(obj, parts.is_part)]
        for cuboid in (c for p in made for c in p["cuboids"]):
            was = drawn_sizes.get(names.get(cuboid["name"]))
            now = [high - low for low, high in zip(cuboid["min"], cuboid["max"])]
            if was and any(abs(d - n) > 1e-7 for d, n in zip(was, now)):
                cuboid["drawn"] = was
        return {
            "format": "fabguide.workslike", "version": 1, "minimum_size": obj.MinimumSize.Value,
            "minimum_wall": obj.MinimumWall.Value,
            "parts": made,
            "joints": [read(j, joints.as_dict) for j in members(obj, joints.is_joint)],
            "configurations": [read(c, configuration.as_dict) for c in members(obj, configuration.is_configuration)],
            "relationships": [read(r, relationships.as_dict) for r in members(obj, relationships.is_relationship)],
            "locks": list(dict.fromkeys(references.names(obj.Locks) + list(locks))),
        }
    except ValueError as error:
        failed = MechanismError(translate("FabGuide", "Mechanism '{}': {}").format(obj.Label, error))
        member = getattr(error, "source", None)
        failed.source = member if getattr(member, "Error", "") else obj  # whose failure it is, as said
        raise failed


def read(member, as_dict):
    """A member of the mechanism as its dict; a failure to read it is the member's own (`source`): what says it in
    its own recompute (a joint, a part) is not echoed by the mechanism, nor the mechanism's by a printable made from
    it (properties.fail)."""
    try:
        return as_dict(member)
    except ValueError as error:
        error.source = member
        raise


def solve(obj):
    """Solve once; write back the boxes and each relationship's Status. A conflict names the relationships
    (and locks) that cannot hold together; one the user's latest edit takes part in refuses the edit: the
    boxes go back to the last solve, exactly."""
    edited = edits(obj)
    drawn_sizes = drawn(obj)
    data = model(obj, edited, drawn_sizes)
    try:
        solved = background.run(translate("FabGuide", "Solving '{}'").format(obj.Label),
                                lambda cancel: fabguide_core.solve(data), stoppable=False)
    except fabguide_core.FormatError as error:
        raise MechanismError(translate("FabGuide", "Mechanism '{}': {}").format(
            obj.Label, messages.in_words(str(error), data, messages.WORKSLIKE)))
    report = solved["report"]
    conflict = report["conflict"]
    if not report["solved"] and {c["subject"] for c in report["conflicts"] if c["kind"] == LOCK} & set(edited):
        refuse(obj, report)
        say_changes(obj, [])
        return solved
    by_name = {r["name"]: r for r in solved["relationships"]}
    for rel in members(obj, relationships.is_relationship):
        others = ", ".join(n for n in conflict if n != rel.Label) or "it cannot hold as the boxes are drawn"
        status = (satisfied(rel, report["notes"]) if report["solved"] else
                  CONFLICT + others if rel.Label in conflict else "")
        if rel.Status != status:
            rel.Status = status
        relationships.keep_pairs(rel, by_name.get(rel.Label, {}), {box.Label: box for box in boxes(obj)})
    obj.Violation = report["violation"]
    if obj.Blamed != report["parts"]:
        obj.Blamed = report["parts"]
    for note in report["notes"] if report["solved"] else []:
        FreeCAD.Console.PrintMessage("{}: {}\n".format(obj.Label, note))
    if not report["solved"]:
        obj.Status = CONFLICT + ", ".join(conflict)
        FreeCAD.Console.PrintWarning(translate("FabGuide", "{}: these cannot hold together: {}. {}\n").format(
            obj.Label, ", ".join(conflict), what_to_do(report["conflicts"])))
        for note in report.get("notes", []):
            FreeCAD.Console.PrintWarning("  {}\n".format(note))
        say_changes(obj, [])
        return solved
    say_changes(obj, write_back(obj, solved))
    obj.Drawn = json.dumps(drawn_sizes)
    place_pivots(obj, solved)
    obj.Status = "Solved"
    return solved


def what_to_do(conflicts):
    """A hint after a conflict (the report's typed conflicts): what the user can change."""
    kinds = {c["kind"] for c in conflicts}
    if kinds & MENDED:
        return translate("FabGuide", "Mend the model as the note below says.")
    hints = [translate("FabGuide", "Change or delete one of the relationships.")]
    if LOCK in kinds:
        hints.append(translate("FabGuide", "Or unlock a box (the mechanism's Locks)."))
    if NO_OVERLAP in kinds:
        hints.append(translate("FabGuide", "Or move the parts that meet apart."))
    return " ".join(hints)


def say_changes(obj, changes):
    """The mechanism's Changes, what this solve did to the boxes (nothing when it wrote none back), also in the
    report view."""
    if obj.Changes != changes:
        obj.Changes = changes
    for change in changes:
        FreeCAD.Console.PrintMessage("{}: {}\n".format(obj.Label, change))


def refuse(obj, report):
    """The user's edit cannot hold with the rest: every box back where the last solve left it, the parts that
    would clash blamed (red), the relationships' statuses as they were."""
    before = remembered(obj.Solved, 6)
    for box in boxes(obj):
        if box.Name in before:
            cuboids.place(box, before[box.Name])
    if obj.Blamed != report["parts"]:
        obj.Blamed = report["parts"]
    obj.Status = "Edit refused: {} cannot hold together; the boxes are as they were".format(
        ", ".join(report["conflict"]))
    FreeCAD.Console.PrintWarning("{}: {}\n".format(obj.Label, obj.Status))


def in_conflict(rel):
    """Whether the last solve found the relationship in a conflict."""
    return rel.Status.startswith(CONFLICT)


def unsolved(obj, error):
    """A mechanism that could not be read says why in its Status; its relationships' statuses no longer hold."""
    obj.Status = error
    if obj.Blamed:
        obj.Blamed = []
    for rel in members(obj, relationships.is_relationship):
        if rel.Status != STALE:
            rel.Status = STALE


def satisfied(rel, notes):
    """"Satisfied", and what inference had to stretch to link every part the relationship names; the graph it
    inferred is kept in Pairs (keep_pairs), and so is the note while those pairs stay."""
    prefix = rel.Label + ": "
    own = [n[len(prefix):] for n in notes if n.startswith(prefix)]
    if not own and getattr(rel, "Pairs", None) and rel.Status.startswith(SATISFIED + "; "):
        return rel.Status
    return "; ".join([SATISFIED] + own)


def place_pivots(obj, solved):
    """The double pivots' pivots where stage 2 of the solve put them."""
    by_name = {j["name"]: j for j in solved["joints"]}
    for joint in members(obj, joints.is_joint):
        if joints.kind(joint) != "double_pivot":
            continue
        for key, prop in (("pivot", "Pivot"), ("base_pivot", "BasePivot")):
            point = FreeCAD.Vector(*by_name[joint.Label][key][1])
            if (getattr(joint, prop) - point).Length > 1e-9:
                setattr(joint, prop, point)


def write_back(obj, solved):
    """Sizes and places the boxes as solved; remembers them to tell the user's next edits apart. Returns what
    changed, a line per box (cuboids.change)."""
    by_label = {c["name"]: c for p in solved["parts"] for c in p["cuboids"]}
    after, changes = {}, []
    for box in boxes(obj):
        c = by_label[box.Label]
        values = [round(v, 7) for a in range(3) for v in (c["min"][a], c["max"][a])]  # IPM noise off
        before = cuboids.coordinates(box)
        if cuboids.place(box, values):
            changes.append(cuboids.change(box.Label, before, values))
        after[box.Name] = values
    obj.Solved = json.dumps(after)
    return [c for c in changes if c]
