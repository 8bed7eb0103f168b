"""Is `pack --time-limit` held at any load? Runs `fabguide pack` on the largest generated shop cut list
(tests/gen/cutlists.py) in free and guillotine mode at each time limit, with 0, 2 and 4 busy processes beside
it, and reports the wall time from the process' start to its exit (start-up, reading and writing included).
    python3 tests/bench/time_limit_benchmark.py [--limits 1 10] [--runs 3]"""
import argparse
import json
import multiprocessing
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "gen"))
import cutlists  # noqa: E402

CLI = os.path.join(HERE, "..", "..", "build", "fabguide")


def busy():
    while True:
        pass


def largest(seeds=40):
    return max((cutlists.problem(s) for s in range(seeds)),
               key=lambda p: sum(part.get("quantity", 1) for part in p["parts"]))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--limits", type=float, nargs="+", default=[1, 10])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--loads", type=int, nargs="+", default=[0, 2, 4])
    args = parser.parse_args(argv)
    problem = largest()
    folder = tempfile.mkdtemp()
    path = os.path.join(folder, "job.pack.json")
    with open(path, "w") as out:
        json.dump(problem, out)
    parts = sum(p.get("quantity", 1) for p in problem["parts"])
    print("{} parts; wall seconds, worst of {} runs (over the limit in brackets)".format(parts, args.runs))
    print("| busy processes | mode | " + " | ".join("--time-limit {:g}".format(t) for t in args.limits) + " |")
    print("|---|---|" + "---|" * len(args.limits))
    for load in args.loads:
        hogs = [multiprocessing.Process(target=busy, daemon=True) for _ in range(load)]
        for hog in hogs:
            hog.start()
        try:
            for mode in ("free", "guillotine"):
                cells = []
                for limit in args.limits:
                    worst = 0.0
                    for _ in range(args.runs):
                        start = time.monotonic()
                        subprocess.run([CLI, "pack", path, "-o", os.path.join(folder, "layout.json"), "--cuts", mode,
                                        "--time-limit", str(limit)], check=True, stdout=subprocess.DEVNULL)
                        worst = max(worst, time.monotonic() - start)
                    cells.append("{:.2f} ({:+.2f})".format(worst, worst - limit))
                print("| {} | {} | {} |".format(load, mode, " | ".join(cells)))
        finally:
            for hog in hogs:
                hog.terminate()


if __name__ == "__main__":
    main(sys.argv[1:])
