"""Works-like document objects, headless: a Mechanism gathers parts (native boxes), joints, configurations
and relationships, solves on recompute, writes the boxes back, keeps the user's edits, names conflicts and
bad input, and survives save/reload, undo and *.workslike.json round trips."""
import json
import math
import os

import FreeCAD
import pytest

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import cuboids, properties
from freecad.fabguide.function import configuration, joints, mechanism, parts, relationships, workslike_file


@pytest.fixture
def doc():
    document = FreeCAD.newDocument("function")
    name = document.Name
    yield document
    if name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(name)


def box(doc, label, low, high):
    b = doc.addObject("Part::Box", "Box")
    b.Label = label
    cuboids.set_coordinates(b, [v for a in range(3) for v in (low[a], high[a])])
    return b


def clamshell(doc, just=True):
    """A lid modelled open behind the body, hinged on its near-top edge; closed (180°) it must cover the body."""
    body, lid = box(doc, "Body", (0, 0, 0), (60, 120, 10)), box(doc, "Lid", (3, 122, 0), (57, 230, 7))
    doc.recompute()
    mech = mechanism.create(doc)
    body_part, lid_part = parts.create(doc, [body], "Base"), parts.create(doc, [lid], "Top")
    hinge = joints.create(doc, "hinge", lid_part, edge=(lid, [cuboids.edge_element(lid, ("near", "top"))]))
    closed = configuration.create(doc, "Closed", [(hinge, 180, 0)])
    cover = relationships.create(doc, "cover", "Top covers base", closed, Covering=[lid_part], Covered=[body_part],
                                 Just=just)
    mech.Group = [body_part, lid_part, hinge, closed, cover]
    doc.recompute()
    return mech, body, lid, cover


def test_a_pose_takes_units_and_an_expression(doc):
    """A configuration's angle is a property of its own: typed with a unit, or bound to a spreadsheet
    cell, and the mechanism solves in the pose the cell gives."""
    mech, body, lid, cover = clamshell(doc)
    closed = next(o for o in mech.Group if configuration.is_configuration(o))
    hinge = closed.Joints[0]
    angle = hinge.Name + "Angle"
    assert closed.getTypeIdOfProperty(angle) == "App::PropertyAngle" and closed.getGroupOfProperty(angle) == "Poses"
    setattr(closed, angle, FreeCAD.Units.Quantity("0.5 rad"))
    assert [a for _, a, _ in configuration.poses(closed)] == [pytest.approx(math.degrees(0.5))]
    sheet = doc.addObject("Spreadsheet::Sheet", "Sheet")
    sheet.set("A1", "180")
    sheet.setAlias("A1", "closed")
    closed.setExpression(angle, "Sheet.closed")
    doc.recompute()
    assert configuration.as_dict(closed)["poses"] == {hinge.Label: pytest.approx(180)}
    assert mech.Status == "Solved" and cover.Status == "Satisfied"
    configuration.set_poses(closed, [])  # the hinge posed no more: its property goes
    assert angle not in closed.PropertiesList


def touched(doc):
    return [o.Label for o in doc.Objects if "Touched" in o.State or properties.failed(o)]


def test_the_mechanism_solves_on_recompute_and_writes_the_boxes_back(doc):
    mech, body, lid, cover = clamshell(doc)
    assert mech.Status == "Solved" and cover.Status == "Satisfied"
    assert relationships.pair_texts(cover) == ["Lid.bottom -> Body.top"]  # the inferred graph is kept
    b, l = cuboids.coordinates(body), cuboids.coordinates(lid)
    # Closed, the lid turns about y = lid.near, z = lid.top: its box lands exactly on the body's top.
    assert l[1] - l[0] == pytest.approx(b[1] - b[0], abs=1e-6) and l[0] == pytest.approx(b[0], abs=1e-6)
    assert l[3] - l[2] == pytest.approx(b[3] - b[2], abs=1e-6)
    assert 2 * l[2] - l[3] == pytest.approx(b[2], abs=1e-6)
    assert l[5] == pytest.approx(b[5], abs=1e-6)
    assert lid.Shape.BoundBox.XMax == pytest.approx(l[1])  # shapes are up to date
    assert touched(doc) == []
    before = cuboids.coordinates(lid)
    doc.recompute()
    assert cuboids.coordinates(lid) == before  # solving a solved design changes nothing


