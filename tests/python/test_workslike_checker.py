"""Unit tests of the independent works-like checker on tiny hand-made models whose answers are known."""
import copy
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import workslike_checker as W  # noqa: E402


def part(name, *cuboids):
    return {"name": name, "cuboids": [dict(c) for c in cuboids]}


def box(name, lo, hi, cavity=False):
    c = {"name": name, "min": list(lo), "max": list(hi)}
    if cavity:
        c["cavity"] = True
    return c


def model(parts, joints=(), configurations=(), relationships=(), locks=()):
    return {"format": "fabguide.workslike", "version": 1, "minimum_size": 1, "parts": list(parts),
            "joints": list(joints), "configurations": list(configurations), "relationships": list(relationships),
            "locks": list(locks)}


def kinds(problems):
    return [p.split(":")[0] for p in problems]


# ---- interpenetration


def test_two_overlapping_boxes_fail():
    m = model([part("a", box("a", [0, 0, 0], [10, 10, 10])), part("b", box("b", [9, 0, 0], [20, 10, 10]))])
    problems = W.check(m)
    assert len(problems) == 1 and "interpenetration" in problems[0] and "overlap by 1 mm" in problems[0]


def test_touching_boxes_pass():
    m = model([part("a", box("a", [0, 0, 0], [10, 10, 10])), part("b", box("b", [10, 0, 0], [20, 10, 10])),
               part("c", box("c", [0, 0, 10], [20, 10, 12]))])
    assert W.check(m) == []


def test_overlap_below_the_tolerance_passes_above_fails():
    m = model([part("a", box("a", [0, 0, 0], [10, 10, 10])), part("b", box("b", [10 - 5e-5, 0, 0], [20, 10, 10]))])
    assert W.check(m) == []
    m["parts"][1]["cuboids"][0]["min"][0] = 10 - 3.3e-4
    assert len(W.check(m)) == 1


def cabinet_with_drawer(drawer_hi_x=90):
    carcass = part("carcass", box("carcass", [0, 0, 0], [100, 100, 60]),
                   box("bay", [10, 0, 10], [90, 90, 50], cavity=True))
    drawer = part("drawer", box("drawer front", [10, -5, 10], [drawer_hi_x, 0, 50]),
                  box("drawer tray", [10, 0, 10], [drawer_hi_x, 90, 50]))
    fit = {"type": "fit_inside", "name": "drawer in its bay", "inner": ["drawer"], "enclosing": "carcass",
           "cavity": "bay", "portion": ["drawer tray"]}
    return model([carcass, drawer], relationships=[fit])


def test_drawer_in_a_cavity_passes():
    assert W.check(cabinet_with_drawer()) == []


def test_drawer_wider_than_its_cavity_fails():
    """The print would cut the tray's room out of the wall (it fits there, as modelled), but the fit says it
    stays inside its bay; without the fit, the tray is in the wall."""
    m = cabinet_with_drawer(drawer_hi_x=92)
    assert any("fit inside 'drawer in its bay'" in p and "sticks out" in p for p in W.check(m))
    m["relationships"] = []
    assert any("interpenetration" in p and "drawer tray" in p for p in W.check(m))


def test_part_with_two_solids_keeps_a_cavity_to_its_own_solid():
    # the cleat is a second solid of the carcass inside the bay's box: it is material, the bay is cut from "carcass"
    m = cabinet_with_drawer()
    m["relationships"] = []  # no fit inside: no room cut for the tray
    m["parts"][0]["cuboids"].append(box("cleat", [10, 80, 10], [20, 90, 20]))
    problems = W.check(m)
    assert any("'drawer tray' and 'cleat'" in p or "'cleat' and 'drawer tray'" in p for p in problems), problems


# ---- posing


def door_model(angle):
    carcass = part("carcass", box("carcass", [0, 0, 0], [400, 300, 600]),
                   box("inside", [18, 0, 18], [382, 282, 582], cavity=True))
    door = part("door", box("door", [18, -18, 18], [382, 0, 582]))
    hinge = {"name": "door hinge", "type": "hinge", "part": "door", "edge": ["door.left", "door.near"]}
    return model([carcass, door], joints=[hinge], configurations=[{"name": "open", "poses": {"door hinge": angle}}])


