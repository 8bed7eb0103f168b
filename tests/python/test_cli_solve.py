"""`fabguide solve` on the bundled works-like example, on a contradictory model and on malformed input."""
import json
import subprocess

import pytest


def solve(cli, *args):
    return subprocess.run([cli, "solve", *args], capture_output=True, text=True, timeout=60)


def test_example_solves_and_every_relationship_holds(fabguide_cli, source_dir, tmp_path):
    out = tmp_path / "solved.workslike.json"
    run = solve(fabguide_cli, source_dir + "/examples/box-with-lid.workslike.json", "-o", str(out))
    assert run.returncode == 0, run.stderr
    assert run.stdout.count("satisfied") == 10 and "part lid" in run.stdout
    solved = json.load(out.open())
    assert solved["report"]["solved"] and solved["report"]["violation"] < 1e-6
    cuboids = {c["name"]: c for p in solved["parts"] for c in p["cuboids"]}
    assert abs(cuboids["lid"]["min"][2] - cuboids["body"]["max"][2]) < 1e-6  # lid on the body
    assert cuboids["body"]["max"][2] == 50  # locked


def test_contradiction_exits_non_zero_naming_the_relationships(fabguide_cli, source_dir, tmp_path):
    model = json.load(open(source_dir + "/examples/box-with-lid.workslike.json"))
    model["relationships"].append({"type": "geometric", "name": "lid taller than the body", "relation": "at_most",
                                   "left": "body.height", "right": "lid.height"})
    model["relationships"].append({"type": "geometric", "name": "lid 5 thick", "left": "lid.height", "right": [],
                                   "offset": 5})
    model["locks"].append("body.bottom")  # the body cannot shrink to make room
    path = tmp_path / "bad.workslike.json"
    path.write_text(json.dumps(model))
    run = solve(fabguide_cli, str(path))
    assert run.returncode == 1
    for name in ("lid taller than the body", "lid 5 thick", "lock: body.top", "lock: body.bottom"):
        assert "'{}'".format(name) in run.stderr, run.stderr
    assert "CONFLICT" in run.stdout


def test_malformed_model_names_the_field(fabguide_cli, tmp_path):
    path = tmp_path / "bad.workslike.json"
    path.write_text(json.dumps({"parts": [{"name": "a", "cuboids": [{"min": [0, 0, 0], "max": [1, 1]}]}]}))
    run = solve(fabguide_cli, str(path))
    assert run.returncode == 1 and "parts[0].cuboids[0].max: must be [x, y, z]" in run.stderr


@pytest.mark.parametrize("command", [
    ["solve", "{src}/examples/box-with-lid.workslike.json", "-o", "out.json"],
    ["pack", "{src}/examples/bookshelf.pack.json", "-o", "layout.json", "--time-limit", "0.3", "--svg", "sheets"],
])
def test_bare_output_names_are_written_in_the_working_folder(fabguide_cli, source_dir, tmp_path, command):
    """`-o out.json` (no folder) is the commonest call; it failed with a filesystem error."""
    run = subprocess.run([fabguide_cli] + [a.format(src=source_dir) for a in command], cwd=str(tmp_path),
                         capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert (tmp_path / command[3]).is_file()
