"""Random command lines for every command (the fuzzers cover the CLI options). Each run picks a command,
an input and some of the options its --help lists (so a new option is fuzzed without a word here), with values
valid, at their limits, and nonsense. Whatever the line, the run must finish (exit 0) or refuse it in one line
(exit 1, "fabguide: error: ..."): no crash, no traceback, no hang, under 2 GB, nothing written outside its folder.
    python3 tests/gen/cli_options.py [--runs N | --minutes M] [--seed S]     exit 1 on a failure, its line kept"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import hostile  # noqa: E402  (one way to run and judge a command line)

SOURCE = os.path.join(HERE, "..", "..")
INPUTS = {
    "pack": ["examples/bookshelf.pack.json", "examples/coffee-table.pack.json", "tests/data/curved-parts.pack.json",
             "tests/data/holes-job.pack.json"],
    "solve": ["examples/box-with-lid.workslike.json", "examples/sliding-box.workslike.json",
              "examples/crate-bed.workslike.json"],
    "printable": ["examples/box-with-lid.workslike.json", "examples/sliding-box.workslike.json"],
    "optimise": ["examples/coffee-table.flatpack.json", "examples/chest.flatpack.json"],
}
TIMES = ("--time-limit", "--part-seconds", "--seconds")  # a valid value is kept small: the run takes it
NUMBERS = ["0", "1", "-1", "2", "0.5", "15", "90", "100", "3", "1e-9", "1e400", "-1e400", "nan", "inf", "-0",
           "18446744073709551616", "9007199254740993", "2147483648", "1,5", "0x10", "1e2", " 1", "9" * 400]
WORDS = ["", "abc", "free", "guillotine", "along", "across", "any", "fdm", "resin", "62x29", "0x0", "250x210x210",
         "1x1x1", "-5x10x10", "nanxnanxnan", "1G", "64M", "63M", "1k", "2T", "\x01", "é", "x" * 5000]
TIME_VALUES = ["0", "0.01", "0.5", "1", "2", "-1", "86401", "nan", "inf", "1e400", "abc", ""]


def options_of(cli, command):
    """The (option, what its value must be or None for a flag) pairs `command --help` lists."""
    text = subprocess.run([cli, command, "--help"], capture_output=True, text=True).stdout
    found = []
    for line in text.splitlines():
        match = re.match(r"\s+(?:-\w,)?(--[\w-]+)(?: ((?:\S| (?=\S))+))?", line)
        if match and match.group(1) != "--help":
            kind = match.group(2) or ""
            found.append((match.group(1), None if not kind or kind.startswith(("Excludes", "Needs")) else kind))
    return found


def valid(option, kind, rng):
    """A value the help says `option` takes, or None when it does not say."""
    bounds = re.search(r"in \[(\S+) - (\S+)\]", kind)
    if bounds:
        low, high = float(bounds.group(1)), float(bounds.group(2))
        if option in TIMES:
            high = min(high, 2)
        x = rng.choice([low, high, rng.uniform(low, min(high, 1000))])
        return str(int(x)) if "INT" in kind else repr(x)
    members = re.search(r"\{([^}]*)\}", kind)
    if members:
        return rng.choice(members.group(1).split(",")).split("->")[0]
    if "SIZE" in kind:
        return rng.choice(["64M", "500M", "2G", "1000000000"])
    if "WxDxH" in kind:
        return "x".join(str(rng.choice([5, 50, 250, 1000])) for _ in range(3))
    if kind.startswith("[FLOAT,FLOAT]"):
        return "{}x{}".format(rng.choice([10, 62, 100, 1000]), rng.choice([10, 29, 100, 1000]))
    return None


def paths(folder, rng):
    """An output path as users and attackers give them: plain, nested, a folder, a link out, a pipe."""
    outside = os.path.join(folder, "..", os.path.basename(folder) + "-outside")
    choice = rng.choice(["file", "nested", "folder", "link", "fifo", "dot"])
    if choice == "file":
        return os.path.join(folder, "out-{}.x".format(rng.randrange(5)))
    if choice == "nested":
        return os.path.join(folder, "a", "b", "c")
    if choice == "folder":
        return folder
    if choice == "link":
        os.makedirs(outside, exist_ok=True)
        link = os.path.join(folder, "link-{}".format(rng.randrange(1000)))
        if not os.path.lexists(link):
            os.symlink(os.path.join(outside, "victim"), link)
        return link
    if choice == "fifo":
        fifo = os.path.join(folder, "fifo")
        if not os.path.exists(fifo):
            os.mkfifo(fifo)
        return fifo
    return os.path.join(folder, ".")


def value(option, kind, folder, rng):
    """Mostly a value the option takes, else nonsense; an output path as people and attackers give them."""
    if option in ("--svg", "--dxf", "--csv", "--report", "--opticutter", "--labels"):  # -o: command_line's
        return paths(folder, rng)
    taken = valid(option, kind, rng)
    if taken is not None and rng.random() < 0.7:
        return taken
    if option in TIMES:
        return rng.choice(TIME_VALUES)
    return rng.choice(NUMBERS + WORDS if rng.random() < 0.5 else NUMBERS)


def command_line(cli, options, folder, rng):
    """A random command line of one command, its input copied into the run's folder."""
    command = rng.choice(sorted(INPUTS))
    source = os.path.join(folder, "input.json")
    shutil.copy(os.path.join(SOURCE, rng.choice(INPUTS[command])), source)
    output = {"pack": "out.json", "solve": "out.json", "optimise": "suggestions", "printable": "printable"}[command]
    argv = [command, source, "-o", os.path.join(folder, output) if rng.random() < 0.7 else paths(folder, rng)]
    others = [(option, kind) for option, kind in options[command] if option != "--output"]
    picked = rng.sample(others, min(len(others), rng.randint(1, 4)))
    for option, kind in picked:
        argv.append(option)
        if kind is not None:
            argv.append(value(option, kind, folder, rng))
    if not any(option in argv for option in TIMES):  # bounded unless the line bounds it
        argv += {"pack": ["--time-limit", "0.5"], "optimise": ["--time-limit", "1"],
                 "printable": ["--part-seconds", "20"], "solve": []}[command]
    return argv


