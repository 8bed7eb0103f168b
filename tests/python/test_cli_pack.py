"""`fabguide pack` on real inputs: the bundled examples and an OR-Datasets strip instance, each
layout checked independently; bad input gives an error that names the field or the part."""
import json
import os
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "bench"))
import layout_check  # noqa: E402
import outline_check  # noqa: E402


def pack(cli, *args):
    return subprocess.run([cli, "pack", *args], capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("example", ["bookshelf", "coffee-table"])
def test_examples_pack_into_valid_layouts(fabguide_cli, source_dir, tmp_path, example):
    source = os.path.join(source_dir, "examples", example + ".pack.json")
    out = tmp_path / "layout.json"
    run = pack(fabguide_cli, source, "-o", str(out), "--time-limit", "0.3")
    assert run.returncode == 0, run.stderr
    problem, layout = json.load(open(source)), json.load(out.open())
    settings = problem["settings"]
    boards = layout["boards"]
    bad = layout_check.problems(layout, layout_check.demand_of_pack_problem(problem),
                                lambda b: (boards[b]["width"], boards[b]["height"], settings["trim"]),
                                clearance=settings["kerf"] + settings["spacing"])
    assert bad == []
    assert 0 < layout["sheet_utilisation"] <= layout["usage"] <= 1
    assert "usage" in run.stdout and "utilisation" in run.stdout


def test_strip_instance_reaches_a_near_optimal_height(fabguide_cli, benchmarks, tmp_path):
    path = os.path.join(benchmarks, "packing", "hopper-turton-c", "C1_1.json")
    instance = json.load(open(path))
    out = tmp_path / "layout.json"
    run = pack(fabguide_cli, "--strip", path, "-o", str(out), "--time-limit", "0.5")
    assert run.returncode == 0, run.stderr
    layout = json.load(out.open())
    width, optimum = instance["Objects"][0]["Length"], instance["Objects"][0]["Height"]
    assert layout_check.problems(layout, layout_check.demand_of_strip_instance(instance),
                                 lambda b: (width, layout["strip_height"], 0)) == []
    assert optimum <= layout["strip_height"] <= optimum * 1.10
    assert all(isinstance(p["part"], int) for p in layout["placements"])


def test_malformed_input_names_the_field(fabguide_cli, tmp_path):
    bad = tmp_path / "bad.pack.json"
    bad.write_text(json.dumps({"boards": [{"width": 100, "height": 100}], "parts": [{"id": "a", "width": 10}]}))
    run = pack(fabguide_cli, str(bad), "-o", str(tmp_path / "out.json"))
    assert run.returncode == 1
    assert "parts[0].height: missing" in run.stderr
    assert not (tmp_path / "out.json").exists()


def test_invalid_json_names_the_file(fabguide_cli, tmp_path):
    bad = tmp_path / "broken.pack.json"
    bad.write_text("{\"boards\": [")
    run = pack(fabguide_cli, str(bad), "-o", str(tmp_path / "out.json"))
    assert run.returncode == 1 and "broken.pack.json: not valid JSON" in run.stderr


def test_oversized_part_is_named(fabguide_cli, tmp_path):
    problem = tmp_path / "big.pack.json"
    problem.write_text(json.dumps({"boards": [{"width": 100, "height": 100}],
                                   "parts": [{"id": "table top", "width": 150, "height": 120}]}))
    run = pack(fabguide_cli, str(problem), "-o", str(tmp_path / "out.json"))
    assert run.returncode == 1
    assert "part 'table top' is larger than every master board" in run.stderr


def test_a_part_longer_than_the_grain_allows_is_named(fabguide_cli, tmp_path):
    # 1500 mm along the grain, which runs across a 2440 x 1220 sheet: it fits only turned, which the grain forbids.
    problem = tmp_path / "grain.pack.json"
    problem.write_text(json.dumps({"boards": [{"width": 2440, "height": 1220, "grain": "height"}],
                                   "parts": [{"id": "side", "width": 1500, "height": 300, "follow_grain": True}]}))
    run = pack(fabguide_cli, str(problem), "-o", str(tmp_path / "out.json"))
    assert run.returncode == 1
    assert "part 'side' is larger than every master board (1500 x 300 mm)" in run.stderr


def test_help_lists_the_commands(fabguide_cli):
    run = subprocess.run([fabguide_cli, "--help"], capture_output=True, text=True)
    assert run.returncode == 0
    assert "pack" in run.stdout and "version" in run.stdout


def test_cut_sheets_open_in_inkscape_and_ezdxf(fabguide_cli, source_dir, tmp_path):
    import csv
    import struct
    import xml.etree.ElementTree as ET

    import ezdxf

    source = os.path.join(source_dir, "examples", "bookshelf.pack.json")
    sheets = tmp_path / "sheets"
    run = pack(fabguide_cli, source, "-o", str(tmp_path / "layout.json"), "--time-limit", "0.3",
               "--svg", str(sheets), "--dxf", str(sheets), "--csv", str(tmp_path / "cutlist.csv"))
    assert run.returncode == 0, run.stderr
    layout = json.load((tmp_path / "layout.json").open())
    board = layout["boards"][0]

    # Inkscape renders the SVG at 25.4 dpi to exactly one pixel per millimetre of the board.
    png = tmp_path / "sheet.png"
    subprocess.run(["inkscape", str(sheets / "sheet-1.svg"), "--export-type=png", "--export-filename=" + str(png),
                    "--export-dpi=25.4"], check=True, capture_output=True, timeout=120)
    width, height = struct.unpack(">II", png.read_bytes()[16:24])
    assert (width, height) == (board["width"], board["height"])
    svg = (sheets / "sheet-1.svg").read_text()
    assert 'width="{:g}mm"'.format(board["width"]) in svg and 'id="outer-cut"' in svg and 'id="engrave"' in svg
    assert svg.count('inkscape:groupmode="layer"') >= 4  # sheet, engrave, inner cut, outer cut (drills: per depth)

    # ezdxf reads the DXF as R2000 with no audit errors, millimetre units and one cut per part.
    doc = ezdxf.readfile(str(sheets / "sheet-1.dxf"))
    assert doc.dxfversion >= "AC1015"
    audit = doc.audit()
    assert not audit.has_errors and not audit.has_fixes, [f.message for f in audit.fixes]
    assert doc.header["$INSUNITS"] == 4
    entities = [(e.dxftype(), e.dxf.layer) for e in doc.modelspace()]
    parts_on_board = [p for p in layout["placements"] if p["board"] == 0]
    assert entities.count(("LWPOLYLINE", "OUTER_CUT")) == len(parts_on_board)
    labels = [e for e in doc.modelspace().query('LWPOLYLINE[layer=="ENGRAVE"]') if not e.closed]
    assert len(labels) >= 2 * len(parts_on_board) and entities.count(("TEXT", "ENGRAVE")) == 0  # strokes, no text
    lettered = ET.fromstring(svg).findall(".//{http://www.w3.org/2000/svg}g[@data-label]")
    assert sorted(g.get("data-label") for g in lettered) == sorted(p["part"] for p in parts_on_board)
    assert "<text" not in svg.split('id="saw"')[0], "laser software drops or substitutes fonts"
    assert entities.count(("LWPOLYLINE", "SHEET")) == 1

    rows = list(csv.DictReader((tmp_path / "cutlist.csv").open()))
    assert sum(int(r["quantity"]) for r in rows) == len(layout["placements"])
    assert {r["material"] for r in rows} == {"birch plywood"} and {r["thickness"] for r in rows} == {"18"}


def test_as_designed_cut_sheets_are_nominal_closed_and_list_their_tabs(fabguide_cli, source_dir, tmp_path):
    # For CAM that offsets by its own tool: every outer cut is the part's rectangle exactly (no kerf/2, which
    # the CAM would add again), closed, no dogbones; the holding tabs are lines on a TABS layer, two per part.
    import xml.etree.ElementTree as ET

    import ezdxf

    problem = json.load(open(os.path.join(source_dir, "examples", "bookshelf.pack.json")))
    problem["settings"].update({"kerf": 6, "dogbone": 6, "tab_width": 8, "tab_below": 100000})
    src = tmp_path / "job.pack.json"
    src.write_text(json.dumps(problem))
    for designed in (True, False):
        out = tmp_path / ("designed" if designed else "machine")
        run = pack(fabguide_cli, str(src), "-o", str(out / "layout.json"), "--iterations", "5", "--dxf", str(out),
                   "--svg", str(out), *(["--as-designed"] if designed else []))
        assert run.returncode == 0, run.stderr
        layout = json.load((out / "layout.json").open())
        on_board = [p for p in layout["placements"] if p["board"] == 0]
        doc = ezdxf.readfile(str(out / "sheet-1.dxf"))
        assert not doc.audit().has_errors
        outers = doc.modelspace().query('LWPOLYLINE[layer=="OUTER_CUT"]')
        tabs = doc.modelspace().query('LINE[layer=="TABS"]')
        if designed:
            boxes = sorted((round(min(x for x, *_ in e.get_points()), 6), round(min(y for _, y, *_ in e.get_points()), 6),
                            round(max(x for x, *_ in e.get_points()), 6), round(max(y for _, y, *_ in e.get_points()), 6))
                           for e in outers)
            assert boxes == sorted((round(p["x"], 6), round(p["y"], 6), round(p["x"] + p["width"], 6),
                                    round(p["y"] + p["height"], 6)) for p in on_board)
            assert all(e.closed for e in outers) and len(tabs) == 2 * len(on_board)
            layers = [g.get("{http://www.inkscape.org/namespaces/inkscape}label")
                      for g in ET.parse(str(out / "sheet-1.svg")).getroot()
                      if g.get("{http://www.inkscape.org/namespaces/inkscape}groupmode") == "layer"]
            assert "Holding tabs (not cut)" in layers and "Outer cut" in layers, layers
        else:
            assert not any(e.closed for e in outers) and len(tabs) == 0, "tabs are gaps in the machine's paths"


def test_an_esicup_irregular_instance_packs_valid_on_its_outlines(fabguide_cli, benchmarks, tmp_path):
    import esicup_benchmark

    path = os.path.join(benchmarks, "packing", "esicup-irregular", "jakobs1.json")
    out = tmp_path / "layout.json"
    run = pack(fabguide_cli, "--strip", path, "-o", str(out), "--time-limit", "1")
    assert run.returncode == 0, run.stderr
    instance, layout = json.load(open(path)), json.load(out.open())
    assert layout["boards"][0]["width"] == instance["strip_height"]  # turned a quarter: its height our width
    assert outline_check.problems(layout, esicup_benchmark.as_problem(instance)) == []
    pieces = sum(item["demand"] * esicup_benchmark.area(item["shape"]["data"]) for item in instance["items"])
    assert pieces / (instance["strip_height"] * layout["strip_height"]) > 0.70  # the record is 0.8925
    instance["items"][3]["shape"]["type"] = "multi_polygon"
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(instance))
    run = pack(fabguide_cli, "--strip", str(bad), "-o", str(tmp_path / "x.json"))
    assert run.returncode != 0 and "items[3].shape.type" in run.stderr


