"""Flat-pack document objects, headless: boards from solids, faces and sketches; master boards; the
layout recomputes, names its errors, survives save/reload and undo, and exports its cut sheets."""
import json
import os
import math
import xml.etree.ElementTree as ET

import FreeCAD
import Part
import Sketcher
import pytest

from freecad.fabguide.material import board, layout, master_board


@pytest.fixture
def doc():
    document = FreeCAD.newDocument("material")
    name = document.Name
    yield document
    if name in FreeCAD.listDocuments():  # a test may have closed it already
        FreeCAD.closeDocument(name)


def box(doc, name, x, y, z, at=(0, 0, 0), rotation=None):
    obj = doc.addObject("Part::Box", name)
    obj.Length, obj.Width, obj.Height = x, y, z
    obj.Placement.Base = FreeCAD.Vector(*at)
    if rotation:
        obj.Placement.Rotation = rotation
    return obj


def shelf_unit(doc):
    """Two 18 mm sides and three shelves as plain Part boxes, then boards made from them."""
    parts = [box(doc, "SideL", 18, 300, 800), box(doc, "SideR", 18, 300, 800, at=(582, 0, 0))]
    parts += [box(doc, "Shelf{}".format(i), 564, 300, 18, at=(18, 0, 100 + 300 * i)) for i in range(3)]
    doc.recompute()
    boards = [board.create(doc, p, label=p.Label.lower()) for p in parts]
    masters = [master_board.create(doc, 1220, 1220, 18, count=0, material="birch plywood")]
    doc.recompute()
    return boards, masters


def test_thickness_and_outline_are_detected_from_thin_solids(doc):
    tilted = box(doc, "Tilted", 400, 250, 12, rotation=FreeCAD.Rotation(FreeCAD.Vector(1, 1, 0), 37))
    doc.recompute()
    b = board.create(doc, tilted, thickness=99)
    doc.recompute()
    assert not b.Error
    assert b.Thickness.Value == pytest.approx(12)
    assert (b.OutlineWidth.Value, b.OutlineHeight.Value) == (pytest.approx(400), pytest.approx(250))


def test_a_board_sits_where_its_source_is(doc):
    moved = box(doc, "Moved", 400, 250, 12, at=(30, 20, 400), rotation=FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 30))
    doc.recompute()
    b = board.create(doc, moved)
    doc.recompute()
    doc.recompute()  # stable on a second recompute too
    for corner in range(8):
        assert (b.Shape.BoundBox.getPoint(corner) - moved.Shape.BoundBox.getPoint(corner)).Length < 1e-9
    frame = board.as_board3(b, "moved")
    assert frame["origin"][2] == pytest.approx(400) or frame["origin"][2] == pytest.approx(412)


def test_a_face_or_a_sketch_with_a_hole_becomes_a_board(doc):
    slab = box(doc, "Slab", 300, 200, 50)
    doc.recompute()
    from_face = board.create(doc, slab, "Face6", thickness=6)  # the top face
    sketch = doc.addObject("Sketcher::SketchObject", "Ring")
    sketch.addGeometry(Part.Circle(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1), 100))
    sketch.addGeometry(Part.Circle(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1), 40))
    ring = board.create(doc, sketch, thickness=6)
    doc.recompute()
    assert from_face.Shape.Volume == pytest.approx(300 * 200 * 6)
    assert ring.Shape.Volume == pytest.approx(math.pi * (100 ** 2 - 40 ** 2) * 6, rel=1e-6)
    part = board.as_board3(ring, "ring")
    assert len(part["holes"]) == 1 and len(part["outline"]) > 100  # the circle is sampled finely


def test_selection_names_of_freecad_1_are_understood():
    assert board.element_name(";g543;SKT;:H1,F.Face3") == "Face3"
    assert board.element_name("Face12") == "Face12"


SQUARE = [(0, 0), (100, 0), (100, 100), (0, 100), (0, 0)]