def test_door_turned_minus_90_about_its_hinge_edge_lands_where_computed_by_hand():
    m = W.Model(door_model(-90))
    # turning -90 about +z through (x 18, y -18): (x, y) -> (18 + (y + 18), -18 - (x - 18))
    # x 18..382, y -18..0  ->  x 18..36, y -382..-18
    b = m.posed(m.cuboids["door"], "open").bbox
    assert b == ([18, -382, 18], [36, -18, 582])
    assert W.check(door_model(-90)) == []


def test_door_turned_plus_90_swings_into_the_carcass_and_fails():
    m = W.Model(door_model(90))
    # +90: (x, y) -> (18 - (y + 18), -18 + (x - 18)): x 0..18, y -18..346: through the carcass' side wall
    b = m.posed(m.cuboids["door"], "open").bbox
    assert b == ([0, -18, 18], [18, 346, 582])
    problems = W.check(door_model(90))
    assert any("interpenetration in 'open'" in p for p in problems)
    assert any(p.startswith("motion collision") and "door hinge" in p for p in problems)


def test_door_at_45_degrees_is_judged_on_turned_boxes():
    m = door_model(-45)
    m["parts"].append(part("post", box("post", [200, -200, 0], [220, -180, 600])))
    problems = W.check(m)  # the door's far end reaches (18 + 364 cos45, -18 - 364 sin45) = (275, -275)
    assert any("interpenetration in 'open'" in p and "'door' and 'post'" in p for p in problems), problems
    # beyond where the door stops (-60 degrees from its hinge, 200 mm out), never swept: clear
    m["parts"][-1]["cuboids"][0].update({"min": [110, -200, 0], "max": [125, -185, 600]})
    assert W.check(m) == []


def test_hinge_about_y_is_right_handed():
    flap = part("flap", box("flap", [0, 0, 0], [10, 50, 100]))
    hinge = {"name": "flap hinge", "type": "hinge", "part": "flap", "edge": ["flap.left", "flap.top"]}
    m = W.Model(model([flap], [hinge], [{"name": "down", "poses": {"flap hinge": 90}}]))
    # +90 about +y through (x 0, z 100) takes +z to +x: (x, z) -> (0 + (z - 100), 100 - (x - 0))
    assert m.posed(m.cuboids["flap"], "down").bbox == ([-100, 0, 90], [0, 50, 100])


def test_sliding_hinge_turns_then_slides():
    m = door_model(0)
    m["joints"][0].update({"type": "sliding_hinge", "axis": "y"})
    m["configurations"][0]["poses"] = {"door hinge": {"angle": 90, "offset": 40}}
    mm = W.Model(m)
    # +90 about (18, -18): x 0..18, y -18..346, then +40 along y
    assert mm.posed(mm.cuboids["door"], "open").bbox == ([0, 22, 18], [18, 386, 582])


def test_chain_applies_the_part_joint_then_its_base_joint():
    body = part("body", box("body", [0, 0, 0], [100, 100, 10]))
    tray = part("tray", box("tray", [0, -100, 10], [100, 0, 12]))
    stop = part("stop", box("stop", [40, -100, 12], [60, -95, 30]))
    joints = [{"name": "tray slide", "type": "slide", "part": "tray", "axis": "y"},
              {"name": "stop hinge", "type": "hinge", "part": "stop", "base": "tray",
               "edge": ["stop.near", "stop.bottom"]}]
    m = W.Model(model([body, tray, stop], joints, [{"name": "in", "poses": {"tray slide": 100, "stop hinge": 90}}]))
    # the stop turns +90 about x through (y -100, z 12): (y, z) -> (-100 - (z - 12), 12 + (y + 100))
    # y -100..-95, z 12..30 -> y -118..-100, z 12..17; then the tray's slide: +100 along y
    assert m.posed(m.cuboids["stop"], "in").bbox == ([40, -18, 12], [60, 0, 17])


