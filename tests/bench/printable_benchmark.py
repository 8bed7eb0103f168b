"""Print-in-place on the thesis' eight works-like examples (Table 4.1, thesis 4.5): per example the bodies, the
least clearance along every motion and the time at full size, then fitted to a desktop printer's build volume
(`--fit`) and sliced there by PrusaSlicer. Run alone: python3 tests/bench/printable_benchmark.py [build-dir]."""
import json
import os
import subprocess
import sys
import tempfile
import time
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

EXAMPLES = ("cabinet", "crate-bar", "crate-bed", "sofa-bunk", "printer", "cellphone", "tablet", "toolbox")
VOLUME = (250, 210, 210)  # a common desktop FDM printer (Prusa MK3S/MK4)
FIT = "x".join(map(str, VOLUME))


def example(name):
    return os.path.join(ROOT, "examples", name + ".workslike.json")


def printable(build, model, out, *options):
    """One run, as its report.json gives it (docs/formats.md); the error's last line when it failed."""
    started = time.monotonic()
    run = subprocess.run([os.path.join(build, "fabguide"), "printable", model, "-o", out, *options],
                         capture_output=True, text=True)
    seconds = time.monotonic() - started
    path = os.path.join(out, "report.json")
    report = json.load(open(path)) if os.path.exists(path) else {}
    return {"ok": run.returncode == 0, "seconds": seconds, "bodies": len(report.get("bodies", [])),
            "clearance": report.get("clearance", {}).get("least_mm"), "scale": report.get("scale", 1.0),
            "where": report.get("clearance", {}).get("where", ""),
            "turned": report.get("turned", False),
            "size": " x ".join("{:.1f}".format(v) for v in report.get("size_mm", [])),
            "notes": report.get("notes", []) + ["in pieces: " + body for body in report.get("loose", [])],
            "error": run.stderr.strip().splitlines()[-1] if run.returncode and run.stderr.strip() else ""}


def sliced(out):
    """PrusaSlicer on the build volume: layers, and whether it kept the bodies as one object."""
    gcode, project = os.path.join(out, "print.gcode"), os.path.join(out, "project.3mf")
    bed = ["--bed-shape", "0x0,{0}x0,{0}x{1},0x{1}".format(*VOLUME), "--max-print-height", str(VOLUME[2])]
    run = subprocess.run(["prusa-slicer", "--export-gcode", *bed, "--output", gcode,
                          os.path.join(out, "assembly.3mf")], capture_output=True, text=True)
    if run.returncode != 0:
        return "refused: " + (run.stderr.strip().splitlines() or ["?"])[-1].strip()
    subprocess.run(["prusa-slicer", "--export-3mf", "--output", project, os.path.join(out, "assembly.3mf")],
                   capture_output=True, text=True, check=True)
    with zipfile.ZipFile(project) as package:
        config = package.read("Metadata/Slic3r_PE_model.config").decode()
    with open(gcode) as f:
        layers = f.read().count(";LAYER_CHANGE")
    return "sliced, {} layers, {} object of {} parts".format(layers, config.count("<object "), config.count("<volume "))


def run(build):
    rows = []
    for name in EXAMPLES:
        with tempfile.TemporaryDirectory() as full, tempfile.TemporaryDirectory() as fitted:
            row = {"name": name, "full": printable(build, example(name), full),
                   "fitted": printable(build, example(name), fitted, "--fit", FIT)}
            row["slicer"] = sliced(fitted) if row["fitted"]["ok"] else "not made: " + row["fitted"]["error"]
        rows.append(row)
    return rows


def notes(result):
    """Joints whose round parts stand proud of a thin part, by count; any other note in full."""
    proud = sum(" proud of its " in n for n in result["notes"])
    return "; ".join(([] if not proud else ["{} joint{} proud".format(proud, "s" if proud > 1 else "")]) +
                     [n for n in result["notes"] if " proud of its " not in n]) or "-"


def clearance(result):
    return "{:.3f}".format(result["clearance"]) if result["clearance"] is not None else "-"


