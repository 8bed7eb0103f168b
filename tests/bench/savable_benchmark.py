"""Sheets first, against known answers: generated designs of 50-100 boards in two thicknesses whose
least design is known to fit on fewer sheets than the boards as drawn (tests/gen/savable_designs.py), at three
amounts of slack in that known layout, each run through `fabguide optimise --seed 1 --threads 2`. Per design:
the sheets known to be enough, the sheets as drawn, the sheets of the best suggestion, the least design as laid
out and its area bound, seconds; every suggestion judged by the independent checker (flatpack_checker.py).

    python3 tests/bench/savable_benchmark.py [build-dir] [--seeds 1-5] [--seconds 8]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "gen"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))
import flatpack_checker  # noqa: E402
import savable_designs  # noqa: E402

SLACKS = (0.90, 0.93, 0.96)


def run(cli, document, seconds, reload=False):
    """(summary, problems the checker finds in its suggestions, wall seconds) of optimise on `document`; with
    `reload`, each suggestion is also reopened from its file."""
    with tempfile.TemporaryDirectory() as folder:
        path, out = os.path.join(folder, "design.flatpack.json"), os.path.join(folder, "out")
        with open(path, "w") as f:
            json.dump(document, f)
        start = time.monotonic()
        done = subprocess.run([cli, "optimise", path, "-o", out, "--seed", "1", "--threads", "2", "--time-limit",
                               str(seconds)], capture_output=True, text=True)
        wall = time.monotonic() - start
        if done.returncode:
            return None, [done.stderr.strip()], wall
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        checked = flatpack_checker.check_output(out, document, cli=cli, reload=reload)
    return summary, ["{}: {}".format(where, p) for where, found in checked.items() for p in found], wall


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"))
    parser.add_argument("--seeds", default="1-5")
    parser.add_argument("--seconds", type=float, default=8)
    args = parser.parse_args(argv[1:])
    first, last = (int(v) for v in args.seeds.split("-"))
    cli = os.path.join(args.build, "fabguide")
    print("| slack | seed | boards | known sheets | as drawn | best suggestion | least design laid out | "
          "least design by area | seconds | checker |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    reached = {}
    for slack in SLACKS:
        for seed in range(first, last + 1):
            document, known = savable_designs.design(seed, slack)
            summary, problems, wall = run(cli, document, args.seconds)
            if summary is None:
                print("| {} | {} | {} | {} | error: {} |".format(slack, seed, len(document["parts"]), known["saved"],
                                                               problems[0][:80]))
                continue
            drawn = summary["before"]["sheets"]
            best = min([s["sheets"] for s in summary["suggestions"]] + [drawn])
            reached.setdefault(slack, []).append(best <= known["saved"])
            print("| {} | {} | {} | {} | {} | {} | {} | {} | {:.1f} | {} |".format(
                slack, seed, len(document["parts"]), known["saved"], drawn, best, summary.get("least_sheets"),
                summary.get("least_sheets_by_area"), wall, "; ".join(problems[:2]) or "pass"))
    for slack, hits in reached.items():
        print("\nslack {}: the known sheets reached on {} of {} designs".format(slack, sum(hits), len(hits)), end="")
    print()


if __name__ == "__main__":
    main(sys.argv)
