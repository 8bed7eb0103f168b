"""The independent flat-pack checker (flatpack_checker.py) on tiny hand-made cases: a three-board shelf in 12 mm
ply on a 1000 x 600 sheet, a suggestion worked out by hand, and that suggestion broken one way at a time. They are
written in format version 1 (boxes by position and size), which the checker and FabGuide still read."""
import copy
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flatpack_checker as C  # noqa: E402

BOARD = {"name": "ply 12", "material": "birch plywood", "width": 1000, "height": 600, "thickness": 12, "count": 2}


def original():
    return {
        "format": "fabguide.flatpack", "version": 1, "title": "tiny shelf",
        "settings": {"resolution": 0.5, "kerf": 0.2, "spacing": 3, "trim": 5, "min_length": 40},
        "boards": [dict(BOARD)],
        "parts": [
            {"id": "left", "position": [0, 0, 0], "size": [12, 250, 400]},
            {"id": "right", "position": [288, 0, 0], "size": [12, 250, 400]},
            {"id": "top", "position": [0, 0, 400], "size": [300, 250, 12]},
            {"id": "shelf", "position": [12, 0, 150], "size": [276, 240, 12]},
        ],
        "constraints": [
            {"kind": "ground", "parts": ["left", "right"], "level": 0},
            {"kind": "equal", "refs": ["left.size.z", "right.size.z"]},
            {"kind": "symmetric", "refs": ["left.centre.x", "right.centre.x"], "about": "top.centre.x"},
            {"kind": "range", "ref": "top.max.z", "min": 380, "max": 450, "name": "height"},
            {"kind": "range", "ref": "top.size.x", "min": 250, "max": 360},
        ],
        "inner_volumes": [{"name": "box", "on": "shelf", "position": [20, 10, 162], "size": [200, 200, 150]}],
        "outer_volume": {"min": [-10, -10, 0], "max": [400, 300, 500]},
    }


def suggestion():
    d = original()
    d["parts"] = [
        {"id": "left", "position": [0, 0, 0], "size": [12, 250, 420]},
        {"id": "right", "position": [308, 0, 0], "size": [12, 250, 420]},
        {"id": "top", "position": [0, 0, 420], "size": [320, 250, 12]},
        {"id": "shelf", "position": [12, 0, 150], "size": [296, 240, 12]},
    ]
    d["usage"] = 0.9
    return d


def layout():
    """By hand: material width is the first long axis (x before y before z); 3.2 mm apart, 5 mm from the edges."""
    return {
        "format": "fabguide.layout", "version": 1, "boards": [dict(BOARD, grain="none")],
        "placements": [
            {"part": "left", "board": 0, "x": 5, "y": 5, "rotation": 0, "width": 250, "height": 420},
            {"part": "right", "board": 0, "x": 260, "y": 5, "rotation": 0, "width": 250, "height": 420},
            {"part": "top", "board": 0, "x": 515, "y": 5, "rotation": 0, "width": 320, "height": 250},
            {"part": "shelf", "board": 0, "x": 515, "y": 260, "rotation": 0, "width": 296, "height": 240},
        ],
    }


def entry(sheets=1, waste=0.239):
    return {"sheets": sheets, "waste_m2": waste, "usage_after": 0.9, "usage": 0.9}


BEFORE = {"sheets": 1, "waste_m2": 0.259, "usage": 0.85}


def check(sugg=None, lay=None, orig=None, summary=None, before=None):
    return C.check_suggestion(orig or original(), sugg or suggestion(), lay or layout(), summary or entry(),
                              before or BEFORE, reload=False)


def part(design, pid):
    return next(p for p in design["parts"] if p["id"] == pid)


def placement(lay, pid):
    return next(p for p in lay["placements"] if p["part"] == pid)


def test_the_hand_made_suggestion_passes():
    assert check() == []


def test_the_original_satisfies_its_own_constraints():
    d = original()
    assert C.constraint_problems(d, d) == []


def test_overlapping_parts_fail():
    lay = layout()
    placement(lay, "right").update(x=200)  # left spans x 5..255
    problems = check(lay=lay)
    assert any(p.startswith("overlapping parts on board 0") and "left" in p and "right" in p for p in problems)


