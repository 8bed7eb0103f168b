"""`fabguide printable`: print-in-place bodies written as files that the tools makers use accept: admesh finds
the STL closed and manifold, PrusaSlicer slices the STL and the 3MF, the STEP is ISO 10303-21; the clearance
along every motion is at least the gap; a model whose parts overlap is refused with the pair named."""
import json
import os
import re
import subprocess
import zipfile

import pytest


def printable(fabguide_cli, source_dir, tmp_path, name, *options):
    out = tmp_path / name
    run = subprocess.run([fabguide_cli, "printable", os.path.join(source_dir, "examples", name + ".workslike.json"),
                          "-o", str(out), *options], capture_output=True, text=True, timeout=600)
    return run, out


def report(out):
    """The run's report.json (docs/formats.md)."""
    return json.loads((out / "report.json").read_text())


def clearance(out):
    return report(out)["clearance"]["least_mm"]


def test_the_cellphone_prints_in_place_and_slices(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "cellphone")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) == pytest.approx(0.4, abs=0.01)
    volumes = [b["volume_mm3"] for b in report(out)["bodies"]]
    assert len(volumes) == 3 and report(out)["ok"]
    # admesh: three closed parts, nothing to fix, the volume of the bodies.
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*3\b", mesh), mesh
    for check in ("Total disconnected facets", "Degenerate facets", "Edges fixed", "Facets reversed",
                  "Backwards edges"):
        assert re.search(check + r"\s*:\s*0\b", mesh), check + "\n" + mesh
    stl_volume = float(re.search(r"Volume\s*:\s*([0-9.]+)", mesh).group(1))
    assert stl_volume == pytest.approx(sum(volumes), rel=0.01)
    # PrusaSlicer slices both the STL and the 3MF.
    for source in ("assembly.stl", "assembly.3mf"):
        gcode = tmp_path / (source + ".gcode")
        sliced = subprocess.run(["prusa-slicer", "--export-gcode", "--output", str(gcode), str(out / source)],
                                capture_output=True, text=True, timeout=300)
        assert sliced.returncode == 0, sliced.stdout + sliced.stderr
        assert gcode.read_text().count(";LAYER_CHANGE") > 10
    assert (out / "assembly.step").read_text().startswith("ISO-10303-21;")
    assert (out / "screen.3mf").stat().st_size > 0 and (out / "battery.stl").stat().st_size > 0


def test_the_crate_bed_gets_pins_and_separate_links(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "crate-bed", "--printer", "resin")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) >= 0.2 - 0.01
    bodies = [b["name"] for b in report(out)["bodies"]]
    for link in ("head pivot left", "head pivot right", "foot pivot left", "foot pivot right"):
        assert link + " link" in bodies
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*7\b", mesh), mesh  # bed, two boards, four links


def test_the_sofa_bunks_facing_pivots_get_links_in_recesses(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "sofa-bunk")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) == pytest.approx(0.4, abs=0.01)  # along both configurations, links included
    links = [b for b in report(out)["bodies"] if b["name"] in ("bunk pivot left link", "bunk pivot right link")]
    assert len(links) == 2 and all(b["volume_mm3"] > 0 for b in links)
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*6\b", mesh), mesh
    assert re.search(r"Backwards edges\s*:\s*0\b", mesh), mesh
    assert report(out)["notes"] == []  # the headrest hinge hangs its yokes on the seat across its 20 mm stand-off


def test_overlapping_parts_are_refused_by_name(fabguide_cli, source_dir, tmp_path):
    # The box with a lid, its drawer modelled inside a solid body with no cavity: refused as drawn,
    # rather than moving the drawer or shrinking the body, with what to do.
    model = json.load(open(os.path.join(source_dir, "examples", "box-with-lid.workslike.json")))
    model["parts"][0]["cuboids"] = model["parts"][0]["cuboids"][:1]
    model["relationships"] = [r for r in model["relationships"] if r["type"] != "fit_inside"]
    path = tmp_path / "no-bay.workslike.json"
    path.write_text(json.dumps(model))
    run = subprocess.run([fabguide_cli, "printable", str(path), "-o", str(tmp_path / "out")], capture_output=True,
                         text=True, timeout=600)
    assert run.returncode == 1 and not (tmp_path / "out" / "assembly.stl").exists()
    assert ("'drawn inside: drawer tray in body' cannot hold together; drawn inside: drawer tray in body: nothing "
            "lets them overlap; make a cavity in 'body' where 'drawer tray' goes") in run.stderr, run.stderr


