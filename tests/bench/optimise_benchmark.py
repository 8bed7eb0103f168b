"""Zero-waste design exploration on the Table 5.1 designs (thesis 5.5): usage before -> after and time per design
with `fabguide optimise`, beside the thesis' numbers, and layout-guided shrinking against random part choice
(thesis Fig. 5.20c-d). Run alone: python3 tests/bench/optimise_benchmark.py [build-dir]."""
import json
import os
import statistics
import subprocess
import sys
import tempfile

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


def optimise(build, name, seed, unguided=False):
    with tempfile.TemporaryDirectory() as out:
        command = [os.path.join(build, "fabguide"), "optimise", os.path.join(ROOT, "examples", name + ".flatpack.json"),
                   "-o", out, "--seed", str(seed), "--threads", "2"] + (["--unguided"] if unguided else [])
        subprocess.run(command, check=True, capture_output=True, text=True)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    best = max([s["usage_after"] for s in summary["suggestions"]], default=summary["usage_before"])
    return summary["usage_before"], best, summary["seconds"]


def run(build):
    rows = []
    for name, (figure, parts, before, after) in THESIS.items():
        guided = [optimise(build, name, seed) for seed in SEEDS]
        unguided = [optimise(build, name, seed, unguided=True) for seed in SEEDS]
        rows.append({"name": name, "figure": figure, "parts": parts, "thesis": (before, after),
                     "before": guided[0][0], "after": statistics.mean(g[1] for g in guided),
                     "seconds": max(g[2] for g in guided), "unguided": statistics.mean(u[1] for u in unguided)})
    return rows


def table(rows):
    lines = ["## Zero-waste design exploration (thesis Table 5.1, Fig. 5.20c-d)", "",
             "`fabguide optimise examples/NAME.flatpack.json -o out --seed S --threads 2` (default time limit 8 s, "
             "G = 3 rounds of 8 orderings) on our reconstructions of the thesis' designs with their kinds of "
             "constraints; usage = part area / layout bounding rectangle; 'after' is the best suggestion, mean over "
             "seeds {}; time is the slowest run. 'Random shrink' replaces the layout's locking chains by random part "
             "sizes (`--unguided`, the thesis' baseline). Usage before is our docking + ordering search on the "
             "unchanged design, so the gain is the design change alone.".format(", ".join(map(str, SEEDS))), "",
             "| design | thesis | parts | before | after | random shrink | seconds | thesis before -> after |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.1f} | {:.2f} -> {:.2f} |".format(
            r["name"], r["figure"], r["parts"], r["before"], r["after"], r["unguided"], r["seconds"], *r["thesis"]))
    after = statistics.median(r["after"] for r in rows)
    improved = sum(r["after"] > r["before"] for r in rows)
    lines += ["", "Median usage after: {:.3f} (target >= 0.95); designs improved: {} of {}; slowest: {:.1f} s "
              "(target <= 10 s).".format(after, improved, len(rows), max(r["seconds"] for r in rows))]
    return "\n".join(lines)


if __name__ == "__main__":
    print(table(run(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build"))))