def test_double_pivot_pose_and_link_length():
    bed = part("bed", box("bed", [0, 0, 0], [100, 200, 30]))
    board = part("board", box("board", [0, 200, 0], [100, 210, 100]))
    pivot = {"name": "pivot", "type": "double_pivot", "part": "board", "base": "bed",
             "pivot": ["board.left", [0, 205, 50]], "base_pivot": ["bed.left", [0, 150, 20]]}
    # +90 about x through (y 150, z 100): (y, z) -> (150 - (z - 100), 100 + (y - 150))
    config = {"name": "folded", "poses": {"pivot": {"angle": 90, "pole": [0, 150, 100]}}}
    m = model([bed, board], [pivot], [config])
    mm = W.Model(m)
    assert mm.posed(mm.cuboids["board"], "folded").bbox == ([0, 150, 150], [100, 250, 160])
    # the pivot (205, 50) goes to (200, 155): 135.1 from the base pivot, but the link is 62.6 long
    problems = W.check(m)
    assert any("double pivot 'pivot'" in p and "link" in p for p in problems), problems
    # a base pivot on the perpendicular bisector of the pivot's two places (here: the pole) keeps the link
    m["joints"][0]["base_pivot"] = ["bed.left", [0, 150, 100]]
    problems = W.check(m)
    assert not any("link" in p for p in problems), problems
    assert any("lies off bed.left" in p for p in problems), problems


# ---- relationships


def lid_on_body(gap=0.0, lid_x=(0, 100), just=False):
    body = part("body", box("body", [0, 0, 0], [100, 60, 40]), box("well", [5, 5, 5], [95, 55, 40], cavity=True))
    lid = part("lid", box("lid", [lid_x[0], 0, 40 + gap], [lid_x[1], 60, 45 + gap]))
    cover = {"type": "cover", "name": "lid covers the well", "covering": ["lid"], "covered": ["body"],
             "just": just}
    return model([body, lid], relationships=[cover])


def test_cover_exact_passes():
    assert W.check(lid_on_body()) == []


def test_cover_with_a_gap_fails():
    problems = W.check(lid_on_body(gap=3))
    assert len(problems) == 1 and "not in one plane" in problems[0], problems


def test_cover_too_small_fails_and_just_cover_too_big_fails():
    small = W.check(lid_on_body(lid_x=(10, 100)))
    assert any("left bare" in p for p in small), small  # the well starts at x 5
    big = W.check(lid_on_body(just=True))
    assert any("reaches past" in p for p in big), big  # the lid is 100 wide, the well 90


def test_cover_pairs_as_written_and_a_dropped_covering_part():
    m = lid_on_body()
    m["parts"].append(part("knob", box("knob", [40, 20, 45], [60, 40, 55])))
    m["relationships"][0]["covering"].append("knob")
    m["relationships"][0]["pairs"] = [["lid.bottom", "well.top"]]
    problems = W.check(m)
    assert problems == ["cover 'lid covers the well' (as modelled): covering part 'knob' has no face in the "
                        "cover's pairs (dropped)"]


def desk(leg_tops=(720, 720, 720, 720), leg_bottoms=(0, 0, 0, 0), pairs=True):
    legs = [part("leg %d" % (i + 1), box("leg %d" % (i + 1), [x, y, leg_bottoms[i]], [x + 40, y + 40, leg_tops[i]]))
            for i, (x, y) in enumerate([(0, 0), (1160, 0), (0, 560), (1160, 560)])]
    top = part("top", box("top", [0, 0, 720], [1200, 600, 745]))
    support = {"type": "support", "name": "legs hold the top", "supporting": ["leg %d" % i for i in range(1, 5)],
               "supported": ["top"]}
    if pairs:
        support["pairs"] = [["leg %d.top" % i, "top.bottom"] for i in range(1, 5)]
    return model(legs + [top], relationships=[support])


def test_support_passes_when_every_leg_reaches_the_top():
    assert W.check(desk()) == []
    assert W.check(desk(pairs=False)) == []


def test_support_short_leg_and_leg_on_another_ground_fail():
    problems = W.check(desk(leg_tops=(720, 717, 720, 720)))
    assert any("leg 2.top at 717" in p for p in problems), problems
    problems = W.check(desk(leg_bottoms=(0, 0, 2, 0)))
    assert any("one ground" in p for p in problems), problems


def test_support_sunk_leg_is_reported_by_the_inferred_pairs_and_the_overlap():
    problems = W.check(desk(leg_tops=(720, 723, 720, 720), pairs=False))
    assert any("'leg 2' is in no pair (dropped)" in p for p in problems), problems
    assert any("interpenetration" in p for p in problems), problems


