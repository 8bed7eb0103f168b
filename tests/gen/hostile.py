"""Near-limit and hostile inputs for every command: sizes just inside and just past what the readers
accept, shapes and counts that once hung or took all the memory, names that break files, nonsense values.
Each case states what a run must do: finish (exit 0) or refuse in one line naming the field (exit 1 and the
given words); either way within its seconds and under 2 GB (`--memory 2G` is passed too).
    python3 tests/gen/hostile.py [--only WORD] [--time-limit 2]     prints the table; exit 1 on any failure"""
import argparse
import copy
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "..", "..")
EXAMPLES = os.path.join(SOURCE, "examples")
MEMORY_KB = 2 * 1024 * 1024
OK = "ok"  # expect: exit 0; a string otherwise: exit 1 and these words; a tuple: either of them


# --- building blocks ---------------------------------------------------------------------------------------

def pack(parts, boards=None, **settings):
    return {"format": "fabguide.pack", "version": 1,
            "boards": boards or [{"width": 2440, "height": 1220, "count": -1}],
            "parts": parts, "settings": dict({"kerf": 3, "resolution": 5}, **settings)}


def square(side, x=0, y=0):
    return [[x, y], [x + side, y], [x + side, y + side], [x, y + side]]


def circle(points, radius=300):
    return [[round(radius + radius * math.cos(2 * math.pi * k / points), 6),
             round(radius + radius * math.sin(2 * math.pi * k / points), 6)] for k in range(points)]


def ell(size=400):
    return [[0, 0], [size, 0], [size, size / 4], [size / 4, size / 4], [size / 4, size], [0, size]]


def perforated(holes_per_side, side=1000):
    """A square plate with holes_per_side² small square holes."""
    pitch = side / (holes_per_side + 1)
    return {"id": "plate", "outline": square(side),
            "holes": [square(pitch / 3, pitch * (i + 1) - pitch / 6, pitch * (j + 1) - pitch / 6)[::-1]
                      for i in range(holes_per_side) for j in range(holes_per_side)]}


def cuboid_part(name, lo, hi):
    return {"name": name, "cuboids": [{"name": name, "min": lo, "max": hi}]}


def chain(joints, kind="slide"):
    """A works-like model of joints+1 cuboids, each jointed to the one below it (a slide along x, or a hinge
    on its lower far edge)."""
    model = {"format": "fabguide.workslike", "version": 1, "parts": [], "joints": []}
    for i in range(joints + 1):
        name = "p{}".format(i)
        model["parts"].append(cuboid_part(name, [0, 0, 30 * i], [20, 20, 30 * i + 20]))
        if i:
            joint = {"name": "j{}".format(i), "type": kind, "part": name, "base": "p{}".format(i - 1)}
            joint.update({"axis": "x"} if kind == "slide" else {"edge": [name + ".far", name + ".bottom"]})
            model["joints"].append(joint)
    return model


def row(cuboids):
    model = {"format": "fabguide.workslike", "version": 1, "parts": []}
    for i in range(cuboids):
        model["parts"].append(cuboid_part("q{}".format(i), [30 * i, 0, 0], [30 * i + 20, 20, 20]))
    return model


def example(name):
    with open(os.path.join(EXAMPLES, name)) as f:
        return json.load(f)


def changed(document, path, value):
    """document with the field at path (a list of keys and indices) set to value."""
    result = copy.deepcopy(document)
    target = result
    for key in path[:-1]:
        target = target[key]
    target[path[-1]] = value
    return result


def box(pid, low, size):
    """A flat-pack part: its lower corner and sizes as the format's corners."""
    return {"id": pid, "min": low, "max": [lo + s for lo, s in zip(low, size)]}


