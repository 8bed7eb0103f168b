"""Common-line cutting on held-out shop cut lists (tests/gen/cutlists.py, seeds 1000-1019; free cuts, kerf 3.2, trim
10, spacing 0): how much of the cut length is shared by two parts and cut once, with the sheets the same as without
it; every DXF sheet judged by the independent cut-path checker.
    python3 tests/bench/common_line_benchmark.py BUILD_DIR [--seconds 1] [--lists 20]"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "gen"))
import cut_path_checker  # noqa: E402
import cutlists  # noqa: E402


def pack(cli, problem, folder, seconds, *options):
    os.makedirs(folder, exist_ok=True)
    src = os.path.join(folder, "job.pack.json")
    with open(src, "w") as f:
        json.dump(problem, f)
    subprocess.run([cli, "pack", src, "-o", os.path.join(folder, "layout.json"), "--time-limit", str(seconds),
                    "--dxf", folder, "--text-labels", *options], check=True, capture_output=True)
    with open(os.path.join(folder, "layout.json")) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("--seconds", type=float, default=1.0)
    parser.add_argument("--lists", type=int, default=20)
    args = parser.parse_args()
    cli = os.path.join(args.build, "fabguide")
    whole = shared = 0.0
    sheets = [0, 0]
    problems = 0
    for seed in range(1000, 1000 + args.lists):
        problem = cutlists.problem(seed)
        problem["settings"].update({"cuts": "free", "spacing": 0})
        with tempfile.TemporaryDirectory() as out:
            plain = pack(cli, problem, os.path.join(out, "plain"), args.seconds)
            once = pack(cli, problem, os.path.join(out, "once"), args.seconds, "--common-line")
            for board in range(len(once["boards"])):
                problems += len(cut_path_checker.problems(
                    once, board, problem["settings"]["kerf"], os.path.join(out, "once", "sheet-{}.dxf".format(board + 1))))
        whole += once["cut_length"] + once["common_line"]
        shared += once["common_line"]
        sheets[0] += len(plain["boards"])
        sheets[1] += len(once["boards"])
        print("seed {}: {} sheets without, {} with; outlines {:.1f} m, {:.1f} m of them shared".format(
            seed, len(plain["boards"]), len(once["boards"]), (once["cut_length"] + once["common_line"]) / 1000,
            once["common_line"] / 1000), flush=True)
    print("| {} cut lists, {:g} s | {} | {} | {:.1f} m | {:.1f} m ({:.1%}) | {} |".format(
        args.lists, args.seconds, sheets[0], sheets[1], whole / 1000, shared / 1000, shared / whole, problems))


if __name__ == "__main__":
    main()