def table(rows):
    lines = ["## Print-in-place (thesis Table 4.1 examples, 4.5)", "",
             "`fabguide printable examples/NAME.workslike.json -o out` (FDM: 0.4 mm gap), then with `--fit {}`: the "
             "largest scale at which the print fits that build volume upright ('turned': a quarter about z), "
             "sliced there by PrusaSlicer (`prusa-slicer --export-gcode --bed-shape ... --max-print-height {}` on `assembly.3mf`; 'one object of "
             "N parts' is what PrusaSlicer kept after loading it: the bodies stay where they are printed). "
             "Clearance is the least distance between two bodies as printed and at 32 poses along every "
             "configuration's motion (must be >= the gap). Notes: joints whose round parts stand proud of a "
             "thin part (the least pin that prints), or what else the run noted.".format(FIT, VOLUME[2]), "",
             "| example | bodies | clearance mm (1:1) | seconds (1:1) | fitted scale | size mm | clearance mm | notes "
             "| PrusaSlicer |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        full, fit = r["full"], r["fitted"]
        lines.append("| {} | {} | {} | {:.1f} | {:.3g}{} | {} | {} | {} | {} |".format(
            r["name"], full["bodies"] or full["error"], clearance(full), full["seconds"], fit["scale"],
            " turned" if fit["turned"] else "",
            fit["size"], clearance(fit), notes(fit), r["slicer"]))
    return "\n".join(lines)


SUITE = os.path.join(ROOT, "tests", "data", "printable")


def suite(build):
    """The product suite of tests/data/printable: each model fitted to the build volume and sliced."""
    rows = []
    for file in sorted(f for f in os.listdir(SUITE) if f.endswith(".workslike.json")):
        with tempfile.TemporaryDirectory() as out:
            result = printable(build, os.path.join(SUITE, file), out, "--fit", FIT)
            rows.append({"name": file[:-len(".workslike.json")], "fitted": result,
                         "slicer": sliced(out) if result["bodies"] else "not made: " + result["error"]})
    return rows


def suite_table(rows):
    lines = ["Products drawn by a designer who had not seen the code (`tests/data/printable`, see its README), "
             "`--fit {}`; ok = every solid valid and in one piece, the clearance >= the gap along every motion:".format(FIT), "",
             "| product | ok | bodies | clearance mm | where | seconds | notes or error | PrusaSlicer |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        fit = r["fitted"]
        lines.append("| {} | {} | {} | {} | {} | {:.1f} | {} | {} |".format(
            r["name"], "yes" if fit["ok"] else "**no**", fit["bodies"] or "-", clearance(fit), fit["where"] or "-",
            fit["seconds"], fit["error"] or notes(fit), r["slicer"]))
    made = sum(r["fitted"]["ok"] for r in rows)
    lines += ["", "{} of {} products print in place (target: all).".format(made, len(rows))]
    return "\n".join(lines)


WALLS = os.path.join(ROOT, "tests", "data", "workslike")


def wall_line(build, rows, columns):
    """A wall of rows x columns cabinets (make_wall.py; 3 cuboids each) printed at 1:1: the scale target is 200
    cuboids within 60 s."""
    with tempfile.TemporaryDirectory() as out:
        model = os.path.join(out, "wall.workslike.json")
        subprocess.run([sys.executable, os.path.join(WALLS, "make_wall.py"), "--rows", str(rows), "--columns",
                        str(columns), "--output", model], check=True, capture_output=True)
        r = printable(build, model, os.path.join(out, "print"))
    cabinets = rows * columns
    return ("- `make_wall.py --rows {} --columns {}`: {} cabinets, {} parts, {} cuboids, {} hinges, 2 configurations: "
            "{}, {} bodies, clearance {} mm, {:.1f} s".format(rows, columns, cabinets, 2 * cabinets, 3 * cabinets,
                                                          cabinets, "ok" if r["ok"] else "**not ok** " + r["error"],
                                                          r["bodies"], clearance(r), r["seconds"]))


def walls(build):
    return "\n".join(["Walls of cabinets at 1:1 (`tests/data/workslike/make_wall.py`; the committed "
                      "wall-of-cabinets.workslike.json is 4 x 6; issue 15's target: 200 cuboids within 60 s):", ""] +
                     [wall_line(build, rows, columns) for rows, columns in ((4, 6), (7, 10))])


if __name__ == "__main__":
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
    print(table(run(build)) + "\n\n" + suite_table(suite(build)) + "\n\n" + walls(build))