def test_opencascade_past_a_parts_time_budget_stops_with_its_name_not_a_hang(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "toolbox", "--part-seconds", "0.001")
    assert run.returncode == 1
    assert re.search(r"error: geometry: the (union|cut) of '[^']+' took longer than its 0.001 s", run.stderr), run.stderr
    assert "--part-seconds" in run.stderr and "Traceback" not in run.stderr
    assert not (out / "assembly.stl").exists()


def test_the_box_with_a_lid_prints_its_drawer_in_its_bay(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "box-with-lid")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) == pytest.approx(0.4, abs=0.01)
    assert report(out)["loose"] == []  # the bay guides the drawer: no rails cut it


def test_a_scaled_print_keeps_the_gap_and_joints_stand_proud_of_thin_parts_or_are_refused(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "crate-bed", "--scale", "0.2")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) == pytest.approx(0.4, abs=0.01)  # the gap stays in mm
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    x = re.search(r"Min X\s*=\s*([-0-9.]+), Max X\s*=\s*([-0-9.]+)", mesh)
    assert x and float(x.group(2)) - float(x.group(1)) < 1000 * 0.2 + 30  # a fifth of the bed, plus the links
    # At 1:5 the toolbox's lid is 2.8 mm thick: its pin (0.8 mm) and yokes stand proud of it, noted; at 1:10
    # (1.4 mm) there is no room for them.
    run, out = printable(fabguide_cli, source_dir, tmp_path, "toolbox", "--scale", "0.2")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) == pytest.approx(0.4, abs=0.01)
    assert any(n.startswith("lid hinge: its round parts are 3.20 mm across, proud of its 2.80 mm thin part")
               for n in report(out)["notes"])
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*3\b", mesh), mesh
    run, _ = printable(fabguide_cli, source_dir, tmp_path, "toolbox", "--scale", "0.1")
    assert run.returncode == 1
    assert "joint 'lid hinge': its parts are too thin (cuboid 'lid' is 1.4 mm as printed; a pin and its yokes " \
        "need 1.6 mm with a 0.4 mm gap)" in run.stderr


def test_the_cabinet_prints_as_six_connected_bodies_clear_of_each_other(fabguide_cli, source_dir, tmp_path):
    # Pocket doors on sliding hinges (slotted yokes), a flip-up flap, a two-cuboid drawer, a lid.
    run, out = printable(fabguide_cli, source_dir, tmp_path, "cabinet")
    assert run.returncode == 0, run.stdout + run.stderr
    assert clearance(out) == pytest.approx(0.4, abs=0.01)
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*6\b", mesh), mesh  # the drawer's front and box stay one body


@pytest.mark.parametrize("options", [("--gap", "2"), ("--scale", "0.3"), ("--scale", "0.229"), ("--scale", "0.15")])
def test_the_cabinet_prints_at_a_large_gap_and_at_desktop_scales(fabguide_cli, source_dir, tmp_path, options):
    # Parts grown by the gap reach their hinges' lines; their sweeps are made piece by piece on each side of the
    # axis (before: OpenCASCADE errors, or the carcass cut to a fragment). 0.229 fits a 250 x 210 x 210 mm bed;
    # at 0.15 the drawer's modelled 2 mm side play is 0.3 mm, widened to the gap.
    run, out = printable(fabguide_cli, source_dir, tmp_path, "cabinet", *options)
    assert run.returncode == 0, run.stdout + run.stderr
    gap = float(options[1]) if options[0] == "--gap" else 0.4
    scale = float(options[1]) if options[0] == "--scale" else 1.0
    assert clearance(out) == pytest.approx(gap, abs=0.01)
    volumes = {b["name"]: b["volume_mm3"] for b in report(out)["bodies"]}
    assert volumes["carcass"] > 30e6 * scale ** 3, volumes  # 37 litres at 1:1 less its compartments
    mesh = subprocess.run(["admesh", str(out / "assembly.stl")], capture_output=True, text=True).stdout
    assert re.search(r"Number of parts\s*:\s*6\b", mesh), mesh


