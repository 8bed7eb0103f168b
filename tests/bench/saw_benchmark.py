"""Sheets for a saw (issue 31): FabGuide's free layouts (Docking and MaxRects) beside its guillotine layouts
(3 stages, and unlimited) on shop cut lists generated from held-out seeds (tests/gen/cutlists.py) and, when
packingsolver's repository is given, on the classic two-dimensional bin-packing classes (Berkey & Wang I-VI,
Martello & Vigo VII-X; items not turned, as the classes define them). Each layout is judged by the independent
checkers (layout_check; saw_checker for guillotine layouts); sheets are set beside the area bound (the parts'
area over a sheet's, per thickness, rounded up).
Usage: saw_benchmark.py [--seconds 1,10] [--lists N] [--classes PACKINGSOLVER_REPO] [--per-class K]
(prints the Markdown section)."""
import argparse
import csv
import io
import json
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "gen"))
import cutlists  # noqa: E402
import layout_check  # noqa: E402
import saw_checker  # noqa: E402

CLI = os.path.join(HERE, "..", "..", "build", "fabguide")
MODES = [("free", 0), ("guillotine", 3), ("guillotine", 0)]
HELD_OUT = range(1000, 1020)  # cut-list seeds never looked at while writing the packer


def laid_out(problem, cuts, stages, seconds):
    """(sheets, wall seconds, problems) of `fabguide pack` on `problem` in mode (cuts, stages)."""
    problem = json.loads(json.dumps(problem))
    problem["settings"].update({"cuts": cuts, "stages": stages})
    with tempfile.TemporaryDirectory() as folder:
        src, out = os.path.join(folder, "job.json"), os.path.join(folder, "layout.json")
        with open(src, "w") as f:
            json.dump(problem, f)
        start = time.monotonic()
        run = subprocess.run([CLI, "pack", src, "-o", out, "--time-limit", str(seconds)], capture_output=True,
                             text=True)
        wall = time.monotonic() - start
        if run.returncode:
            return None, wall, [run.stderr.strip()]
        with open(out) as f:
            layout = json.load(f)
    if cuts == "guillotine":
        found = saw_checker.problems(layout, problem)
    else:
        s = problem["settings"]
        found = layout_check.problems(layout, layout_check.demand_of_pack_problem(problem),
                                      lambda i: (layout["boards"][i]["width"], layout["boards"][i]["height"],
                                                 s.get("trim", 0)), s.get("kerf", 0) + s.get("spacing", 0))
    return len(layout["boards"]), wall, found


def class_instances(repo, per_class):
    """(name, problem) of the 2BP classes in packingsolver's repository (a git directory or a checkout)."""
    def read(path):
        if os.path.isdir(os.path.join(repo, "data")):
            with open(os.path.join(repo, path)) as f:
                return f.read()
        return subprocess.run(["git", "--git-dir", repo, "show", "HEAD:" + path], capture_output=True, text=True,
                              check=True).stdout
    for number in range(1, 11):
        folder = "data/rectangle/{}".format("berkey1987" if number <= 6 else "martello1998")
        for size in (20, 40, 60, 80, 100):
            for k in range(1, per_class + 1):
                stem = "{}/Class_{:02d}.2bp_{}_{}".format(folder, number, size, k)
                bins = list(csv.DictReader(io.StringIO(read(stem + "_bins.csv"))))[0]
                items = list(csv.DictReader(io.StringIO(read(stem + "_items.csv"))))
                yield "class {} n={} #{}".format(number, size, k), {
                    "format": "fabguide.pack", "version": 1, "settings": {"resolution": 1},
                    "boards": [{"name": "bin", "width": float(bins["WIDTH"]), "height": float(bins["HEIGHT"]),
                                "count": -1}],
                    "parts": [{"id": "item {}".format(i["ID"]), "width": float(i["WIDTH"]),
                               "height": float(i["HEIGHT"]), "quantity": int(i.get("COPIES") or 1),
                               "orientations": [0]} for i in items]}


def table(title, instances, seconds):
    """Markdown rows: per mode, the sheets summed, % above the area bound, worst wall time, problems."""
    rows, bound = {}, 0
    for name, problem in instances:
        bound += saw_checker.least_sheets(problem)
        for cuts, stages in MODES:
            sheets, wall, found = laid_out(problem, cuts, stages, seconds)
            row = rows.setdefault((cuts, stages), [0, 0.0, []])
            row[0] += sheets or 0
            row[1] = max(row[1], wall)
            row[2] += ["{}: {}".format(name, p) for p in found[:1]]
    out = ["", "**{}** at {} s: area bound {} sheets".format(title, seconds, bound), "",
           "| mode | sheets | above the bound % | slowest wall s | checker problems |", "|---|---|---|---|---|"]
    for (cuts, stages), (sheets, wall, found) in rows.items():
        mode = cuts if cuts == "free" else "guillotine, {} stages".format(stages or "unlimited")
        out.append("| {} | {} | {:.2f} | {:.2f} | {} |".format(mode, sheets, 100.0 * (sheets - bound) / bound, wall,
                                                               len(found) or "none"))
        out += ["  - " + p for p in found[:3]]
    return out


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", default="1")
    parser.add_argument("--lists", type=int, default=len(HELD_OUT))
    parser.add_argument("--classes", default="")
    parser.add_argument("--per-class", type=int, default=1)
    args = parser.parse_args(argv)
    lines = ["## Sheets for a saw (issue 31)", "", "`python3 tests/bench/saw_benchmark.py {}`".format(" ".join(argv))]
    for seconds in [float(s) for s in args.seconds.split(",")]:
        lists = [("cut list {}".format(s), cutlists.problem(s)) for s in list(HELD_OUT)[:args.lists]]
        lines += table("{} generated shop cut lists (seeds {}-{})".format(len(lists), HELD_OUT[0],
                                                                          HELD_OUT[0] + len(lists) - 1),
                       lists, seconds)
        if args.classes:
            lines += table("2BP classes I-X, {} instance(s) per class and size".format(args.per_class),
                           list(class_instances(args.classes, args.per_class)), seconds)
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
