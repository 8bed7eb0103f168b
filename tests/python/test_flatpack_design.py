"""Flat-pack design objects, headless (thesis 5.1, 5.3.5): a design of Part::Box boards keeps its constraints as
the user edits, shows its usage, undoes an edit that no longer fits, survives save/reload and undo; an edit the
constraints refuse or keep in part leaves every box and inner volume where it belongs, exactly, through undo and
reopening; suggestions from the core applied to it keep every constraint; a parametric design driven by a
spreadsheet is optimised through its gradients; each box's Grain reaches the layout, files and suggestions."""
import glob
import json
import os
import re

import FreeCAD
import pytest

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import cuboids
from freecad.fabguide.material import design, master_board, parametric


@pytest.fixture
def doc():
    document = FreeCAD.newDocument("flatpack")
    document.UndoMode = 1
    name = document.Name
    yield document
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


@pytest.fixture
def table(doc, source_dir):
    obj = design.from_file(doc, os.path.join(source_dir, "examples", "coffee-table.flatpack.json"))
    doc.recompute()
    return obj


def box(doc, label):
    return doc.getObjectsByLabel(label)[0]


def size(doc, label, axis):
    return getattr(box(doc, label), cuboids.SIZES[axis]).Value


def test_a_design_from_a_file_lays_out_and_shows_its_usage(doc, table, source_dir):
    with open(os.path.join(source_dir, "examples", "coffee-table.flatpack.json")) as f:
        expected = fabguide_core.lay_out_design(json.load(f))["usage"]
    assert table.Usage == pytest.approx(expected)
    assert table.Status.startswith("Usage ")
    assert len(design.boxes(table)) == 4
    assert len([c for c in table.Group if design.is_constraint(c)]) == 8
    assert all(c.Status == design.SATISFIED for c in table.Group if design.is_constraint(c))
    assert not [o.Name for o in doc.Objects if "Touched" in o.State]


def test_an_edit_is_kept_and_the_rest_adapts(doc, table):
    doc.openTransaction("widen")
    box(doc, "top").Length = 760
    doc.recompute()
    doc.commitTransaction()
    assert size(doc, "top", 0) == pytest.approx(760)
    # The legs stay flush with the top's ends, symmetric about its centre; the shelf widens between them.
    left, right, top = (cuboids.coordinates(box(doc, n)) for n in ("left", "right", "top"))
    assert left[0] == pytest.approx(top[0]) and right[1] == pytest.approx(top[1])
    assert size(doc, "shelf", 0) == pytest.approx(760 - 24)
    assert "Touched" not in table.State
    doc.undo()
    doc.recompute()
    assert size(doc, "top", 0) == pytest.approx(720)
    assert size(doc, "shelf", 0) == pytest.approx(696)


def test_an_edit_is_laid_out_once_and_a_recompute_that_changes_nothing_keeps_the_layout(doc, table, monkeypatch):
    """An edit is one core call, which lays out once. FreeCAD recomputes a design again after its boxes moved: that
    pass calls nothing (a layout is a search of LIVE_SECONDS). A change of the boxes or of a setting is laid out
    afresh."""
    calls = []
    edit = fabguide_core.edit_design
    monkeypatch.setattr(fabguide_core, "edit_design", lambda *a, **k: calls.append(1) or edit(*a, **k))
    monkeypatch.setattr(fabguide_core, "lay_out_design", None)  # the recompute lays out through edit_design only
    box(doc, "top").Length = 760
    doc.recompute()
    assert len(calls) == 1 and "Touched" not in table.State
    laid = table.LayoutJson
    table.touch()
    doc.recompute()
    assert len(calls) == 1 and table.LayoutJson == laid
    table.Kerf = 3
    doc.recompute()
    assert len(calls) == 2 and json.loads(table.LayoutJson)["design"]["settings"]["kerf"] == 3


def test_an_edit_past_a_range_is_kept_as_far_as_the_range_allows(doc, table):
    box(doc, "top").Length = 2000  # the range allows 720 x 1.25 = 900
    doc.recompute()
    assert size(doc, "top", 0) == pytest.approx(900, abs=1e-3)
    assert "held by Range top.size.x (max)" in table.Status


