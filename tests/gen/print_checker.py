"""An independent checker of print-in-place output: it reads what `fabguide printable` wrote (the STL
of each body, report.json for the names, scale and gap) and the model it printed, and shares no code with
FabGuide.

- every part of the model is in exactly one body (parts fused only where the format says they may be);
- each body's mesh is closed (every edge shared by two triangles, consistently oriented) and one piece;
- no two bodies intersect as printed (a vertex of one inside the other);
- the clearance the report states is at least the gap;
- given the solved model it printed: no two bodies intersect in any configuration or on the way to it (MOVES
  poses, each body moved as its part, a link round its base pivot); no material removed where no part ever goes
  (untouched_points: points of each part that no other part, in any pose or along any motion, and no joint's
  geometry comes near, must be inside the part's body as printed).

check(model_path, folder, solved_path=None) -> list of problems (empty: passes). Poses come from the works-like
checker's model (tests/python/workslike_checker.py), also independent of FabGuide."""

import json
import math
import os
import re
import struct

import numpy

import workslike_checker as works

MOVES = 8  # poses on the way to each configuration where bodies must not meet
POSES = 64  # poses on the way to each configuration where untouched material is judged
GRID = 5  # sample points along each side of a cuboid
LEAST_ROUND = 1.6  # mm as printed: the least round part a joint has (a 0.8 mm pin, its gap and wall)


def read_stl(path):
    """Triangles of a binary STL as an (n, 3, 3) array of its float32 coordinates."""
    with open(path, "rb") as f:
        data = f.read()
    count = struct.unpack_from("<I", data, 80)[0]
    if len(data) != 84 + 50 * count:
        raise ValueError("%s: %d bytes for %d triangles" % (os.path.basename(path), len(data), count))
    records = numpy.frombuffer(data, dtype=numpy.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]),
                               count=count, offset=84)
    return records["v"].copy()


def welded(triangles):
    """Vertex indices of each triangle: a mesh's triangles share a vertex where they share its coordinates, to
    the bit (as admesh reads it)."""
    _, index = numpy.unique(triangles.reshape(-1, 3), axis=0, return_inverse=True)
    return index.reshape(-1, 3)


def closed(faces):
    """How many edges keep a mesh from being a closed, oriented surface: each directed edge as often as its
    reverse (two solids of a body that meet along an edge share it twice each way)."""
    edges = numpy.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    edges = edges[edges[:, 0] != edges[:, 1]]
    directed = {}
    for a, b in map(tuple, edges):
        directed[(a, b)] = directed.get((a, b), 0) + 1
    bad = sum(1 for (a, b), n in directed.items() if directed.get((b, a), 0) != n)
    return bad


def pieces(faces):
    """How many connected pieces a mesh's triangles make (sharing vertices)."""
    parent = list(range(int(faces.max()) + 1 if len(faces) else 0))

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b, c in faces:
        ra, rb, rc = root(a), root(b), root(c)
        parent[rb] = ra
        parent[root(rc)] = ra
    used = numpy.unique(faces)
    return len({root(v) for v in used})


def inside(points, triangles):
    """Whether each point lies inside the closed mesh: the parity of crossings of a ray along +x (tilted a
    little, so it misses edges). Only triangles across the points' y and z and beyond their least x can
    cross."""
    if not len(points):
        return numpy.zeros(0, dtype=bool)
    lo, hi = points.min(axis=0), points.max(axis=0)
    t_lo, t_hi = triangles.min(axis=1), triangles.max(axis=1)
    drift = 1e-3 + 2e-4 * max(0.0, float(t_hi[:, 0].max()) - lo[0])  # the tilted ray's, in y and z
    triangles = triangles[(t_hi[:, 0] >= lo[0]) & (t_hi[:, 1] >= lo[1] - drift) & (t_lo[:, 1] <= hi[1] + drift) &
                          (t_hi[:, 2] >= lo[2] - drift) & (t_lo[:, 2] <= hi[2] + drift)]
    direction = numpy.array([1.0, 1e-4 * math.sqrt(2), 1e-4 * math.sqrt(3)])
    v0, v1, v2 = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    e1, e2 = v1 - v0, v2 - v0
    h = numpy.cross(direction, e2)
    a = numpy.einsum("ij,ij->i", e1, h)
    ok = numpy.abs(a) > 1e-12
    f = numpy.where(ok, 1.0 / numpy.where(ok, a, 1.0), 0.0)
    result = numpy.zeros(len(points), dtype=bool)
    for start in range(0, len(points), 64):  # 64 points against every triangle at once
        s = points[start:start + 64, None, :] - v0
        u = f * numpy.einsum("ptj,tj->pt", s, h)
        q = numpy.cross(s, e1)
        v = f * (q @ direction)
        t = f * numpy.einsum("tj,ptj->pt", e2, q)
        hits = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        result[start:start + 64] = numpy.count_nonzero(hits, axis=1) % 2 == 1
    return result