def test_kerf_gap_too_small_fails():
    lay = layout()
    placement(lay, "right").update(x=257)  # 2 mm from left, kerf + spacing is 3.2
    problems = check(lay=lay)
    assert any(p.startswith("gap too small") and "2 mm apart" in p and "3.2" in p for p in problems), problems
    placement(lay, "right").update(x=258.2)  # exactly kerf + spacing: fine
    assert check(lay=lay) == []


def test_part_outside_the_trimmed_board_fails():
    lay = layout()
    placement(lay, "left").update(x=2)  # trim is 5
    assert any("trimmed by 5" in p for p in check(lay=lay))
    lay = layout()
    placement(lay, "shelf").update(board=0, y=357)  # 357 + 240 = 597 > 600 - 5
    assert any("not inside board 0" in p for p in check(lay=lay))


def test_wrong_quantity_fails():
    lay = layout()
    lay["placements"].pop()
    assert any(p.startswith("quantity: shelf laid out 0 times") for p in check(lay=lay))
    sugg, orig = suggestion(), original()
    part(sugg, "shelf")["quantity"] = 2
    part(orig, "shelf")["quantity"] = 2
    lay = layout()
    lay["placements"].append({"part": "shelf", "board": 0, "x": 5, "y": 430, "rotation": 90, "width": 240,
                              "height": 296})  # 430 + 296 > 595: also outside, but the count is right
    problems = check(sugg=sugg, orig=orig, lay=lay)
    assert not any(p.startswith("quantity") for p in problems)


def test_part_size_not_the_suggestions_board_fails():
    lay = layout()
    placement(lay, "top").update(width=300)  # the suggestion's top is 320 wide
    assert any("laid out 300 x 250" in p and "320 x 250" in p for p in check(lay=lay))
    lay = layout()
    placement(lay, "shelf").update(rotation=90)  # turned, but width and height not swapped
    assert any("rotation 90" in p for p in check(lay=lay))


def test_follow_grain_across_the_grain_fails():
    orig, sugg, lay = original(), suggestion(), layout()
    for d in (orig, sugg):
        part(d, "top")["follow_grain"] = True  # its first long axis, x
    lay["boards"][0]["grain"] = "height"  # unturned, the top's length (x) runs across the sheet's grain
    assert any("grain runs across" in p and "(top)" in p for p in check(orig=orig, sugg=sugg, lay=lay))
    lay["boards"][0]["grain"] = "width"
    assert check(orig=orig, sugg=sugg, lay=lay) == []


def test_broken_equal_constraint_fails():
    sugg = suggestion()
    part(sugg, "right")["size"][2] = 410  # right side no longer as tall as the left (and off the top)
    problems = check(sugg=sugg)
    assert any(p.startswith("constraints[1] equal") and "broken" in p for p in problems), problems


def test_broken_range_and_symmetry_fail():
    sugg = suggestion()
    for pid in ("left", "right"):
        part(sugg, pid)["size"][2] = 460
    part(sugg, "top")["position"][2] = 460  # top.max.z 472 > 450
    problems = check(sugg=sugg)
    assert any(p.startswith("constraints[3] range 'height' broken") for p in problems), problems
    sugg = suggestion()
    part(sugg, "top")["position"][0] = 10  # sides no longer symmetric about the top's centre
    part(sugg, "top")["size"][0] = 310
    problems = check(sugg=sugg)
    assert any(p.startswith("constraints[2] symmetric") for p in problems), problems


def test_broken_ground_and_below_ground_fail():
    sugg = suggestion()
    for p in sugg["parts"]:
        p["position"][2] -= 5
    problems = check(sugg=sugg)
    assert any(p.startswith("constraints[0] ground") for p in problems)
    assert any(p.startswith("below ground: left.min.z = -5") for p in problems)


def test_snap_broken_fails():
    sugg = suggestion()
    part(sugg, "top")["position"][2] = 425  # a 5 mm gap above the sides
    problems = check(sugg=sugg)
    assert any(p.startswith("snap setting") and "no longer touch along z" in p for p in problems), problems