def test_an_edit_that_does_not_fit_the_master_board_is_undone_with_the_reason(doc, table):
    table.Group = [o for o in table.Group if not design.is_constraint(o)]  # nothing holds the shelf back
    box(doc, "shelf").Width = 1300
    doc.recompute()
    assert size(doc, "shelf", 1) == pytest.approx(260)
    assert table.Status == "Edit undone: part 'shelf' is larger than every master board"


def test_an_edit_that_overflows_the_board_is_absorbed_by_the_parts_beside_it(doc, table):
    # Without ranges, a top 1000 mm wide fits in no layout: the parts sharing its line across the board give way.
    table.Group = [o for o in table.Group if not (design.is_constraint(o) and o.Kind == "range")]
    doc.recompute()
    box(doc, "top").Length = 1000
    doc.recompute()
    assert size(doc, "top", 0) == pytest.approx(1000)
    assert "edit absorbed: fit " in table.Status, table.Status
    fabguide_core.lay_out_design(design.flatpack(table))  # every constraint holds and it fits


def test_save_and_reload_keep_the_design(doc, table, tmp_path):
    path = str(tmp_path / "table.FCStd")
    doc.saveAs(path)
    before = design.parts_of(table)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        obj = next(o for o in reopened.Objects if design.is_design(o))
        reopened.recompute()
        assert design.parts_of(obj) == before
        assert obj.Usage > 0.9
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_a_suggestion_applied_keeps_every_constraint_and_wastes_less(doc, table):
    result = fabguide_core.optimise(design.flatpack(table), seed=3, threads=2, time_limit=20)
    assert result["suggestions"]
    best = result["suggestions"][0]
    before = result["before"]  # the maker's measure: fewer sheets, or as many and less waste
    assert best["sheets"] < before["sheets"] or (best["sheets"] == before["sheets"] and
                                                 best["waste_m2"] < before["waste_m2"])
    doc.openTransaction("accept")
    design.apply_parts(table, best["design"]["parts"], laid=best)
    kept = {"boards": best["layout"]["boards"], "placements": best["layout"]["placements"]}
    assert design.flatpack(table)["layout"] == kept == best["design"]["layout"]
    doc.recompute()
    doc.commitTransaction()
    assert table.Usage == pytest.approx(best["usage"], abs=0.02)
    assert len(json.loads(table.LayoutJson)["layout"]["boards"]) == best["sheets"]  # on the sheets suggested
    assert all(c.Status == design.SATISFIED for c in table.Group if design.is_constraint(c))
    fabguide_core.lay_out_design(design.flatpack(table))  # reads back: every constraint holds


def test_optimise_reports_progress_and_can_be_cancelled(table):
    token = fabguide_core.CancelToken()
    seen = []

    def progress(done, best):
        seen.append((done, best))
        token.cancel()

    result = fabguide_core.optimise(design.flatpack(table), progress=progress, cancel=token)
    assert result["stopped"]
    assert seen and 0 < seen[0][0] < 1


def spreadsheet_box(doc):
    """A box of 12 mm boards (sides, ends, a bottom) whose sizes follow spreadsheet aliases side and height, the
    boards 500 mm apart along x (so none touches another); returns the sheet and the boards by name."""
    sheet = doc.addObject("Spreadsheet::Sheet", "Params")
    for cell, alias, v in (("A1", "side", "300"), ("A2", "height", "170")):
        sheet.set(cell, v)
        sheet.setAlias(cell, alias)
    boards = {}
    for name, length, width in (("side", "Params.side", "Params.height"), ("end", "Params.side - 24", "Params.height"),
                                ("bottom", "Params.side - 24", "Params.side - 24")):
        b = doc.addObject("Part::Box", name)
        b.Height = 12
        b.setExpression("Length", length)
        b.setExpression("Width", width)
        b.Placement.Base.x = 500 * len(boards)
        boards[name] = b
    doc.recompute()
    return sheet, boards


