"""tests/bench/same_outputs.py, which shows a refactor keeps behaviour: a case's hash is what it wrote (not when),
the same on a second run, and another when a file or the exit status differs."""
import json
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "bench"))
import same_outputs  # noqa: E402


def write(folder, files):
    for name, text in files.items():
        (folder / name).write_text(text)
    return str(folder)


def test_a_reports_time_is_left_out_and_its_figures_are_not(tmp_path):
    a, b, c = (tmp_path / n for n in "abc")
    for f in (a, b, c):
        f.mkdir()
    report = {"ok": True, "clearance": {"least_mm": 0.4}, "seconds": 3.2}
    first = same_outputs.digest(write(a, {"report.json": json.dumps(report)}), 0, "")
    assert same_outputs.digest(write(b, {"report.json": json.dumps(dict(report, seconds=9.9))}), 0, "") == first
    moved = dict(report, clearance={"least_mm": 0.39})
    assert same_outputs.digest(write(c, {"report.json": json.dumps(moved)}), 0, "") != first
    assert same_outputs.digest(str(a), 1, "") != first


@pytest.mark.parametrize("name", ["box-with-lid", "sliding-box"])
def test_a_solve_hashes_alike_twice_and_not_like_another_model(name):
    build = os.environ["FABGUIDE_BUILD_DIR"]
    cases = {c[0]: c for c in same_outputs.cases(0, False)}
    case = cases["solve examples/%s.workslike.json" % name]
    other = cases["solve examples/cellphone.workslike.json"]
    assert same_outputs.run(build, case) == same_outputs.run(build, case)
    assert same_outputs.run(build, case) != same_outputs.run(build, other)
