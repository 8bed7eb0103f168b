"""The sloppy works-like suite (tests/data/workslike): each model solved by `fabguide solve`, how much
the solve changed it, how long it took, and what the independent checker (tests/python/workslike_checker.py)
says of the result; contradictory models must be refused naming what their expectations list.
Run alone: python3 tests/bench/workslike_suite_benchmark.py [build-dir]."""
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(ROOT, "tests", "data", "workslike")
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))
import workslike_checker  # noqa: E402


def largest_change(original, solved):
    before = {c["name"]: c for p in original["parts"] for c in p["cuboids"]}
    return max((abs(a - b) for p in solved["parts"] for c in p["cuboids"]
                for a, b in zip(c["min"] + c["max"], before[c["name"]]["min"] + before[c["name"]]["max"])), default=0)


def run(build):
    expectations = json.load(open(os.path.join(DATA, "expectations.json")))
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for name, expected in sorted(expectations.items()):
            path = os.path.join(DATA, name)
            solved_path = os.path.join(out, "solved.json")
            started = time.monotonic()
            solve = subprocess.run([os.path.join(build, "fabguide"), "solve", path, "-o", solved_path],
                                   capture_output=True, text=True)
            seconds = time.monotonic() - started
            original = json.load(open(path))
            parts = len(original["parts"])
            if expected["solvable"]:
                solved = json.load(open(solved_path)) if solve.returncode == 0 else None
                problems = workslike_checker.check(solved, original) if solved else ["not solved"]
                notes = len(solved["report"]["notes"]) if solved else 0
                rows.append((name, parts, "solved" if solved else "refused", largest_change(original, solved)
                             if solved else None, notes, "pass" if not problems else problems[0], seconds))
            else:
                named = all("'{}'".format(n) in solve.stderr for n in expected["must_name"])
                rows.append((name, parts, "refused" if solve.returncode == 1 else "solved", None, 0,
                             "names all of " + ", ".join(expected["must_name"]) if named and solve.returncode == 1
                             else "FAIL: " + solve.stderr.strip()[:120], seconds))
    return rows


def table(rows):
    lines = ["## Works-like on sloppy models (issue 13)", "",
             "`python3 tests/bench/workslike_suite_benchmark.py`: every model of `tests/data/workslike` solved by "
             "`fabguide solve` (wall time of the command, reading and writing included); the largest change of any "
             "coordinate; inference notes (parts linked beyond the face or support distance); and the independent "
             "checker's verdict (no overlap in the base pose, in any configuration or along the motions, every "
             "relationship holding, openings open, walls ≥ 1 mm, locks kept). Contradictory models must be refused "
             "naming what their expectations list.", "",
             "| model | parts | result | largest change mm | notes | independent check | s |", "|---|---|---|---|---|---|---|"]
    for name, parts, result, change, notes, check, seconds in rows:
        lines.append("| {} | {} | {} | {} | {} | {} | {:.3f} |".format(
            name.replace(".workslike.json", ""), parts, result, "-" if change is None else "{:.1f}".format(change),
            notes, check, seconds))
    return "\n".join(lines)


if __name__ == "__main__":
    print(table(run(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build"))))