def test_an_edit_is_kept_and_the_rest_adapts(doc):
    mech, body, lid, cover = clamshell(doc)
    was = lid.Length.Value
    body.Length = 80
    doc.recompute()
    assert cuboids.coordinates(body)[1] - cuboids.coordinates(body)[0] == pytest.approx(80)
    assert lid.Length.Value == pytest.approx(80, abs=1e-6)  # the lid follows to keep covering
    assert mech.Status == "Solved" and touched(doc) == []
    assert mech.Changes == ["Lid: Length {:g} → 80 mm".format(was)]  # the solve's doing, not the user's edit


def test_conflicts_are_named_and_leave_the_boxes_alone(doc):
    mech, body, lid, cover = clamshell(doc)
    narrow = relationships.create(doc, "geometric", "Top 40 wide", Left=[(lid, "width")], Offset=40)
    mech.Group = mech.Group + [narrow]
    mech.Locks = [(body, "left"), (body, "right")]
    kept = cuboids.coordinates(body), cuboids.coordinates(lid)
    doc.recompute()
    assert mech.Status == "Conflict: Top 40 wide, Top covers base, lock: Body.left, lock: Body.right"
    assert cover.Status == "Conflict: Top 40 wide, lock: Body.left, lock: Body.right"
    assert (cuboids.coordinates(body), cuboids.coordinates(lid)) == kept


@pytest.mark.parametrize("spoil, message", [
    (lambda d, m: setattr(d.getObjectsByLabel("Lid")[0], "Placement",
                          FreeCAD.Placement(FreeCAD.Vector(), FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 10))),
     "'Lid' is rotated"),
    (lambda d, m: setattr(d.getObjectsByLabel("Lid hinge")[0], "Edge", None), "Joint 'Lid hinge': choose the Edge"),
    (lambda d, m: setattr(d.getObjectsByLabel("Top covers base")[0], "Pairs",
                          [(d.getObjectsByLabel("Lid")[0], "bottom"), (d.getObjectsByLabel("Body")[0], "near")]),
     "Body.near and Lid.bottom are linked but not parallel"),
    (lambda d, m: setattr(d.getObjectsByLabel("Lid")[0], "Height", 5e9),  # said in the user's words
     r"Mechanism 'Mechanism': part 'Top' box 'Lid' height as drawn: .*beyond"),
])
def test_bad_input_is_an_error_naming_the_object(doc, spoil, message):
    mech, body, lid, cover = clamshell(doc)
    doc.getObjectsByLabel("Top hinge")[0].Label = "Lid hinge"
    spoil(doc, mech)
    with pytest.raises(ValueError, match=message):
        mechanism.solve(mech)