def test_small_parts_are_cut_from_the_holes_of_big_ones(fabguide_cli, source_dir, tmp_path):
    # Picture frames whose windows would be waste, a side table top with a cable hole, hexagon coasters with a
    # hole, key tags: every coaster and tag is laid in a window or the cable hole, clear of its edge by the kerf
    # and spacing (checked on the outlines), and the router cuts each of them before the hole around it.
    import ezdxf

    source = os.path.join(source_dir, "tests", "data", "holes-job.pack.json")
    run = pack(fabguide_cli, source, "-o", str(tmp_path / "layout.json"), "--time-limit", "2", "--dxf",
               str(tmp_path / "dxf"))
    assert run.returncode == 0, run.stderr
    problem, layout = json.load(open(source)), json.load((tmp_path / "layout.json").open())
    assert outline_check.problems(layout, problem) == []
    parts = {p["id"]: p for p in problem["parts"]}
    shapes = [(p["part"], p["board"], outline_check.placed(parts[p["part"]], p)) for p in layout["placements"]]
    guests = [(part, board, rings) for part, board, rings in shapes if part in ("coaster", "key tag")]
    assert len(guests) == 18
    for part, board, rings in guests:
        assert any(b == board and any(outline_check.inside(hole, rings[0][0]) for hole in host[1:])
                   for _, b, host in shapes), part
    assert len(layout["boards"]) == 2  # the second for a shelf only
    for sheet in sorted((tmp_path / "dxf").glob("sheet-*.dxf")):
        cuts = [[tuple(p[:2]) for p in e.get_points()]
                for e in ezdxf.readfile(str(sheet)).modelspace().query('LWPOLYLINE[layer ? ".*_CUT"]')]
        for i, inner in enumerate(cuts):  # a cut comes after every cut it encloses
            for j, outer in enumerate(cuts):
                if i != j and all(outline_check.inside(outer, q) for q in inner[:3]):
                    assert i < j, (sheet.name, i, j)