def to_boxes(points, lo, hi):
    """Distance of each point (the last axis: x, y, z) from the nearest of the boxes [lo[i], hi[i]] (0 inside)."""
    out = numpy.maximum(numpy.maximum(lo - points[..., None, :], points[..., None, :] - hi), 0.0)
    return numpy.sqrt((out * out).sum(axis=-1)).min(axis=-1)


def to_segments(points, a, b):
    """Distance of each point (N) from each segment a[p]-b[p] (P): P x N."""
    d = b - a
    t = numpy.clip(numpy.einsum("pnj,pj->pn", points[None] - a[:, None], d) /
                   numpy.maximum(numpy.einsum("pj,pj->p", d, d), 1e-12)[:, None], 0.0, 1.0)
    return numpy.linalg.norm(points[None] - (a[:, None] + t[..., None] * d[:, None]), axis=2)


def moved(transforms, points):
    """The points (N) moved by each of the P rigid transforms: P x N."""
    r, t = transforms
    return points @ r.transpose(0, 2, 1) + t[:, None]


def unmoved(transforms, points):
    """The points each of the P rigid transforms moves onto points[p] (P x N): P x N."""
    r, t = transforms
    return (points - t[:, None]) @ r


def part_frames(model):
    """A part's model transforms at the poses (k, f) of a way (f of the way to configuration k), stacked as
    numpy arrays (P rotations, P translations), each transform computed once."""
    frames = {}

    def way_frames(part, way):
        if (part, tuple(way)) not in frames:
            rs, ts = zip(*(model.part_transform(part, k, f) for k, f in way))
            frames[part, tuple(way)] = numpy.array(rs, float), numpy.array(ts, float)
        return frames[part, tuple(way)]
    return way_frames


def joint_reach(model, j, scale, gap):
    """How far round its axis or pivots a joint's geometry may cut: round parts up to the thickness of its
    part (proud of a thin part), bridges to a part twice that off, and the least round part and its gaps."""
    face = j["edge"][0] if "edge" in j else j["pivot"][0]
    c = model.face(face)[0]
    return 3 * min(h - l for l, h in zip(c.lo, c.hi)) + (LEAST_ROUND + 2 * gap) / scale