def test_fit_inside_just_apart_flush_geometric():
    m = cabinet_with_drawer()
    fit = m["relationships"][0]
    fit["just"] = [["drawer tray.left", "bay.left"], ["drawer tray.far", "bay.far"]]
    fit["apart"] = []
    m["relationships"] += [
        {"type": "flush", "name": "front flush", "faces": ["drawer front.far", "carcass.near"]},
        {"type": "geometric", "name": "front as wide as the tray", "left": "drawer front.width",
         "right": [{"quantity": "drawer tray.width", "times": 1}], "offset": 0},
        {"type": "geometric", "name": "tray below the top", "relation": "at_most", "left": "drawer tray.top",
         "right": "carcass.top", "offset": -10}]
    assert W.check(m) == []
    m["relationships"][-1]["offset"] = -11
    m["relationships"][1]["faces"] = ["drawer front.near", "carcass.near"]
    fit["just"].append(["drawer tray.right", "carcass.right"])
    problems = W.check(m)
    assert len(problems) == 3 and {"geometric 'tray below the top' (as modelled)", "flush 'front flush' (as modelled)",
                                   "fit inside 'drawer in its bay' (as modelled)"} == set(kinds(problems))


# ---- openings, walls, locks


def test_a_tray_standing_in_a_box_does_not_close_the_tray_compartments():
    box_part = part("box", box("box", [0, 0, 0], [100, 100, 60]), box("inside", [5, 5, 5], [95, 95, 60], cavity=True))
    tray = part("tray", box("tray", [5, 5, 5], [95, 95, 30]), box("compartment", [8, 8, 8], [92, 92, 30], cavity=True))
    upper = part("upper", box("upper", [5, 5, 30], [95, 95, 50]))  # rests on the tray: touches, does not close
    fit = {"type": "fit_inside", "name": "trays in the box", "inner": ["tray", "upper"], "enclosing": "box",
           "cavity": "inside"}
    m = model([box_part, tray, upper], relationships=[fit])
    assert W.check(m) == []
    m["parts"][2]["cuboids"][0]["min"][2] = 29  # sunk 1 mm into the tray: into its rim, a skin in its compartment
    problems = W.check(m)
    assert any(p.startswith("opening closed: 'upper'") and "compartment.top" in p for p in problems), problems
    assert any("interpenetration" in p and "'tray' and 'upper'" in p for p in problems), problems
    assert not any("inside.top" in p for p in problems), problems  # both belong in the box's cavity


def test_opening_sealed_by_a_skin_of_the_solid_fails():
    original = cabinet_with_drawer()
    solved = copy.deepcopy(original)
    solved["parts"][0]["cuboids"][1]["min"][1] = 1  # the bay's mouth now 1 mm behind the carcass' face
    solved["parts"][1]["cuboids"][1]["min"][1] = 1
    problems = W.check(solved, original)
    assert any(p.startswith("opening sealed: bay.near lies 1 mm inside carcass.near") for p in problems), problems


def test_a_door_skin_sunk_behind_an_opening_closes_it():
    m = door_model(-90)
    m["parts"][1]["cuboids"][0].update({"min": [18, -17, 18], "max": [382, 1, 582]})
    m["relationships"] = [{"type": "cover", "name": "door covers", "covering": ["door"], "covered": ["carcass"],
                           "pairs": [["door.far", "inside.near"]], "just": True}]
    problems = W.check(m)
    assert any(p.startswith("opening closed: 'door'") for p in problems), problems
    assert any("not in one plane" in p for p in problems), problems


def test_thin_wall_fails():
    original = cabinet_with_drawer()
    solved = copy.deepcopy(original)
    solved["parts"][0]["cuboids"][1]["max"][1] = 99.5  # the back wall 0.5 mm
    problems = W.check(solved, original)
    assert any(p.startswith("thin wall: bay.far leaves 0.5 mm") for p in problems), problems
    solved["parts"][0]["cuboids"][1]["max"][1] = 100
    problems = W.check(solved, original)
    assert any(p.startswith("thin wall: bay.far leaves 0 mm") for p in problems), problems


