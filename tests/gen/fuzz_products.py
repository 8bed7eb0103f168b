#!/usr/bin/env python3
"""Generated products at scale: each seed's product (products.py) is made contradictory for one seed in
three (contradict.py), drawn roughly (roughen.py), solved by `fabguide solve` and judged: a solvable product must
solve to a model the independent checker passes, a contradictory one must exit 1 naming its known conflict, and
a sample of the solved ones must print (`fabguide printable --fit`) with every print check passing
(print_checker.py). Prints a table of failures by class, each with the seeds that reproduce it.

    python3 tests/gen/fuzz_products.py --products 2000 [--first 0] [--prints 200] [--jobs 2] [--keep DIR]

`--seeds 12,40` runs those seeds only; `--keep DIR` writes each failing seed's rough model there."""

import argparse
import collections
import json
import multiprocessing
import os
import random
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "python"))
import contradict  # noqa: E402
import print_checker  # noqa: E402
import products  # noqa: E402
import roughen  # noqa: E402
import workslike_checker  # noqa: E402

CLI = os.path.join(HERE, "..", "..", "build", "fabguide")
FIT = "250x210x210"  # a desktop printer's build volume (the README's)


def case(seed):
    """The rough model of a seed, whether it is solvable, and its known conflict."""
    product = products.generate(seed)
    model, known = product.model, None
    rng = random.Random(seed * 7919 + 1)
    if seed % 3 == 2:
        made = contradict.contradict(model, rng)
        if made:
            model, known = made
    rough, done = roughen.roughen(model, rng)
    return {"seed": seed, "model": rough, "known": known, "features": sorted(product.features), "rough": done,
            "redraws": product.redraws}


def shape(text):
    """A problem's class: its words without names and numbers."""
    text = re.sub(r"'[^']*'", "_", text)
    text = re.sub(r"\([^()]*\)", "", text)
    text = re.sub(r"-?[0-9][0-9.e+-]*", "", text)
    return " ".join(text.split()[:7])


def conflict_class(stderr):
    names = re.findall(r"'([^']*)'", stderr.split("\n")[0])
    kinds = sorted({n.split(":")[0] if ":" in n else "relationship" for n in names})
    return "+".join(kinds) or "no names"


