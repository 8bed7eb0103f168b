"""Kills at random moments: a command, or FreeCAD's Export Cut Sheets, writes its set of files over the
set an earlier run of another job left in the same folder and is killed, by SIGKILL or SIGTERM, at a random moment, its writes and renames
slowed by strace half of the time. Then the folder, read as fabguide reads it (a commit journal the kill left is
completed first: this file's own reading of the journal), must hold one whole set, the old or the new; and after
the next run, exactly that run's set and no stray file.
    python3 tests/gen/kills.py [--kills 100] [--seed 1]      prints a table; exit 1 on any failure"""
import argparse
import io
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "..", "..")
EXAMPLES = os.path.join(SOURCE, "examples")
SLOWED = ["strace", "-f", "-qq", "-o", "/dev/null",
          "-e", "inject=write,pwrite64,writev:delay_exit=1000",
          "-e", "inject=rename,renameat,renameat2,unlink,unlinkat:delay_exit=40000"]


def can_slow():
    """Whether strace may trace here (a container may forbid ptrace): if not, no run is slowed."""
    try:
        return subprocess.run(SLOWED + ["true"], capture_output=True).returncode == 0
    except OSError:
        return False


def pack_job(folder, quantity):
    """A pack job of `quantity` shelves on as many boards as it takes (the two jobs lay out different sheets)."""
    job = {"format": "fabguide.pack", "version": 1, "boards": [{"width": 2440, "height": 1220, "count": -1}],
           "parts": [{"id": "shelf", "width": 800, "height": 300, "quantity": quantity}],
           "settings": {"kerf": 3, "spacing": 0, "trim": 0, "resolution": 5}}
    path = os.path.join(folder, "shelves-{}.pack.json".format(quantity))
    with open(path, "w") as out:
        json.dump(job, out)
    return path


def commands(cli, work):
    """Per command, the two jobs and the command line that runs one into a folder."""
    return {
        "pack": ([pack_job(work, 40), pack_job(work, 60)],
                 lambda job, out: [cli, "pack", job, "-o", os.path.join(out, "layout.json"),
                                   "--svg", os.path.join(out, "svg"), "--dxf", os.path.join(out, "dxf"),
                                   "--csv", os.path.join(out, "cutlist.csv"), "--iterations", "3000",
                                   "--time-limit", "60"]),
        "optimise": ([os.path.join(EXAMPLES, name) for name in ("coffee-table.flatpack.json",
                                                                "chest.flatpack.json")],
                     lambda job, out: [cli, "optimise", job, "-o", out, "--rounds", "1", "--threads", "1",
                                       "--time-limit", "120"]),
        "printable": ([os.path.join(EXAMPLES, name) for name in ("box-with-lid.workslike.json",
                                                                 "sliding-box.workslike.json")],
                      lambda job, out: [cli, "printable", job, "-o", out]),
        "FreeCAD export": ([os.path.join(EXAMPLES, name) for name in ("bookshelf.FCStd", "coffee-table.FCStd")],
                           lambda job, out: [sys.executable, os.path.join(HERE, "export_layout.py"), job, out]),
    }


def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def content(path, name=None):
    """What a file says, less what changes from run to run (times, dates, zip timestamps, a PDF's streams); `name`,
    the name it is read as, tells its kind (a temporary's own name does not)."""
    data = open(path, "rb").read()
    name = name or path
    if name.endswith(".json"):
        return json.dumps(without_times(json.loads(data)), sort_keys=True)
    if name.endswith(".step"):
        return b"".join(line for line in io.BytesIO(data) if not line.startswith(b"FILE_NAME"))
    if name.endswith(".pdf"):  # its text: cairo's streams differ from run to run (dates, font subset tags)
        return subprocess.run(["pdftotext", "-layout", path, "-"], capture_output=True).stdout
    if name.endswith(".3mf"):
        with zipfile.ZipFile(io.BytesIO(data)) as archive:
            return {name: archive.read(name) for name in sorted(archive.namelist())}
    return data


def listing(folder):
    return sorted(os.path.relpath(os.path.join(root, name), folder)
                  for root, _, names in os.walk(folder) for name in names)


def as_read(folder):
    """The set as fabguide reads it: a journal `.fabguide-commit-*` (JSON: renames [from, to] and removes, in
    its own folder; batch: the commit's journals in every folder) is completed first when all its batch's
    journals are there, and the temporaries `.NAME.partial-*` are nobody's files."""
    files = {}
    for root, _, names in os.walk(folder):
        for name in names:
            files[os.path.join(root, name)] = os.path.join(root, name)
        for name in names:
            if name.startswith(".fabguide-commit-"):
                journal = json.load(open(os.path.join(root, name)))
                if not all(os.path.exists(sibling) for sibling in journal.get("batch", [])):
                    continue  # its commit had not begun its renames, or had done them all
                for source, target in journal.get("renames", []):
                    if os.path.join(root, source) in files:
                        files[os.path.join(root, target)] = files.pop(os.path.join(root, source))
                for gone in journal.get("removes", []):
                    files.pop(os.path.join(root, gone), None)
    return {os.path.relpath(path, folder): content(real, path) for path, real in files.items()
            if not os.path.basename(path).startswith(".")}