def test_lock_residue_is_reported():
    original = cabinet_with_drawer()
    original["locks"] = ["carcass.right"]
    solved = copy.deepcopy(original)
    solved["parts"][0]["cuboids"][0]["max"][0] = 100 + 3.3e-7
    problems = W.check(solved, original)
    assert len(problems) == 1 and "lock 'carcass.right' moved by 3.3e-07" in problems[0] and "residue" in problems[0]


def test_missing_relationship_in_the_solved_file_is_reported():
    original = cabinet_with_drawer()
    solved = copy.deepcopy(original)
    solved["relationships"] = []
    assert W.check(solved, original) == ["relationship 'drawer in its bay' is missing from the solved model"]


# ---- motion


def test_a_door_swings_open_before_a_tray_slides_out():
    """Motions turn in the first half of the way, slide in the second (docs/formats.md): the tray comes out of
    the bay after the door has swung clear."""
    m = door_model(-90)
    m["parts"].append(part("tray", box("tray", [100, 20, 100], [300, 280, 120])))
    m["joints"].append({"name": "tray slide", "type": "slide", "part": "tray", "axis": "y"})
    m["configurations"][0]["poses"]["tray slide"] = -250
    m["relationships"] = [{"type": "fit_inside", "name": "tray inside", "inner": ["tray"], "enclosing": "carcass",
                           "cavity": "inside"}]
    warnings = []
    assert W.check(m, warnings=warnings) == [] and warnings == []
    m["configurations"][0]["poses"]["door hinge"] = -30  # ajar: the tray hits it
    assert any(p.startswith("motion collision") and "'door' and 'tray'" in p for p in W.check(m))


def test_two_parts_turning_at_once_collide_only_as_a_warning():
    """Two doors that meet, both swinging open: print-in-place bevels each by the other's path."""
    carcass = part("carcass", box("carcass", [0, 0, 0], [400, 300, 600]),
                   box("inside", [18, 0, 18], [382, 282, 582], cavity=True))
    left = part("left", box("left", [18, -18, 18], [200, 0, 582]))
    right = part("right", box("right", [200, -18, 18], [382, 0, 582]))
    hinges = [{"name": "left hinge", "type": "hinge", "part": "left", "edge": ["left.left", "left.far"]},
              {"name": "right hinge", "type": "hinge", "part": "right", "edge": ["right.right", "right.far"]}]
    m = model([carcass, left, right], hinges, [{"name": "in", "poses": {"left hinge": 90, "right hinge": -90}}])
    warnings = []
    assert W.check(m, warnings=warnings) == []
    assert any("'left' and 'right'" in w for w in warnings), warnings


def test_a_slide_through_a_wall_is_a_problem_on_the_way():
    m = cabinet_with_drawer()
    # the drawer slides along x from the bay into the side wall and beyond, ending clear of the carcass
    m["joints"] = [{"name": "drawer slide", "type": "slide", "part": "drawer", "axis": "x"}]
    m["configurations"] = [{"name": "away", "poses": {"drawer slide": 200}}]
    m["relationships"] = []  # no fit inside: nothing cuts its way
    problems = W.check(m)
    assert any(p.startswith("motion collision") and "drawer slide" in p for p in problems), problems


def test_print_in_place_cuts_the_room_a_fit_inside_sweeps_and_no_more():
    """A fit inside the enclosing part's box (no cavity): the print cuts what the inner parts sweep on the way
    to the fit's configuration. Measured in 'away', the tray's way out through the wall is cut;
    measured as modelled, only the tray's place is, and its way out through the wall is a collision."""
    m = cabinet_with_drawer()
    m["joints"] = [{"name": "drawer slide", "type": "slide", "part": "drawer", "axis": "x"}]
    m["configurations"] = [{"name": "away", "poses": {"drawer slide": 200}}, {"name": "back", "poses": {"drawer slide": -200}}]
    fit = {"type": "fit_inside", "name": "drawer in", "inner": ["drawer"], "enclosing": "carcass", "configuration": "away"}
    m["relationships"] = [fit]
    problems = W.check(m)
    assert not [p for p in problems if "'away'" in p and ("interpenetration" in p or "motion" in p)], problems
    assert any("motion collision" in p and "'back'" in p for p in problems), problems  # the other way: no room
    del fit["configuration"]
    assert any("motion collision" in p and "'away'" in p for p in W.check(m))