def test_a_parametric_design_driven_by_a_spreadsheet_is_optimised(doc):
    """Two sides, two ends and a bottom, through the core's parametric search directly."""
    sheet, boards = spreadsheet_box(doc)

    def sizes(parameters):
        sheet.set("A1", str(parameters[0]))
        sheet.set("A2", str(parameters[1]))
        doc.recompute()
        return [v for b in boards.values() for v in (b.Length.Value, b.Width.Value, b.Height.Value)]

    parts = [{"id": "side", "quantity": 2}, {"id": "end", "quantity": 2}, {"id": "bottom", "quantity": 1}]
    sheets = {"boards": [{"width": 900, "height": 600, "thickness": 12}], "settings": {"resolution": 1}}
    with pytest.raises(fabguide_core.FormatError, match='parts.1..grain: must be "free", "x", "y" or "z", got "Y"'):
        fabguide_core.optimise_parametric([parts[0], dict(parts[1], grain="Y")], sizes, [300, 170], [200, 100],
                                          [400, 300], sheets)
    result = fabguide_core.optimise_parametric(parts, sizes, [300, 170], [200, 100], [400, 300], sheets,
                                               rounds=2, time_limit=30)
    best = result["suggestions"][0]
    before = result["before"]  # the maker's measure: fewer sheets, or as many and less waste
    assert best["sheets"] < before["sheets"] or (best["sheets"] == before["sheets"] and
                                                 best["waste_m2"] < before["waste_m2"])
    side, height = best["parameters"]
    assert 200 <= side <= 400 and 100 <= height <= 300
    sizes(best["parameters"])
    assert boards["bottom"].Length.Value == pytest.approx(side - 24)
    assert [s["parameters"] for s in best["path"]][0] == [300, 170]
    # Every side is affine in the aliases: the bound over the box takes each at its least (side 200, height 100),
    # whose area (0.11 m² with kerf) fits one sheet.
    assert result["least_sheets_by_area"] == result["least_sheets_bound"] == 1


EXAMPLES = ["chest", "l-worktable", "low-chair", "parrot-shelf", "shelf-and-chest", "shelf-and-table",
            "stylised-chair", "yin-chair"]
SUITE = sorted(glob.glob(os.path.join(os.path.dirname(__file__), "..", "data", "flatpack", "*.flatpack.json")))


@pytest.mark.parametrize("name", EXAMPLES)
def test_every_example_imports_and_exports_as_the_same_design(doc, source_dir, name):
    path = os.path.join(source_dir, "examples", name + ".flatpack.json")
    obj = design.from_file(doc, path)
    doc.recompute()
    assert not obj.Error, obj.Status
    with open(path) as f:
        assert obj.Usage == pytest.approx(fabguide_core.lay_out_design(json.load(f))["usage"])
    exported = json.loads(json.dumps(design.flatpack(obj)))  # as Export writes it
    assert fabguide_core.lay_out_design(exported)["usage"] == pytest.approx(obj.Usage)


def grain_of(part):
    """A file part's grain axis (docs/formats.md): the older follow_grain is the first long axis, x before y."""
    if "grain" in part or not part.get("follow_grain"):
        return part.get("grain", "free")
    size = design.sizes(part)
    return "xyz"[[k for k in range(3) if k != size.index(min(size))][0]]


@pytest.mark.parametrize("path", SUITE, ids=os.path.basename)
def test_every_suite_design_exports_as_it_was_imported(doc, path):
    """The zero-waste suite (tests/data/flatpack, up to 61 boards) through FreeCAD and back, without a recompute:
    the same boards where they were, with their grain; the same settings, master boards and constraints, which the
    core reads as it read the file."""
    with open(path) as f:
        original = json.load(f)
    exported = json.loads(json.dumps(design.flatpack(design.from_file(doc, path))))  # as Export writes it
    fabguide_core.check_design(exported)
    assert [(p["id"], p.get("grain", "free")) for p in exported["parts"]] == [
        (p["id"], grain_of(p)) for p in original["parts"]]
    for mine, theirs in zip(exported["parts"], original["parts"]):
        assert mine["min"] + mine["max"] == pytest.approx(theirs["min"] + theirs["max"]), mine["id"]
    assert [c["kind"] for c in exported["constraints"]] == [c["kind"] for c in original.get("constraints", [])]
    assert len(exported["inner_volumes"]) == len(original.get("inner_volumes", []))
    assert [(b["width"], b["height"], b["thickness"]) for b in exported["boards"]] == [
        (b["width"], b["height"], b["thickness"]) for b in original["boards"]]
    for key, value in original.get("settings", {}).items():
        assert exported["settings"].get(key, value) == pytest.approx(value), key
    assert exported["settings"]["min_length"] == original["settings"]["min_length"]