def test_curved_parts_get_their_labels_in_their_material(fabguide_cli, source_dir, tmp_path):
    # Round seats with a hand hole, crescents, coasters with a hole, an L top, tapered legs: each label's centre
    # and both ends of its text lie in the part's material (checked here against the cut paths: inside the
    # part's outer cut, in none of its hole cuts), and the DXF turns a label along a standing leg.
    import ezdxf

    source = os.path.join(source_dir, "tests", "data", "curved-parts.pack.json")
    run = pack(fabguide_cli, source, "-o", str(tmp_path / "layout.json"), "--time-limit", "1", "--dxf",
               str(tmp_path / "dxf"), "--text-labels")
    assert run.returncode == 0, run.stderr
    doc = ezdxf.readfile(str(tmp_path / "dxf" / "sheet-1.dxf"))
    assert not doc.audit().has_errors
    cuts = [[tuple(p[:2]) for p in e.get_points()] for e in doc.modelspace().query('LWPOLYLINE[layer ? ".*_CUT"]')]
    texts = list(doc.modelspace().query("TEXT"))
    assert texts
    for text in texts:
        x, y = text.dxf.insert.x, text.dxf.insert.y
        half = 0.3 * text.dxf.height * len(text.dxf.text)
        along = round(text.dxf.rotation) % 180 == 90
        for px, py in ((x, y), (x + (0 if along else half), y + (half if along else 0)),
                       (x - (0 if along else half), y - (half if along else 0))):
            around = [c for c in cuts if outline_check.inside(c, (px, py))]
            # inside exactly one outer cut and no hole: the innermost path holding it is its part's outline
            assert len(around) == 1, (text.dxf.text, px, py, len(around))