def whole(folder):
    return {path: content(os.path.join(folder, path)) for path in listing(folder)}


def start(argv, slowed):
    return subprocess.Popen((SLOWED if slowed else []) + argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def worker(run, argv, slowed):
    """The process that writes (strace's child when slowed): signals go to it, not to strace, nor to the
    children strace forks at its start to try what the kernel allows."""
    if not slowed:
        return run.pid
    children = "/proc/{0}/task/{0}/children".format(run.pid)
    program = os.path.basename(argv[0]).encode()
    for _ in range(5000):
        try:
            for pid in open(children).read().split():
                with open("/proc/{}/cmdline".format(pid), "rb") as cmdline:
                    if os.path.basename(cmdline.read().split(b"\0")[0]) == program:
                        return int(pid)
        except OSError:
            if run.poll() is not None:
                return None
        time.sleep(0.001)
    return None


def reference(argv, slowed=False):
    """Runs `argv` to its end: the seconds it took."""
    began = time.monotonic()
    run = start(argv, slowed)
    _, error = run.communicate(timeout=600)
    assert run.returncode == 0, error.decode()
    return time.monotonic() - began


def trials(cli, kills, seed, names=None):
    """Kills `kills` runs, spread over the commands; returns rows (command, signal, slowed, moment, outcome,
    failure or '')."""
    rng = random.Random(seed)
    slowable = can_slow()
    work = tempfile.mkdtemp(prefix="fabguide-kills-")
    rows = []
    try:
        chosen = {name: spec for name, spec in commands(cli, work).items() if names is None or name in names}
        sets = {}
        for name, (jobs, argv) in chosen.items():
            sets[name] = []
            for k, job in enumerate(jobs):
                out = os.path.join(work, "{}-{}".format(name, k))
                plain = reference(argv(job, out))
                slow = plain
                if slowable and k == 1:  # the job the trials kill: how long it takes slowed
                    slow = reference(argv(job, os.path.join(work, "slow")), slowed=True)
                    shutil.rmtree(os.path.join(work, "slow"))
                sets[name].append((out, whole(out), plain, slow))
            assert sets[name][0][1] != sets[name][1][1], name + ": the two jobs write the same set"
        for trial in range(kills):
            name = list(chosen)[trial % len(chosen)]
            jobs, argv = chosen[name]
            (old_folder, old, _, _), (_, new, plain, slow) = sets[name]
            sig = rng.choice([signal.SIGKILL, signal.SIGTERM])
            slowed = rng.random() < 0.5 and slowable
            moment = rng.uniform(0, 1.1 * (slow if slowed else plain))
            folder = os.path.join(work, "trial-{}".format(trial))
            shutil.copytree(old_folder, folder)
            run = start(argv(jobs[1], folder), slowed)
            pid = worker(run, argv(jobs[1], folder), slowed)
            time.sleep(moment)
            try:
                if pid:
                    os.kill(pid, sig)
            except ProcessLookupError:
                pass
            _, error = run.communicate(timeout=120)
            failure = ""
            if run.returncode not in (0, 130, 143, 128 + signal.SIGKILL, -signal.SIGKILL, -signal.SIGTERM):
                failure = "exit {}: {}".format(run.returncode, error.decode().strip()[-300:])
            seen = as_read(folder)
            outcome = "new" if seen == new else "old" if seen == old else "mixed"
            cut_short = any(name.startswith(".fabguide-commit-") for path in [folder]
                            for _, _, names in os.walk(path) for name in names)
            if outcome == "mixed" and not failure:
                failure = "a mixed or broken set: {} files differ from the old, {} from the new".format(
                    sum(seen.get(p) != old.get(p) for p in set(seen) | set(old)),
                    sum(seen.get(p) != new.get(p) for p in set(seen) | set(new)))
            reference(argv(jobs[0], folder))  # the next run
            if not failure and whole(folder) != old:
                strays = sorted(set(listing(folder)) - set(old))
                failure = "after the next run: " + (", ".join(strays[:5]) if strays else "not its set")
            rows.append((name, signal.Signals(sig).name, slowed, moment, outcome, failure, cut_short))
            shutil.rmtree(folder)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return rows


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--kills", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--cli", default=os.path.join(SOURCE, "build", "fabguide"))
    args = parser.parse_args(argv)
    rows = trials(args.cli, args.kills, args.seed)
    print("| command | signal | slowed | kills | left the old set | left the new set | of which cut short in its "
          "renames (completed from the journal) | failures |")
    print("|---|---|---|---:|---:|---:|---:|---:|")
    for key in sorted({(r[0], r[1], r[2]) for r in rows}):
        mine = [r for r in rows if (r[0], r[1], r[2]) == key]
        print("| {} | {} | {} | {} | {} | {} | {} | {} |".format(
            key[0], key[1], "yes" if key[2] else "no", len(mine), sum(r[4] == "old" for r in mine),
            sum(r[4] == "new" for r in mine), sum(r[6] for r in mine), sum(bool(r[5]) for r in mine)))
    for row in rows:
        if row[5]:
            print("FAILED {} {} slowed={} at {:.3f} s: {}".format(*row[:4], row[5]))
    return 1 if any(r[5] for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
