"""The product suite of tests/data/printable: products drawn as designers draw them, not from the
thesis, each printed in place fitted to a desktop printer (250 x 210 x 210 mm). Judged by what the run wrote
(report.json: every body valid and in one piece, the least clearance at 32 poses of every motion at least the
gap, the size inside the build volume) and by admesh reading the STL closed, not by the words it printed.
PrusaSlicer slices them in `make bench` (tests/bench/printable_benchmark.py)."""
import glob
import json
import os
import re
import subprocess

import pytest

from conftest import sample

VOLUME = (250, 210, 210)
SUITE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data", "printable")
PRODUCTS = sample(sorted(os.path.basename(p)[:-len(".workslike.json")]  # CI's Debian 13 run: one in twelve
                         for p in glob.glob(os.path.join(SUITE, "*.workslike.json"))))


@pytest.mark.parametrize("name", PRODUCTS)
def test_the_product_prints_in_place_fitted_to_a_desktop_printer(fabguide_cli, tmp_path, name):
    out = tmp_path / name
    run = subprocess.run([fabguide_cli, "printable", os.path.join(SUITE, name + ".workslike.json"), "-o", str(out),
                          "--fit", "x".join(map(str, VOLUME))], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    report = json.loads((out / "report.json").read_text())
    assert report["ok"] and not report["invalid"] and not report["loose"], report
    assert report["clearance"]["least_mm"] >= report["gap_mm"] - 1e-6, report["clearance"]
    assert all(size <= room + 0.01 for size, room in zip(report["size_mm"], VOLUME)), report["size_mm"]
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*{}\b".format(len(report["bodies"])), mesh), mesh
    for check in ("Degenerate facets", "Edges fixed", "Facets reversed", "Backwards edges"):
        assert re.search(check + r"\s*:\s*0\b", mesh), check + "\n" + mesh


def test_a_four_bar_drawn_with_a_link_over_the_others_pin_is_refused_by_name(fabguide_cli, tmp_path):
    """The folding table as first drawn, both links on the left faces: refused naming both links and what to
    change, and nothing written."""
    run = subprocess.run([fabguide_cli, "printable", os.path.join(SUITE, "refused",
                                                                  "folding-table-leaf-as-drawn.workslike.json"),
                          "-o", str(tmp_path / "out")], capture_output=True, text=True, timeout=600)
    assert run.returncode == 1, run.stderr
    assert "the four-bar of 'upper link' and 'lower link' has a link over the other's pin" in run.stderr
    assert "put the links on other faces" in run.stderr
    assert not (tmp_path / "out").exists()


def test_a_print_that_does_not_pass_ends_saying_why(fabguide_cli, tmp_path):
    """A product whose folding door's leaf (turning upon turns) meets another hinge's yokes
    (tests/data/printable/not-printable): the files are written to look at, report.json says not ok, and the last
    line on stderr says why, naming the parts and the joint."""
    run = subprocess.run([fabguide_cli, "printable", os.path.join(SUITE, "not-printable",
                                                                  "folding-door-beside-thick-door.workslike.json"),
                          "-o", str(tmp_path / "out")], capture_output=True, text=True, timeout=600)
    assert run.returncode == 1, run.stdout + run.stderr
    last = run.stderr.strip().split("\n")[-1]
    assert re.fullmatch(r"fabguide printable: not printable as it is: parts come 0\.\d{3} mm apart, under the 0\.40 mm "
                        r"gap, leaf and door B in 'A open' at \d+% near .*joint 'B hinge' is in the way.* \(the files are "
                        r"written to look at\)", last), last
    assert not json.loads((tmp_path / "out" / "report.json").read_text())["ok"]
