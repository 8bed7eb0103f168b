"""Guillotine layouts for a saw on shop cut lists generated from seeds (tests/gen/cutlists.py: kitchens
and wardrobes, two materials, grain on the fronts), with kerf, trim, spacing, stages and the first cut's direction
varied per seed; every layout judged by the independent saw checker (tests/gen/saw_checker.py), which is itself
shown to reject spoiled layouts. The search is bounded by work (--iterations), not by time."""
import copy
import csv
import json
import os
import random
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "gen"))
import cutlists  # noqa: E402
import saw_checker  # noqa: E402
import savable_designs  # noqa: E402

SEEDS = range(0, 150)


def varied(seed):
    """The cut list of `seed` with its settings varied the way shops set them."""
    problem = cutlists.problem(seed)
    problem["settings"].update({"kerf": [0, 3.2, 4.8][seed % 3], "trim": [10, 0][seed % 2],
                                "spacing": 1 if seed % 5 == 0 else 0,
                                "stages": [2, 3, 0, 1][seed % 4], "first_cut": ["any", "along", "across"][seed % 3]})
    return problem


def laid_out(cli, problem, tmp_path, *options, iterations=20):
    src, out = tmp_path / "cutlist.pack.json", tmp_path / "layout.json"
    src.write_text(json.dumps(problem))
    run = subprocess.run([cli, "pack", str(src), "-o", str(out), "--iterations", str(iterations), "--time-limit",
                          "600", *options], capture_output=True, text=True)
    return run, (json.loads(out.read_text()) if run.returncode == 0 else None)


@pytest.mark.parametrize("seed", SEEDS)
def test_a_shop_cut_list_comes_apart_by_its_listed_saw_cuts(fabguide_cli, tmp_path, seed):
    problem = varied(seed)
    run, layout = laid_out(fabguide_cli, problem, tmp_path)
    assert run.returncode == 0, run.stderr
    assert saw_checker.problems(layout, problem) == []
    assert len(layout["boards"]) >= saw_checker.least_sheets(problem)
    assert "saw cuts " in run.stdout


def small_bins(seed):
    """A two-dimensional bin-packing instance like Berkey & Wang's class I: 20-100 items of 1-10 x 1-10 in 10 x 10
    bins, not turned, no kerf: parts that fill whole pieces (a strip the width of the bin, a slab the width of its
    strip), which a saw makes no cut for."""
    rng = random.Random(seed)
    return {"format": "fabguide.pack", "version": 1,
            "settings": {"resolution": 1, "cuts": "guillotine", "stages": [1, 2, 3, 0][seed % 4],
                         "first_cut": ["any", "along", "across"][seed % 3]},
            "boards": [{"name": "bin", "width": 10, "height": 10, "count": -1}],
            "parts": [{"id": "item {}".format(k), "width": rng.randint(1, 10), "height": rng.randint(1, 10),
                       "orientations": [0]} for k in range(rng.choice([20, 40, 60, 80, 100]))]}


@pytest.mark.parametrize("seed", range(1, 6))
def test_boards_cut_from_whole_sheets_at_92_percent_go_back_on_those_sheets(fabguide_cli, tmp_path, seed):
    """The least designs of tests/gen/savable_designs.py at slack 0.96: 53-94 boards in two thicknesses, cut from
    4-6 whole sheets by construction and filling them to 92 %. One greedy fill per order left a sheet more on
    every one of them; the beam search finds the sheets they came from."""
    _, known = savable_designs.design(seed, slack=0.96)
    problem = savable_designs.least_pack_problem(known)
    run, layout = laid_out(fabguide_cli, problem, tmp_path, "--cuts", "guillotine", "--stages", "3", iterations=128)
    assert run.returncode == 0, run.stderr
    assert len(layout["boards"]) == known["saved"], run.stdout
    assert saw_checker.problems(layout, problem) == []


@pytest.mark.parametrize("seed", range(0, 60))
def test_small_bins_of_whole_pieces_are_numbered_by_the_cuts_made(fabguide_cli, tmp_path, seed):
    problem = small_bins(seed)
    run, layout = laid_out(fabguide_cli, problem, tmp_path)
    assert run.returncode == 0, run.stderr
    assert saw_checker.problems(layout, problem) == []