def joint_places(model, j):
    """A joint's geometry as segments, each with the part whose frame it stands in (None: the ground) and a
    radius beyond its reach: a hinge's axis along its edge, in its base's frame and its part's; a double
    pivot's pivots, the link's length round
    each (a link recessed into its base turns all the way round its base pivot)."""
    if "edge" in j:
        (ca, sa), (cb, sb) = model.face(j["edge"][0]), model.face(j["edge"][1])
        along = 3 - sa // 2 - sb // 2
        a = [0.0, 0.0, 0.0]
        a[sa // 2], a[sb // 2] = ca.side(sa), cb.side(sb)
        b = list(a)
        a[along], b[along] = ca.lo[along], ca.hi[along]
        # the yokes stay with the base; the knuckle goes with the part (along a sliding hinge's travel)
        return [(j.get("base"), numpy.array(a), numpy.array(b), 0.0), (j["part"], numpy.array(a), numpy.array(b), 0.0)]
    pivot, base = numpy.array(j["pivot"][1], float), numpy.array(j["base_pivot"][1], float)
    link = float(numpy.linalg.norm(pivot - base))
    return [(j["part"], pivot, pivot, link), (j["base"], base, base, link)]


def untouched_points(model, part, scale, gap, frame=None):
    """Points of a part's material, in its frame as modelled, deeper than a gap in it, that no other part comes
    within the gaps and rails of (2 gaps and 1.5 mm as printed), as modelled, in any configuration or along the
    way to it (POSES poses; between two, a part may pass within half its move), and that no joint's geometry
    reaches. `frame`: part_frames(model), shared by the parts of one model."""
    frame = frame or part_frames(model)
    margin = (2 * gap + 1.5) / scale
    points = []
    for s in model.solids(part):
        axes = [numpy.linspace(s.lo[i], s.hi[i], 2 * GRID + 1)[1::2] for i in range(3)]
        grid = numpy.stack(numpy.meshgrid(*axes, indexing="ij"), -1).reshape(-1, 3)
        # deeper than the gap a face may step back by (the whole face, where a part comes near some of it)
        inset = (gap + 0.1) / scale
        points.append(grid[numpy.all((grid > numpy.array(s.lo) + inset) & (grid < numpy.array(s.hi) - inset),
                                     axis=1)])
    points = numpy.concatenate(points)
    for c in model.part_cuboids[part]:
        if c.cavity:
            points = points[to_boxes(points, numpy.array([c.lo]), numpy.array([c.hi])) > 1e-9]
    boxes = {q: (numpy.array([s.lo for s in model.solids(q)]), numpy.array([s.hi for s in model.solids(q)]))
             for q in model.parts if q != part and model.solids(q)}
    corners = {q: numpy.array([[x, y, z] for s in model.solids(q) for x in (s.lo[0], s.hi[0])
                               for y in (s.lo[1], s.hi[1]) for z in (s.lo[2], s.hi[2])]) for q in boxes}
    places = [(place, joint_reach(model, j, scale, gap)) for j in model.joints.values()
              if j["type"] in ("hinge", "sliding_hinge", "double_pivot") for place in joint_places(model, j)]
    ways = [[(None, 1.0)]] + [[(k, i / POSES) for i in range(POSES + 1)] for k in model.configuration_order]
    for way in ways:  # every pose of a way at once; the points a check drops are not checked again
        at = frame(part, way)
        world = moved(at, points)  # P x N
        for q, (lo, hi) in boxes.items():
            others = frame(q, way)
            near = numpy.concatenate([to_boxes(unmoved(others, chunk), lo, hi)
                                      for chunk in numpy.array_split(world, 1 + len(points) // 256, axis=1)], axis=1)
            keep = (near > margin).all(axis=0)
            if len(way) > 1:  # on the way between two poses: within half the move
                posed = unmoved(at, moved(others, corners[q]))  # q's corners in the part's frame
                step = numpy.linalg.norm(posed[1:] - posed[:-1], axis=2).max(axis=1)
                keep &= (numpy.minimum(near[1:], near[:-1]) > margin + 0.55 * step[:, None]).all(axis=0)
            points, world = points[keep], world[:, keep]
        for (place, a, b, radius), reach in places:
            ends = numpy.array([a, b])
            ends = moved(frame(place, way), ends) if place else numpy.broadcast_to(ends, (len(way), 2, 3))
            ends = unmoved(at, ends)
            points = points[(to_segments(points, ends[:, 0], ends[:, 1]) > radius + reach).all(axis=0)]
    return points


def on_the_bed(points, scale, turned):
    """Model points as `fabguide printable` writes them: scaled, turned a quarter about z if it turned them."""
    p = points * scale
    return numpy.stack([-p[:, 1], p[:, 0], p[:, 2]], axis=1) if turned else p


def removed_material(solved, report, meshes):
    """Problems: bodies missing material where nothing comes near (untouched_points)."""
    model = works.Model(solved)
    scale, turned, gap = float(report["scale"]), bool(report.get("turned")), float(report["gap_mm"])
    problems, frame = [], part_frames(model)
    for body, triangles in meshes.items():
        for part in body.split(" + "):
            if part not in model.parts:
                continue  # a link
            points = untouched_points(model, part, scale, gap, frame)
            if not len(points):
                continue
            out = ~inside(on_the_bed(points, scale, turned), triangles)
            if out.any():
                p = points[out][0]
                problems.append("body '%s': material of '%s' removed where no part goes (%d of %d untouched "
                                "points), e.g. at (%.1f, %.1f, %.1f) mm as modelled"
                                % (body, part, out.sum(), len(points), p[0], p[1], p[2]))
    return problems


def link_motion(model, joint, k, f):
    """A double pivot's link `f` of the way to configuration k: turned round its base pivot with the base."""
    base = model.part_transform(joint["base"], k, f)
    pose = model.configurations[k].get(joint["name"]) if k is not None else None
    if pose is None:
        return base
    normal, _, b, _, _, _, link = model.pivot_geometry(joint, pose)
    return works.compose(base, works.rotation(normal, link * min(1.0, 2 * f), b))


def body_motion(model, body, k, f):
    """The model transform of a printed body `f` of the way to configuration k: its first part's, or its
    link's; None for a body the model does not name."""
    part = body.split(" + ")[0]
    if part in model.parts:
        return model.part_transform(part, k, f)
    for j in model.joints.values():
        if j["type"] == "double_pivot" and body in (j["name"] + " link", j["name"]):
            return link_motion(model, j, k, f)
    return None


def on_the_bed_motion(transform, scale, turned):
    """A model transform as it moves the bodies written on the bed (scaled, perhaps turned): R' = Q R Qt,
    t' = scale Q t."""
    q = numpy.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]) if turned else numpy.eye(3)
    r, t = numpy.array(transform[0]), numpy.array(transform[1])
    return q @ r @ q.T, scale * (q @ t)


def meeting(solved, report, meshes, per_pair=100):
    """Problems: two bodies that meet (a vertex of one inside the other) in a configuration or on the way."""
    model = works.Model(solved)
    scale, turned = float(report["scale"]), bool(report.get("turned"))
    names = [b for b in meshes if body_motion(model, b, None, 1.0) is not None]
    vertices = {b: numpy.unique(meshes[b].reshape(-1, 3), axis=0) for b in names}
    problems, met = [], set()
    for k in model.configuration_order:
        for i in range(1, MOVES + 1):
            posed = {}
            for b in names:
                r, t = on_the_bed_motion(body_motion(model, b, k, i / MOVES), scale, turned)
                posed[b] = (meshes[b] @ r.T + t, vertices[b] @ r.T + t)
            bounds = {b: (v.min(axis=0), v.max(axis=0)) for b, (_, v) in posed.items()}
            for x, a in enumerate(names):
                for b in names[x + 1:]:
                    lo = numpy.maximum(bounds[a][0], bounds[b][0])
                    hi = numpy.minimum(bounds[a][1], bounds[b][1])
                    if (a, b) in met or numpy.any(hi <= lo):
                        continue
                    for one, other in ((a, b), (b, a)):
                        near = posed[one][1]
                        near = near[numpy.all((near >= lo) & (near <= hi), axis=1)]  # a corner on the other
                        near = near[numpy.linspace(0, len(near) - 1, min(per_pair, len(near))).astype(int)]
                        if len(near) and numpy.any(inside(near, posed[other][0])):
                            met.add((a, b))
                            problems.append("bodies '%s' and '%s' meet %s" % (a, b, works.where(k, i / MOVES)))
                            break
    return problems


def file_name(body):
    """The file name `fabguide printable` gives a body (docs/formats.md)."""
    return re.sub(r"[^A-Za-z0-9]", "-", body)


def check(model_path, folder, solved_path=None):
    problems = []
    with open(model_path) as f:
        model = json.load(f)
    try:
        with open(os.path.join(folder, "report.json")) as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        return ["no readable report.json: %s" % e]
    if not report.get("ok"):
        problems.append("the report says not ok: invalid %s, loose %s" % (report.get("invalid"), report.get("loose")))
    gap = float(report["gap_mm"])
    least = report.get("clearance", {}).get("least_mm")
    if least is not None and least < gap - 0.01:
        problems.append("clearance %.3f mm under the gap %.2f mm (%s)" % (least, gap, report["clearance"].get("where")))
    bodies = [b["name"] for b in report.get("bodies", [])]
    links = {j["name"] + " link" for j in model.get("joints", []) if j["type"] == "double_pivot"}
    named = [p for b in bodies if b not in links for p in b.split(" + ")]
    for part in model["parts"]:
        n = named.count(part["name"])
        if n != 1:
            problems.append("part '%s' is in %d bodies" % (part["name"], n))
    meshes = {}
    for body in bodies:
        path = os.path.join(folder, file_name(body) + ".stl")
        if not os.path.exists(path):
            if len(file_name(body)) <= 80:
                problems.append("body '%s' has no STL" % body)
            continue
        triangles = read_stl(path)
        faces = welded(triangles)
        bad = closed(faces)
        if bad:
            problems.append("body '%s': mesh not closed (%d edges not shared by two triangles)" % (body, bad))
        n = pieces(faces)
        if n != 1:
            problems.append("body '%s' is in %d pieces" % (body, n))
        meshes[body] = triangles.astype(numpy.float64)
    names = list(meshes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            lo = numpy.maximum(meshes[a].min(axis=(0, 1)), meshes[b].min(axis=(0, 1)))
            hi = numpy.minimum(meshes[a].max(axis=(0, 1)), meshes[b].max(axis=(0, 1)))
            if numpy.any(hi <= lo):
                continue
            vertices = numpy.unique(meshes[a].reshape(-1, 3), axis=0)
            near = vertices[numpy.all((vertices > lo) & (vertices < hi), axis=1)]
            if len(near) and numpy.any(inside(near[:400], meshes[b])):
                problems.append("bodies '%s' and '%s' intersect as printed" % (a, b))
    if solved_path:
        with open(solved_path) as f:
            solved = json.load(f)
        problems += meeting(solved, report, meshes) + removed_material(solved, report, meshes)
    return problems
