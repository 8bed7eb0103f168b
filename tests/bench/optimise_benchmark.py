"""Zero-waste design exploration on the Table 5.1 designs (thesis 5.5) and the furniture suite: sheets,
waste, usage and the largest offcut before -> after and wall time per design with `fabguide optimise`, beside the
thesis' numbers, and layout-guided shrinking against random part choice (thesis Fig. 5.20c-d).
Run alone: python3 tests/bench/optimise_benchmark.py [build-dir]."""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Our reconstruction -> (thesis figure, parts, usage before, usage after) from Table 5.1.
THESIS = {
    "coffee-table": ("Fig. 5.1", 4, 0.78, 0.89),
    "parrot-shelf": ("Fig. 5.16a", 7, 0.66, 0.92),
    "chest": ("Fig. 5.16b", 9, 0.66, 0.80),
    "low-chair": ("Fig. 5.16c", 8, 0.76, 0.83),
    "yin-chair": ("Fig. 5.16d", 16, 0.79, 0.86),
    "l-worktable": ("Fig. 5.17a", 6, 0.85, 0.96),
    "shelf-and-table": ("Fig. 5.17b", 11, 0.85, 0.97),
    "stylised-chair": ("Fig. 5.17c", 8, 0.74, 0.97),
    "shelf-and-chest": ("Fig. 5.17d", 16, 0.89, 0.98),
}
SEEDS = (1, 2)


def optimise(build, path, seed, unguided=False, limit=8):
    """The user's design and the first suggestion (the maker's best), as summary.json gives them, the wall time, the
    least design's sheets as laid out and the area bound (every side as short as any variation has it: no variation
    needs fewer sheets)."""
    with tempfile.TemporaryDirectory() as out:
        command = [os.path.join(build, "fabguide"), "optimise", path, "-o", out, "--seed", str(seed), "--threads",
                   "2", "--time-limit", str(limit)] + (["--unguided"] if unguided else [])
        started = time.monotonic()
        subprocess.run(command, check=True, capture_output=True, text=True)
        wall = time.monotonic() - started
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    before = summary["before"]
    return (before, (summary["suggestions"] or [before])[0], wall, summary.get("least_sheets", 0),
            summary.get("least_sheets_by_area", 0))


def example(name):
    return os.path.join(ROOT, "examples", name + ".flatpack.json")


def run(build):
    rows = []
    for name, (figure, parts, before, after) in THESIS.items():
        guided = [optimise(build, example(name), seed) for seed in SEEDS]
        unguided = [optimise(build, example(name), seed, unguided=True) for seed in SEEDS]
        rows.append({"name": name, "figure": figure, "parts": parts, "thesis": (before, after), "runs": guided,
                     "unguided": unguided, "limit": 8})
    return rows


def suite(build):
    """The furniture suite of tests/data/flatpack, seed 1, 8 s each."""
    folder = os.path.join(ROOT, "tests", "data", "flatpack")
    rows = []
    for file in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        if file.endswith(".flatpack.json"):
            with open(os.path.join(folder, file)) as f:
                parts = len(json.load(f)["parts"])
            rows.append({"name": file[:-len(".flatpack.json")], "parts": parts, "limit": 8,
                         "runs": [optimise(build, os.path.join(folder, file), 1)]})
    return rows


def offcut(entry):
    w, h = entry["largest_offcut"]
    return "{:.0f} x {:.0f}".format(w, h)


def measured(row):
    """Mean over the runs: sheets, waste and usage before and after, the reduction, wall seconds."""
    before, after = row["runs"][0][:2]
    mean = lambda key, k: statistics.mean(run[k][key] for run in row["runs"])  # noqa: E731
    return {"sheets": (before["sheets"], min(r[1]["sheets"] for r in row["runs"])),
            "least": min(r[3] for r in row["runs"]), "bound": max(r[4] for r in row["runs"]),
            "waste": (before["waste_m2"], mean("waste_m2", 1)), "usage": (before["usage"], mean("usage", 1)),
            "offcut": (offcut(before), offcut(after)), "seconds": max(r[2] for r in row["runs"])}


def least(m):
    """The least design's sheets as laid out / the sheets no variation beats by its parts' area alone."""
    return "{} / {}".format(m["least"], m["bound"])


def reduction(m):
    return 1 - m["waste"][1] / m["waste"][0] if m["waste"][0] > 0 else 0.0