def test_a_slide_without_a_cavity_runs_on_dovetail_rails(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "sliding-box")
    assert run.returncode == 0, run.stdout + run.stderr
    assert report(out)["loose"] == []
    assert clearance(out) == pytest.approx(0.4, abs=0.01)  # also all along the slide open
    volumes = {b["name"]: b["volume_mm3"] for b in report(out)["bodies"]}
    # The box gained a tongue; the lid (100 x 60 x 8 less its gap) lost a groove.
    assert volumes["box"] > 100 * 60 * 40 - 90 * 50 * 35
    assert volumes["lid"] < 100 * 60 * 8
    gcode = tmp_path / "box.gcode"
    sliced = subprocess.run(["prusa-slicer", "--export-gcode", "--output", str(gcode), str(out / "assembly.3mf")],
                            capture_output=True, text=True, timeout=300)
    assert sliced.returncode == 0, sliced.stdout + sliced.stderr


def test_a_print_fitted_to_a_build_volume_slices_on_that_bed_as_one_object(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "toolbox", "--fit", "250x210x210")
    assert run.returncode == 0, run.stdout + run.stderr
    assert not report(out)["turned"]
    scale = report(out)["scale"]
    assert scale == pytest.approx(250 / 541.6, rel=0.01)  # 539 mm long (1 mm walls), and the hinge stands out
    size = report(out)["size_mm"]
    assert size[0] == pytest.approx(250, abs=0.05) and size[1] <= 210 and size[2] <= 210
    assert clearance(out) == pytest.approx(0.4, abs=0.01)
    # PrusaSlicer slices it on that bed and keeps the bodies together: one object, a part per body.
    bed = ["--bed-shape", "0x0,250x0,250x210,0x210", "--max-print-height", "210"]
    sliced = subprocess.run(["prusa-slicer", "--export-gcode", *bed, "--output", str(tmp_path / "t.gcode"),
                             str(out / "assembly.3mf")], capture_output=True, text=True, timeout=300)
    assert sliced.returncode == 0, sliced.stdout + sliced.stderr
    project = tmp_path / "project.3mf"
    subprocess.run(["prusa-slicer", "--export-3mf", "--output", str(project), str(out / "assembly.3mf")],
                   capture_output=True, text=True, timeout=300, check=True)
    with zipfile.ZipFile(project) as package:
        config = package.read("Metadata/Slic3r_PE_model.config").decode()
    assert config.count("<object ") == 1
    assert sorted(re.findall(r'type="volume" key="name" value="([^"]+)"', config)) == ["box", "lid", "tray"]
    # The tablet (320 x 420 mm open) prints larger turned a quarter: its 420 along the bed's 250.
    run, out = printable(fabguide_cli, source_dir, tmp_path, "tablet", "--fit", "250x210x210")
    assert run.returncode == 0, run.stdout + run.stderr
    assert report(out)["turned"]
    assert report(out)["scale"] == pytest.approx(250 / 420, rel=0.01)
    size = report(out)["size_mm"]
    assert size[0] == pytest.approx(250, abs=0.05) and 190 <= size[1] < 200, size
    sliced = subprocess.run(["prusa-slicer", "--export-gcode", *bed, "--output", str(tmp_path / "tablet.gcode"),
                             str(out / "assembly.3mf")], capture_output=True, text=True, timeout=300)
    assert sliced.returncode == 0, sliced.stdout + sliced.stderr
    # A build volume that is not one is refused by name; one too small for the joints names the scale.
    run, _ = printable(fabguide_cli, source_dir, tmp_path, "toolbox", "--fit", "250x210")
    assert run.returncode != 0 and "--fit: expected width x depth x height in mm" in run.stderr
    run, _ = printable(fabguide_cli, source_dir, tmp_path, "toolbox", "--fit", "40x40x40")
    assert run.returncode == 1 and "joint 'lid hinge': its parts are too thin" in run.stderr
    assert re.search(r"at scale 0\.07\d*, which fits 40 x 40 x 40 mm", run.stderr), run.stderr


