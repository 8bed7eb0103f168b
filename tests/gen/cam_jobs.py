"""Generated furniture taken to the CNC: run inside FreeCAD (`freecadcmd cam_jobs.py` with FABGUIDE_CAM_SEEDS and
FABGUIDE_CAM_OUT set), each seed is a carcass nobody drew (sides, top, bottom, shelves, a back, sometimes a door
with a handle hole; rough sizes; 12-19 mm boards), laid out with random cutting settings (joints, dogbones,
holding tabs, spacing), a tool bit of a random diameter written as a user's *.fctb, and a post-processor (grbl or
linuxcnc). Make CAM Job turns it into jobs and each job is posted; per sheet the G-code and what the independent
checker (gcode_checker.py) needs are written as seed-S-sheet-N.nc / .json. One seed in eight lays the parts out
closer than the tool: that must be refused, naming the Kerf. seed-S.json says what happened to each seed.
FABGUIDE_CAM_SEEDS is a list of seeds and ranges, "0-15,28"."""
import json
import os
import random
import traceback

import FreeCAD
import Part

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import properties
from freecad.fabguide.material import board, cam, layout, master_board


def box(doc, name, size, at):
    obj = doc.addObject("Part::Box", name.replace(" ", ""))
    obj.Label = name
    obj.Length, obj.Width, obj.Height = size
    obj.Placement.Base = FreeCAD.Vector(*at)
    return obj


def carcass(doc, rng):
    """A cabinet of boards meeting at right angles, and sometimes a door in front of it with a round hole."""
    t = rng.choice([12.0, 15.0, 18.0, 19.0])
    w, h, d = rng.uniform(300, 800), rng.uniform(300, 900), rng.uniform(200, 420)
    solids = [box(doc, "Side L", (t, d, h), (0, 0, 0)), box(doc, "Side R", (t, d, h), (w - t, 0, 0)),
              box(doc, "Top", (w - 2 * t, d, t), (t, 0, h - t)), box(doc, "Bottom", (w - 2 * t, d, t), (t, 0, 0))]
    for i in range(rng.randint(0, 2)):
        z = t + (h - 2 * t) * (i + 1) / (3 + rng.random())
        solids.append(box(doc, "Shelf {}".format(i + 1), (w - 2 * t, d - rng.uniform(0, 40), t), (t, 0, z)))
    if rng.random() < 0.5:
        solids.append(box(doc, "Back", (w - 2 * t, t, h - 2 * t), (t, d, t)))
    if rng.random() < 0.5:
        door = box(doc, "Door plate", (w, t, h), (0, -100, 0))
        hole = doc.addObject("Part::Cylinder", "Handle")
        hole.Radius = rng.uniform(10, 25)
        hole.Height = 3 * t
        hole.Placement = FreeCAD.Placement(FreeCAD.Vector(w * rng.uniform(0.2, 0.8), -100 - t, h * 0.7),
                                           FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), -90))
        cut = doc.addObject("Part::Cut", "Door")
        cut.Base, cut.Tool = door, hole
        solids.append(cut)
    doc.recompute()
    boards = [board.create(doc, s, label=s.Label) for s in solids]
    for s in solids:
        s.Visibility = False
    return boards, t


def user_bit(folder, diameter):
    """The user's own end mill: FreeCAD's 5 mm one with another diameter, as a *.fctb file."""
    with open(cam.library_bits()[cam.BITS["end mill"]]) as source:
        bit = json.load(source)
    bit["name"] = "{:g} mm end mill".format(diameter)
    bit["parameter"]["Diameter"] = "{} mm".format(diameter)
    bit["parameter"]["CuttingEdgeHeight"] = "30 mm"
    bit["parameter"]["Length"] = "50 mm"
    path = os.path.join(folder, "endmill-{:g}.fctb".format(diameter))
    with open(path, "w") as out:
        json.dump(bit, out)
    return path