@pytest.mark.parametrize("name", ["coffee-table", "sideboard-18-6mm"])
def test_a_file_an_older_version_wrote_imports_as_this_version_writes_it(doc, source_dir, name):
    """Format version 1 (boxes by position and size) makes the boxes, volumes and constraints its version 2 twin
    makes (tests/data/flatpack/version-1), and is exported as version 2."""
    twin = FreeCAD.newDocument("Twin")  # labels as in the file: in one document the second would be renamed
    try:
        exported = [json.loads(json.dumps(design.flatpack(design.from_file(d, os.path.join(source_dir, *where))))) for
                    d, where in ((doc, ("tests", "data", "flatpack", "version-1", name + ".flatpack.json")),
                                 (twin, ("examples" if name == "coffee-table" else "tests/data/flatpack",
                                         name + ".flatpack.json")))]
    finally:
        FreeCAD.closeDocument(twin.Name)
    assert exported[0]["version"] == 2 and exported[0] == exported[1]


def test_a_file_without_min_length_keeps_each_board_to_twice_its_own_thickness(doc, tmp_path):
    """The format's default: FreeCAD's MinimumLength 0 stands for it (it had taken twice the first master board's
    thickness for every board, so a 6 mm back could not shrink below 36 mm where the command line allows 12)."""
    with open(SUITE[0]) as f:
        original = json.load(f)
    del original["settings"]["min_length"]
    path = tmp_path / "design.flatpack.json"
    path.write_text(json.dumps(original))
    obj = design.from_file(doc, str(path))
    assert obj.MinimumLength.Value == 0
    exported = design.flatpack(obj)
    assert "min_length" not in exported["settings"]
    obj.MinimumLength = 50
    assert design.flatpack(obj)["settings"]["min_length"] == 50


def test_a_design_driven_by_spreadsheet_aliases_is_suggested_new_values(doc):
    """The same box as above, as a FlatpackDesign whose Parameters name the aliases: Suggest changes them."""
    sheet, boards = spreadsheet_box(doc)
    boxes = list(boards.values())
    obj = design.create(doc, boxes, [master_board.create(doc, 900, 600, 12)])
    obj.Parameters = ["Params.side 200 400", "Params.height 100 300"]
    doc.recompute()
    assert not obj.Error, obj.Status
    result = parametric.optimise(obj, time_limit=6, rounds=1)
    assert parametric.value(sheet, "side") == 300  # restored
    best = result["suggestions"][0]
    before = result["before"]  # the maker's measure: fewer sheets, or as many and less waste
    assert best["sheets"] < before["sheets"] or (best["sheets"] == before["sheets"] and
                                                 best["waste_m2"] < before["waste_m2"])
    side, height = best["parameters"]
    assert 200 <= side <= 400 and 100 <= height <= 300
    parametric.set_values(obj, parametric.parameters(obj), best["parameters"])
    assert boxes[2].Length.Value == pytest.approx(side - 24)
    assert obj.Usage == pytest.approx(best["usage"], abs=0.03)
    obj.Parameters = ["Params.depth 1 2"]
    with pytest.raises(parametric.ParameterError, match="no spreadsheet 'Params' with an alias 'depth'"):
        parametric.parameters(obj)


def test_a_parametric_design_cuts_each_board_from_its_thickness_along_its_grain(doc):
    """Sides and ends with their grain up (y), a 6 mm bottom: every layout the parametric search gives lays each
    board on master boards of its own thickness and the grained ones along the sheet's grain, at the parameters
    of that layout (the crates saved a sheet only by laying 21 parts across the grain)."""
    sheet, boards = spreadsheet_box(doc)
    boards["bottom"].Height = 6
    doc.recompute()
    grained, plain = master_board.create(doc, 900, 600, 12), master_board.create(doc, 900, 600, 6)
    grained.Grain, grained.Count = "Along width", -1
    obj = design.create(doc, list(boards.values()), [grained, plain])
    boards["side"].Grain = boards["end"].Grain = "Y"
    obj.Parameters = ["Params.side 200 400", "Params.height 100 300"]
    doc.recompute()
    result = parametric.optimise(obj, time_limit=4, rounds=1)
    params = parametric.parameters(obj)
    for laid, values in [(result["before"], [300, 170])] + [(s, s["parameters"]) for s in result["suggestions"]]:
        parametric.set_values(obj, params, values, boxes_only=True)
        sheets = laid["layout"]["boards"]
        for at in laid["layout"]["placements"]:
            b = boards[at["part"]]
            sides = [b.Length.Value, b.Width.Value, b.Height.Value]
            assert sheets[at["board"]]["thickness"] == min(sides), (at, sides)
            if b.Grain == "Y":  # its y side along the sheet's width, the grain's way
                assert at["rotation"] in (0, 180) and at["width"] == pytest.approx(sides[1]), (at, sides)
    parametric.set_values(obj, params, [300, 170])