def flatpack_row(parts, touching=True):
    """A flat-pack design of `parts` upright boards side by side, touching (snapped in a row) or apart on a
    grid, cut from as many sheets as it takes."""
    design = example("coffee-table.flatpack.json")
    design["boards"][0]["count"] = -1
    if touching:
        design["parts"] = [box("b{}".format(i), [i * 12, 0, 0], [12, 450, 400]) for i in range(parts)]
    else:
        design["parts"] = [box("b{}".format(i), [i % 400 * 24, i // 400 % 100 * 60, i // 40000 * 60], [12, 45, 40])
                           for i in range(parts)]
    design["constraints"] = []
    design.pop("inner_volumes", None)
    design.pop("outer_volume", None)
    return design


def renamed(part, name, model=None):
    """The box with a lid with `part` (and its cuboid of that name) renamed everywhere it is named."""
    def rename(value):
        if isinstance(value, dict):
            return {k: rename(v) if k != "poses" else v for k, v in value.items()}
        if isinstance(value, list):
            return [rename(v) for v in value]
        if value == part or (isinstance(value, str) and value.startswith(part + ".")):
            return name + value[len(part):]
        return value
    return rename(model or example("box-with-lid.workslike.json"))


# --- the cases ----------------------------------------------------------------------------------------------

def cases(limit):
    """(name, command argv with {in} and {out}, input document or None, expect, seconds)."""
    t = str(limit)
    lay = ["pack", "{in}", "-o", "{out}/layout.json", "--time-limit", t]
    strip = ["pack", "--strip", "{in}", "-o", "{out}/strip.json", "--time-limit", t]
    solve = ["solve", "{in}", "-o", "{out}/solved.json"]
    printable = ["printable", "{in}", "-o", "{out}/print"]
    optimise = ["optimise", "{in}", "-o", "{out}/suggestions", "--time-limit", t]
    within = limit + 1
    rects = [{"id": "r{}".format(k), "width": 100 + 7 * k % 500, "height": 80 + 13 * k % 400, "quantity": 1}
             for k in range(300)]
    yield "pack: an outline of 100,000 points", lay, pack([{"id": "disc", "outline": circle(100000)}]), OK, within
    yield "pack: an outline of 1,000,000 points", lay, pack([{"id": "disc", "outline": circle(1000000)}]), \
        (OK, "parts[0].outline"), within
    yield "pack: 10,000 holes in one part", lay, pack([perforated(100)]), (OK, "parts[0]"), within
    yield "pack: 1,000 holes in one part", lay, pack([perforated(32)]), OK, within
    yield "pack: a hole touching its outline", lay, pack([{"id": "frame", "outline": square(100),
                                                           "holes": [square(50, 0, 20)[::-1]]}]), \
        "parts[0].holes[0]: touches the outline", within
    yield "pack: 100,000 allowed orientations", lay, pack([{"id": "a", "width": 100, "height": 50,
                                                           "orientations": list(range(100000))}]), \
        "parts[0].orientations", within
    yield "pack: rotation step 1 on 200 rectangles", lay + ["--rotation-step", "1"], pack(rects[:200]), \
        (OK, "rotation"), within
    yield "pack: rotation step 1 on 20 irregular parts", lay + ["--rotation-step", "1"], \
        pack([{"id": "l{}".format(k), "outline": ell(200 + k)} for k in range(20)]), OK, within
    yield "pack: 50,000 units", lay, pack([{"id": "tile", "width": 7, "height": 6, "quantity": 50000}]), OK, within
    yield "pack: 50,001 units", lay, pack([{"id": "tile", "width": 7, "height": 6, "quantity": 50001}]), \
        "parts: more than 50000 parts", within
    yield "pack: 5,000 distinct irregular parts", lay, \
        pack([{"id": "t{}".format(k), "outline": [[0, 0], [60 + k % 50, 0], [0, 40 + k % 30]]}
              for k in range(5000)]), OK, within
    yield "pack: 2,000 ells on a board at the cell limit", lay, \
        pack([{"id": "ell", "outline": ell(), "quantity": 2000}],
             [{"width": 20000, "height": 10000, "count": -1}], resolution=1.42), OK, within
    yield "pack: a board past 20 m", lay, pack(rects[:5], [{"width": 20001, "height": 1000}]), "boards[0]", \
        within
    yield "pack: 100 boards of irregular parts at 1 mm", lay, \
        pack([{"id": "p{}".format(k), "outline": [[0, 0], [15000, 0], [15000, 4000], [7000, 8000], [0, 8000]]}
              for k in range(100)], [{"width": 20000, "height": 10000, "count": 100}], resolution=1, kerf=0), \
        "settings.resolution 1 mm needs", within
    yield "pack: the same at 5 mm", lay, \
        pack([{"id": "p{}".format(k), "outline": [[0, 0], [15000, 0], [15000, 4000], [7000, 8000], [0, 8000]]}
              for k in range(100)], [{"width": 20000, "height": 10000, "count": 100}], resolution=5, kerf=0), \
        (OK, "settings.resolution 5 mm needs"), within
    yield "pack: a resolution coarser than the board", lay, pack(rects[:3], resolution=5000), \
        "settings.resolution", within
    yield "pack: a resolution of a micrometre", lay, pack(rects[:3], resolution=0.001), "grid cells", within
    yield "pack: a kerf wider than the board", lay, pack(rects[:3], kerf=5000), (OK, "larger than every"), within
    yield "pack: a negative kerf", lay, pack(rects[:3], kerf=-1), "settings.kerf", within
    yield "pack: a misspelt setting", lay, changed(pack(rects[:3]), ["settings", "kerff"], 3), "kerf", within
    yield "pack: a part 1 km long", lay, pack([{"id": "beam", "width": 1e6, "height": 50}]), "beam", within
    yield "pack: a number past 1e300", lay, pack([{"id": "a", "width": 1e300, "height": 50}]), "parts[0]", within
    yield "pack: JSON nested 10,000 deep", lay, "[" * 10000 + "]" * 10000, "nest", within
    yield "pack: ids of control characters and 1 MB", lay + ["--svg", "{out}/svg", "--dxf", "{out}/dxf",
                                                             "--csv", "{out}/cut.csv"], \
        pack([{"id": name, "width": 300, "height": 200} for name in
              ["line\nbreak", "nul\u0000byte", 'quote " & <tag>', "Tür – 棚 🪚", "x" * 1000000]]), OK, within
    yield "pack: 2,000 rectangles for a saw", lay + ["--cuts", "guillotine"], \
        pack([dict(r, quantity=7) for r in rects]), OK, within
    yield "pack: 1,000 parts of two thicknesses, with grain", lay, \
        pack([dict(r, thickness=18 if k % 2 else 6, follow_grain=True, quantity=3) for k, r in enumerate(rects)],
             [{"width": 2440, "height": 1220, "count": -1, "thickness": 18, "grain": "width"},
              {"width": 2440, "height": 1220, "count": -1, "thickness": 6, "grain": "width"}]), OK, within
    yield "pack: output onto a device", ["pack", "{in}", "-o", "/dev/null"], pack(rects[:3]), "/dev/null", within
    yield "pack: output into a file as if a folder", ["pack", "{in}", "-o", "{in}/layout.json"], pack(rects[:3]), \
        "input.json: not a folder", within
    yield "pack: a time limit of a millisecond", ["pack", "{in}", "-o", "{out}/l.json", "--time-limit", "0.001"], \
        pack(rects), (OK, "time"), within
    yield "pack: a seed of 2^64", lay + ["--seed", str(2 ** 64)], pack(rects[:3]), "--seed", within
    yield "pack: a strip of 50,000 items", strip, \
        {"Objects": [{"Length": 1000, "Height": 1000}], "Items": [{"Length": 7, "Height": 6, "Demand": 50000}]}, \
        OK, within
    yield "pack: a strip of 199,999 items", strip, \
        {"Objects": [{"Length": 1000, "Height": 1000}], "Items": [{"Length": 7, "Height": 6, "Demand": 199999}]}, \
        "more than 50000 parts", within
    yield "pack: a strip of 300 items up to 1 km tall", strip, \
        {"Objects": [{"Length": 1000, "Height": 1000}],
         "Items": [{"Length": 50 + 37 * k % 250, "Height": 100000 + 7919 * k % 900000, "Demand": 1}
                   for k in range(300)]}, OK, within
    yield "pack: an ESICUP piece of 100,000 points", strip, \
        {"items": [{"demand": 3, "allowed_orientations": [0, 180],
                    "shape": {"type": "simple_polygon", "data": circle(100000, 100)}}], "strip_height": 1000}, OK, \
        within
    yield "pack: 2,000 ESICUP pieces", strip, \
        {"items": [{"demand": 2000, "allowed_orientations": [0, 180],
                    "shape": {"type": "simple_polygon",
                              "data": [[0, 0], [2100, 60], [3000, 700], [2800, 1400], [1000, 1200], [100, 1440]]}}],
         "strip_height": 4900}, OK, within
    yield "pack: an ESICUP orientation of 45°", strip, \
        {"items": [{"demand": 1, "allowed_orientations": [45],
                    "shape": {"type": "simple_polygon", "data": square(10)}}], "strip_height": 100}, \
        "allowed_orientations", within
    yield "pack: a 1 km ESICUP piece on a thin strip", strip, \
        {"items": [{"demand": 2, "allowed_orientations": [0],
                    "shape": {"type": "simple_polygon", "data": [[0, 0], [1e6, 0], [1e6, 5], [0, 10]]}}],
         "strip_height": 20}, (OK, "items[0]", "items: the strip, gridded at"), within

    yield "solve: 10,000 cuboids", solve, row(10000), OK, 11
    yield "solve: 10,001 cuboids", solve, row(10001), "more than 10000 cuboids", 11
    yield "solve: a chain of 64 joints", solve, chain(64), OK, 11
    yield "solve: a chain of 65 joints", solve, chain(65), "more than 64 joints in a chain", 11
    yield "solve: a chain of 64 hinges", solve, chain(64, "hinge"), OK, 11
    yield "solve: coordinates of 1e6 mm", solve, \
        changed(example("box-with-lid.workslike.json"), ["parts", 0, "cuboids", 0, "max"], [1e6, 1e6, 1e6]), \
        (OK, "cannot hold together"), 11
    yield "solve: a hinge angle of a billion degrees", solve, \
        changed(example("box-with-lid.workslike.json"), ["configurations", 0, "poses", "lid hinge"], 1e9), \
        "lid hinge", 11
    yield "solve: a relationship naming no cuboid", solve, \
        changed(example("box-with-lid.workslike.json"), ["relationships", 0, "faces", 0], "nothing.bottom"), \
        "nothing", 11
    yield "solve: 3,000 relationships", solve, \
        changed(example("box-with-lid.workslike.json"), ["relationships"],
                [dict(r, name="{} {}".format(r["name"], k)) for k in range(300)
                 for r in example("box-with-lid.workslike.json")["relationships"]]), (OK, "relationships"), 11
    yield "solve: 51 configurations of 2,000 cuboids", solve, \
        dict(chain(1), parts=chain(1)["parts"] + row(2000)["parts"][2:],
             configurations=[{"name": "k{}".format(k), "poses": {"j1": k}} for k in range(51)]), \
        "cuboids times configurations", 11
    yield "solve: a minimum size of 0", solve, changed(example("box-with-lid.workslike.json"), ["minimum_size"], 0), \
        OK, 11
    yield "solve: names of control characters", solve, renamed("lid", "li\u0000d\n\u0007"), OK, 11

    yield "printable: a hinged box at 1e6 mm", printable, \
        changed(example("box-with-lid.workslike.json"), ["parts", 0, "cuboids", 0, "max"], [1e6, 80, 50]), \
        (OK, "5000 mm"), 30
    yield "printable: at scale 100", printable + ["--scale", "100"], example("box-with-lid.workslike.json"), \
        "5000 mm", 30
    yield "printable: at scale 0.001", printable + ["--scale", "0.001"], example("box-with-lid.workslike.json"), \
        (OK, "joint 'lid hinge': its parts are too thin"), 30
    yield "printable: a gap of 10 mm", printable + ["--gap", "10"], example("box-with-lid.workslike.json"), \
        (OK, "joint 'lid hinge': its parts are too thin"), 30
    yield "printable: a millisecond per part", printable + ["--part-seconds", "0.001"], \
        example("box-with-lid.workslike.json"), (OK, "seconds"), 30
    yield "printable: a build volume of 1 mm", printable + ["--fit", "1x1x1"], \
        example("box-with-lid.workslike.json"), (OK, "which fits 1 x 1 x 1 mm"), 30
    yield "printable: bodies named alike and CON", printable, \
        renamed("body", "a b", renamed("lid", "a-b", renamed("drawer", "CON"))), OK, 30
    yield "printable: a body named assembly", printable, renamed("lid", "assembly"), OK, 30

    yield "optimise: 5,000 boards touching in a row", optimise, flatpack_row(5000), "parts: more than 200 boards", \
        within
    yield "optimise: 200 boards apart, 5 of each", optimise, \
        changed(flatpack_row(200, touching=False), ["parts", 0, "quantity"], 5), ".quantity: more than 200 boards to cut", within
    yield "optimise: an equality of 100,000 references", optimise, \
        changed(example("chest.flatpack.json"), ["constraints"],
                [{"kind": "equal", "refs": ["plinth-front.size.z"] * 100000}]), "constraints[0].refs", within
    yield "optimise: 1,000 rounds in the time limit", optimise + ["--rounds", "1000"], \
        example("coffee-table.flatpack.json"), OK, within
    yield "optimise: 199,999 parts", optimise, flatpack_row(199999, touching=False), "parts: more than 200 boards", \
        within
    yield "optimise: 200 boards touching in a row", optimise, flatpack_row(200), OK, within
    yield "optimise: a design breaking its own constraints", optimise, \
        changed(example("chest.flatpack.json"), ["constraints"],
                [{"kind": "fixed", "ref": "plinth-front.size.z", "value": 10},
                 {"kind": "fixed", "ref": "plinth-front.size.z", "value": 20}]), \
        "does not satisfy its own constraints: fixed plinth-front.size.z = 10", within
    yield "optimise: a negative seed", optimise + ["--seed", "-1"], example("coffee-table.flatpack.json"), \
        "--seed", within


# --- running them -------------------------------------------------------------------------------------------

def run(cli, argv, timeout):
    """One run, killed past `timeout` seconds: a CompletedProcess with its `seconds` (wall), `cpu_seconds` (work,
    which a busy machine does not stretch as it does wall time) and `peak_kb`, the process's own high-water mark
    read while it runs (wait4's includes what it had before exec, a copy of this script; it stands in for a run
    too short to be read)."""
    began = time.monotonic()
    process = subprocess.Popen([cli] + argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    streams = {}
    readers = [threading.Thread(target=lambda name=name: streams.__setitem__(name, getattr(process, name).read()))
               for name in ("stdout", "stderr")]
    for reader in readers:
        reader.start()
    peak = 0
    while os.waitid(os.P_PID, process.pid, os.WEXITED | os.WNOHANG | os.WNOWAIT) is None:
        try:
            with open("/proc/{}/status".format(process.pid)) as status:
                peak = max([peak] + [int(line.split()[1]) for line in status if line.startswith("VmHWM:")])
        except (OSError, ValueError):
            pass
        if time.monotonic() - began > timeout:
            process.kill()
        time.sleep(0.005)
    _, status, usage = os.wait4(process.pid, 0)
    for reader in readers:
        reader.join()
    result = subprocess.CompletedProcess([cli] + argv, os.waitstatus_to_exitcode(status), streams["stdout"],
                                         streams["stderr"])
    result.seconds = time.monotonic() - began
    result.cpu_seconds = usage.ru_utime + usage.ru_stime
    result.peak_kb = peak or usage.ru_maxrss
    return result


def judge(expect, status, error, seconds, peak, budget, timed):
    """What is wrong with a run, or ''."""
    lines = error.strip().split("\n") if error.strip() else []
    refusals = [expect] if isinstance(expect, str) and expect != OK else \
        [e for e in expect if e != OK] if isinstance(expect, tuple) else []
    finishes = expect == OK or (isinstance(expect, tuple) and OK in expect)
    if peak > MEMORY_KB:
        return "{} MB of memory".format(peak // 1024)
    if timed and seconds > budget:
        return "{:.1f} s, more than {} s".format(seconds, budget)
    if status == 0 and finishes:
        return ""
    if status == 1 and refusals and any(r in error for r in refusals) and len(lines) <= 3 and \
            not any(word in error for word in ("terminate", "Traceback", "internal error", "bad_alloc")):
        return ""
    return "exit {}: {}".format(status, error.strip()[-300:] or "(nothing said)")


def results(cli, limit=2.0, timed=True, only=""):
    """Runs every case: rows (name, exit status, seconds, budget, peak MB, what it said, what is wrong or '')."""
    for name, command, document, expect, budget in cases(limit):
        if only not in name:
            continue
        folder = tempfile.mkdtemp(prefix="fabguide-hostile-")
        try:
            source = os.path.join(folder, "input.json")
            with open(source, "w") as out:
                out.write(document if isinstance(document, str) else json.dumps(document))
            argv = [a.replace("{in}", source).replace("{out}", folder) for a in command] + ["--memory", "2G"]
            r = run(cli, argv, budget + 60)
            status, error, seconds, peak = r.returncode, r.stderr, r.seconds, r.peak_kb
            wrong = judge(expect, status, error, seconds, peak, budget, timed)
        finally:
            shutil.rmtree(folder, ignore_errors=True)
        said = error.strip().split("\n")[-1][:110].replace("|", "/") if status else "finished"
        yield name, status, seconds, budget, peak // 1024, said, wrong


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--only", default="", help="cases whose name contains this")
    parser.add_argument("--time-limit", type=float, default=2)
    parser.add_argument("--untimed", action="store_true", help="do not judge the time (a loaded machine)")
    parser.add_argument("--cli", default=os.path.join(SOURCE, "build", "fabguide"))
    args = parser.parse_args(argv)
    failures = 0
    print("| case | exit | seconds | budget | peak MB | said |")
    print("|---|---:|---:|---:|---:|---|")
    for name, status, seconds, budget, peak, said, wrong in results(args.cli, args.time_limit, not args.untimed,
                                                                     args.only):
        print("| {} | {} | {:.2f} | {} | {} | {} |".format(name, status, seconds, budget, peak,
                                                           ("**" + wrong + "**") if wrong else said), flush=True)
        failures += bool(wrong)
    print("\n{} failures".format(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
