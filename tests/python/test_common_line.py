"""Common-line cutting on shop cut lists generated from seeds (tests/gen/cutlists.py), kerf, trim and
spacing varied per seed: every layout judged by the independent layout checker (its parts, slid together, still a
kerf apart and inside the trim) and every DXF sheet by the independent cut-path checker
(tests/gen/cut_path_checker.py: every part's edge cut, none twice, nothing cut off the parts' edges), which is
itself shown to reject the files without common-line cutting and spoiled ones. The search is bounded by work
(--iterations)."""
import json
import os
import subprocess
import sys

import ezdxf
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "gen"))
sys.path.insert(0, os.path.join(HERE, "..", "bench"))
import cut_path_checker  # noqa: E402
import cutlists  # noqa: E402
import layout_check  # noqa: E402

# Seeds 0-11 give each kerf, trim, spacing and dogbone of varied() together once;
# FABGUIDE_COMMON_LINE_SEEDS=200 for a benchmark run.
SEEDS = range(int(os.environ.get("FABGUIDE_COMMON_LINE_SEEDS") or 12))


def varied(seed):
    problem = cutlists.problem(seed)
    problem["settings"].update({"cuts": "free", "kerf": [3.2, 0.2, 6.35, 0][seed % 4], "trim": [10, 0, 5][seed % 3],
                                "spacing": 0.5 if seed % 6 == 5 else 0, "dogbone": 6 if seed % 2 else 0})
    return problem


def cut(cli, problem, out, *options):
    out.mkdir(exist_ok=True)
    src = out / "job.pack.json"
    src.write_text(json.dumps(problem))
    run = subprocess.run([cli, "pack", str(src), "-o", str(out / "layout.json"), "--iterations", "3",
                          "--time-limit", "600", "--dxf", str(out), "--text-labels", *options],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run, json.loads((out / "layout.json").read_text())


def perimeters(layout):
    return sum(2 * (p["width"] + p["height"]) for p in layout["placements"])


@pytest.mark.parametrize("seed", SEEDS)
def test_a_line_two_parts_share_is_cut_once(fabguide_cli, tmp_path, seed):
    problem = varied(seed)
    kerf = problem["settings"]["kerf"]
    run, layout = cut(fabguide_cli, problem, tmp_path, "--common-line")
    s, boards = problem["settings"], layout["boards"]
    assert not layout_check.problems(layout, layout_check.demand_of_pack_problem(problem),
                                     lambda b: (boards[b]["width"], boards[b]["height"], s["trim"]),
                                     clearance=s["kerf"] + s["spacing"])
    shared = 0.0
    for board in range(len(layout["boards"])):
        sheet = str(tmp_path / "sheet-{}.dxf".format(board + 1))
        found = cut_path_checker.problems(layout, board, kerf, sheet)
        assert not found, "seed {} sheet {}: {}".format(seed, board + 1, found[:5])
        shared += cut_path_checker.shared_length(cut_path_checker.part_edges(layout, board, kerf))
    # The layout's figures agree with what the checker measures on the parts.
    assert layout["common_line"] == pytest.approx(shared, abs=0.01 * len(layout["placements"]))
    assert layout["cut_length"] == pytest.approx(perimeters(layout) - shared, abs=0.01 * len(layout["placements"]))
    if problem["settings"]["spacing"] > 0:
        assert shared == 0  # parts more than a kerf apart share nothing
    else:
        assert shared > 0, "cut lists of 80-400 parts lay some side by side"
        assert "common line" in run.stdout


def test_the_checker_rejects_lines_cut_twice_edges_left_uncut_and_stray_cuts(fabguide_cli, tmp_path):
    problem = varied(0)
    kerf = problem["settings"]["kerf"]
    _, layout = cut(fabguide_cli, problem, tmp_path / "twice")  # without common-line cutting
    sheet = str(tmp_path / "twice" / "sheet-1.dxf")
    assert any("cut twice" in p for p in cut_path_checker.problems(layout, 0, kerf, sheet))
    assert not cut_path_checker.problems(layout, 0, kerf, sheet, once=False)

    _, layout = cut(fabguide_cli, problem, tmp_path / "once", "--common-line")
    sheet = str(tmp_path / "once" / "sheet-1.dxf")
    doc = ezdxf.readfile(sheet)
    opened = [e for e in doc.modelspace().query('LWPOLYLINE[layer=="OUTER_CUT"]') if not e.closed]
    assert opened, "common-line cutting leaves open paths"
    doc.modelspace().delete_entity(opened[0])
    doc.saveas(str(tmp_path / "missing.dxf"))
    assert any("is not cut" in p for p in cut_path_checker.problems(layout, 0, kerf, str(tmp_path / "missing.dxf")))

    doc = ezdxf.readfile(sheet)
    moved = doc.modelspace().query('LWPOLYLINE[layer=="OUTER_CUT"]')[0]
    moved.set_points([(x + 0.1, y) for x, y, *_ in moved.get_points()])
    doc.saveas(str(tmp_path / "moved.dxf"))
    found = cut_path_checker.problems(layout, 0, kerf, str(tmp_path / "moved.dxf"))
    assert any("on no part's edge" in p for p in found) and any("is not cut" in p for p in found)


def test_as_designed_files_refuse_common_line_cutting(fabguide_cli, tmp_path):
    src = tmp_path / "job.pack.json"
    src.write_text(json.dumps(varied(0)))
    run = subprocess.run([fabguide_cli, "pack", str(src), "-o", str(tmp_path / "layout.json"), "--common-line",
                          "--as-designed"], capture_output=True, text=True)
    assert run.returncode != 0 and "--as-designed" in run.stderr and "--common-line" in run.stderr