def two_boards(doc, second_length):
    """Boards a (300 mm) and b, side by side on a 1000 x 600 master board, in a design recomputed."""
    a = doc.addObject("Part::Box", "a")
    a.Length, a.Width, a.Height = 300, 200, 12
    b = doc.addObject("Part::Box", "b")
    b.Length, b.Width, b.Height = second_length, 200, 12
    b.Placement.Base = FreeCAD.Vector(0, 400, 0)
    doc.recompute()
    obj = design.create(doc, [a, b], [master_board.create(doc, 1000, 600, 12)])
    doc.recompute()
    return a, b, obj


def test_a_new_constraint_that_does_not_hold_moves_the_boards_the_least(doc):
    a, b, obj = two_boards(doc, 340)
    design.add_constraint(obj, "equal", "same length", Refs=["a.size.x", "b.size.x"])
    doc.recompute()
    assert not obj.Error, obj.Status
    assert a.Length.Value == pytest.approx(b.Length.Value)
    assert {a.Length.Value, b.Length.Value} <= {300.0, 340.0}  # one board changed, not both
    assert "boards moved so that every constraint holds" in obj.Status
    assert len(obj.Changes) == 1 and obj.Changes[0].startswith(("a: Length 300 → 340 mm", "b: Length 340 → 300 mm"))
    design.add_constraint(obj, "fixed", "a is 300", Refs=["a.size.x"], Value=250)
    design.add_constraint(obj, "fixed", "b is 340", Refs=["b.size.x"], Value=340)
    doc.recompute()
    assert obj.Error and obj.Status.startswith("Constraints broken:")
    marked = {c.Label: c.Status.startswith("Broken") for c in obj.Group if design.is_constraint(c)}
    assert marked == {"same length": False, "a is 300": True, "b is 340": False}, marked
    with pytest.raises(fabguide_core.ConstraintError, match="does not satisfy its own constraints: a is 300") as broken:
        fabguide_core.lay_out_design(design.flatpack(obj))  # a FormatError of its own kind, told apart by type
    assert broken.value.names == ["a is 300"]  # what it is about, read as an attribute, not from the words
    with pytest.raises(fabguide_core.FormatError) as raised:
        fabguide_core.lay_out_design(dict(design.flatpack(obj), constraints=[{"name": "x", "type": "fixed"}]))
    assert raised.value.field.startswith("constraints[0].")
    assert raised.value.names == []


def test_boards_drawn_equal_get_equal_constraints_an_edit_carries_and_a_deletion_frees(doc):
    boards = []
    for k, (x, y) in enumerate([(0, 0), (482, 0), (0, 282), (482, 282)]):  # four legs under a top
        leg = doc.addObject("Part::Box", "leg")
        leg.Label, (leg.Length, leg.Width, leg.Height) = "leg {}".format(k + 1), (18, 18, 400)
        leg.Placement.Base = FreeCAD.Vector(x, y, 0)
        boards.append(leg)
    top = doc.addObject("Part::Box", "top")
    top.Label, (top.Length, top.Width, top.Height) = "top", (500, 300, 18)
    top.Placement.Base = FreeCAD.Vector(0, 0, 400)
    doc.recompute()
    obj = design.create(doc, boards + [top], [master_board.create(doc, 1220, 610, 18)])
    obj.Snap = False  # the legs held by nothing but being drawn alike
    kept = design.keep_drawn_equal(obj)
    assert sorted(c.Label for c in kept) == ["drawn equal: size.y of leg 1, leg 2, leg 3, leg 4",
                                            "drawn equal: size.z of leg 1, leg 2, leg 3, leg 4"]
    doc.recompute()
    doc.openTransaction("taller leg")
    boards[2].Height = 450
    doc.recompute()
    doc.commitTransaction()
    assert [b.Height.Value for b in boards] == pytest.approx([450] * 4), obj.Status
    doc.removeObject(next(c for c in kept if "size.z" in c.Label).Name)  # free them
    doc.openTransaction("one leg taller")
    boards[0].Height = 480
    doc.recompute()
    doc.commitTransaction()
    assert [b.Height.Value for b in boards] == pytest.approx([480, 450, 450, 450]), obj.Status
    again = design.keep_drawn_equal(obj)  # the three legs still alike, along the side no constraint holds
    assert [c.Label for c in again] == ["drawn equal: size.z of leg 2, leg 3, leg 4"]