def summary_lines(rows):
    ms = [measured(r) for r in rows]
    multi = [m for m in ms if m["sheets"][0] > 1]
    saved = sum(m["sheets"][1] < m["sheets"][0] for m in multi)
    improved = sum(reduction(m) > 0 or m["sheets"][1] < m["sheets"][0] for m in ms)
    over = max(m["seconds"] - r["limit"] for m, r in zip(ms, rows))
    why = [r["name"] for m, r in zip(ms, rows) if not (reduction(m) > 0 or m["sheets"][1] < m["sheets"][0])]
    proved = sum(m["sheets"][1] == m["bound"] for m in ms)
    return ["", "Designs improved: {} of {}{}; median waste reduction {:.0%} (target >= 10 %); multi-sheet designs "
            "saving a sheet: {} of {} (target >= a third; the others need as many sheets with every part as small "
            "as their constraints allow: 'least sheets'); on the sheets the area bound over the "
            "variations allows: {} of {}; largest overshoot of the time limit: {:+.2f} s "
            "(target <= 1 s).".format(improved, len(ms), " (not: {}, see its least sheets and the output's 'left "
                                      "out')".format(", ".join(why)) if why else "",
                                      statistics.median(reduction(m) for m in ms) if ms else 0, saved, len(multi),
                                      proved, len(ms), over)]


def table(rows, suite_rows=()):
    lines = ["## Zero-waste design exploration (thesis Table 5.1, Fig. 5.20c-d; issue 14)", "",
             "`fabguide optimise examples/NAME.flatpack.json -o out --seed S --threads 2 --time-limit 8` (G = 3 "
             "rounds of 8 orderings) on our reconstructions of the thesis' designs with their kinds of constraints. "
             "The search first shrinks the design to its least (every part as small as its constraints allow) "
             "and, when that fits on fewer sheets, bisects for the least shrink that does (FEWERSHEETS); then the "
             "thesis' rounds minimise the boards' cost (sheets), then the thesis' usage measure. A suggestion is kept "
             "only with fewer sheets, or as many and less waste (m² of the sheets used not in parts), and "
             "suggestions are ranked by cost, sheets, waste, largest offcut. 'sheets' after is the fewest of the "
             "first suggestions, 'least sheets' what the least design needs as laid out / the sheets its parts' "
             "area alone needs with every side as short as any variation has it (a linear programme per side: no "
             "variation beats that bound); waste and usage after are the first "
             "suggestion's, mean over seeds {}; seconds is the "
             "slowest wall time of the command. 'Random shrink' replaces the layout's locking chains by random part "
             "sizes (`--unguided`, the thesis' baseline): its waste after. Usage = part area / layout bounding "
             "rectangle (thesis 5.2.3).".format(", ".join(map(str, SEEDS))), "",
             "| design | thesis | parts | sheets | least sheets | waste m² | reduction | random shrink m² | usage "
             "| largest offcut mm | seconds | thesis usage |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        m = measured(r)
        unguided = statistics.mean(u[1]["waste_m2"] for u in r["unguided"])
        lines.append("| {} | {} | {} | {} -> {} | {} | {:.3f} -> {:.3f} | {:.0%} | {:.3f} | {:.3f} -> {:.3f} "
                     "| {} -> {} | {:.1f} | {:.2f} -> {:.2f} |".format(
                         r["name"], r["figure"], r["parts"], *m["sheets"], least(m), *m["waste"], reduction(m),
                         unguided, *m["usage"], *m["offcut"], m["seconds"], *r["thesis"]))
    lines += summary_lines(rows)
    if suite_rows:
        lines += ["", "The furniture suite (`tests/data/flatpack`, seed 1, 8 s each):", "",
                  "| design | parts | sheets | least sheets | waste m² | reduction | usage | largest offcut mm "
                  "| seconds |", "|---|---|---|---|---|---|---|---|---|"]
        for r in suite_rows:
            m = measured(r)
            lines.append("| {} | {} | {} -> {} | {} | {:.3f} -> {:.3f} | {:.0%} | {:.3f} -> {:.3f} | {} -> {} "
                         "| {:.1f} |".format(r["name"], r["parts"], *m["sheets"], least(m), *m["waste"],
                                             reduction(m), *m["usage"], *m["offcut"], m["seconds"]))
        lines += summary_lines(suite_rows)
        lines += ["", "Both together:"] + summary_lines(list(rows) + list(suite_rows))[1:]
    return "\n".join(lines)


if __name__ == "__main__":
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
    print(table(run(build), suite(build)))
