"""Make CAM Job, end to end on furniture nobody drew: tests/gen/cam_jobs.py makes each seed's carcass, lays it out,
makes the CAM jobs in FreeCAD (freecadcmd, this machine's FreeCAD: Path in 0.20, CAM in 1.0) and posts them with
grbl or linuxcnc; the independent checker (tests/gen/gcode_checker.py) then reads every G-code file as a machine
would and judges it against the parts as designed. The checker itself is shown to fail on spoiled G-code."""
import glob
import json
import os
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "gen"))
import gcode_checker  # noqa: E402
from cam_jobs import seeds  # noqa: E402
from conftest import sample  # noqa: E402

# CI: 8 designs (FABGUIDE_SAMPLE=N: one in N of them, as CI's Debian 13 run judges), and every seed that once
# failed (tags the dressup dropped on finger notches, a hole's offset within CAM's tolerance);
# FABGUIDE_CAM_SEEDS=0-999 for a benchmark run.
SEEDS = os.environ.get("FABGUIDE_CAM_SEEDS", ",".join(map(str, sample(range(8)))) + ",28,91,114,125,134,198")



@pytest.fixture(scope="module")
def posted(tmp_path_factory, source_dir):
    out = str(tmp_path_factory.mktemp("cam"))
    env = dict(os.environ, FABGUIDE_CAM_SEEDS=SEEDS, FABGUIDE_CAM_OUT=out)
    run = subprocess.run(["freecadcmd", os.path.join(source_dir, "tests", "gen", "cam_jobs.py")], env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=1800)
    wanted = seeds(SEEDS)
    reports = [json.load(open(os.path.join(out, "seed-{}.json".format(s)))) for s in wanted
               if os.path.exists(os.path.join(out, "seed-{}.json".format(s)))]
    assert len(reports) == len(wanted), run.stdout[-3000:]
    return out, reports


def check(spec, gcode):
    tools = spec["tools"]
    return gcode_checker.problems(
        gcode, spec["parts"], spec["thickness"], spec["radius"], mill=tools["endmill"][0],
        drill_tools=tools.get("drill", []), engrave_tool=(tools.get("v-bit") or [None])[0] if spec["labels"] else None,
        drills=spec["drills"], strokes=spec["strokes"], tabbed=set(spec["tabbed"]), tab_width=spec["tab_width"],
        dogbones=spec["dogbones"], through=spec["through"], feed=spec["feed"])


def sheets(out):
    for path in sorted(glob.glob(os.path.join(out, "seed-*-sheet-*.json"))):
        with open(path) as spec, open(path[:-5] + ".nc") as gcode:
            yield os.path.basename(path), json.load(spec), gcode.read()


def test_every_design_is_posted_or_refused_by_name(posted):
    _, reports = posted
    crashed = [r for r in reports if r["outcome"] == "crashed"]
    assert not crashed, crashed[0]["error"]
    for r in reports:
        if r.get("too_close"):
            assert r["outcome"] == "refused" and "Kerf" in r["error"], r
        else:
            assert r["outcome"] == "posted", r
    assert sum(r["outcome"] == "posted" for r in reports) >= len(reports) * 3 // 4


def test_every_posted_sheet_passes_the_checker(posted):
    out, _ = posted
    results = {name: check(spec, gcode) for name, spec, gcode in sheets(out)}
    assert results
    failed = {name: found for name, found in results.items() if found}
    assert not failed, json.dumps(failed, indent=1)[:3000]


def test_the_jobs_cut_drill_engrave_and_tag(posted):
    """The generated designs between them use every operation, so each kind is checked above."""
    out, _ = posted
    specs = [spec for _, spec, _ in sheets(out)]
    assert any(s["drills"] for s in specs) and any(s["tabbed"] for s in specs)
    assert any(s["dogbones"] for s in specs) and any(s["labels"] for s in specs)
    assert {s["post"] for s in specs} == {"grbl", "linuxcnc"}
    assert {s["material"] for s in specs} == {"plywood", "MDF"}, "sheets of two materials, each at its own feed"
    assert any(p["holes"] for s in specs for p in s["parts"])


def spoiled(gcode, change):
    """The G-code with every X word changed by `change`."""
    import re
    return re.sub(r"X(-?\d+\.?\d*)", lambda m: "X{:.3f}".format(change(float(m.group(1)))), gcode)


def test_the_checker_finds_spoiled_gcode(posted):
    out, _ = posted
    name, spec, gcode = next(iter(sheets(out)))
    assert check(spec, gcode) == [], name
    assert any("cuts into" in p for p in check(spec, spoiled(gcode, lambda x: x + 1.0)))  # shifted 1 mm
    import re
    low = min(float(z) for z in re.findall(r"Z(-?\d+\.\d+)", gcode))
    assert abs(low + spec["through"]) < 0.01, "the profiles cut to the allowance below the sheet"
    shallow = gcode.replace("Z{:.3f}".format(low), "Z{:.3f}".format(low + 1))  # the last pass 1 mm short
    assert any("not cut through" in p for p in check(spec, shallow))
    assert any("not cut through" in p for p in check(dict(spec, through=spec["through"] + 0.3), gcode))
    deep = gcode.replace("Z{:.3f}".format(low), "Z{:.3f}".format(low - 1))  # 1 mm into the machine's bed
    assert any("below the sheet" in p for p in check(spec, deep))
    assert check(dict(spec, radius=spec["radius"] + 1), gcode)  # a fatter tool than the one used
    assert any("fed at" in p for p in check(dict(spec, feed=spec["feed"] + 100), gcode))  # another material's feed
    cut = gcode.splitlines()
    assert check(spec, "\n".join(cut[: len(cut) // 2]))  # half the program


def test_a_feed_is_given_for_all_or_per_material_and_a_missing_one_is_named():
    from freecad.fabguide.material import cam

    assert cam.for_material(1200, "MDF", "feed") == 1200
    assert cam.for_material({"MDF": 900, "oak": 1800}, "oak", "feed") == 1800
    with pytest.raises(cam.CamError, match=r"^no spindle speed for the material 'oak' \(given for 'MDF'\)$"):
        cam.for_material({"MDF": 18000}, "oak", "spindle speed")
