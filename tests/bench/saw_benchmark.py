"""Sheets for a saw: FabGuide's free layouts (Docking and MaxRects) beside its guillotine layouts
(3 stages, and unlimited) on shop cut lists generated from held-out seeds (tests/gen/cutlists.py) and, when
packingsolver's repository is given, on the classic two-dimensional bin-packing classes (Berkey & Wang I-VI,
Martello & Vigo VII-X; items not turned, as the classes define them). Each layout is judged by the independent
checkers (layout_check; saw_checker for guillotine layouts); sheets are set beside the area bound (the parts'
area over a sheet's, per thickness, rounded up).
With --packingsolver BIN (built by build_packingsolver.sh), packingsolver's free (rectangle) and 3-stage guillotine
(rectangleguillotine, 3NAR: non-exact, either first direction) solvers run beside FabGuide on the same instances
and time limits; kerf, spacing and trim go in as the usual equivalence (each item and the trimmed sheet grown by
the kerf), one run per sheet thickness; their sheet counts are theirs, not checked here.
With --maxrects FOLDER (build_maxrects.sh), a plain MaxRects (npm's maxrects-packer, free cuts, one run, the
same kerf equivalence) runs beside them too.
Usage: saw_benchmark.py [--seconds 1,10] [--lists N] [--classes PACKINGSOLVER_REPO] [--per-class K]
[--packingsolver BIN] [--maxrects FOLDER] (prints the Markdown section)."""
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


def grown(problem):
    """Per sheet thickness with parts, (sheet, items) as packers without kerf take a job: the trimmed sheet and each
    item grown by the kerf (and spacing), items as (width, height, copies, fixed: may not turn)."""
    s = problem["settings"]
    gap, trim = s.get("kerf", 0) + s.get("spacing", 0), s.get("trim", 0)
    groups = []
    for board in problem["boards"]:
        parts = [p for p in problem["parts"] if p.get("thickness", board.get("thickness")) == board.get("thickness")]
        if parts:
            groups.append(((board["width"] - 2 * trim + gap, board["height"] - 2 * trim + gap),
                           [(p["width"] + gap, p["height"] + gap, p.get("quantity", 1),
                             p.get("orientations") == [0] or (bool(p.get("follow_grain")) and
                                                              board.get("grain", "none") != "none"))
                            for p in parts]))
    return groups


def by_packingsolver(binary, problem, kind, seconds):
    """(sheets, wall seconds, problems) of packingsolver's `kind` solver, one run per thickness (the time limit
    shared between them), summed."""
    groups = grown(problem)
    sheets, wall = 0, 0.0
    for (width, height), items in groups:
        with tempfile.TemporaryDirectory() as folder:
            items_csv, bins, out = (os.path.join(folder, n) for n in ("items.csv", "bins.csv", "out.json"))
            with open(items_csv, "w") as f:
                f.write("WIDTH,HEIGHT,COPIES,ORIENTED\n")
                for w, h, copies, fixed in items:
                    f.write("{},{},{},{}\n".format(w, h, copies, int(fixed)))
            with open(bins, "w") as f:
                f.write("WIDTH,HEIGHT\n{},{}\n".format(width, height))
            command = [os.path.join(binary, "packingsolver_" + kind), "-i", items_csv, "-b", bins, "-f",
                       "bin-packing", "--bin-infinite-copies", "-t", str(seconds / len(groups)), "-o", out, "-v", "0"]
            if kind == "rectangleguillotine":
                command += ["-p", "3NAR"]
            start = time.monotonic()
            run = subprocess.run(command, capture_output=True, text=True)
            wall += time.monotonic() - start
            if run.returncode:
                return None, wall, [run.stderr.strip()[-200:]]
            with open(out) as f:
                solution = json.load(f)["Output"]["Solution"]
            if solution["NumberOfItems"] != sum(copies for _, _, copies, _ in items):
                return None, wall, ["packingsolver placed {} of the items".format(solution["NumberOfItems"])]
            sheets += solution["NumberOfBins"]
    return sheets, wall, []


def by_maxrects(folder, problem):
    """(sheets, wall seconds, problems) of a plain MaxRects (npm's maxrects-packer in `folder`,
    tests/bench/maxrects.js), one run per thickness, summed."""
    start = time.monotonic()
    run = subprocess.run(["node", os.path.join(HERE, "maxrects.js"), folder], capture_output=True, text=True,
                         input=json.dumps([{"sheet": sheet, "items": items} for sheet, items in grown(problem)]))
    wall = time.monotonic() - start
    if run.returncode:
        return None, wall, [run.stderr.strip()[-200:]]
    return sum(json.loads(run.stdout)), wall, []


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


def table(title, instances, seconds, packingsolver="", maxrects=""):
    """Markdown rows: per mode, the sheets summed, % above the area bound, worst wall time, problems."""
    rows, bound = {}, 0
    runs = [(mode, lambda problem, mode=mode: laid_out(problem, *mode, seconds)) for mode in MODES]
    if packingsolver:
        runs += [(("packingsolver", kind), lambda problem, kind=kind: by_packingsolver(packingsolver, problem, kind,
                                                                                       seconds))
                 for kind in ("rectangle", "rectangleguillotine")]
    if maxrects:
        runs.append((("maxrects", 0), lambda problem: by_maxrects(maxrects, problem)))
    for name, problem in instances:
        bound += saw_checker.least_sheets(problem)
        for mode, run in runs:
            sheets, wall, found = run(problem)
            row = rows.setdefault(mode, [0, 0.0, []])
            row[0] += sheets or 0
            row[1] = max(row[1], wall)
            row[2] += ["{}: {}".format(name, p) for p in found[:1]]
    out = ["", "**{}** at {} s: area bound {} sheets".format(title, seconds, bound), "",
           "| mode | sheets | above the bound % | slowest wall s | checker problems |", "|---|---|---|---|---|"]
    for (cuts, stages), (sheets, wall, found) in rows.items():
        mode = ("FabGuide free" if cuts == "free" else "MaxRects (npm maxrects-packer 2.7.4, one run)"
                if cuts == "maxrects" else "packingsolver {}".format(
                    "free (rectangle)" if stages == "rectangle" else "guillotine, 3 stages (rectangleguillotine 3NAR)")
                if cuts == "packingsolver" else "FabGuide guillotine, {} stages".format(stages or "unlimited"))
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
    parser.add_argument("--packingsolver", default="", help="folder of packingsolver_rectangle(guillotine)")
    parser.add_argument("--maxrects", default="", help="folder of npm's maxrects-packer (build_maxrects.sh)")
    args = parser.parse_args(argv)
    lines = ["## Sheets for a saw (issue 31)", "", "`python3 tests/bench/saw_benchmark.py {}`".format(" ".join(argv))]
    for seconds in [float(s) for s in args.seconds.split(",")]:
        lists = [("cut list {}".format(s), cutlists.problem(s)) for s in list(HELD_OUT)[:args.lists]]
        lines += table("{} generated shop cut lists (seeds {}-{})".format(len(lists), HELD_OUT[0],
                                                                          HELD_OUT[0] + len(lists) - 1),
                       lists, seconds, args.packingsolver, args.maxrects)
        if args.classes:
            lines += table("2BP classes I-X, {} instance(s) per class and size".format(args.per_class),
                           list(class_instances(args.classes, args.per_class)), seconds, args.packingsolver,
                           args.maxrects)
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1:])