def test_inner_volume_moves_with_its_board_and_must_stay_free():
    sugg = suggestion()
    part(sugg, "shelf")["position"][2] = 250  # the box (150 tall) now reaches z 412 > the top at 420? no: 262..412
    assert not any("inner volume" in p for p in check(sugg=sugg))
    part(sugg, "shelf")["position"][2] = 300  # 312..462: through the top
    problems = check(sugg=sugg)
    assert any(p.startswith("inner volume 'box' (on shelf) intruded by top") for p in problems), problems


def test_a_board_shrunk_from_under_its_inner_volume_fails():
    """The box, drawn 10 mm from the shelf's front edge and 200 mm deep, moves with that edge; the shelf
    may not shrink from under it."""
    sugg = suggestion()
    part(sugg, "shelf")["size"][1] = 209
    problems = check(sugg=sugg)
    assert any(p.startswith("inner volume 'box': off shelf by 1 mm on its upper side along y") for p in problems), \
        problems
    part(sugg, "shelf")["size"][1] = 210
    assert not any("off shelf" in p for p in check(sugg=sugg))


def test_suggestions_alike_to_a_maker_fail():
    first, second = suggestion(), suggestion()
    part(second, "shelf")["size"][0] += 9  # within 10 mm on every board
    assert C.alike_problems([first, second]) == ["suggestion 2: no board differs by 10 mm from suggestion 1"]
    part(second, "shelf")["size"][0] += 1
    assert C.alike_problems([first, second]) == []


def test_a_board_grown_out_of_its_role_fails():
    sugg = suggestion()
    part(sugg, "shelf")["size"][1] = 361  # 240 mm drawn: at most 1.5 times
    assert any(p.startswith("shelf grew along y from 240 to 361 mm, more than max_growth 1.5 times")
               for p in C.structure_problems(original(), sugg))
    part(sugg, "shelf")["size"][1] = 360
    assert not any("grew" in p for p in C.structure_problems(original(), sugg))


def test_outer_volume_fails():
    sugg = suggestion()
    for p in sugg["parts"]:
        p["position"][0] += 100  # right side reaches x 420 > 400
    assert any(p.startswith("outer volume: right.max.x") for p in check(sugg=sugg))


def test_new_interpenetration_fails_old_cross_halving_passes():
    orig, sugg = original(), suggestion()
    cross = {"id": "divider", "position": [150, 0, 162], "size": [12, 240, 100]}
    orig["parts"].append(dict(cross, position=[150, 0, 162]))
    sugg["parts"].append(dict(cross, position=[160, 0, 162]))
    orig["inner_volumes"] = []
    lay = layout()
    lay["placements"].append({"part": "divider", "board": 0, "x": 5, "y": 430, "rotation": 0, "width": 240,
                              "height": 100})
    summary = entry(waste=0.239 - 0.024)  # the divider's 240 x 100 is part area too
    assert check(orig=orig, sugg=sugg, lay=lay, summary=summary) == []
    # a halving slot across the shelf in the original: the divider and the shelf may overlap there
    part(orig, "divider")["position"][2] = 140
    part(sugg, "divider")["position"][2] = 140
    assert check(orig=orig, sugg=sugg, lay=lay, summary=summary) == []
    # but one sunk into the top is new
    part(sugg, "top")["position"][2] = 230
    problems = check(orig=orig, sugg=sugg, lay=lay, summary=summary)
    assert any(p.startswith("interpenetration: ") and "top" in p for p in problems), problems


def test_more_sheets_fails():
    lay = layout()
    lay["boards"].append(dict(BOARD, grain="none"))
    placement(lay, "shelf").update(board=1, x=5, y=5)
    problems = check(lay=lay, summary=entry(sheets=2))
    assert any(p.startswith("costs more: boards costing 2, 1 before") for p in problems), problems
    # and a summary that miscounts is caught too
    assert any(p.startswith("summary says 1 sheets") for p in check(lay=lay, summary=entry(sheets=1)))
    # an offcut already owned (cost 0) is no sheet bought
    lay["boards"][1]["cost"] = 0
    problems = check(lay=lay, summary=entry(sheets=1, waste=C.waste_of(lay)))
    assert not any(p.startswith(("costs more", "more sheets", "summary says")) for p in problems), problems


def test_more_waste_on_as_many_sheets_fails():
    problems = check(summary=entry(waste=0.3))
    assert any(p.startswith("wastes more") for p in problems)
    assert C.waste_of(layout()) == (1000 * 600 - 250 * 420 * 2 - 320 * 250 - 296 * 240) / 1e6