def test_save_reload_recompute_reproduces_the_geometry(doc, tmp_path):
    mech, body, lid, cover = clamshell(doc)
    body.Width = 150
    doc.recompute()
    solved = {b.Label: cuboids.coordinates(b) for b in (body, lid)}
    path = str(tmp_path / "clamshell.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    again = FreeCAD.openDocument(path)
    try:
        for obj in again.Objects:
            obj.touch()
        again.recompute()
        mech = again.getObjectsByLabel("Mechanism")[0]
        assert mech.Status == "Solved"
        for label, coordinates in solved.items():
            assert cuboids.coordinates(again.getObjectsByLabel(label)[0]) == pytest.approx(coordinates, abs=1e-6)
    finally:
        FreeCAD.closeDocument(again.Name)


def test_an_edit_and_its_solve_undo_as_one_step(doc):
    doc.UndoMode = 1
    mech, body, lid, cover = clamshell(doc)
    before = cuboids.coordinates(body), cuboids.coordinates(lid)
    doc.openTransaction("Edit")
    body.Length = 90
    doc.recompute()
    doc.commitTransaction()
    assert lid.Length.Value == pytest.approx(90, abs=1e-6)
    doc.undo()
    doc.recompute()
    assert (cuboids.coordinates(body), cuboids.coordinates(lid)) == pytest.approx(before, abs=1e-6)


def test_the_example_imports_solves_and_exports_as_the_core_reads_it(doc, source_dir, tmp_path):
    path = os.path.join(source_dir, "examples", "box-with-lid.workslike.json")
    mech = workslike_file.read(doc, path)
    doc.recompute()
    assert mech.Label == "box-with-lid" and mech.Status == "Solved", mech.Status
    statuses = {r.Label: r.Status for r in mech.Group if relationships.is_relationship(r)}
    assert len(statuses) == 10 and set(statuses.values()) == {"Satisfied"}
    with open(path) as f:
        expected = fabguide_core.solve(json.load(f))
    out = str(tmp_path / "out.workslike.json")
    workslike_file.write(mech, out)
    with open(out) as f:
        exported = json.load(f)
    assert fabguide_core.solve(exported)["report"]["solved"]
    solved = {c["name"]: c for p in expected["parts"] for c in p["cuboids"]}
    for p in exported["parts"]:
        for c in p["cuboids"]:
            assert c["min"] + c["max"] == pytest.approx(solved[c["name"]]["min"] + solved[c["name"]]["max"], abs=1e-5)
    assert touched(doc) == []


def test_every_relationship_kind_the_core_knows_is_one_the_workbench_makes_and_hints_read_the_cores_kinds():
    core = fabguide_core.conflict_kinds()
    assert {k["name"] for k in core if k["relationship"]} == set(relationships.KINDS)
    assert set(mechanism.HINTED) <= {k["name"] for k in core}


def test_every_joint_kind_the_core_knows_is_a_joint_the_workbench_makes_and_moves_as_the_core_does(doc):
    core = {k["name"]: (k["turns"], k["slides"]) for k in fabguide_core.joint_kinds()}
    assert set(core) == set(joints.KINDS)
    lid, body = box(doc, "Lid", (0, 0, 40), (100, 60, 45)), box(doc, "Body", (0, 0, 0), (100, 60, 40))
    doc.recompute()
    lid_part, body_part = parts.create(doc, [lid], "Lid part"), parts.create(doc, [body], "Body part")
    for name, (turns, slides) in core.items():
        made = joints.create(doc, name, lid_part, base=body_part, axis="z" if slides else None)
        assert (joints.turns(made), joints.slides(made)) == (turns, slides), name


def test_the_hint_after_a_conflict_follows_the_kinds_the_core_gives_not_the_names():
    def hint(parts, locks=()):
        model = {"format": "fabguide.workslike", "version": 1, "locks": list(locks),
                 "parts": [{"name": name, "cuboids": [{"name": cuboid, "min": low, "max": high}]}
                           for name, cuboid, low, high in parts]}
        report = fabguide_core.solve(model)["report"]
        assert not report["solved"] and len(report["conflicts"]) == len(report["conflict"]), report
        return mechanism.what_to_do(report["conflicts"])

    inside = hint([("Carcass", "carcass", [0, 0, 0], [600, 400, 800]),
                   ("Tray", "tray", [30, 0, 610], [570, 380, 770])])
    assert inside == "Mend the model as the note below says."
    # Parts named like the core's words change nothing: the kinds decide.
    locked = hint([("lock: A", "a", [0, 0, 0], [10, 10, 10]), ("one piece", "b", [8, 0, 0], [20, 10, 10])],
                  ["a.right", "b.left"])
    assert "unlock a box" in locked and "move the parts that meet apart" in locked and "Mend" not in locked


def test_parts_are_kept_apart_and_parts_that_must_overlap_are_blamed(doc):
    a, b = box(doc, "A", (0, 0, 0), (100, 50, 50)), box(doc, "B", (97, 10, 0), (200, 40, 50))  # 3 mm into A
    doc.recompute()
    mech = mechanism.create(doc)
    mech.Group = [parts.create(doc, [a], "Part A"), parts.create(doc, [b], "Part B")]
    doc.recompute()
    assert mech.Status == "Solved" and mech.Blamed == []
    assert cuboids.coordinates(a)[1] == 98.5 and cuboids.coordinates(b)[0] == 98.5  # 1.5 mm each, exactly
    mech.Locks = [(a, "right")]
    b.Placement.Base.x = 90  # the user pushes B into A, whose side is locked: refused, B goes back
    doc.recompute()
    assert mech.Status == ("Edit refused: lock: A.right, lock: B.left, no overlap: Part A, Part B cannot hold "
                           "together; the boxes are as they were"), mech.Status
    assert mech.Blamed == ["Part A", "Part B"] and cuboids.coordinates(b)[0] == 98.5


def test_a_door_beyond_the_face_distance_takes_part_and_says_so(doc):
    carcass, door = box(doc, "Carcass", (0, 0, 0), (400, 300, 600)), box(doc, "Door", (0, -25, 0), (400, -7, 600))
    doc.recompute()
    mech = mechanism.create(doc)
    front, back = parts.create(doc, [door], "Front"), parts.create(doc, [carcass], "Back")
    cover = relationships.create(doc, "cover", "Door closes", Covering=[front], Covered=[back], Just=True)
    mech.Group = [front, back, cover]
    doc.recompute()
    assert mech.Status == "Solved"
    assert cover.Status == "Satisfied; Front: 7 mm from Carcass.near, beyond the 5 mm face distance; linked to it"
    assert cuboids.coordinates(door)[3] == cuboids.coordinates(carcass)[2]  # on the face, exactly


def test_the_cabinet_imports_with_cavities_and_an_edit_widens_both_doors(doc, source_dir):
    mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "cabinet.workslike.json"))
    doc.recompute()
    assert mech.Status == "Solved", mech.Status
    carcass = doc.getObjectsByLabel("carcass part")[0]
    assert [b.Label for b in carcass.Cavities] == ["upper compartment", "middle compartment", "lower compartment",
                                                   "top well"]
    left, right = doc.getObjectsByLabel("left door")[0], doc.getObjectsByLabel("right door")[0]
    assert left.Shape.BoundBox.XMin == pytest.approx(18) and right.Shape.BoundBox.XMax == pytest.approx(582)
    compartment = doc.getObjectsByLabel("upper compartment")[0]
    compartment.Length = compartment.Length.Value + 40  # the user widens it
    doc.recompute()
    assert mech.Status == "Solved", mech.Status
    assert left.Length.Value == pytest.approx(302, abs=1e-5) and right.Length.Value == pytest.approx(302, abs=1e-5)
    assert cuboids.coordinates(right)[1] == pytest.approx(622, abs=1e-5)