def run(cli, args, timeout=300):
    try:
        return subprocess.run([cli] + args, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None


def judge(seed, cli=CLI, print_it=False, keep=None):
    """(seed, class or None, detail, seconds, features, contradictory) for one seed; class None: it passed."""
    started = time.time()
    c = case(seed)
    verdict = judge_model(c["model"], c["known"], cli, print_it)
    if verdict and keep:
        os.makedirs(keep, exist_ok=True)
        with open(os.path.join(keep, "seed-%d.workslike.json" % seed), "w") as f:
            json.dump(dict(c["model"], generated={"seed": seed, "known": c["known"], "rough": c["rough"],
                                                    "failure": verdict}), f, indent=1)
    kind, detail = verdict or (None, "")
    return seed, kind, detail, time.time() - started, c["features"], c["known"] is not None


def judge_model(model, known, cli=CLI, print_it=False):
    """(class, detail) of a rough model's failure, or None: solved and checked (and printed and checked), or
    refused naming its known conflict."""
    with tempfile.TemporaryDirectory() as tmp:
        path, out = os.path.join(tmp, "model.workslike.json"), os.path.join(tmp, "solved.workslike.json")
        with open(path, "w") as f:
            json.dump(model, f)
        verdict = solve_and_check(cli, {"model": model, "known": known}, path, out)
        if verdict is None and print_it and known is None:
            verdict = print_and_check(cli, path, os.path.join(tmp, "print"))
    return verdict


def solve_and_check(cli, c, path, out):
    r = run(cli, ["solve", path, "-o", out])
    if r is None:
        return "solve: timeout", ""
    if r.returncode not in (0, 1) or "terminate called" in r.stderr:
        return "solve: crash (exit %d)" % r.returncode, r.stderr[-300:]
    known = c["known"]
    if known:
        if r.returncode == 0:
            return "contradiction solved (%s)" % known["kind"], r.stdout[-300:]
        missing = [n for n in known["must_name"] if "'%s'" % n not in r.stderr]
        missing += [" or ".join(group) for group in known["one_of"] if not any("'%s'" % n in r.stderr for n in group)]
        if missing:
            return "conflict misnamed (%s)" % known["kind"], "missing %s in: %s" % (missing, r.stderr[:400])
        return None
    if r.returncode == 1:
        return "refused solvable: " + conflict_class(r.stderr), r.stderr[:400]
    with open(out) as f:
        solved = json.load(f)
    problems, _ = workslike_checker.check_all(solved, c["model"])
    if problems:
        return "silent: " + shape(problems[0]), problems[0]
    return None


def print_and_check(cli, path, folder):
    """The print, judged on the model as its own solve left it (solved.workslike.json): the relationships
    hold there, and the bodies clear each other along its motions."""
    r = run(cli, ["printable", path, "-o", folder, "--fit", FIT, "--part-seconds", "30"], timeout=600)
    if r is None:
        return "print: timeout", ""
    if r.returncode not in (0, 1) or "terminate called" in r.stderr:
        return "print: crash (exit %d)" % r.returncode, r.stderr[-300:]
    if r.returncode == 1:
        lines = r.stdout.split("\n")
        said = [line for line in lines if line.startswith(("IN PIECES", "INVALID"))] or \
            [line for line in lines if line.startswith("minimum clearance")]
        said = said[0] if said else (r.stderr.strip() or r.stdout.strip()).split("\n")[-1]
        return "print refused: " + shape(said), said[-400:]
    solved = os.path.join(folder, "solved.workslike.json")
    with open(path) as f, open(solved) as g:
        problems, _ = workslike_checker.check_all(json.load(g), json.load(f))
    if problems:
        return "print's solve: " + shape(problems[0]), problems[0]
    problems = print_checker.check(path, folder, solved)
    if problems:
        return "print: " + shape(problems[0]), problems[0]
    return None


def run_all(seeds, cli=CLI, prints=0, jobs=None, keep=None):
    """Every seed judged, then `prints` of the solvable ones (evenly spread) printed too, on `jobs` processes:
    (results, the seeds printed, seconds)."""
    started = time.time()
    with multiprocessing.Pool(jobs or os.cpu_count() or 1) as pool:
        results = pool.starmap(judge, [(s, cli, False, keep) for s in seeds], chunksize=1)
        solvable = [r[0] for r in results if not r[5]]
        chosen = solvable[::max(1, len(solvable) // prints)][:prints] if prints else []
        printed = {r[0]: r for r in pool.starmap(judge, [(s, cli, True, keep) for s in chosen], chunksize=1)}
    return [printed.get(r[0], r) for r in results], set(chosen), time.time() - started


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--products", type=int, default=300)
    parser.add_argument("--first", type=int, default=0)
    parser.add_argument("--seeds", default="")
    parser.add_argument("--prints", type=int, default=0, help="how many of the solvable products to print too")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--cli", default=CLI)
    parser.add_argument("--keep", default="")
    parser.add_argument("--json", default="", help="write the results there")
    args = parser.parse_args(argv)
    seeds = [int(s) for s in args.seeds.split(",")] if args.seeds else list(range(args.first, args.first + args.products))
    results, printed, seconds = run_all(seeds, args.cli, args.prints, args.jobs, args.keep or None)
    print("\n".join(summary(results, printed, seconds)))
    if args.json:
        with open(args.json, "w") as f:
            json.dump([{"seed": s, "class": k, "detail": d, "seconds": t, "features": fe, "contradictory": co}
                       for s, k, d, t, fe, co in results], f, indent=1)
    return 1 if any(k for _, k, *_ in results) else 0


def rate(passed, total):
    return "%d of %d (%.1f %%)" % (passed, total, 100.0 * passed / max(1, total))


def summary(results, printed, seconds):
    """The pass rates and a table of failures by class, each with the seeds that reproduce it."""
    contradictory = [r for r in results if r[5]]
    solvable = [r for r in results if not r[5]]
    failed = collections.defaultdict(list)
    for seed, kind, detail, *_ in results:
        if kind:
            failed[kind].append((seed, detail))

    def passed(rs):
        return sum(1 for r in rs if not r[1] or r[1].startswith("print"))

    prints = [r for r in results if r[0] in printed]
    lines = ["%d products (%d solvable, %d contradictory), %d printed, %.0f s" % (
        len(results), len(solvable), len(contradictory), len(prints), seconds),
        "solvable solved and checked: " + rate(passed(solvable), len(solvable)),
        "contradictory refused naming the conflict: " + rate(passed(contradictory), len(contradictory)),
        "printed with every check passing: " + rate(sum(1 for r in prints if not r[1]), len(prints)),
        "", "| class | count | seeds |", "|---|---|---|"]
    lines += ["| %s | %d | %s |" % (kind, len(cases), " ".join(str(s) for s, _ in cases[:12]))
              for kind, cases in sorted(failed.items(), key=lambda kv: -len(kv[1]))]
    for kind, cases in sorted(failed.items(), key=lambda kv: -len(kv[1])):
        lines += ["", "%s, e.g. seed %d:" % (kind, cases[0][0]), "  " + cases[0][1][:600].replace("\n", "\n  ")]
    return lines


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
