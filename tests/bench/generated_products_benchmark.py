"""Generated products (tests/gen): 2000 products solved and checked, 200 of them printed fitted to a
desktop printer and checked, with the failures by class; and how long a solve takes from the command line
(start-up included) on the products and on a wall of 510 cuboids. Part of `make bench`; on its own:
python3 tests/bench/generated_products_benchmark.py [PRODUCTS PRINTS]."""
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "gen"))
sys.path.insert(0, os.path.join(ROOT, "tests", "data", "workslike"))
import fuzz_products  # noqa: E402
import make_wall  # noqa: E402


def solve_seconds(cli, path, runs=1):
    """The least wall time of `runs` solves of a model from the command line."""
    best = float("inf")
    for _ in range(runs):
        started = time.perf_counter()
        subprocess.run([cli, "solve", path], capture_output=True, check=False)
        best = min(best, time.perf_counter() - started)
    return best


def timings(cli, count=200):
    """Solve times of the first `count` solvable products (parts, seconds), and of the 510-cuboid wall."""
    import json
    out = []
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "model.workslike.json")
        for seed in range(count):
            c = fuzz_products.case(seed)
            if c["known"]:
                continue
            with open(path, "w") as f:
                json.dump(c["model"], f)
            out.append((len(c["model"]["parts"]), solve_seconds(cli, path)))
        with open(path, "w") as f:
            json.dump(make_wall.wall(rows=10, columns=17), f)
        wall = solve_seconds(cli, path, runs=3)
    return out, wall


def section(build, products=2000, prints=200):
    cli = os.path.join(build, "fabguide")
    results, printed, seconds = fuzz_products.run_all(list(range(products)), cli, prints)
    solves, wall = timings(cli)
    small = sorted(t for n, t in solves if n <= 30)
    lines = ["## Generated products (issue 30)", "",
             "`python3 tests/bench/generated_products_benchmark.py` (or `make fuzz-products PRODUCTS=%d PRINTS=%d`): "
             "seeds 0-%d of tests/gen, drawn roughly, one in three contradictory; solvable ones solved by `fabguide "
             "solve` and judged by the independent checker, contradictory ones must exit 1 naming their known "
             "conflict; %d of the solvable ones, evenly spread, printed (`fabguide printable --fit 250x210x210`) "
             "and judged by tests/gen/print_checker.py (bodies, meshes, pieces, bodies meeting as printed and along "
             "every motion, material missing where no part goes). Targets: >= 99.5 %% of the solvable, every "
             "contradictory one, >= 98 %% of the prints." % (products, prints, products - 1, prints), ""]
    lines += fuzz_products.summary(results, printed, seconds)
    lines += ["", "Solve from the command line, start-up included, first 200 seeds' solvable "
              "products of at most 30 parts: median %.0f ms, 90th percentile %.0f ms, most %.0f ms (target 50 ms); "
              "the wall of 170 cabinets (510 cuboids, `make_wall.py --rows 10 --columns 17`): %.0f ms (target "
              "300 ms)." % (1e3 * statistics.median(small), 1e3 * small[int(0.9 * len(small))], 1e3 * small[-1],
                            1e3 * wall)]
    return "\n".join(lines)


if __name__ == "__main__":
    args = [int(a) for a in sys.argv[1:3]]
    print(section(os.path.join(ROOT, "build"), *args))