@pytest.mark.parametrize("name", ["box-with-lid", "cabinet", "cellphone", "crate-bar", "crate-bed", "printer", "sofa-bunk",
                                  "tablet", "toolbox", "sliding-box"])
def test_every_example_imports_solves_and_round_trips(doc, source_dir, tmp_path, name):
    mech = workslike_file.read(doc, os.path.join(source_dir, "examples", name + ".workslike.json"))
    doc.recompute()
    assert mech.Status == "Solved", mech.Status
    rels = [r for r in mech.Group if relationships.is_relationship(r)]
    assert rels and {r.Status for r in rels} == {"Satisfied"}
    assert touched(doc) == []
    out = str(tmp_path / "again.workslike.json")
    workslike_file.write(mech, out)
    again = workslike_file.read(doc, out)  # a second mechanism from the export: same boxes, same answer
    doc.recompute()
    assert again.Status == "Solved"
    first, second = mechanism.boxes(mech), mechanism.boxes(again)
    flat = [[v for b in boxes for v in cuboids.coordinates(b)] for boxes in (first, second)]
    assert len(first) == len(second) and flat[0] == pytest.approx(flat[1], abs=1e-6)


def test_the_printable_cellphone_has_separate_valid_bodies_that_keep_their_gap(doc, source_dir, tmp_path):
    from freecad.fabguide.function import printable

    mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "cellphone.workslike.json"))
    doc.recompute()
    made = printable.create(doc, mech)
    doc.recompute()
    assert not made.Error
    bodies = {c.BodyName: c for c in made.Group if c.BodyName != printable.CAVITIES}
    assert sorted(bodies) == ["base part", "battery part", "screen part"]  # named like the parts
    for body in bodies.values():
        assert body.Shape.isValid() and len(body.Shape.Solids) >= 1
    assert made.MinimumClearance.Value == pytest.approx(0.4, abs=0.01)
    # The battery fits its bay with the gap all round: its volume is the modelled one less the gap.
    battery = doc.getObjectsByLabel("battery")[0]
    modelled = battery.Shape.Volume  # the box, as modelled and solved
    assert bodies["battery part"].Shape.Volume < modelled
    # Resin prints with a smaller gap; the bodies follow.
    made.Printer = "Resin (0.2 mm gap)"
    doc.recompute()
    assert made.Gap.Value == pytest.approx(0.2) and made.MinimumClearance.Value == pytest.approx(0.2, abs=0.01)
    written = printable.export(made, str(tmp_path))
    assert {os.path.basename(p) for p in written} >= {"assembly.stl", "assembly.3mf", "assembly.step", "screen-part.stl"}