def test_a_second_print_into_the_folder_leaves_no_files_of_bodies_since_renamed(fabguide_cli, source_dir, tmp_path):
    run, out = printable(fabguide_cli, source_dir, tmp_path, "cellphone")
    assert run.returncode == 0, run.stderr
    (out / "my notes.txt").write_text("kept")
    model = json.load(open(os.path.join(source_dir, "examples", "cellphone.workslike.json")))
    old = model["parts"][-1]["name"]
    text = json.dumps(model).replace('"{}"'.format(old), '"renamed part"')
    path = tmp_path / "renamed.workslike.json"
    path.write_text(text)
    olds = [f.name for f in out.iterdir() if f.stem.startswith(old.replace(" ", "-")) or f.stem.startswith(old)]
    assert olds, sorted(f.name for f in out.iterdir())
    run = subprocess.run([fabguide_cli, "printable", str(path), "-o", str(out)], capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    left = sorted(f.name for f in out.iterdir())
    assert not set(olds) & set(left), "the old body's files went with the new set: {}".format(left)
    assert "my notes.txt" in left
    assert sorted(os.path.basename(f) for f in report(out)["files"]) == [n for n in left if n != "my notes.txt"]


def test_bodies_whose_names_read_alike_get_files_of_their_own(fabguide_cli, source_dir, tmp_path):
    text = open(os.path.join(source_dir, "examples", "cellphone.workslike.json")).read()
    for old, new in (("base", "a b"), ("screen", "a-b"), ("battery", "con")):  # con: a device on Windows
        text = text.replace('"{}'.format(old), '"{}'.format(new))
    path = tmp_path / "alike.workslike.json"
    path.write_text(text)
    out = tmp_path / "out"
    run = subprocess.run([fabguide_cli, "printable", str(path), "-o", str(out)], capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    stems = sorted({f.stem for f in out.glob("*.stl")})
    assert stems == ["a-b", "a-b-2", "assembly", "con-2"], stems


def test_a_print_longer_than_5_m_is_refused_before_any_geometry(fabguide_cli, source_dir, tmp_path):
    """A model at 1e6 mm or --scale 100 did not finish (meshing its joints to 0.01 mm). The cabinet is
    600 mm wide: at 100 it would be 60 m, refused at once (the 2.1 m sofa bunk prints at 1:1, above)."""
    run, out = printable(fabguide_cli, source_dir, tmp_path, "cabinet", "--scale", "100")
    assert run.returncode == 1
    assert run.stderr.strip() == ("fabguide: error: the print would be 60000 mm long along x; FabGuide prints up "
                                  "to 5000 mm: print it at a smaller scale, or fitted to your printer")
    assert not out.exists()


def test_the_print_writes_the_model_as_it_solved_it(fabguide_cli, tmp_path):
    """A lid drawn 2.4 mm thick, pushed 1 mm into its box: the least change alone thins it to 1.4 mm, under the
    1.6 mm its hinge needs at a 0.4 mm gap, so the print's own solve lifts it instead. solved.workslike.json says
    what the bodies were made from, and reads back as a works-like model."""
    model = {"format": "fabguide.workslike", "version": 1,
             "parts": [{"name": "box", "cuboids": [{"name": "box", "min": [0, 0, 0], "max": [40, 30, 20]},
                                                   {"name": "well", "min": [2, 2, 2], "max": [38, 28, 20],
                                                    "cavity": True}]},
                       {"name": "lid", "cuboids": [{"name": "lid", "min": [0, 0, 18.5], "max": [40, 30, 20.9]}]}],
             "joints": [{"name": "lid hinge", "type": "hinge", "part": "lid", "edge": ["lid.far", "lid.bottom"]}],
             "configurations": [{"name": "open", "poses": {"lid hinge": -90}}],
             "relationships": [{"type": "cover", "name": "lid covers the well", "covering": ["lid"],
                                "covered": ["box"]}]}
    path = tmp_path / "lidded.workslike.json"
    path.write_text(json.dumps(model))

    def lid(solved):
        c = next(c for p in solved["parts"] for c in p["cuboids"] if c["name"] == "lid")
        return c["min"][2], c["max"][2]

    run = subprocess.run([fabguide_cli, "solve", str(path), "-o", str(tmp_path / "solved.workslike.json")],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    low, high = lid(json.loads((tmp_path / "solved.workslike.json").read_text()))
    assert high - low == pytest.approx(1.4, abs=1e-6)
    run = subprocess.run([fabguide_cli, "printable", str(path), "-o", str(tmp_path / "out")],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    out = tmp_path / "out"
    assert "solved.workslike.json" in report(out)["files"]
    low, high = lid(json.loads((out / "solved.workslike.json").read_text()))
    assert high - low == pytest.approx(2.4, abs=1e-6)
    assert "lid: kept 2.4 mm thick, not thinned to 1.4 mm, for a joint's round parts on it (1.6 mm at this scale " \
        "and gap)" in report(out)["notes"]
    again = subprocess.run([fabguide_cli, "solve", str(out / "solved.workslike.json"),
                            "-o", str(tmp_path / "again.workslike.json")], capture_output=True, text=True, timeout=600)
    assert again.returncode == 0, again.stderr
