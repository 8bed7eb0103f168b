#!/usr/bin/env python3
"""Whether two builds write the same files on the same inputs, byte for byte: a change meant to keep behaviour
(a refactor) is shown to keep it. Each case runs the command-line tools on a bundled input; what the case wrote
(every file, its exit status and its last line on stderr) is hashed.

    python3 tests/bench/same_outputs.py BASE_BUILD NEW_BUILD [--seeds 200] [--prints]

Cases: every works-like fixture, example and kept regression solved, and `--seeds` generated products
(tests/gen); every pack example laid out with a fixed seed and a bounded search (`--iterations`, one thread),
its cut sheets and cut list written; with `--prints`, the small works-like examples printed (STL, report.json
and the solved model; STEP and 3MF carry dates). Times are not compared: a report's `seconds` is left out. Each
case runs twice on the base build; one that differs there is not deterministic, and is listed, not compared.
`make same-outputs BASE=<commit>` builds that commit beside this one and runs it. Exits 1 when a case differs."""

import argparse
import glob
import hashlib
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "gen"))
import fuzz_products  # noqa: E402

PRINTS = ["box-with-lid", "cellphone", "sliding-box", "toolbox"]


def models(seeds):
    """(name, works-like model) of every case to solve."""
    paths = sorted(glob.glob(os.path.join(ROOT, "examples", "*.workslike.json")) +
                   glob.glob(os.path.join(ROOT, "tests", "data", "workslike", "*.json")) +
                   glob.glob(os.path.join(ROOT, "tests", "data", "printable", "*.workslike.json")) +
                   glob.glob(os.path.join(ROOT, "tests", "gen", "regressions", "*.json")))
    for path in paths:
        with open(path) as f:
            model = json.load(f)
        model.pop("generated", None)
        yield os.path.relpath(path, ROOT), model
    for seed in range(seeds):
        yield "generated seed %d" % seed, fuzz_products.case(seed)["model"]


def cases(seeds, prints):
    """(name, input file or model, command arguments after the tool, the tool) of every case; OUT stands for
    the case's own folder."""
    for name, model in models(seeds):
        yield "solve " + name, model, ["solve", "IN", "-o", "OUT/solved.workslike.json"], "fabguide"
    for path in sorted(glob.glob(os.path.join(ROOT, "examples", "*.pack.json"))):
        yield ("pack " + os.path.relpath(path, ROOT), path,
               ["pack", "IN", "-o", "OUT/layout.json", "--svg", "OUT/svg", "--dxf", "OUT/dxf", "--csv", "OUT/cut.csv",
                "--seed", "1", "--iterations", "200", "--threads", "1", "--time-limit", "600"], "fabguide")
    for name in PRINTS if prints else []:
        path = os.path.join(ROOT, "examples", name + ".workslike.json")
        yield "printable " + name, path, ["printable", "IN", "-o", "OUT/print"], "fabguide-print"


def digest(folder, status, stderr):
    """The hash of what a case wrote: each file's name and bytes (STEP and 3MF left out, a JSON report's
    `seconds` dropped), its exit status and its last line on stderr."""
    h = hashlib.sha256(("%d\n%s\n" % (status, stderr.strip().split("\n")[-1])).encode())
    for path in sorted(glob.glob(os.path.join(folder, "**", "*"), recursive=True)):
        if os.path.isdir(path) or path.endswith((".step", ".3mf")):
            continue
        with open(path, "rb") as f:
            data = f.read()
        if path.endswith("report.json"):
            report = json.loads(data)
            report.pop("seconds", None)
            data = json.dumps(report, sort_keys=True).encode()
        h.update(os.path.relpath(path, folder).encode() + b"\n" + data)
    return h.hexdigest()


def run(build, case):
    name, source, arguments, tool = case
    with tempfile.TemporaryDirectory() as tmp:
        path, folder = source, os.path.join(tmp, "out")
        os.mkdir(folder)
        if not isinstance(source, str):
            path = os.path.join(tmp, "in.json")
            with open(path, "w") as f:
                json.dump(source, f)
        args = [path if a == "IN" else a.replace("OUT", folder) for a in arguments]
        r = subprocess.run([os.path.join(build, tool)] + args, capture_output=True, text=True, timeout=1800)
        return digest(folder, r.returncode, r.stderr.replace(tmp, "TMP"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--seeds", type=int, default=200)
    parser.add_argument("--prints", action="store_true")
    a = parser.parse_args()
    same, differ, varies = 0, [], []
    for case in cases(a.seeds, a.prints):
        base = run(a.base, case)
        if run(a.base, case) != base:
            varies.append(case[0])
        elif run(a.new, case) != base:
            differ.append(case[0])
        else:
            same += 1
    print("%d cases the same, %d differ, %d not deterministic" % (same, len(differ), len(varies)))
    for name in differ:
        print("differs: " + name)
    for name in varies:
        print("not deterministic: " + name)
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