def test_a_printable_fits_the_build_volume_and_keeps_that_setting_when_saved(doc, source_dir, tmp_path):
    from freecad.fabguide.function import printable

    mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "toolbox.workslike.json"))
    doc.recompute()
    made = printable.create(doc, mech)
    doc.recompute()
    assert made.Scale == 1 and made.PrintSize.startswith("541.6 x")  # a 539 mm toolbox and its hinge
    made.FitToBuildVolume = True  # 250 x 210 x 210 mm by default
    doc.recompute()
    size = [float(v) for v in made.PrintSize.split(" mm")[0].split(" x ")]
    assert made.Scale == pytest.approx(250 / 541.6, rel=0.01)
    assert size[0] == pytest.approx(250, abs=0.05) and size[1] <= 210 and size[2] <= 210
    assert made.MinimumClearance.Value == pytest.approx(0.4, abs=0.01)  # the gap stays in mm
    assert made.getEditorMode("Scale") == ["ReadOnly"]
    # Export writes the bodies as made, at once; after an edit it asks for a recompute first, naming the edit.
    import Part
    written = printable.export(made, str(tmp_path / "print"))
    step = Part.read([p for p in written if p.endswith("assembly.step")][0])
    assert [step.BoundBox.XLength, step.BoundBox.YLength] == pytest.approx(size[:2], abs=0.1)
    lid = doc.getObjectsByLabel("lid")[0]
    lid.Height = lid.Height.Value + 5
    with pytest.raises(printable.PrintableError, match=r"\(lid changed\); recompute first"):
        printable.export(made, str(tmp_path / "stale"))
    lid.Height = lid.Height.Value - 5
    doc.recompute()
    path = str(tmp_path / "fitted.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    again = FreeCAD.openDocument(path)
    try:
        reloaded = [o for o in again.Objects if printable.is_printable(o)][0]
        assert reloaded.FitToBuildVolume and reloaded.Scale == pytest.approx(250 / 541.6, rel=0.01)
        reloaded.BuildVolume = FreeCAD.Vector(250, 0, 210)
        with pytest.raises(printable.PrintableError, match="BuildVolume must be greater than 0"):
            printable.fit(reloaded)
        again.recompute()
        assert reloaded.Error and reloaded.Scale == pytest.approx(250 / 541.6, rel=0.01)
        reloaded.FitToBuildVolume = False
        reloaded.Scale = 0  # refused as it is typed
        assert reloaded.Scale == pytest.approx(250 / 541.6, rel=0.01)
    finally:
        FreeCAD.closeDocument(again.Name)


def test_the_printable_body_names_come_without_making_the_bodies(source_dir):
    # Make Printable creates one Part::Feature per body before the first recompute makes them.
    with open(os.path.join(source_dir, "examples", "crate-bed.workslike.json")) as f:
        model = json.load(f)
    names = fabguide_core.printable_body_names(model)
    assert names == [b["name"] for b in fabguide_core.printable(model, 0.4, False)["bodies"]]
    assert names[3:] == ["head pivot left link", "head pivot right link", "foot pivot left link",
                         "foot pivot right link"]


def test_a_printable_turned_to_fit_is_shown_as_modelled_and_exported_turned(doc, source_dir, tmp_path):
    import Part
    from freecad.fabguide.function import printable

    mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "tablet.workslike.json"))
    doc.recompute()
    made = printable.create(doc, mech)
    made.FitToBuildVolume = True  # 250 x 210 x 210: the 420 mm long open tablet lies along the 250
    doc.recompute()
    assert made.TurnedOnBed and made.PrintSize.endswith(", turned a quarter on the bed")
    assert made.Scale == pytest.approx(250 / 420, rel=0.01)
    shown = Part.makeCompound([c.Shape for c in made.Group if c.BodyName != printable.CAVITIES]).BoundBox
    assert shown.YLength == pytest.approx(250, abs=0.05)  # beside the mechanism, as modelled
    written = printable.export(made, str(tmp_path))
    exported = Part.read([p for p in written if p.endswith("assembly.step")][0]).BoundBox
    assert exported.XLength == pytest.approx(250, abs=0.05) and exported.YLength == pytest.approx(shown.XLength)