def judge(status, error, seconds, peak, outside, timed):
    """What is wrong with a run, or '' (its time judged only when `timed`: a test does not judge wall time)."""
    if os.path.exists(os.path.join(outside, "victim")):
        return "wrote through a link out of its folder"
    said = error.strip().split("\n")[-1] if error.strip() else ""
    if status == 1 and said.startswith("fabguide: error: ") and not any(
            word in error for word in ("terminate", "Traceback", "internal error", "bad_alloc")):
        error = said  # a search's progress lines may come before its refusal
    return hostile.judge((hostile.OK, "fabguide: error: "), status, error, seconds, peak, 60, timed)


def runs(cli, seed, count, minutes, timed=True):
    """(run number, argv, exit status, seconds, what is wrong) for each run until count or minutes."""
    rng = random.Random(seed)
    options = {command: options_of(cli, command) for command in INPUTS}
    began = time.monotonic()
    n = 0
    while (count and n < count) or (minutes and time.monotonic() - began < minutes * 60):
        folder = tempfile.mkdtemp(prefix="fabguide-options-")
        outside = folder + "-outside"
        try:
            argv = command_line(cli, options, folder, rng)
            r = hostile.run(cli, argv + ["--memory", "2G"], 90)
            status, seconds = r.returncode, r.seconds
            wrong = judge(status, r.stderr, seconds, r.peak_kb, outside, timed)
        finally:
            shutil.rmtree(folder, ignore_errors=True)
            shutil.rmtree(outside, ignore_errors=True)
        yield n, argv, status, seconds, wrong
        n += 1


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=0)
    parser.add_argument("--minutes", type=float, default=0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--cli", default=os.path.join(SOURCE, "build", "fabguide"))
    args = parser.parse_args(argv)
    if not args.runs and not args.minutes:
        args.runs = 100
    counts, failures = {}, 0
    for n, line, status, seconds, wrong in runs(args.cli, args.seed, args.runs, args.minutes):
        counts[status] = counts.get(status, 0) + 1
        if wrong:
            failures += 1
            print("run {}: {!r}: {}".format(n, line, wrong), flush=True)
    print("{} runs: {}; {} failures".format(sum(counts.values()), ", ".join(
        "exit {}: {}".format(s, c) for s, c in sorted(counts.items())), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