@pytest.mark.parametrize("make, message", [
    (lambda doc: Part.makeSphere(50), "has no planar face"),
    (lambda doc: Part.makeCone(50, 20, 80), "not a flat board"),
    (lambda doc: Part.makeBox(10, 10, 10).fuse(Part.makeBox(30, 30, 5)), "not a flat board"),
    (lambda doc: Part.makeBox(150, 150, 150), "150 mm thick and 150 mm wide, a block or a post"),
    (lambda doc: Part.makeBox(50, 50, 700), "50 mm thick and 50 mm wide, a block or a post"),
    (lambda doc: Part.makeCylinder(20, 40), "40 mm thick and 40 mm wide, a block or a post"),
    (lambda doc: Part.Compound([Part.makePolygon([FreeCAD.Vector(x, y, z) for x, y in SQUARE]) for z in (0, 50)]),
     "its closed wires do not lie in one plane"),  # the sheets of a layout, drawn at their heights
    (lambda doc: Part.makePolygon([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(100, 0, 0), FreeCAD.Vector(0, 0, 9)]),
     "needs closed wires"),
])
def test_shapes_that_are_not_boards_are_refused_by_name(doc, make, message):
    source = doc.addObject("Part::Feature", "Blob")
    source.Shape = make(doc)
    b = board.create(doc, source, label="Odd")
    with pytest.raises(board.BoardError, match="Board 'Odd' \\(source 'Blob'\\): .*" + message):
        b.Proxy.recompute(b)
    doc.recompute()
    assert b.Error


def test_fabguides_own_objects_make_no_board(doc):
    """A master board (a layout, a board) is FabGuide's, not a part of the model: no board is made of it whole."""
    master = master_board.create(doc, thickness=18)
    doc.recompute()
    with pytest.raises(board.BoardError, match="^'MasterBoard': is FabGuide's Master board, not a part of your model"):
        board.slab_of(master, None, 18, "'{}'".format(master.Label))


def test_layout_packs_every_board_and_reports_usage(doc):
    boards, masters = shelf_unit(doc)
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    assert not lay.Error
    result = json.loads(lay.LayoutJson)
    assert len(result["placements"]) == 5 and lay.SheetCount == len(result["boards"]) == 1
    assert 0 < lay.SheetUtilisation <= lay.Usage <= 1
    assert lay.WasteArea.Value == pytest.approx(1220 * 1220 - (2 * 800 * 300 + 3 * 564 * 300))
    assert len(lay.Shape.Faces) == 1 + 5  # the sheet and the parts
    model = boards[0].Shape.BoundBox
    for b in boards[1:]:
        model.add(b.Shape.BoundBox)
    assert lay.Shape.BoundBox.XMin > model.XMax  # shown beside the model, not on it


def test_changing_a_board_updates_the_layout(doc):
    boards, masters = shelf_unit(doc)
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    before = lay.Usage
    boards[2].Quantity = 2
    doc.recompute()
    assert len(json.loads(lay.LayoutJson)["placements"]) == 6
    assert lay.Usage != before


def test_layout_errors_name_the_board_at_fault(doc):
    boards, masters = shelf_unit(doc)
    lay = layout.create(doc, boards, masters)
    masters[0].Thickness = 12
    doc.recompute()
    assert lay.Error
    with pytest.raises(layout.LayoutError, match="'sidel' is 18 mm thick: no master board is"):
        lay.Proxy.recompute(lay)
    masters[0].Thickness = 18
    masters[0].Width, masters[0].Height = 500, 500
    with pytest.raises(layout.LayoutError, match="board 'side.' is larger than every master board|part 'side.'"):
        lay.Proxy.recompute(lay)
    assert all(not b.Error for b in boards)  # the user's boards are untouched


def test_boards_of_two_thicknesses_are_each_cut_from_master_boards_of_theirs(doc):
    boards, masters = shelf_unit(doc)
    back = board.create(doc, box(doc, "Back", 600, 6, 800, at=(0, 300, 0)), thickness=6, label="back")
    thin = master_board.create(doc, 1220, 1220, 6, label="hardboard")
    lay = layout.create(doc, boards + [back], masters + [thin])
    doc.recompute()
    assert not lay.Error, lay.Error
    laid = json.loads(lay.LayoutJson)
    sheets = {i: b["name"] for i, b in enumerate(laid["boards"])}
    on = {p["part"]: sheets[p["board"]] for p in laid["placements"]}
    assert on["back"] == "hardboard" and all(on[b.Label] != "hardboard" for b in boards), on