def test_free_rotation_lays_slats_across_offcuts_too_small_for_them_square(fabguide_cli, source_dir, tmp_path):
    # 620 mm slats on 500 mm offcuts fit only turned across the diagonal; gussets may turn freely; the name plate
    # follows the grain and keeps its quarter turns. Checked on the real outlines, and the DXF audited.
    import ezdxf

    source = os.path.join(source_dir, "tests", "data", "free-rotation.pack.json")
    square = pack(fabguide_cli, source, "-o", str(tmp_path / "square.json"))
    assert square.returncode != 0 and "part 'slat' is larger than every master board" in square.stderr
    run = pack(fabguide_cli, source, "-o", str(tmp_path / "layout.json"), "--rotation-step", "15", "--time-limit",
               "2", "--dxf", str(tmp_path / "dxf"), "--svg", str(tmp_path / "svg"))
    assert run.returncode == 0, run.stderr
    problem, layout = json.load(open(source)), json.load((tmp_path / "layout.json").open())
    assert outline_check.problems(layout, problem, rotation_step=15) == []
    assert outline_check.problems(layout, problem) != []  # the checker refuses the same turns when not asked for
    turns = {p["part"]: p["rotation"] for p in layout["placements"]}
    assert turns["slat"] % 90 != 0 and turns["slat"] % 15 == 0
    assert turns["name plate"] in (0, 180)
    assert len(layout["boards"]) == 2
    for dxf in sorted((tmp_path / "dxf").iterdir()):
        doc = ezdxf.readfile(str(dxf))
        auditor = doc.audit()
        assert not auditor.has_errors, [str(e) for e in auditor.errors]
    bad = pack(fabguide_cli, source, "-o", str(tmp_path / "bad.json"), "--rotation-step", "7")
    assert bad.returncode != 0 and "rotation_step must divide 90" in bad.stderr and "Traceback" not in bad.stderr