def test_unchanged_suggestion_fails():
    sugg = original()
    lay = layout()
    for pid, (w, h) in {"left": (250, 400), "right": (250, 400), "top": (300, 250), "shelf": (276, 240)}.items():
        placement(lay, pid).update(width=w, height=h)
    problems = check(sugg=sugg, lay=lay)
    assert "unchanged: the suggestion is the original design" in problems


def test_thickness_changed_or_parts_renamed_fail():
    sugg = suggestion()
    part(sugg, "top")["size"][2] = 15
    assert any("no longer 12 thick" in p for p in check(sugg=sugg))
    sugg = suggestion()
    sugg["parts"][0]["id"] = "side"
    assert check(sugg=sugg)[0].startswith("parts: ")


def test_a_part_on_a_board_of_another_thickness_fails():
    # A 6 mm back on the 6 mm board passes; laid on the 12 mm one it fails.
    thin = dict(BOARD, name="hardboard 6", thickness=6)
    orig, sugg, lay = original(), suggestion(), layout()
    for d in (orig, sugg):
        d["boards"].append(dict(thin))
        d["parts"].append({"id": "back", "position": [0, 250, 0], "size": [320, 6, 420]})
    back = {"part": "back", "board": 1, "x": 5, "y": 5, "rotation": 0, "width": 320, "height": 420}
    lay["boards"].append(dict(thin, grain="none"))
    lay["placements"].append(back)
    assert not any("thick" in p for p in check(orig=orig, sugg=sugg, lay=lay))
    back.update(board=0, x=515, y=510, height=80)
    assert any("a 6 mm part on board 0, 12 mm thick" in p for p in check(orig=orig, sugg=sugg, lay=lay))


def test_reload_refused_is_reported(fabguide_cli, tmp_path):
    good = copy.deepcopy(suggestion())
    assert C.reload_problems(good, fabguide_cli) == []
    bad = copy.deepcopy(good)
    part(bad, "right")["size"][2] = 410  # breaks its own "equal" constraint: the reader refuses it
    problems = C.reload_problems(bad, fabguide_cli)
    assert len(problems) == 1 and problems[0].startswith("reload refused: `fabguide optimise SUGGESTION` exits 1")
    assert C.reload_problems(good, fabguide_cli, cost=0) == ["reopened on boards that cost 1, found on 0"]
    assert C.check_suggestion(original(), good, layout(), entry(), BEFORE, cli=fabguide_cli) == []


def test_a_part_grain_axis_sets_its_material_width_and_must_follow_the_sheet():
    orig, sugg, lay = original(), suggestion(), layout()
    for d in (orig, sugg):
        part(d, "left")["grain"] = "z"  # vertical grain on the side: material width is its height, 420
    problems = check(orig=orig, sugg=sugg, lay=lay)  # laid 250 x 420 unturned: that is across its length
    assert any("laid out 250 x 420 (rotation 0), the board is 420 x 250" in p for p in problems), problems
    placement(lay, "left").update(rotation=90)  # turned: 250 x 420 as placed is right
    assert check(orig=orig, sugg=sugg, lay=lay) == []
    lay["boards"][0]["grain"] = "width"  # but on a sheet whose grain runs along x its grain is now across
    assert any("grain runs across" in p and "placement 0 (left)" in p for p in check(orig=orig, sugg=sugg, lay=lay))
    lay["boards"][0]["grain"] = "height"
    assert check(orig=orig, sugg=sugg, lay=lay) == []
    part(sugg, "left")["grain"] = "free"
    assert any("grain changed" in p for p in check(orig=orig, sugg=sugg, lay=lay))


def test_summary_waste_must_be_the_sheets_bought_less_the_parts():
    assert check(summary=entry(waste=0.23896)) == []
    problems = check(summary=entry(waste=0.2)) + check(summary=entry(waste=0.25))
    assert [p for p in problems if p.startswith("summary waste_m2")] == [
        "summary waste_m2 0.2000 is not the sheets bought less the parts, 0.2390 m2",
        "summary waste_m2 0.2500 is not the sheets bought less the parts, 0.2390 m2"]
