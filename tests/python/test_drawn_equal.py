"""Boards drawn equal stay equal (functional growth only): `fabguide optimise --keep-drawn-equal` on the
suite's designs with posts, legs, rails and shelves drawn alike; every suggestion is judged by the independent
checker (flatpack_checker.py, drawn_equal_problems besides its every other check), itself shown to catch one rail
grown alone. The search is bounded by --rounds as well as time."""
import copy
import json
import os
import subprocess

import pytest

import flatpack_checker
from freecad.fabguide.core import fabguide_core

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "..", "data", "flatpack")
DESIGNS = ["bunk-bed", "laser-stool-6mm", "shop-shelving", "tv-bench"]


def load(path):
    with open(path) as f:
        return json.load(f)


def optimise(cli, path, out, seconds=3, rounds=2):
    return subprocess.run([cli, "optimise", str(path), "-o", str(out), "--seed", "1", "--threads", "2",
                           "--time-limit", str(seconds), "--rounds", str(rounds), "--keep-drawn-equal"],
                          capture_output=True, text=True, timeout=300)


@pytest.mark.parametrize("name", DESIGNS)
def test_boards_drawn_equal_stay_equal_in_every_suggestion(fabguide_cli, tmp_path, name):
    path = os.path.join(SUITE, name + ".flatpack.json")
    original = load(path)
    run = optimise(fabguide_cli, path, tmp_path)
    assert run.returncode == 0, run.stderr
    said = [line for line in run.stdout.splitlines() if line.startswith("kept equal")]
    assert said, "{}: its legs, rails or shelves are drawn alike".format(name)
    summary = load(tmp_path / "summary.json")
    before_layout = load(tmp_path / summary["before"]["layout"])
    problems = []
    for entry in summary["suggestions"]:
        suggestion = load(tmp_path / entry["file"])
        assert len(suggestion["constraints"]) == len(original.get("constraints", [])) + len(said)  # written in it
        found = flatpack_checker.check_suggestion(original, suggestion, load(tmp_path / entry["layout"]), entry,
                                                  summary["before"], cli=fabguide_cli,
                                                  suggestion_path=str(tmp_path / entry["file"]),
                                                  before_layout=before_layout)
        found += flatpack_checker.drawn_equal_problems(original, suggestion)
        problems += ["{}: {}".format(entry["file"], p) for p in found]
    assert problems == []


def test_a_design_holding_them_already_gets_none_again(fabguide_cli, tmp_path):
    design = load(os.path.join(SUITE, "bunk-bed.flatpack.json"))
    design["constraints"] += fabguide_core.drawn_equal(design)
    assert fabguide_core.drawn_equal(design) == []
    path = tmp_path / "held.flatpack.json"
    path.write_text(json.dumps(design))
    run = optimise(fabguide_cli, path, tmp_path / "out", seconds=0.5, rounds=1)
    assert run.returncode == 0 and "kept equal" not in run.stdout, run.stdout + run.stderr


def test_the_inferred_constraints_name_the_boards_and_sides():
    design = load(os.path.join(SUITE, "bunk-bed.flatpack.json"))
    sizes = {p["id"]: [hi - lo for lo, hi in zip(p["min"], p["max"])] for p in design["parts"]}
    inferred = fabguide_core.drawn_equal(design)
    rails = ["lower-rail-front", "lower-rail-back", "upper-rail-front", "upper-rail-back"]
    assert {"kind": "equal", "name": "drawn equal: size.x of " + ", ".join(rails),
            "refs": [r + ".size.x" for r in rails]} in inferred
    for c in inferred:  # boards alike on every side, not just on the one constrained
        boards = [r.rsplit(".", 2)[0] for r in c["refs"]]
        assert len(boards) >= 2 and all(sizes[b] == sizes[boards[0]] for b in boards), c


def test_the_checker_catches_a_rail_grown_alone():
    original = load(os.path.join(SUITE, "bunk-bed.flatpack.json"))
    spoiled = copy.deepcopy(original)
    rail = next(p for p in spoiled["parts"] if p["id"] == "upper-rail-back")
    rail["max"][0] += 50
    assert flatpack_checker.drawn_equal_problems(original, original) == []
    found = flatpack_checker.drawn_equal_problems(original, spoiled)
    assert len(found) == 1 and "upper-rail-back" in found[0], found