def test_the_room_of_a_part_carried_by_the_enclosing_part_is_cut_in_its_frame():
    """A rack in a pull-out that slides out: the rack's room is where it goes in the pull-out, not its path."""
    carcass = part("carcass", box("carcass", [0, 0, 0], [100, 100, 100]),
                   box("bay", [10, 0, 10], [90, 90, 90], cavity=True))
    pull = part("pull-out", box("pull-out", [12, 0, 12], [88, 88, 60]))  # solid: the print cuts the rack's room
    rack = part("rack", box("rack", [20, 10, 50], [80, 80, 79]))  # drawn lifted
    joints = [{"name": "out", "type": "slide", "part": "pull-out", "axis": "y"},
              {"name": "lift", "type": "slide", "part": "rack", "axis": "z", "base": "pull-out"}]
    fit = {"type": "fit_inside", "name": "rack in", "inner": ["rack"], "enclosing": "pull-out", "configuration": "down"}
    configurations = [{"name": "down", "poses": {"lift": -20}}, {"name": "out", "poses": {"out": -95}}]
    m = model([carcass, pull, rack], joints, configurations, [fit])
    assert W.check(m) == []
    room = W.rooms(W.Model(m), 1e-4)[("rack", "pull-out")]
    assert [(lo, hi) for lo, hi, _ in room] == [([20, 10, 30], [80, 80, 79])]  # lowered in it, not carried out




@pytest.mark.parametrize("angle", [30, 45, 60, 135])
def test_turned_box_in_a_cavity_is_not_an_overlap(angle):
    frame = part("frame", box("frame", [0, 0, 0], [100, 100, 100]),
                 box("room", [10, 10, 10], [90, 90, 90], cavity=True))
    stick = part("stick", box("stick", [45, 45, 20], [55, 55, 80]))
    turn = {"name": "turn", "type": "hinge", "part": "stick", "edge": ["stick.left", "stick.near"]}
    m = model([frame, stick], [turn], [{"name": "turned", "poses": {"turn": angle}}])
    assert W.check(m) == []
    m["configurations"][0]["poses"]["turn"] = angle + 180  # round the other way: still inside
    assert W.check(m) == []


def test_cover_intent_read_from_the_drawing():
    body = part("body", box("body", [0, 0, 0], [200, 60, 40]), box("well a", [5, 5, 5], [95, 55, 40], cavity=True),
                box("well b", [105, 5, 5], [195, 55, 40], cavity=True))
    lid = part("lid", box("lid", [0, 0, 47], [200, 60, 52]))  # 7 mm above: beyond the 5 mm cover distance
    original = model([body, lid], relationships=[{"type": "cover", "name": "lid covers the wells",
                                                  "covering": ["lid"], "covered": ["body"]}])
    solved = copy.deepcopy(original)
    solved["parts"][1]["cuboids"][0].update({"min": [0, 0, 40], "max": [100, 60, 45]})  # only over well a
    solved["relationships"][0]["pairs"] = [["lid.bottom", "well a.top"]]
    assert W.check(solved) == []  # as written, it holds
    problems = W.check(solved, original)
    assert len(problems) == 1 and "well b.top" in problems[0] and "left bare" in problems[0], problems


# ---- every part one piece


def test_a_part_drawn_in_pieces_fails_and_joined_passes():
    m = cabinet_with_drawer()
    tray = m["parts"][1]["cuboids"][1]
    tray["min"][1] = 0.5  # a hair behind its front
    assert any("'drawer' is in 2 pieces" in p and "0.5 mm apart" in p for p in W.check(m))
    tray["min"][1] = 0
    assert W.check(m) == []


def test_a_cavity_cutting_its_cuboid_in_two_fails():
    m = model([part("shelf", box("shelf", [0, 0, 0], [100, 50, 20]), box("slot", [40, 0, 0], [60, 50, 10], cavity=True))])
    assert W.check(m) == []  # a notch from below: still one piece
    m["parts"][0]["cuboids"][1]["max"][2] = 20
    assert any("cavity 'slot' cuts 'shelf' in two" in p for p in W.check(m))
