"""The shop's paperwork from `fabguide pack --report --labels` on generated shop cut lists (tests/gen/cutlists.py)
with edge banding drawn at random: read back with poppler's pdftotext/pdfinfo, as a person would read the
printout, and checked against figures computed here from the problem and the layout, not by the core."""
import json
import os
import random
import re
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "gen"))
import cutlists  # noqa: E402

BANDS = ["oak 1 mm", "white ABS 2 mm"]


def banded(seed):
    problem = cutlists.problem(seed)
    rng = random.Random(seed)
    for part in problem["parts"]:
        sides = rng.sample(["L1", "L2", "W1", "W2"], rng.randint(0, 4))
        if sides:
            part["edge_banding"] = {side: rng.choice(BANDS) for side in sides}
    if seed % 2:
        problem["settings"].update(cuts="guillotine", stages=3)
    return problem


def pdf_text(path):
    return subprocess.run(["pdftotext", "-layout", str(path), "-"], check=True, stdout=subprocess.PIPE,
                          text=True).stdout


def pages(path):
    info = subprocess.run(["pdfinfo", str(path)], check=True, stdout=subprocess.PIPE, text=True).stdout
    return int(re.search(r"Pages:\s+(\d+)", info).group(1))


@pytest.mark.parametrize("seed", [1, 2, 5])
def test_report_and_labels_say_what_the_layout_is(tmp_path, fabguide_cli, seed):
    problem = banded(seed)
    (tmp_path / "job.pack.json").write_text(json.dumps(problem))
    subprocess.run([fabguide_cli, "pack", str(tmp_path / "job.pack.json"), "-o", str(tmp_path / "layout.json"),
                    "--report", str(tmp_path / "report.pdf"), "--labels", str(tmp_path / "labels.pdf"),
                    "--label-size", "62x29", "--iterations", "30"], check=True, stdout=subprocess.PIPE)
    layout = json.loads((tmp_path / "layout.json").read_text())
    sheets, placements = len(layout["boards"]), layout["placements"]
    parts = {p["id"]: p for p in problem["parts"]}
    rows = len({(p["part"], p["board"]) for p in placements})
    assert pages(tmp_path / "report.pdf") in (sheets + (rows + 23) // 24, sheets + (rows + 23) // 24 + 1)
    assert pages(tmp_path / "labels.pdf") == len(placements) == sum(p.get("quantity", 1) for p in parts.values())
    text = pdf_text(tmp_path / "report.pdf")
    for number, pid in enumerate(parts, 1):  # every part in the cut list, under its number
        assert re.search(r"^\s*{}\s+{}\s".format(number, re.escape(pid)), text, re.M), pid
    assert re.search(r"^Sheets\s+{} \({} parts\)".format(sheets, len(placements)), text, re.M)
    totals = {band: value for band, value in re.findall(r"^Edge banding (.+?)\s+([\d.]+ m)$", text, re.M)}
    for band in BANDS:
        length = sum(part.get("quantity", 1) * (part["width"] if side.startswith("L") else part["height"])
                     for part in parts.values() for side, b in part.get("edge_banding", {}).items() if b == band)
        if length:
            assert totals[band] == "{:.2f} m".format(length / 1000)
    waste = re.search(r"^Waste\s+([\d.]+) m2 \(([\d.]+) %\)", text, re.M)
    sheet_area = sum(b["width"] * b["height"] for b in layout["boards"])
    part_area = sum(parts[p["part"]]["width"] * parts[p["part"]]["height"] for p in placements)
    assert float(waste.group(1)) == pytest.approx((sheet_area - part_area) / 1e6, abs=0.006)
    if problem["settings"].get("cuts") == "guillotine":
        saw = re.search(r"^Saw cut length\s+([\d.]+) m", text, re.M)
        cut = sum(((c["to"][0] - c["from"][0]) ** 2 + (c["to"][1] - c["from"][1]) ** 2) ** 0.5
                  for sheet in layout["saw_cuts"] for c in sheet)
        assert float(saw.group(1)) == pytest.approx(cut / 1000, abs=0.006)
    labels = pdf_text(tmp_path / "labels.pdf").split("\f")
    first = placements[0]
    assert any(first["part"] in label and "sheet {}".format(first["board"] + 1) in label for label in labels)


def test_a_label_too_small_is_refused_by_name(tmp_path, fabguide_cli):
    (tmp_path / "job.pack.json").write_text(json.dumps(banded(1)))
    run = subprocess.run([fabguide_cli, "pack", str(tmp_path / "job.pack.json"), "-o", str(tmp_path / "l.json"),
                          "--labels", str(tmp_path / "labels.pdf"), "--label-size", "10x5", "--iterations", "5"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert run.returncode != 0 and "label size 10 x 5 mm" in run.stderr
    assert not (tmp_path / "labels.pdf").exists() and not (tmp_path / "l.json").exists()


def test_opticutter_import_lists_every_part_and_sheet_per_thickness(tmp_path, fabguide_cli):
    """optiCutter's keyed CSV (N name, M material, K kerf, S stock, P part: length, width, quantity, label,
    can turn), read back here: one file per thickness, every part once with its quantity and turning."""
    import csv

    problem = banded(3)
    (tmp_path / "job.pack.json").write_text(json.dumps(problem))
    subprocess.run([fabguide_cli, "pack", str(tmp_path / "job.pack.json"), "-o", str(tmp_path / "l.json"),
                    "--opticutter", str(tmp_path / "job.csv"), "--iterations", "5"], check=True,
                   stdout=subprocess.PIPE)
    thicknesses = sorted({b["thickness"] for b in problem["boards"]})
    seen = {}
    for t in thicknesses:
        rows = list(csv.reader((tmp_path / "job-{:g}mm.csv".format(t)).open()))
        keys = [r[0] for r in rows]
        assert keys[:3] == ["N", "M", "K"] and float(rows[2][1]) == problem["settings"]["kerf"]
        stock = [r for r in rows if r[0] == "S"]
        assert [(float(r[1]), float(r[2])) for r in stock] == [(b["width"], b["height"]) for b in problem["boards"]
                                                               if b["thickness"] == t]
        for r in rows:
            if r[0] == "P":
                part = next(p for p in problem["parts"] if p["id"] == r[4])
                assert part["thickness"] == t and (float(r[1]), float(r[2])) == (part["width"], part["height"])
                assert (r[5] == "y") == (90 in part.get("orientations", [0, 90, 180, 270])
                                         and not part.get("follow_grain", False))
                seen[r[4]] = int(r[3])
    assert seen == {p["id"]: p.get("quantity", 1) for p in problem["parts"]}
