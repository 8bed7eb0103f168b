"""Irregular strip packing on the nine ESICUP instances: `fabguide pack --strip` on each for a
time limit, the density (the pieces' area over the strip's height times the length used, computed here from the
instance) beside the best published one, each layout checked on the real outlines by outline_check. Run alone:
python3 tests/bench/esicup_benchmark.py [build-dir] [seconds]."""
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
INSTANCES = os.path.join(os.path.dirname(ROOT), "shared", "benchmarks", "packing", "esicup-irregular")
RECORDS = {"albano": 89.82, "dagli": 90.17, "fu": 92.40, "jakobs1": 89.25, "mao": 86.87, "marques": 92.02,
           "shirts": 90.92, "swim": 79.83, "trousers": 92.62}  # sparrow, 2025 (../shared/benchmarks/README.md)
sys.path.insert(0, HERE)
import outline_check  # noqa: E402


def area(points):
    return abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]))) / 2


def as_problem(instance):
    """The instance as outline_check reads a problem: each piece turned a quarter clockwise, as `pack` reads it."""
    parts = [{"id": k, "quantity": item["demand"], "outline": [[y, -x] for x, y in item["shape"]["data"]]}
             for k, item in enumerate(instance["items"])]
    return {"parts": parts, "settings": {}}


def run(build, name, seconds):
    instance = json.load(open(os.path.join(INSTANCES, name + ".json")))
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "layout.json")
        started = time.monotonic()
        done = subprocess.run([os.path.join(build, "fabguide"), "pack", "--strip",
                               os.path.join(INSTANCES, name + ".json"), "-o", out, "--time-limit", str(seconds)],
                              capture_output=True, text=True)
        elapsed = time.monotonic() - started
        if done.returncode:
            return {"name": name, "error": done.stderr.strip().splitlines()[-1], "seconds": elapsed}
        layout = json.load(open(out))
    pieces = sum(item["demand"] * area(item["shape"]["data"]) for item in instance["items"])
    density = 100 * pieces / (instance["strip_height"] * layout["strip_height"])
    return {"name": name, "density": density, "seconds": elapsed,
            "problems": outline_check.problems(layout, as_problem(instance))}


def table(rows, seconds):
    lines = ["## Irregular strip packing (ESICUP)", "",
             "`fabguide pack --strip ../shared/benchmarks/packing/esicup-irregular/NAME.json --time-limit {}` "
             "(the strip turned a quarter: its height is our width, 650 grid cells across; the orientations each "
             "piece allows; filled bottom-left in a tenth of the time, the search's eight starts two at a time on "
             "this 2-core machine, then shrunk by overlap minimisation, one search a core, in four phases, and "
             "compacted on the outlines); "
             "density = the pieces' area / (strip height x length used), computed from the instance; every layout "
             "checked on the real outlines (tests/bench/outline_check.py)."
             .format(seconds),
             "", "| instance | FabGuide density % | best published % (sparrow, 2025) | points below | seconds | "
             "check |", "|---|---|---|---|---|---|"]
    for r in rows:
        if "error" in r:
            lines.append("| {} | - | {:.2f} | - | {:.1f} | {} |".format(r["name"], RECORDS[r["name"]], r["seconds"],
                                                                       r["error"]))
            continue
        lines.append("| {} | {:.2f} | {:.2f} | {:.2f} | {:.1f} | {} |".format(
            r["name"], r["density"], RECORDS[r["name"]], RECORDS[r["name"]] - r["density"], r["seconds"],
            "; ".join(r["problems"][:2]) or "valid"))
    return "\n".join(lines)


if __name__ == "__main__":
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
    seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 60
    print(table([run(build, name, seconds) for name in sorted(RECORDS)], seconds))