def test_save_and_reload_reproduce_the_layout(doc, tmp_path):
    boards, masters = shelf_unit(doc)
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    saved, name = lay.LayoutJson, lay.Name
    path = str(tmp_path / "shelf.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        again = reopened.getObject(name)
        assert again.LayoutJson == saved
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        assert not again.Error
        assert again.LayoutJson == saved
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_undo_removes_a_layout_in_one_step(doc):
    doc.UndoMode = 1
    boards, masters = shelf_unit(doc)
    doc.openTransaction("Layout")
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    doc.commitTransaction()
    name = lay.Name
    doc.undo()
    assert doc.getObject(name) is None
    assert all(doc.getObject(b.Name) for b in boards)


def test_export_writes_what_the_layout_shows(doc, tmp_path):
    boards, masters = shelf_unit(doc)
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    written = layout.export_cut_sheets(lay, str(tmp_path / "sheets"))
    names = sorted(p.split("/")[-1] for p in written)
    assert names == ["Layout-cutlist.csv", "Layout-labels.pdf", "Layout-opticutter.csv", "Layout-report.pdf", "Layout-sheet-1.dxf",
                     "Layout-sheet-1.svg"]
    svg = (tmp_path / "sheets" / "Layout-sheet-1.svg").read_text()
    cuts = ET.fromstring(svg).findall(".//{http://www.w3.org/2000/svg}g[@id='outer-cut']/{http://www.w3.org/2000/svg}path")
    assert 'width="1220mm"' in svg and len(cuts) == 5 and 'data-label="sidel"' in svg
    csv = (tmp_path / "sheets" / "Layout-cutlist.csv").read_text().splitlines()
    assert csv[0] == ("part,quantity,width,height,thickness,material,board,grain,edge_L1,edge_L2,edge_W1,edge_W2,"
                      "label") and len(csv) == 6


def test_edge_banding_picked_on_a_face_reaches_the_cut_list_and_the_sheet(doc, tmp_path):
    """A shelf's front face is the side of its outline it lies on; the band goes into the problem, the cut list
    and the drawing, along that edge of the placed part."""
    boards, masters = shelf_unit(doc)
    shelf = boards[2]
    front = next("Face{}".format(i + 1) for i, f in enumerate(shelf.Shape.Faces)
                 if abs(f.normalAt(0, 0).y + 1) < 1e-9)  # the face towards -y, 564 mm long
    side = board.side_of(shelf, front)
    assert side in ("L1", "L2"), side  # along the shelf's length
    top = next("Face{}".format(i + 1) for i, f in enumerate(shelf.Shape.Faces) if abs(f.normalAt(0, 0).z) > 0.5)
    assert board.side_of(shelf, top) is None
    setattr(shelf, "Edge" + side, "birch 2 mm")
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    assert json.loads(lay.ProblemJson)["parts"][2]["edge_banding"] == {side: "birch 2 mm"}
    layout.export_cut_sheets(lay, str(tmp_path))
    rows = {r.split(",")[0]: r.split(",") for r in (tmp_path / "Layout-cutlist.csv").read_text().splitlines()}
    header = rows.pop("part")
    assert rows["shelf0"][header.index("edge_" + side)] == "birch 2 mm"
    assert all(rows[p][header.index("edge_L1")] == "" for p in rows if p != "shelf0")
    svg = ET.fromstring((tmp_path / "Layout-sheet-1.svg").read_text())
    bands = svg.findall(".//{http://www.w3.org/2000/svg}g[@id='edge-banding']/{http://www.w3.org/2000/svg}line")
    assert [b.get("data-band") for b in bands] == ["birch 2 mm"]
    length = math.hypot(float(bands[0].get("x2")) - float(bands[0].get("x1")),
                        float(bands[0].get("y2")) - float(bands[0].get("y1")))
    assert abs(length - 564) < 0.1


def test_two_layouts_share_a_folder_and_a_re_export_replaces_its_set_whole(doc, tmp_path):
    boards, masters = shelf_unit(doc)
    first = layout.create(doc, boards, masters, label="Shelf unit")
    second = layout.create(doc, boards, [master_board.create(doc, 1220, 610, 18, 0)], label="Shelf unit/small")
    doc.recompute()
    assert second.SheetCount > 1
    layout.export_cut_sheets(first, str(tmp_path))
    layout.export_cut_sheets(second, str(tmp_path))
    files = sorted(os.listdir(tmp_path))
    assert "Shelf-unit-sheet-1.svg" in files and "Shelf-unit-small-sheet-1.svg" in files, files
    # The small sheets grown to hold everything on one: its old sheet-2 files go, the other layout's stay.
    second.MasterBoards[0].Width, second.MasterBoards[0].Height = 2440, 1220
    doc.recompute()
    assert second.SheetCount == 1
    layout.export_cut_sheets(second, str(tmp_path))
    files = sorted(os.listdir(tmp_path))
    assert [f for f in files if f.startswith("Shelf-unit-small-sheet-")] == [
        "Shelf-unit-small-sheet-1.dxf", "Shelf-unit-small-sheet-1.svg"], files
    assert "Shelf-unit-sheet-1.svg" in files


def test_export_before_recompute_is_refused(doc):
    lay = layout.create(doc, [], [])
    with pytest.raises(layout.LayoutError, match="has not been computed"):
        layout.export_cut_sheets(lay, "/tmp/never")


def test_thick_boards_are_doweled_and_the_holes_reach_the_cut_sheets(doc, tmp_path):
    import ezdxf

    boards, masters = shelf_unit(doc)  # 18 mm: dowels under the default Auto joints
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    assert len(lay.Connectors) == 6 and all("3 dowels" in c for c in lay.Connectors), lay.Connectors
    layout.export_cut_sheets(lay, str(tmp_path))
    svg = (tmp_path / "Layout-sheet-1.svg").read_text()
    assert svg.count("<circle") == 18 and 'data-depth="9"' in svg
    dxf = ezdxf.readfile(str(tmp_path / "Layout-sheet-1.dxf"))
    drills = [e for e in dxf.modelspace() if e.dxf.layer == "DRILL_9MM"]  # the depth in the layer's name
    assert len(drills) == 18 and all(e.dxftype() == "CIRCLE" and e.dxf.radius == 4 for e in drills)
    assert dxf.layers.has_entry("DRILL_9MM") and not dxf.audit().has_errors


def test_thin_boards_get_finger_joints_that_change_the_cut_outlines(doc, tmp_path):
    parts = [box(doc, "Side", 6, 200, 300), box(doc, "Shelf", 300, 200, 6, at=(6, 0, 150))]
    doc.recompute()
    boards = [board.create(doc, p, label=p.Label + " board", thickness=6) for p in parts]
    lay = layout.create(doc, boards, [master_board.create(doc, 600, 400, 6)])
    doc.recompute()
    assert lay.Connectors == ["Shelf board into Side board: 7 finger tabs"]  # 200 mm / 12 mm: 15 fingers
    parts_cut = {p["id"]: p for p in json.loads(lay.ProblemJson)["parts"]}
    assert len(parts_cut["Side board"]["holes"]) == 7  # through-slots for the shelf's tabs
    assert len(parts_cut["Shelf board"]["outline"]) > 4
    # Cut by a 3 mm router bit: every corner of the 7 slots gets a dogbone, so the cut paths gain points there.
    import ezdxf

    def cut_points(folder):
        layout.export_cut_sheets(lay, str(folder))
        cuts = ezdxf.readfile(str(folder / "Layout-sheet-1.dxf")).modelspace().query('LWPOLYLINE[layer ? ".*_CUT"]')
        return sum(len(e) for e in cuts)

    square = cut_points(tmp_path / "square")
    lay.Dogbone = 3
    doc.recompute()
    assert json.loads(lay.ProblemJson)["settings"]["dogbone"] == 3
    assert cut_points(tmp_path / "dogbones") >= square + 7 * 4 * 3
    lay.Joints = "None"
    doc.recompute()
    assert lay.Connectors == [] and json.loads(lay.ProblemJson)["parts"][0]["holes"] == []


def test_techdraw_pages_show_the_report_are_redrawn_on_rerun_and_refused_in_error(doc, tmp_path):
    from freecad.fabguide.material import techdraw

    boards, masters = shelf_unit(doc)
    masters[0].Width, masters[0].Height, masters[0].Count = 1220, 610, 0  # two sheets
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    assert lay.SheetCount >= 2
    pages = techdraw.make_pages(lay)
    assert len(pages) == lay.SheetCount + 1  # a page per sheet, then the cut list and totals
    for page in pages:
        assert "Invalid" not in page.State and page.Template.Template.endswith("A4_Landscape_blank.svg")
        (drawing,) = page.Views
        assert "<svg" in drawing.Symbol and 'width="297mm"' in drawing.Symbol and drawing.Scale == 1  # A4 wide
    kept = len(doc.Objects)
    names = [p.Name for p in pages]
    again = techdraw.make_pages(lay)
    assert [p.Name for p in again] == names and len(doc.Objects) == kept  # redrawn one for one
    masters[0].Width, masters[0].Height = 2440, 1220  # one sheet: the first page kept, the extra ones gone
    doc.recompute()
    fewer = techdraw.make_pages(lay)
    assert len(fewer) == lay.SheetCount + 1 < len(names) and fewer[0].Name == names[0]
    assert not any(doc.getObject(name) for name in names[len(fewer):])
    masters[0].Width = 100  # the layout in error: no page drawn from its last good layout
    doc.recompute()
    with pytest.raises(layout.LayoutError, match="Mend that first"):
        techdraw.make_pages(lay)
    with pytest.raises(layout.LayoutError, match="Mend that first"):
        layout.export_cut_sheets(lay, str(tmp_path))


@pytest.mark.parametrize("grain, turned", [("Along width", False), ("Along height", True)])
def test_boards_following_the_grain_keep_their_length_along_it(doc, grain, turned):
    boards, masters = shelf_unit(doc)
    masters[0].Grain = grain
    for b in boards:
        b.Rotation = "Follow grain"
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    for p in json.loads(lay.LayoutJson)["placements"]:
        assert (p["rotation"] % 180 != 0) == turned, p


def test_each_master_board_turns_grain_following_boards_its_own_way(doc):
    boards, masters = shelf_unit(doc)
    masters[0].Width, masters[0].Height, masters[0].Count, masters[0].Grain = 1220, 610, 1, "Along width"
    masters.append(master_board.create(doc, 610, 1220, 18, count=0, label="Offcut"))
    masters[1].Grain = "Along height"
    for b in boards:
        b.Rotation = "Follow grain"
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    result = json.loads(lay.LayoutJson)
    assert len(result["boards"]) >= 2 and {b["grain"] for b in result["boards"]} == {"width", "height"}
    for p in result["placements"]:
        along_height = result["boards"][p["board"]]["grain"] == "height"
        assert (p["rotation"] % 180 != 0) == along_height, p


def test_coplanar_boards_in_contact_are_cut_as_one_piece(doc):
    bar = box(doc, "Bar", 300, 50, 6)
    stem = box(doc, "Stem", 50, 200, 6, at=(125, 50, 0))
    doc.recompute()
    boards = [board.create(doc, p, label=p.Label + " board", thickness=6) for p in (bar, stem)]
    lay = layout.create(doc, boards, [master_board.create(doc, 600, 400, 6)])
    doc.recompute()
    placements = json.loads(lay.LayoutJson)["placements"]
    assert [p["part"] for p in placements] == ["Bar board + Stem board"]
    assert lay.Usage < 1  # the T's notches are part of its layout rectangle
    boards[1].Quantity = 2
    with pytest.raises(layout.LayoutError, match="'Bar board', 'Stem board' lie in one plane and touch"):
        lay.Proxy.recompute(lay)


def test_core_errors_name_what_the_user_named(doc):
    from freecad.fabguide import messages

    assert messages.in_words("parts[1].outline: encloses no area",
                             {"parts": [{"id": "Bar board + Stem board"}, {"id": "Leg board"}]}, messages.PACK) == \
        "board 'Leg board' outline: encloses no area"
    works = {"parts": [{"name": "Base", "cuboids": [{"name": "b"}]}, {"name": "Drawer", "cuboids": [{"name": "Tray"}]}],
             "joints": [{"name": "lid hinge"}], "relationships": [{"name": "lid covers", "covering": ["Lid"]}]}
    for path, words in (("parts[1].cuboids[0].max[2]", "part 'Drawer' box 'Tray' top"),
                        ("joints[0].part", "joint 'lid hinge' part"),
                        ("relationships[0].covering[0]", "relationship 'lid covers' covering 'Lid'"),
                        ("parts[2].name", "parts[2].name")):  # leads nowhere: kept as it is
        assert messages.in_words(path + ": wrong", works, messages.WORKSLIKE) == words + ": wrong"


@pytest.mark.parametrize("make, prop, bad, message", [
    (lambda doc: master_board.create(doc, 1000, 600, 12), "Count", -5,
     "Master board 'MasterBoard': Count must be 0 (as many as needed) or more; kept 1"),
    (lambda doc: master_board.create(doc, 1000, 600, 12), "Thickness", 0,
     "Master board 'MasterBoard': Thickness must be greater than 0; kept 12"),
    (lambda doc: layout.create(doc, *shelf_unit(doc)), "RotationStep", 7,
     "Layout 'Layout': RotationStep must be 0 or a divisor of 90 (e.g. 15, 30, 45); kept 0"),
    (lambda doc: master_board.create(doc, 1000, 600, 12), "Width", float("inf"),  # from a script
     "Master board 'MasterBoard': Width must be a finite number; kept 1"),
    (lambda doc: layout.create(doc, *shelf_unit(doc)), "TimeLimit", float("nan"),
     "Layout 'Layout': TimeLimit must be a finite number; kept"),
])
def test_a_bad_value_is_refused_as_it_is_typed(doc, make, prop, bad, message, monkeypatch):
    obj = make(doc)
    doc.recompute()
    before, said = getattr(obj, prop), []
    monkeypatch.setattr(FreeCAD.Console, "PrintError", said.append)
    setattr(obj, prop, bad)
    assert getattr(obj, prop) == before  # refused at once: the old value stays
    assert len(said) == 1 and said[0].startswith(message), said
    doc.recompute()
    assert not obj.Error


def test_free_rotation_lays_a_slat_across_an_offcut_it_fits_only_diagonally(doc):
    slat = board.create(doc, box(doc, "Slat", 620, 40, 6), label="slat")
    offcut = master_board.create(doc, 500, 500, 6, count=0, material="birch plywood")
    lay = layout.create(doc, [slat], [offcut])
    doc.recompute()
    assert "slat" in lay.Error  # no quarter turn fits it
    lay.RotationStep = 15
    doc.recompute()
    assert not lay.Error, lay.Error
    placed = json.loads(lay.LayoutJson)["placements"][0]
    assert placed["rotation"] % 90 != 0 and placed["rotation"] % 15 == 0
    assert placed["width"] <= 500 and placed["height"] <= 500


# Labels a user (or a script) can give: line breaks, control characters, markup, unicode, a 20,000-character name,
# paths and a Windows device name.
HOSTILE_LABELS = ["line\nbreak", "bell\u0007 del\u007f", 'quote " & <tag>', "comma, semicolon; pipe|",
                  "Tür – 棚 🪚", "x" * 20000, "../../escape", "CON"]


def test_export_of_hostile_labels_gives_files_real_parsers_read_inside_the_folder(doc, tmp_path):
    """The FreeCAD exports: boards and a layout labelled as users and scripts label them export files
    that XML, DXF and CSV parsers read, named inside the folder given."""
    import csv
    import ezdxf

    boards, masters = shelf_unit(doc)
    for b, label in zip(boards, HOSTILE_LABELS):
        b.Label = label
    for label in ("../../escape", "CON", "line\nbreak"):
        lay = layout.create(doc, boards, masters, label=label)
        doc.recompute()
        folder = tmp_path / "sheets"
        written = layout.export_cut_sheets(lay, str(folder))
        assert all(os.path.dirname(os.path.abspath(p)) == str(folder) for p in written), written
        for path in written:
            if path.endswith(".svg"):
                ET.parse(path)
            elif path.endswith(".dxf"):
                ezdxf.readfile(path)
            elif path.endswith("-cutlist.csv"):
                with open(path, newline="", encoding="utf-8") as f:
                    assert len(list(csv.reader(f))) == 1 + len(boards)
    assert sorted(os.listdir(tmp_path)) == ["sheets"], "nothing beside the folder"


def test_export_into_what_is_no_folder_is_refused_by_name_and_writes_nowhere(doc, tmp_path):
    """A file, a pipe, or a link planted to a folder elsewhere: refused naming it, nothing written through."""
    boards, masters = shelf_unit(doc)
    lay = layout.create(doc, boards, masters)
    doc.recompute()
    (tmp_path / "a file").write_text("mine")
    os.mkfifo(str(tmp_path / "a pipe"))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (tmp_path / "out").mkdir()
    os.symlink(str(elsewhere / "victim.svg"), str(tmp_path / "out" / "Layout-sheet-1.svg"))
    for folder in ("a file", "a pipe"):
        with pytest.raises(Exception, match=folder):
            layout.export_cut_sheets(lay, str(tmp_path / folder))
    layout.export_cut_sheets(lay, str(tmp_path / "out"))
    assert (tmp_path / "a file").read_text() == "mine" and os.listdir(str(elsewhere)) == []
    assert not os.path.islink(str(tmp_path / "out" / "Layout-sheet-1.svg")), "the link is replaced, not followed"