@pytest.fixture
def bookcase(doc, source_dir):
    """Four equal shelves between sides symmetric about the top, A4 binders resting on the bottom and on shelf 1."""
    obj = design.from_file(doc, os.path.join(source_dir, "tests", "data", "flatpack", "bookcase-1800.flatpack.json"))
    doc.recompute()
    return obj


@pytest.fixture
def console(capfd):
    """FreeCAD's errors and warnings as the report view shows them: the text printed since the last call."""
    FreeCAD.Console.SetStatus("Console", "Err", True)
    FreeCAD.Console.SetStatus("Console", "Wrn", True)
    yield lambda: "".join(capfd.readouterr())
    FreeCAD.Console.SetStatus("Console", "Err", False)
    FreeCAD.Console.SetStatus("Console", "Wrn", False)


def geometry(obj):
    """Every box and inner volume as [xmin, xmax, ymin, ymax, zmin, zmax] by label, read from its solid."""
    return {o.Label: [getattr(o.Shape.BoundBox, a + end) for a in "XYZ" for end in ("Min", "Max")]
            for o in design.boxes(obj) + design.inner_volumes(obj)}


def assert_geometry(obj, expected):
    got = geometry(obj)
    assert got.keys() == expected.keys()
    for label, bounds in expected.items():
        assert got[label] == pytest.approx(bounds, abs=1e-9), label


def entered(obj):
    """(volume, board) for each board through an inner volume other than the one it rests on: their solids'
    common part, computed by OpenCASCADE, not by FabGuide."""
    return [(v.Label, b.Label) for v in design.inner_volumes(obj) for b in design.boxes(obj)
            if b != v.On and v.Shape.common(b.Shape).Volume > 1e-6]


def statuses(obj):
    return {o.Label: o.Status for o in obj.Group if design.is_constraint(o) or design.is_volume(o)}