def run(seed, out):
    rng = random.Random(seed)
    doc = FreeCAD.newDocument("cam{}".format(seed))
    try:
        boards, t = carcass(doc, rng)
        masters = [master_board.create(doc, rng.choice([1220.0, 1250.0]), rng.choice([1220.0, 2440.0, 2500.0]), t,
                                       count=0)]
        if rng.random() < 0.4:  # one sheet of plywood, then MDF: each material cut at its own feed and speed
            masters[0].Count = 1
            masters.append(master_board.create(doc, 1220.0, 2440.0, t, count=0, material="MDF"))
        lay = layout.create(doc, boards, masters)
        diameter = rng.choice([3.175, 5.0, 6.0, 6.35])
        too_close = seed % 8 == 7
        lay.Spacing = 0 if too_close else rng.uniform(0, 3)
        lay.Kerf = diameter - (1 if too_close else 0)
        lay.Joints = rng.choice(list(layout.JOINTS))
        lay.Dogbone = diameter if rng.random() < 0.5 else 0
        lay.TabWidth = rng.uniform(4, 8) if rng.random() < 0.5 else 0
        lay.TabBelow = rng.uniform(250, 700)
        lay.Iterations = 20  # bounded work: the layout is not what is tested here
        doc.recompute()
        if properties.failed(lay):
            return {"seed": seed, "outcome": "layout refused", "error": lay.Error}
        post = rng.choice(["grbl", "linuxcnc"])
        through = rng.choice([0.0, cam.THROUGH, 0.5])
        feeds = {m: rng.choice([800.0, cam.FEED, 2400.0]) for m in cam.materials(lay)}  # as the panel gives them
        if rng.random() < 0.3:
            feeds = cam.FEED  # a script's one feed for all
        spindles = {m: rng.choice([12000.0, cam.SPINDLE]) for m in cam.materials(lay)}
        try:
            jobs = cam.make_jobs(lay, bit=user_bit(out, diameter), post=post, through=through, feed=feeds,
                                 spindle=spindles)
        except cam.CamError as error:
            return {"seed": seed, "outcome": "refused", "error": str(error), "too_close": too_close}
        problem, result = json.loads(lay.ProblemJson), json.loads(lay.LayoutJson)
        sheets = fabguide_core.cut_sheets(problem, result)
        placed = fabguide_core.placed_outlines(problem, result)
        for n, (job, sheet) in enumerate(zip(jobs, sheets)):
            stem = os.path.join(out, "seed-{}-sheet-{}".format(seed, n + 1))
            cam.post(job, stem + ".nc")
            roles = {}
            for controller in job.Tools.Group:
                bit = controller.Tool  # its shape file: BitShape up to FreeCAD 1.0, ShapeID from 1.1
                shape = os.path.basename(str(getattr(bit, "BitShape", "") or getattr(bit, "ShapeID", ""))).split(".")[0]
                roles.setdefault(shape, []).append(controller.ToolNumber)
            with open(stem + ".json", "w") as spec:
                json.dump({"seed": seed, "post": post, "thickness": sheet["thickness"], "radius": diameter / 2,
                           "through": through, "material": sheet["material"],
                           "feed": feeds[sheet["material"]] if isinstance(feeds, dict) else feeds,
                           "parts": [dict(p, id=p["part"]) for p in placed if p["board"] == n],
                           "drills": sheet["drills"], "tools": roles, "dogbones": lay.Dogbone.Value > 0,
                           "tabbed": sorted({c["part"] for c in sheet["cuts"] if c["tabbed"] and not c["hole"]}),
                           "tab_width": lay.TabWidth.Value, "labels": sum(map(len, sheet["lettering"])),
                           "strokes": [s for label in sheet["lettering"] for s in label if len(s) > 1]}, spec)
        return {"seed": seed, "outcome": "posted", "sheets": len(jobs), "too_close": too_close,
                "operations": sum(len(j.Operations.Group) for j in jobs)}
    except Exception:  # a crash is a finding: the checker side reports it with its traceback
        return {"seed": seed, "outcome": "crashed", "error": traceback.format_exc()}
    finally:
        FreeCAD.closeDocument(doc.Name)


def seeds(text):
    """'0-15,28,91' -> 0, 1, ..., 15, 28, 91."""
    result = []
    for item in text.split(","):
        first, _, last = item.partition("-")
        result += range(int(first), int(last or first) + 1)
    return result


def main():
    out = os.environ["FABGUIDE_CAM_OUT"]
    os.makedirs(out, exist_ok=True)
    for seed in seeds(os.environ["FABGUIDE_CAM_SEEDS"]):
        with open(os.path.join(out, "seed-{}.json".format(seed)), "w") as report:
            json.dump(run(seed, out), report)


if "FABGUIDE_CAM_OUT" in os.environ:  # run by freecadcmd (which names the script's module after its file)
    main()
