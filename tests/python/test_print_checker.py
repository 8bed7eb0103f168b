"""The print checker's judgement of material (tests/gen/print_checker.py) on bodies made by hand: a body whole where
no part goes passes, scaled and turned as `fabguide printable` writes it too; one with material missing there is
named."""
import os
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "gen"))
import print_checker  # noqa: E402

# A 40 mm block with a 4 mm lid on it, hinged at the lid's far bottom edge, opened a quarter turn.
SOLVED = {"format": "fabguide.workslike", "version": 1,
          "parts": [{"name": "block", "cuboids": [{"name": "block", "min": [0, 0, 0], "max": [40, 40, 40]}]},
                    {"name": "lid", "cuboids": [{"name": "lid", "min": [0, 0, 40], "max": [40, 40, 44]}]}],
          "joints": [{"name": "lid hinge", "type": "hinge", "part": "lid", "edge": ["lid.far", "lid.bottom"]}],
          "configurations": [{"name": "open", "poses": {"lid hinge": -90}}]}


def box_triangles(lo, hi, scale=1.0, turned=False):
    """A closed mesh of the box, outward, as print_checker.read_stl returns one (scaled, turned if asked)."""
    corner = [[(lo, hi)[i >> k & 1][k] for k in range(3)] for i in range(8)]
    quads = [(0, 2, 6, 4), (1, 5, 7, 3), (0, 4, 5, 1), (2, 3, 7, 6), (0, 1, 3, 2), (4, 6, 7, 5)]
    triangles = numpy.array([[corner[q[0]], corner[q[i]], corner[q[i + 1]]] for q in quads for i in (1, 2)],
                            dtype=float) * scale
    if turned:
        triangles = numpy.stack([-triangles[..., 1], triangles[..., 0], triangles[..., 2]], axis=-1)
    return triangles


def test_a_whole_body_passes_as_modelled_and_scaled_and_turned():
    for scale, turned in ((1.0, False), (0.5, True)):
        meshes = {"block": box_triangles([0, 0, 0], [40, 40, 40], scale, turned),
                  "lid": box_triangles([0, 0, 40.4], [40, 40, 44], scale, turned)}
        report = {"scale": scale, "turned": turned, "gap_mm": 0.4}
        assert print_checker.removed_material(SOLVED, report, meshes) == []


def test_material_missing_where_no_part_goes_is_named():
    # The block printed half as tall: its lower half's points deep inside it, far from the lid's way and its
    # hinge, are missing.
    meshes = {"block": box_triangles([0, 0, 0], [40, 40, 20]), "lid": box_triangles([0, 0, 40.4], [40, 40, 44])}
    problems = print_checker.removed_material(SOLVED, {"scale": 1.0, "gap_mm": 0.4}, meshes)
    assert len(problems) == 1 and "material of 'block' removed where no part goes" in problems[0], problems


def test_where_a_part_passes_or_a_joint_stands_nothing_is_judged():
    model = print_checker.works.Model(SOLVED)
    points = print_checker.untouched_points(model, "block", 1.0, 0.4)
    assert len(points)
    assert points[:, 2].max() < 40 - 2.3  # the lid rests on the top: nothing within the gaps and rails of it
    hinge = numpy.array([0.0, 40.0, 40.0])
    assert numpy.hypot(*(points[:, 1:] - hinge[1:]).T).min() > 3 * 4 + 1.6 + 0.8  # the hinge's reach


def test_bodies_that_meet_on_the_way_are_named():
    # A post behind the block where the lid stands when opened (y 40-44, z 40-80): as printed nothing meets.
    solved = dict(SOLVED, parts=SOLVED["parts"] + [
        {"name": "post", "cuboids": [{"name": "post", "min": [10, 42, 45], "max": [30, 50, 60]}]}])
    meshes = {"block": box_triangles([0, 0, 0], [40, 40, 40]), "lid": box_triangles([0, 0, 40.4], [40, 40, 44]),
              "post": box_triangles([10, 42, 45], [30, 50, 60])}
    report = {"scale": 1.0, "gap_mm": 0.4}
    assert print_checker.meeting(SOLVED, report, {b: meshes[b] for b in ("block", "lid")}) == []
    problems = print_checker.meeting(solved, report, meshes)
    assert problems and problems[0].startswith("bodies 'lid' and 'post' meet on the way to 'open'"), problems