def test_a_fixed_part_rides_on_its_base_and_prints_as_one_body_with_it(doc, tmp_path):
    """A knob sunk into a hinged lid, held by a fixed joint: it moves with the lid, the solve leaves it sunk, it
    prints fused to the lid, and the joint survives a workslike round trip; without a base it is named."""
    from freecad.fabguide.function import printable

    body, lid = box(doc, "Body", (0, 0, 0), (40, 40, 10)), box(doc, "Lid", (0, 0, 10), (40, 40, 14))
    knob = box(doc, "Knob", (15, 2, 13), (25, 8, 20))
    doc.recompute()
    mech = mechanism.create(doc)
    body_part, lid_part, knob_part = (parts.create(doc, [b], name) for b, name in
                                      ((body, "Base"), (lid, "Top"), (knob, "Handle")))
    hinge = joints.create(doc, "hinge", lid_part, edge=(lid, [cuboids.edge_element(lid, ("far", "bottom"))]))
    held = joints.create(doc, "fixed", knob_part, base=lid_part, label="Knob on lid")
    opened = configuration.create(doc, "Open", [(hinge, -90, 0)])
    mech.Group = [body_part, lid_part, knob_part, hinge, held, opened]
    doc.recompute()
    assert mech.Status == "Solved", mech.Status
    assert cuboids.coordinates(knob) == [15, 25, 2, 8, 13, 20]  # still sunk 1 mm into the lid
    made = printable.create(doc, mech)
    doc.recompute()
    assert not made.Error
    bodies = {c.BodyName: c for c in made.Group if c.BodyName != printable.CAVITIES}
    assert sorted(bodies) == ["Base", "Top + Handle"]
    assert len(bodies["Top + Handle"].Shape.Solids) == 1
    assert made.MinimumClearance.Value >= 0.4 - 0.01
    path = str(tmp_path / "knob.workslike.json")
    workslike_file.write(mech, path)
    written = json.load(open(path))
    assert {"name": "Knob on lid", "type": "fixed", "part": "Handle", "base": "Top"} in written["joints"]
    held.Base = None
    with pytest.raises(ValueError, match="Fixed joint 'Knob on lid': choose the Base part it holds 'Handle' to"):
        mechanism.solve(mech)


def old_style(obj, name, texts):
    """`obj`'s references `name` as FabGuide saved them before links: box labels in strings."""
    obj.removeProperty(name)
    obj.addProperty("App::PropertyStringList", name, "Old", "")
    setattr(obj, name, texts)


def test_renaming_boxes_keeps_every_reference(doc, tmp_path):
    mech, body, lid, cover = clamshell(doc)
    wide = relationships.create(doc, "geometric", "Lid as wide", Left=[(lid, "width")], Right=[(body, "width")])
    mech.Group = mech.Group + [wide]
    mech.Locks = [(body, "left")]
    doc.recompute()
    assert mech.Status == "Solved" and not mech.Error
    lid.Label, body.Label = "Cap", "Shell"
    mech.touch()
    doc.recompute()
    assert mech.Status == "Solved" and cover.Status == "Satisfied" and wide.Status == "Satisfied"
    assert relationships.pair_texts(cover) == ["Cap.bottom -> Shell.top"]
    model = mechanism.model(mech)
    assert model["locks"] == ["Shell.left"] and model["relationships"][1]["left"][0]["quantity"] == "Cap.width"
    path = str(tmp_path / "renamed.FCStd")
    doc.saveAs(path)
    again = FreeCAD.openDocument(path)
    try:
        cover = again.getObjectsByLabel("Top covers base")[0]
        assert relationships.pair_texts(cover) == ["Cap.bottom -> Shell.top"]
    finally:
        FreeCAD.closeDocument(again.Name)


def test_deleting_a_box_fails_in_one_sentence_and_no_status_stays_solved(doc):
    mech, body, lid, cover = clamshell(doc)
    doc.removeObject(lid.Name)
    doc.recompute()  # no exception, no traceback: the mechanism says why
    assert mech.Error and mech.Status == mech.Error and mech.Error.startswith("Mechanism 'Mechanism': ")
    assert "\n" not in mech.Error
    assert cover.Status == mechanism.STALE