def test_the_command_line_chooses_the_cuts_over_the_file(fabguide_cli, tmp_path):
    problem = cutlists.problem(3)
    problem["settings"]["cuts"] = "free"
    run, layout = laid_out(fabguide_cli, problem, tmp_path, "--cuts", "guillotine", "--stages", "2",
                           "--first-cut", "across")
    assert run.returncode == 0, run.stderr
    problem["settings"].update({"cuts": "guillotine", "stages": 2, "first_cut": "across"})
    assert saw_checker.problems(layout, problem) == []
    first = [c for c in layout["saw_cuts"][0] if c["stage"] == 1][0]
    assert first["from"][0] == first["to"][0], "the first cuts run across the sheet (lines x = constant)"
    run, layout = laid_out(fabguide_cli, problem, tmp_path, "--cuts", "free")
    assert run.returncode == 0 and "saw_cuts" not in layout


def test_bad_cut_settings_and_a_part_too_long_are_named(fabguide_cli, tmp_path):
    for field, value in (("cuts", "bandsaw"), ("stages", -2), ("first_cut", "diagonal")):
        problem = cutlists.problem(0)
        problem["settings"][field] = value
        run, _ = laid_out(fabguide_cli, problem, tmp_path)
        assert run.returncode != 0 and "settings." + field in run.stderr, run.stderr
        assert "Traceback" not in run.stderr and "terminate" not in run.stderr
    problem = cutlists.problem(0)
    problem["parts"].append({"id": "worktop 3600x600", "width": 3600, "height": 600, "thickness": 18})
    run, _ = laid_out(fabguide_cli, problem, tmp_path)
    assert run.returncode != 0 and "worktop 3600x600" in run.stderr, run.stderr


def test_the_saw_checker_rejects_spoiled_layouts(fabguide_cli, tmp_path):
    problem = cutlists.problem(2)
    run, good = laid_out(fabguide_cli, problem, tmp_path)
    assert run.returncode == 0 and saw_checker.problems(good, problem) == []
    kerf = problem["settings"]["kerf"]

    def spoiled(change):
        layout = copy.deepcopy(good)
        change(layout)
        return saw_checker.problems(layout, problem)

    def drop_a_first_stage_cut(layout):
        cuts = layout["saw_cuts"][0]
        cuts.remove([c for c in cuts if c["stage"] == 1][0])

    def move_a_cut_into_its_part(layout):
        cut = [c for c in layout["saw_cuts"][0] if c["stage"] == 1][0]
        axis = 0 if cut["from"][0] == cut["to"][0] else 1
        cut["from"][axis] -= kerf
        cut["to"][axis] -= kerf

    def list_a_wrong_stage(layout):
        [c for c in layout["saw_cuts"][0] if c["stage"] == 2][0]["stage"] = 1

    assert any("shares its piece" in p or "not cut free" in p for p in spoiled(drop_a_first_stage_cut))
    assert any("cuts into a part" in p or "edge to edge" in p for p in spoiled(move_a_cut_into_its_part))
    assert any("listed stage" in p for p in spoiled(list_a_wrong_stage))
    one_stage = copy.deepcopy(problem)
    one_stage["settings"]["stages"] = 1
    assert any("past the limit" in p for p in saw_checker.problems(good, one_stage))
    spoiled_demand = copy.deepcopy(good)
    spoiled_demand["placements"].pop()
    assert any("placed" in p for p in saw_checker.problems(spoiled_demand, problem))


def test_the_cut_list_says_which_parts_follow_the_grain(fabguide_cli, tmp_path):
    problem = cutlists.problem(4)
    run, layout = laid_out(fabguide_cli, problem, tmp_path, "--csv", str(tmp_path / "cutlist.csv"))
    assert run.returncode == 0, run.stderr
    rows = list(csv.DictReader((tmp_path / "cutlist.csv").open()))
    follows = {p["id"]: p["follow_grain"] for p in problem["parts"]}
    assert rows and all((r["grain"] == "width") == follows[r["part"]] for r in rows)
    assert sum(int(r["quantity"]) for r in rows) == len(layout["placements"])