def reopened(doc, tmp_path):
    """The document saved, closed, opened again and recomputed from scratch; returns (document, design)."""
    path = str(tmp_path / "design.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    again = FreeCAD.openDocument(path)
    for o in again.Objects:
        o.touch()
    again.recompute()
    return again, next(o for o in again.Objects if design.is_design(o))


def test_a_refused_edit_leaves_the_design_as_it_was_through_undo_and_reopening(doc, bookcase, tmp_path, console):
    design.add_constraint(bookcase, "fixed", "width 864", Refs=["top.size.x"], Value=864)
    doc.recompute()
    before = geometry(bookcase)
    assert before["A4 binders on shelf 1"] == [30, 830, 10, 275, 438.4, 758.4]
    doc.openTransaction("longer shelf")
    box(doc, "shelf-1").Length = 900  # the shelves are equal and the sides 864 mm apart: it cannot be
    doc.recompute()
    doc.commitTransaction()
    assert_geometry(bookcase, before)  # the binders did not go 18 mm into the left side
    assert "; edit refused, held by equal shelves, width 864" in bookcase.Status, bookcase.Status
    assert set(statuses(bookcase).values()) == {design.SATISFIED}
    assert not entered(bookcase)
    doc.undo()
    doc.recompute()
    assert_geometry(bookcase, before)
    assert not [o.Name for o in doc.Objects if o.State != ["Up-to-date"]]
    again, obj = reopened(doc, tmp_path)
    try:
        assert_geometry(obj, before)
        assert not [o.Name for o in again.Objects if o.State != ["Up-to-date"]]
        assert set(statuses(obj).values()) == {design.SATISFIED}
    finally:
        FreeCAD.closeDocument(again.Name)
    assert console() == ""


def test_an_edit_kept_in_part_carries_the_volumes_with_their_boards_and_undo_restores_it(doc, bookcase, tmp_path,
                                                                                        console):
    before = geometry(bookcase)
    doc.openTransaction("longer shelf")
    box(doc, "shelf-1").Length = 1000  # the carcass may be 1000 mm wide at most
    doc.recompute()
    doc.commitTransaction()
    assert "; edit kept 74%, held by width 800-1000 (max), equal shelves, " in bookcase.Status, bookcase.Status
    after = geometry(bookcase)
    assert after["top"][1] == pytest.approx(982, abs=1e-3) and after["side-right"][0] == after["top"][1]
    assert {tuple(after["shelf-{}".format(k)][:2]) for k in range(1, 5)} == {tuple(after["top"][:2])}
    for v in design.inner_volumes(bookcase):  # they keep 12 mm from the left edge of their boards, which stays
        assert after[v.Label] == pytest.approx(before[v.Label], abs=1e-9)
        assert after[v.Label][0] - after[v.On.Label][0] == pytest.approx(12, abs=1e-9)
    assert not entered(bookcase)
    assert set(statuses(bookcase).values()) == {design.SATISFIED}
    doc.undo()
    doc.recompute()
    assert_geometry(bookcase, before)
    doc.redo()
    doc.recompute()
    assert_geometry(bookcase, after)
    again, obj = reopened(doc, tmp_path)
    try:
        assert_geometry(obj, after)
        assert not entered(obj)
        assert not [o.Name for o in again.Objects if o.State != ["Up-to-date"]]
    finally:
        FreeCAD.closeDocument(again.Name)
    assert console() == ""


def placed(obj, label):
    """(the part's width in the layout problem, its extent along the sheet's x) in the design's layout."""
    laid = json.loads(obj.LayoutJson)
    part = next(p for p in laid["problem"]["parts"] if p["id"] == label)
    at = next(p for p in laid["layout"]["placements"] if p["part"] == label)
    return part["width"], at["width"] if at["rotation"] in (0, 180) else at["height"]


def test_a_box_grain_lays_its_board_with_the_width_along_the_sheet_grain(doc, table):
    assert all(b.getGroupOfProperty("Grain") == "FabGuide" and b.Grain == "Free" for b in design.boxes(table))
    assert box(doc, "shelf").getEnumerationsOfProperty("Grain") == ["Free", "X", "Y", "Z"]
    table.MasterBoards[0].Grain = "Along width"
    box(doc, "shelf").Grain = "Y"  # across the shelf: its 260 mm along the sheet's grain
    box(doc, "left").Grain = "Z"  # up the leg
    doc.recompute()
    assert not table.Error, table.Status
    assert placed(table, "shelf") == (260, 260) and placed(table, "left") == (400, 400)
    assert [p.get("grain") for p in design.parts_of(table)] == [None, "z", None, "y"]
    box(doc, "shelf").Grain = "X"
    doc.recompute()
    assert placed(table, "shelf") == (696, 696)


def test_a_grain_through_the_thickness_is_refused_with_the_box_named(doc, table):
    box(doc, "shelf").Grain = "Z"
    doc.recompute()
    assert table.Error
    assert table.Status == ("Design '{}': box 'shelf' grain: \"z\" runs across the board, through its 12 mm "
                            "thickness; choose an axis of its face (x or y) or \"free\"".format(table.Label))
    box(doc, "shelf").Grain = "Y"
    doc.recompute()
    assert not table.Error, table.Status


def test_grain_reads_from_a_file_and_is_kept_by_a_suggestion_and_reopening(doc, bookcase, tmp_path, source_dir):
    with open(os.path.join(source_dir, "tests", "data", "flatpack", "bookcase-1800.flatpack.json")) as f:
        data = json.load(f)
    grains = {p["id"]: p.get("grain") for p in data["parts"]}
    exported = design.flatpack(bookcase)
    assert {p["id"]: p.get("grain") for p in exported["parts"]} == grains
    assert exported["boards"][0]["grain"] == "width"
    assert fabguide_core.lay_out_design(exported)["usage"] == pytest.approx(bookcase.Usage)
    assert placed(bookcase, "side-left") == (1800, 1800)
    suggestions = fabguide_core.optimise(exported, seed=1, threads=2, time_limit=4)["suggestions"]
    assert suggestions
    doc.openTransaction("accept")
    design.apply_parts(bookcase, suggestions[0]["design"]["parts"])
    doc.recompute()
    doc.commitTransaction()
    assert {p["id"]: p.get("grain") for p in design.parts_of(bookcase)} == grains
    assert not bookcase.Error, bookcase.Status
    assert not entered(bookcase)
    again, obj = reopened(doc, tmp_path)
    try:
        assert {p["id"]: p.get("grain") for p in design.parts_of(obj)} == grains
        assert placed(obj, "side-left") == (1800, 1800)
    finally:
        FreeCAD.closeDocument(again.Name)


def test_an_offcut_master_board_of_cost_0_is_cut_before_new_sheets(doc, table):
    # The coffee table's sheet, and a leftover the maker has (Cost 0) as large as the table needs, listed after
    # it: the table is cut from the leftover and no sheet is bought.
    sheet = table.MasterBoards[0]
    assert sheet.Cost == 1 and master_board.as_problem_board(sheet)["cost"] == 1
    offcut = master_board.create(doc, 1220, 915, sheet.Thickness.Value, 1, sheet.Material, "offcut", cost=0)
    table.MasterBoards = [sheet, offcut]
    doc.recompute()
    laid = json.loads(table.LayoutJson)["layout"]
    used = [b["name"] for b in laid["boards"]]
    assert used == ["offcut"], used
    assert not table.Error, table.Status
    offcut.Cost = -1  # refused as it is typed
    assert offcut.Cost == 0


def test_renaming_a_board_keeps_its_constraints_and_deleting_one_says_which(doc):
    a, b, obj = two_boards(doc, 300)
    same = design.add_constraint(obj, "equal", "same length", Refs=["a.size.x", "b.size.x"])
    doc.recompute()
    a.Label = "Left side"
    b.Length = 320
    doc.recompute()
    assert not obj.Error, obj.Status
    assert a.Length.Value == pytest.approx(320) and same.Status == design.SATISFIED
    assert design.constraint_dict(same)["refs"] == ["Left side.size.x", "b.size.x"]
    doc.removeObject(b.Name)
    doc.recompute()  # no traceback: the design says what is wrong
    assert "constraint 'same length' refs: needs at least 2 references" in obj.Error, obj.Error
    assert obj.Status == obj.Error and same.Status.startswith("Broken: "), obj.Status


def test_a_range_takes_its_min_as_typed_and_names_a_min_above_its_max(doc):
    a, b, obj = two_boards(doc, 340)
    span = design.add_constraint(obj, "range", "a's length", Refs=["a.size.x"], Min=250, Max=350)
    doc.recompute()
    before = a.Length.Value
    for typed in (4, 40, 400):  # "400" as the property editor applies it, keystroke by keystroke
        span.Min = typed
    assert span.Min.Value == 400, "kept as typed, not cut at a keystroke"
    doc.recompute()
    said = r"Constraint 'a's length': its Min \(400[.0]* mm\) is more than its Max \(350[.0]* mm\)"  # user's decimals
    assert re.fullmatch(said, span.Error) and re.search(said, obj.Error) and a.Length.Value == before, obj.Error
    span.Max, span.Min = 500, 280
    doc.recompute()
    assert not obj.Error and not span.Error and span.Status == design.SATISFIED, obj.Status


def test_a_document_of_plain_numbers_opens_with_lengths(doc, tmp_path):
    a, b, obj = two_boards(doc, 340)
    span = design.add_constraint(obj, "range", "a's length", Refs=["a.size.x"], Min=250, Max=350)
    span.removeProperty("Min")  # as FabGuide saved a range before its bounds were lengths
    span.addProperty("App::PropertyFloat", "Min", "Constraint", "")
    span.Min = 250.0
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    again = FreeCAD.openDocument(path)
    try:
        span = again.getObjectsByLabel("a's length")[0]
        assert span.getTypeIdOfProperty("Min") == "App::PropertyDistance" and span.Min.Value == 250
        assert design.constraint_dict(span)["min"] == 250 and design.constraint_dict(span)["max"] == 350
    finally:
        FreeCAD.closeDocument(again.Name)