def test_a_document_of_label_references_opens_with_links(doc, tmp_path):
    mech, body, lid, cover = clamshell(doc)
    wide = relationships.create(doc, "geometric", "Lid as wide", Left=[(lid, "width")], Right=[(body, "width")])
    mech.Group = mech.Group + [wide]
    old_style(cover, "Pairs", ["Lid.bottom -> Body.top"])
    old_style(mech, "Locks", ["Body.left", "Gone.top"])  # a box deleted long ago: left out, with a warning
    old_style(wide, "Left", ["Lid.width"])
    path = str(tmp_path / "old.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    again = FreeCAD.openDocument(path)
    try:
        mech, cover = again.getObjectsByLabel("Mechanism")[0], again.getObjectsByLabel("Top covers base")[0]
        assert all(o.getTypeIdOfProperty(p) == "App::PropertyLinkSubList"
                   for o, p in ((mech, "Locks"), (cover, "Pairs"), (again.getObjectsByLabel("Lid as wide")[0], "Left")))
        assert relationships.pair_texts(cover) == ["Lid.bottom -> Body.top"]
        assert mechanism.model(mech)["locks"] == ["Body.left"]
        again.getObjectsByLabel("Lid")[0].Label = "Cap"
        mech.touch()
        again.recompute()
        assert mech.Status == "Solved" and relationships.pair_texts(cover) == ["Cap.bottom -> Body.top"]
    finally:
        FreeCAD.closeDocument(again.Name)


def test_a_file_the_core_refuses_is_refused_with_its_field_path(doc, tmp_path):
    model = {"format": "fabguide.workslike", "version": 1,
             "parts": [{"name": "body", "cuboids": [{"name": "body", "min": [0, 0, 0], "max": [10, 10, 10]}]},
                       {"name": "lid", "cuboids": [{"name": "lid", "min": [0, 0, 10], "max": [10, 10, 12]}]}],
             "relationships": [{"type": "flush", "name": "level", "faces": ["lid.left", "bodyy.left"]}]}
    path = tmp_path / "typo.workslike.json"
    path.write_text(json.dumps(model))
    with pytest.raises(ValueError, match=r"^typo.workslike.json: relationships\[0\]\.faces\[1\]: no cuboid named "
                                         r"'bodyy'"):
        workslike_file.read(doc, str(path))
    assert doc.Objects == []


def test_a_file_imports_with_the_cores_defaults_and_keeps_what_it_gives(doc, tmp_path):
    """The import builds from the core's normal form: an unnamed cuboid gets the name the core gives it, the
    defaults are the core's, and a cover's distance given in the file is kept (and written back)."""
    model = {"parts": [{"name": "body", "cuboids": [{"min": [0, 0, 0], "max": [60, 40, 20]}]},
                       {"name": "lid", "cuboids": [{"min": [0, 0, 21], "max": [60, 40, 24]}]}],
             "relationships": [{"type": "cover", "name": "lid on top", "covering": ["lid"], "covered": ["body"],
                                "distance": 8},
                               {"type": "geometric", "name": "thin lid", "left": "lid.height", "right": []}]}
    path = tmp_path / "plain.workslike.json"
    path.write_text(json.dumps(model))
    mech = workslike_file.read(doc, str(path))
    cover, thin = [o for o in mech.Group if relationships.is_relationship(o)]
    assert sorted(o.Label for o in doc.Objects if o.TypeId == "Part::Box") == ["body", "lid"]
    assert (cover.Distance.Value, cover.Just, cover.Pairs) == (8, False, [])
    assert (thin.Relation, thin.Offset.Value) == ("Equal", 0)
    assert (mech.MinimumSize, mech.MinimumWall) == (1, 1)
    out = tmp_path / "again.workslike.json"
    workslike_file.write(mech, str(out))
    assert json.loads(out.read_text())["relationships"][0]["distance"] == 8


def test_the_preview_moves_parts_as_the_print_does_turns_first_then_slides(doc, source_dir):
    from freecad.fabguide.gui import posing

    mech = workslike_file.read(doc, os.path.join(source_dir, "examples", "cabinet.workslike.json"))
    doc.recompute()
    door = doc.getObjectsByLabel("left door hinge")[0]
    model = mechanism.model(mech)
    half = posing.part_motions(model, mech, {door.Name: (90, 60, FreeCAD.Vector())}, 0.5)[door.Part.Label]
    whole = posing.part_motions(model, mech, {door.Name: (90, 60, FreeCAD.Vector())}, 1.0)[door.Part.Label]
    assert half.Rotation.Angle == pytest.approx(math.pi / 2)  # halfway: swung open, not yet slid in
    assert whole.Rotation.Angle == pytest.approx(math.pi / 2)
    assert (whole.Base - half.Base).Length == pytest.approx(60)  # then the 60 mm slide, along y
    assert abs((whole.Base - half.Base).y) == pytest.approx(60)
    with pytest.raises(ValueError, match=r"^joint 'left door hinge' angle: 1000000000.0 is beyond"):  # said, not a path
        posing.part_motions(model, mech, {door.Name: (1e9, 0, FreeCAD.Vector())})


def test_a_length_typed_stays_a_length_or_is_refused_by_name_never_a_move(doc):
    mech, body, lid, cover = clamshell(doc, just=False)
    width = lid.Length.Value
    fixed = relationships.create(doc, "geometric", "Lid as wide as now", Left=[(lid, "width")], Offset=width)
    mech.Group = mech.Group + [fixed]
    doc.recompute()
    left = cuboids.coordinates(lid)[0]
    lid.Length = width + 40  # the user types a length the fixed width refuses: not a 40 mm move of the lid
    doc.recompute()
    assert mech.Status.startswith("Edit refused: ") and "lock: Lid.left" in mech.Status, mech.Status
    assert "lock: Lid.right" in mech.Status and cuboids.coordinates(lid)[0] == left
    assert lid.Length.Value == width and fixed.Status == "Satisfied"  # the model exactly as it was


def test_a_solve_that_changes_nothing_lists_no_changes(doc):
    mech, body, lid, cover = clamshell(doc)
    body.Length = 80
    doc.recompute()
    assert mech.Changes  # the lid followed
    narrow = relationships.create(doc, "geometric", "Top 40 wide", Left=[(lid, "width")], Offset=40)
    mech.Group = mech.Group + [narrow]
    mech.Locks = [(body, "left"), (body, "right")]
    doc.recompute()
    assert mech.Status.startswith("Conflict: ") and mech.Changes == []  # nothing written back


def test_successive_solves_do_not_thin_a_part_below_half_of_what_was_drawn(doc, tmp_path):
    """A door drawn 20 mm thick, made flush with one stop (thinned to 10.2 mm, just above half), then
    with a stop 5 mm nearer: it keeps its 10.2 mm and moves, rather than thinning to 5.2 (a quarter of what was
    drawn). The drawn size is saved with the document, and written to the exported model."""
    door, stop = box(doc, "Door", (0, 0, 0), (100, 20, 200)), box(doc, "Stop", (0, 10.2, 0), (100, 30, 10))
    doc.recompute()
    mech = mechanism.create(doc)
    door_part, stop_part = parts.create(doc, [door], "Door part"), parts.create(doc, [stop], "Stop part")
    flush = relationships.create(doc, "flush", "Door on the stop", Faces=[(door, "Face4"), (stop, "Face3")])
    mech.Group = [door_part, stop_part, flush]
    mech.Locks = [(stop, side) for side in cuboids.SIDES]
    doc.recompute()
    assert mech.Status == "Solved" and door.Width.Value == pytest.approx(10.2, abs=1e-6)
    doc.openTransaction("Move the stop")
    stop.Placement.Base.y = 5.2
    doc.commitTransaction()
    doc.recompute()
    assert mech.Status == "Solved", mech.Status
    assert door.Width.Value == pytest.approx(10.2, abs=1e-6), "moved rather than thinned below half of 20 mm"
    assert door.Placement.Base.y + door.Width.Value == pytest.approx(5.2, abs=1e-6)
    path = str(tmp_path / "doors.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    mech = reopened.getObjectsByLabel("Mechanism")[0]
    assert json.loads(mech.Drawn)[reopened.getObjectsByLabel("Door")[0].Name] == pytest.approx([100, 20, 200])
    workslike_file.write(mech, str(tmp_path / "doors.workslike.json"))
    written = json.load(open(str(tmp_path / "doors.workslike.json")))
    assert written["parts"][0]["cuboids"][0]["drawn"] == pytest.approx([100, 20, 200])
    FreeCAD.closeDocument(reopened.Name)


@pytest.mark.parametrize("solved, drawn", [("null", "garbage"), ('{"Box": "x"}', "[1, 2]"), ("{", '{"Box": [1e999]}')])
def test_nonsense_in_the_hidden_memory_of_solves_is_forgotten_not_a_traceback(doc, solved, drawn):
    """A script (or Show all in the property editor) can write anything into Solved and Drawn: the mechanism then
    solves as a new one would, without a traceback."""
    mech, body, lid, cover = clamshell(doc)
    mech.Solved, mech.Drawn = solved, drawn
    body.Length = 70
    doc.recompute()
    assert mech.Status == "Solved" and not mech.Error, (mech.Status, mech.Error)
