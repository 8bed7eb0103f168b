"""An independent checker of print-in-place output (issue 30): it reads what `fabguide printable` wrote (the STL
of each body, report.json for the names, scale and gap) and the model it printed, and shares no code with
FabGuide.

- every part of the model is in exactly one body (parts fused only where the format says they may be);
- each body's mesh is closed (every edge shared by two triangles, consistently oriented) and one piece;
- no two bodies intersect as printed (a vertex of one inside the other);
- the clearance the report states is at least the gap.

check(model_path, folder) -> list of problems (empty: passes)."""

import json
import math
import os
import re
import struct

import numpy


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
    little, so it misses edges)."""
    direction = numpy.array([1.0, 1e-4 * math.sqrt(2), 1e-4 * math.sqrt(3)])
    v0, v1, v2 = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    e1, e2 = v1 - v0, v2 - v0
    h = numpy.cross(direction, e2)
    a = numpy.einsum("ij,ij->i", e1, h)
    ok = numpy.abs(a) > 1e-12
    f = numpy.where(ok, 1.0 / numpy.where(ok, a, 1.0), 0.0)
    result = numpy.zeros(len(points), dtype=bool)
    for i, p in enumerate(points):
        s = p - v0
        u = f * numpy.einsum("ij,ij->i", s, h)
        q = numpy.cross(s, e1)
        v = f * (q @ direction)
        t = f * numpy.einsum("ij,ij->i", e2, q)
        hits = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
        result[i] = bool(numpy.count_nonzero(hits) % 2)
    return result


def file_name(body):
    """The file name `fabguide printable` gives a body (docs/formats.md)."""
    return re.sub(r"[^A-Za-z0-9]", "-", body)


def check(model_path, folder):
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
    return problems
