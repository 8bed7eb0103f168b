#!/usr/bin/env python3
"""An independent, physical checker for solved works-like models (`*.workslike.json`).

It trusts nothing the solver says about itself (the file's "report" is ignored) and shares no code with
FabGuide: it reads the JSON, poses every part with its own rigid transforms and judges the result as a
product designer would:

- no two parts' material interpenetrates, as modelled, in every configuration and at 64 poses along the
  motion to each configuration; where a fit inside holds, the enclosing part has the room print-in-place cuts
  for it taken out (what its inner parts sweep on the way to the fit's configuration, in the enclosing part's
  frame; for a fit as modelled, where they are) and nothing more. A collision on the way is a problem, except
  between two parts that each turn by a joint of their own (print-in-place bevels each by the other's path: a
  warning, for the print's check to judge);
- every part is one piece: its solid cuboids joined face to face, none cut in two by its own cavity, and a part
  a fixed joint holds joined to its base;
- every relationship holds as written in the solved file (cover, fit inside, support, flush, geometric),
  every part a relationship names takes part in it, every lock keeps its value;
- every opening of the original model (a cavity side on its solid's side, within 0.5 mm as drawn, or one a
  part that fits inside the cavity goes out through in a configuration) still lies on the solid's side, and, as
  modelled, no other part's material closes it: material that crosses the opening's plane within the opening
  and lies mostly in front of it (a skin of a door sunk behind the face). Parts that belong in the cavity pass
  through: those mostly behind the plane (a drawer's box), the inner parts of a fit inside in that cavity,
  parts that go into it in a configuration, and what is fixed to them or to a part covering it. A part in front
  that only touches (a door, named by a cover or not) does not close it;
- every cavity keeps a wall of at least 1 mm on its sides that are not openings;
- a cover drawn without pairs also holds as the checker reads it from the drawing itself (facing faces within
  twice the cover distance, overlapping by half): a face the solver's inference left out must still be covered;
- double pivots: the pivot faces stay coplanar and the link keeps its length in every configuration.

Conventions (docs/formats.md): x left -> right, y near -> far, z bottom -> top. A hinge turns its part about
the edge where its two named faces meet, right-handed about +x/+y/+z by the angle; a slide shifts it along its
axis; a sliding hinge turns, then shifts; a double pivot's configuration turns the part by the angle about the
pivot faces' normal through the pole. A part's own joint applies first, then its base's, out to the ground.
In a configuration, a relationship's faces are the sides of the bounding box of the moved cuboid. Along a
motion, every joint turns in the first half of the way and slides in the second (angles and offsets scale
linearly within their half); a double pivot follows its four-bar in the first half (the part turns about its
pivot, the link the shorter way round the base pivot).

Use: check(solved, original=None, tolerance=1e-4) -> list of problems (empty: passes);
check_all(...) -> (problems, warnings). From a shell: python3 workslike_checker.py SOLVED [ORIGINAL].
"""

import itertools
import json
import math
import sys

AXES = "xyz"
SIDES = ("left", "right", "near", "far", "bottom", "top")
SIZES = {"width": 0, "depth": 1, "height": 2}
MINIMUM_WALL = 1.0  # mm, every cavity keeps this much material on a side that is not an opening
OPENING_HAIR = 0.5  # mm, a cavity side this close to its solid's side as drawn is an opening (a rough mouth)
LOCK_TOLERANCE = 1e-9  # a lock keeps the user's value exactly: a residue of 3e-7 shows in FreeCAD
MOTION_SAMPLES = 64  # poses along each motion, besides its ends
ROOM_SAMPLES = 64  # poses of a fit inside's inner parts on the way, for the room the print cuts

# --------------------------------------------------------------------------------------------------------
# small vector algebra


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def add(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def scale(a, s):
    return [a[0] * s, a[1] * s, a[2] * s]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def mat_vec(m, v):
    return [dot(m[0], v), dot(m[1], v), dot(m[2], v)]


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


IDENTITY = ([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 0.0])


def cos_sin(degrees):
    """Exact for multiples of 90 degrees, so axis-aligned poses stay exact."""
    quarter = degrees / 90.0
    if abs(quarter - round(quarter)) < 1e-12:
        return [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(round(quarter)) % 4]
    r = math.radians(degrees)
    return math.cos(r), math.sin(r)


def rotation(axis, degrees, through):
    """Rigid transform (R, t): a right-handed turn about the line along `axis` (0, 1, 2) through `through`."""
    c, s = cos_sin(degrees)
    u, w = (axis + 1) % 3, (axis + 2) % 3
    m = [[0.0] * 3 for _ in range(3)]
    m[axis][axis] = 1.0
    m[u][u], m[u][w] = c, -s
    m[w][u], m[w][w] = s, c
    t = sub(through, mat_vec(m, through))
    return m, t


def translation(axis, offset):
    t = [0.0, 0.0, 0.0]
    t[axis] = offset
    return IDENTITY[0], t


def compose(outer, inner):
    """outer after inner."""
    (ro, to), (ri, ti) = outer, inner
    return mat_mul(ro, ri), add(mat_vec(ro, ti), to)


def apply(transform, p):
    return add(mat_vec(transform[0], p), transform[1])


def axis_aligned(transform):
    return all(abs(v) < 1e-12 or abs(abs(v) - 1) < 1e-12 for row in transform[0] for v in row)


def fmt(v):
    return "%.4g" % v


# --------------------------------------------------------------------------------------------------------
# boxes: axis-aligned (lo, hi) and oriented (centre, axes, half sizes)


def box_intersection(a, b):
    lo = [max(a[0][i], b[0][i]) for i in range(3)]
    hi = [min(a[1][i], b[1][i]) for i in range(3)]
    return (lo, hi)


def box_thickness(b):
    return min(b[1][i] - b[0][i] for i in range(3))


def box_subtract(a, c, tol):
    """a minus c as disjoint boxes, dropping slivers thinner than tol."""
    inter = box_intersection(a, c)
    if box_thickness(inter) <= 0:
        return [a]
    pieces = []
    lo, hi = list(a[0]), list(a[1])
    for i in range(3):
        if inter[0][i] > lo[i]:
            plo, phi = list(lo), list(hi)
            phi[i] = inter[0][i]
            pieces.append((plo, phi))
            lo[i] = inter[0][i]
        if inter[1][i] < hi[i]:
            plo, phi = list(lo), list(hi)
            plo[i] = inter[1][i]
            pieces.append((plo, phi))
            hi[i] = inter[1][i]
    return [p for p in pieces if box_thickness(p) > tol]


def box_volume(b):
    """0 for an empty box (an intersection of boxes apart)."""
    return math.prod(max(0.0, b[1][i] - b[0][i]) for i in range(3))


def box_text(b):
    return "x %s..%s y %s..%s z %s..%s" % tuple(fmt(v) for i in range(3) for v in (b[0][i], b[1][i]))


class Oriented:
    """A cuboid moved by a rigid transform: corners, centre, unit axes, half sizes."""

    def __init__(self, lo, hi, transform):
        self.lo, self.hi, self.transform = list(lo), list(hi), transform
        self.aligned = axis_aligned(transform)
        self.corners = [apply(transform, [(lo, hi)[i][0], (lo, hi)[j][1], (lo, hi)[k][2]])
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)]
        self.bbox = ([min(c[i] for c in self.corners) for i in range(3)],
                     [max(c[i] for c in self.corners) for i in range(3)])
        self.centre = apply(transform, [(lo[i] + hi[i]) / 2 for i in range(3)])
        r = transform[0]
        self.axes = [[r[0][i], r[1][i], r[2][i]] for i in range(3)]
        self.half = [(hi[i] - lo[i]) / 2 for i in range(3)]

    def radius_along(self, axis):
        return sum(self.half[i] * abs(dot(self.axes[i], axis)) for i in range(3))

    def halfspaces(self):
        """Six (normal, offset) with normal . x <= offset inside."""
        out = []
        for i in range(3):
            c = dot(self.axes[i], self.centre)
            out.append((self.axes[i], c + self.half[i]))
            out.append((scale(self.axes[i], -1), -(c - self.half[i])))
        return out

    def polyhedron(self):
        """Faces (lists of corner points in order) of the moved cuboid."""
        lo, hi, t = self.lo, self.hi, self.transform

        def p(x, y, z):
            return apply(t, [(lo, hi)[x][0], (lo, hi)[y][1], (lo, hi)[z][2]])

        return [[p(0, 0, 0), p(0, 1, 0), p(0, 1, 1), p(0, 0, 1)], [p(1, 0, 0), p(1, 0, 1), p(1, 1, 1), p(1, 1, 0)],
                [p(0, 0, 0), p(0, 0, 1), p(1, 0, 1), p(1, 0, 0)], [p(0, 1, 0), p(1, 1, 0), p(1, 1, 1), p(0, 1, 1)],
                [p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0)], [p(0, 0, 1), p(0, 1, 1), p(1, 1, 1), p(1, 0, 1)]]


def separating_axes(a, b):
    axes = list(a.axes) + list(b.axes)
    for u in a.axes:
        for v in b.axes:
            c = cross(u, v)
            n = norm(c)
            if n > 1e-9:
                axes.append(scale(c, 1 / n))
    return axes


def sat_depth(a, b):
    """Least overlap of two oriented boxes over the separating axes (<= 0: apart or touching)."""
    depth = float("inf")
    d = sub(b.centre, a.centre)
    for axis in separating_axes(a, b):
        depth = min(depth, a.radius_along(axis) + b.radius_along(axis) - abs(dot(d, axis)))
    return depth


def clip(poly, normal, offset, eps=1e-9):
    """A convex polyhedron (faces) cut to normal . x <= offset."""
    faces, cap = [], []
    for face in poly:
        out = []
        n = len(face)
        for i in range(n):
            a, b = face[i], face[(i + 1) % n]
            da, db = dot(normal, a) - offset, dot(normal, b) - offset
            if da <= eps:
                out.append(a)
            if abs(da) <= eps:
                cap.append(a)
            if (da < -eps and db > eps) or (da > eps and db < -eps):
                p = add(a, scale(sub(b, a), da / (da - db)))
                out.append(p)
                cap.append(p)
        if len(out) >= 3:
            faces.append(out)
    unique = []
    for p in cap:
        if all(norm(sub(p, q)) > 1e-9 for q in unique):
            unique.append(p)
    if len(unique) >= 3:
        centre = scale([sum(p[i] for p in unique) for i in range(3)], 1 / len(unique))
        ref = sub(unique[0], centre)
        if norm(ref) < 1e-12:
            ref = sub(unique[1], centre)
        other = cross(normal, ref)
        unique.sort(key=lambda p: math.atan2(dot(sub(p, centre), other), dot(sub(p, centre), ref)))
        faces.append(unique)
    return faces


def poly_width(poly, axis):
    values = [dot(p, axis) for f in poly for p in f]
    return max(values) - min(values) if values else 0.0


def oriented_overlap(a, b, a_cavities, b_cavities, tol):
    """Depth of the overlap of a's and b's material (solid minus cavities), oriented boxes; 0 when none."""
    if sat_depth(a, b) <= tol:
        return 0.0
    region = a.polyhedron()
    for normal, offset in b.halfspaces():
        region = clip(region, normal, offset)
        if not region:
            return 0.0
    axes = separating_axes(a, b)
    pieces = [region]
    for cavity in list(a_cavities) + list(b_cavities):
        remaining = []
        for piece in pieces:
            rest = piece
            for normal, offset in cavity.halfspaces():
                outside = clip(rest, scale(normal, -1), -offset)
                if outside and min(poly_width(outside, ax) for ax in axes) > tol:
                    remaining.append(outside)
                rest = clip(rest, normal, offset)
                if not rest:
                    break
        pieces = remaining
    if not pieces:
        return 0.0
    return max(min(poly_width(p, ax) for ax in axes) for p in pieces)


# --------------------------------------------------------------------------------------------------------
# the model


class Cuboid:
    def __init__(self, name, part, lo, hi, cavity):
        self.name, self.part, self.lo, self.hi, self.cavity = name, part, list(lo), list(hi), cavity
        self.solid = None  # a cavity: the solid cuboid it is cut from

    def side(self, s):
        return (self.lo, self.hi)[s % 2][s // 2]


def overlap_volume(a, b):
    v = 1.0
    for i in range(3):
        v *= max(0.0, min(a.hi[i], b.hi[i]) - max(a.lo[i], b.lo[i]))
    return v


class Model:
    def __init__(self, data):
        self.data = data
        self.minimum_size = float(data.get("minimum_size", 1))
        self.parts = []  # names in order
        self.cuboids = {}
        self.part_cuboids = {}
        for part in data.get("parts", []):
            name = part["name"]
            self.parts.append(name)
            self.part_cuboids[name] = []
            cuboids = part.get("cuboids", [])
            for k, c in enumerate(cuboids):
                cname = c.get("name", name + (str(k + 1) if len(cuboids) > 1 else ""))
                cub = Cuboid(cname, name, c["min"], c["max"], bool(c.get("cavity", False)))
                self.cuboids[cname] = cub
                self.part_cuboids[name].append(cub)
        for name in self.parts:  # a cavity is cut from the solid cuboid of its part it overlaps most
            solids = [c for c in self.part_cuboids[name] if not c.cavity]
            for c in self.part_cuboids[name]:
                if c.cavity:
                    best = max(solids, key=lambda s: overlap_volume(s, c)) if solids else None
                    c.solid = best if best is not None and overlap_volume(best, c) > 0 else None
        self.joints = {}
        self.joint_order = []
        for j in data.get("joints", []):
            self.joints[j["name"]] = j
            self.joint_order.append(j["name"])
        self.configurations = {}
        self.configuration_order = []
        for c in data.get("configurations", []):
            self.configurations[c["name"]] = c.get("poses", {})
            self.configuration_order.append(c["name"])
        self.relationships = data.get("relationships", [])
        self.locks = data.get("locks", [])
        self.material = {}  # posed_material's, per part and transform

    # ---- names
    def face(self, text):
        """'cuboid.side' -> (cuboid, side index)."""
        name, _, what = text.rpartition(".")
        return self.cuboids[name], SIDES.index(what)

    def solids(self, part):
        return [c for c in self.part_cuboids[part] if not c.cavity]

    def cavities_of(self, solid):
        return [c for c in self.part_cuboids[solid.part] if c.cavity and c.solid is solid]

    def part_joint(self, part):
        for name in self.joint_order:
            if self.joints[name]["part"] == part:
                return name
        return None

    # ---- posing
    def joint_transform(self, name, pose, fraction=1.0):
        """A joint's move `fraction` of the way to its pose: turns in the first half of the way, slides in the
        second (docs/formats.md)."""
        j = self.joints[name]
        kind = j["type"]
        turning, sliding = min(1.0, 2 * fraction), max(0.0, 2 * fraction - 1)
        if kind == "double_pivot":
            return self.pivot_transform(j, pose, turning)
        transform = IDENTITY
        angle = offset = 0.0
        if kind == "sliding_hinge":
            angle, offset = float(pose["angle"]), float(pose["offset"])
        elif kind == "hinge":
            angle = float(pose)
        elif kind == "slide":
            offset = float(pose)
        if kind in ("hinge", "sliding_hinge"):
            (ca, sa), (cb, sb) = self.face(j["edge"][0]), self.face(j["edge"][1])
            axis = 3 - sa // 2 - sb // 2
            through = [0.0, 0.0, 0.0]
            through[sa // 2] = ca.side(sa)
            through[sb // 2] = cb.side(sb)
            transform = rotation(axis, angle * turning, through)
        if kind in ("slide", "sliding_hinge"):
            transform = compose(translation(AXES.index(j["axis"]), offset * sliding), transform)
        return transform

    def pivot_geometry(self, j, pose):
        """The pivot plane's normal, the two pivots, the pole, and the four-bar's link and part turns."""
        cuboid, side = self.face(j["pivot"][0])
        normal = side // 2
        a = [float(v) for v in j["pivot"][1]]
        b = [float(v) for v in j["base_pivot"][1]]
        pole = [float(v) for v in pose["pole"]]
        angle = float(pose["angle"])
        end = apply(rotation(normal, angle, pole), a)
        u, w = (normal + 1) % 3, (normal + 2) % 3
        start_dir = math.atan2(a[w] - b[w], a[u] - b[u])
        end_dir = math.atan2(end[w] - b[w], end[u] - b[u])
        link = math.degrees(end_dir - start_dir)
        link = (link + 180.0) % 360.0 - 180.0  # the link turns the shorter way round
        if abs(link) > 180.0 - 1e-3:  # half a turn either way (to a thousandth of a degree): as the part turns
            link = math.copysign(180.0, angle)
        return normal, a, b, pole, angle, end, link

    def pivot_transform(self, j, pose, fraction):
        normal, a, b, pole, angle, _, link = self.pivot_geometry(j, pose)
        if fraction == 1.0:
            return rotation(normal, angle, pole)
        # along the four-bar: the part turns about its pivot, the link carries it round the base pivot
        return compose(rotation(normal, link * fraction, b), rotation(normal, (angle - link) * fraction, a))

    def chain(self, part):
        """The joints of a part's chain: its own, then its base's, out to the ground."""
        out, seen = [], set()
        while part is not None and part not in seen:
            seen.add(part)
            j = self.part_joint(part)
            if j is None:
                break
            out.append(j)
            part = self.joints[j].get("base")
        return out

    def part_transform(self, part, configuration, fraction=1.0):
        if configuration is None:
            return IDENTITY
        poses = self.configurations[configuration]
        transform = IDENTITY
        for j in self.chain(part):
            if j in poses:
                transform = compose(self.joint_transform(j, poses[j], fraction), transform)
        return transform

    def posed_joints(self, part, configuration):
        if configuration is None:
            return []
        poses = self.configurations[configuration]
        return [j for j in self.chain(part) if j in poses]

    def posed(self, cuboid, configuration):
        return Oriented(cuboid.lo, cuboid.hi, self.part_transform(cuboid.part, configuration))

    def value(self, cuboid, side, configuration):
        """A side of the cuboid's bounding box in the configuration."""
        box = self.posed(cuboid, configuration).bbox
        return box[side % 2][side // 2]

    def quantity(self, text, configuration):
        name, _, what = text.rpartition(".")
        cuboid = self.cuboids[name]
        if what in SIZES:
            box = self.posed(cuboid, configuration).bbox
            return box[1][SIZES[what]] - box[0][SIZES[what]]
        return self.value(cuboid, SIDES.index(what), configuration)

    def expression(self, value, configuration):
        items = value if isinstance(value, list) else [value]
        total = 0.0
        for item in items:
            if isinstance(item, dict):
                total += float(item.get("times", 1)) * self.quantity(item["quantity"], configuration)
            else:
                total += self.quantity(item, configuration)
        return total


def is_opening(model, cavity, side, hair):
    """A cavity side on its solid's side (within hair as drawn), or one a part that fits inside the cavity goes
    out through: posed in a configuration where no fit of it there is measured, half of a cuboid of it that
    must fit lies beyond that side, across the cavity (a shelf pulled out of an oven)."""
    if cavity.solid is not None and abs(cavity.side(side) - cavity.solid.side(side)) <= hair:
        return True
    n = side // 2
    fits = [r for r in model.relationships if r.get("type") == "fit_inside" and r.get("cavity") == cavity.name]
    for r in fits:
        for part in r.get("inner", []):
            measured = {configuration_of(f) for f in fits if part in f.get("inner", [])}
            cuboids = [model.cuboids[c] for c in r["portion"]] if r.get("portion") else model.solids(part)
            for k in model.configuration_order:
                if k in measured:
                    continue
                for c in cuboids:
                    lo, hi = model.posed(c, k).bbox
                    beyond = hi[n] - cavity.hi[n] if side % 2 else cavity.lo[n] - lo[n]
                    across = all(min(hi[i], cavity.hi[i]) > max(lo[i], cavity.lo[i]) for i in range(3) if i != n)
                    if across and beyond >= (hi[n] - lo[n]) / 2:
                        return True
    return False


def where(configuration, fraction=1.0):
    if configuration is None:
        return "as modelled"
    if fraction == 1.0:
        return "in '%s'" % configuration
    return "on the way to '%s' at %d%%" % (configuration, round(100 * fraction))


# --------------------------------------------------------------------------------------------------------
# interpenetration


def posed_material(model, part, transform):
    """Each solid cuboid of a part under a transform, with the cavities cut from it (kept: in most poses along
    a motion most parts stand still)."""
    key = (part, tuple(v for row in transform[0] for v in row), tuple(transform[1]))
    if key not in model.material:
        model.material[key] = [(s, Oriented(s.lo, s.hi, transform),
                             [Oriented(c.lo, c.hi, transform) for c in model.cavities_of(s)])
                            for s in model.solids(part)]
    return model.material[key]


def material_overlap(mp, mq, tol):
    """The deepest overlap of two parts' posed material (posed_material): (depth, text) or None."""
    worst = None
    for sp, op, cavities_p in mp:
        for sq, oq, cavities_q in mq:
            if any(min(op.bbox[1][i], oq.bbox[1][i]) - max(op.bbox[0][i], oq.bbox[0][i]) <= tol for i in range(3)):
                continue
            if op.aligned and oq.aligned:
                pieces = [box_intersection(op.bbox, oq.bbox)]
                for c in cavities_p + cavities_q:
                    pieces = [r for piece in pieces for r in box_subtract(piece, c.bbox, tol)]
                pieces = [r for r in pieces if box_thickness(r) > tol]
                if not pieces:
                    continue
                piece = max(pieces, key=box_thickness)
                depth, text = box_thickness(piece), box_text(piece)
            else:
                depth = oriented_overlap(op, oq, cavities_p, cavities_q, tol)
                if depth <= tol:
                    continue
                text = "turned boxes"
            if worst is None or depth > worst[0]:
                worst = (depth, "'%s' and '%s' overlap by %s mm (%s)" % (sp.name, sq.name, fmt(depth), text))
    return worst


def inverse(transform):
    r, t = transform
    rt = [[r[j][i] for j in range(3)] for i in range(3)]
    return rt, scale(mat_vec(rt, t), -1)


def rooms(model, tol):
    """The room print-in-place cuts for each fit inside (thesis 4.5.1): what its inner parts sweep on the way
    to the fit's configuration, in the frame of the enclosing part, which may move too (a toolbox's tray drawn
    through the box's side gets a slot there); for a fit as modelled, the inner parts where they are.
    {(inner, enclosing): [(lo, hi, transform in the enclosing part's frame)]}. Boxes that slide along one axis
    are joined into the box they sweep."""
    out = {}
    for r in model.relationships:
        if r.get("type") != "fit_inside":
            continue
        k, enclosing = configuration_of(r), r["enclosing"]
        steps = [0.0] if k is None else [i / ROOM_SAMPLES for i in range(ROOM_SAMPLES + 1)]
        for inner in r.get("inner", []):
            boxes = out.setdefault((inner, enclosing), [])
            for c in model.solids(inner):
                poses = [compose(inverse(model.part_transform(enclosing, k, f)), model.part_transform(inner, k, f))
                         for f in steps]
                boxes.extend(joined_slides(c, poses, tol))
    return out


def joined_slides(c, poses, tol):
    """Cuboid c at each pose, as (lo, hi, transform); runs of axis-aligned poses that only shift it along one
    axis, each overlapping the last, as the one box they sweep."""
    out, run = [], []

    def flush():
        if run:
            boxes = [Oriented(c.lo, c.hi, t).bbox for t in run]
            out.append(([min(b[0][i] for b in boxes) for i in range(3)], [max(b[1][i] for b in boxes) for i in range(3)],
                        IDENTITY))
            run.clear()

    for t in poses:
        if not axis_aligned(t):
            flush()
            out.append((c.lo, c.hi, t))
            continue
        if run:
            a, b = Oriented(c.lo, c.hi, run[-1]).bbox, Oriented(c.lo, c.hi, t).bbox
            first = Oriented(c.lo, c.hi, run[0]).bbox
            moved = [i for i in range(3) if abs(b[0][i] - first[0][i]) > 1e-9 or abs(b[1][i] - first[1][i]) > 1e-9]
            if len(moved) > 1 or any(b[0][i] > a[1][i] + tol or a[0][i] > b[1][i] + tol for i in range(3)):
                flush()
        run.append(t)
    flush()
    return out


def fixed_together(model, p, q):
    """Parts a fixed joint holds together (directly or through other fixed joints): one body."""
    def root(part):
        seen = set()
        while part not in seen:
            seen.add(part)
            j = model.part_joint(part)
            if j is None or model.joints[j]["type"] != "fixed":
                return part
            part = model.joints[j].get("base")
        return part
    return root(p) == root(q)


def turns_in(model, joints, configuration):
    """Whether any of the joints turns the part in the configuration."""
    poses = model.configurations[configuration]
    for j in joints:
        kind, pose = model.joints[j]["type"], poses[j]
        angle = float(pose) if kind == "hinge" else float(pose["angle"]) if isinstance(pose, dict) else 0.0
        if kind in ("hinge", "sliding_hinge", "double_pivot") and abs(angle) > 1e-9:
            return True
    return False


def check_overlaps(model, configuration, tol, problems, fraction=1.0, warnings=None, room=None):
    """Material of two parts overlapping: every pair as modelled; in a configuration or on the way there,
    the pairs that move relative to each other (the others were judged as modelled). A fit inside's
    enclosing part has the room its inner parts sweep cut out (rooms())."""
    transforms = {p: model.part_transform(p, configuration, fraction) for p in model.parts}
    material = {p: posed_material(model, p, transforms[p]) for p in model.parts}
    bounds = {p: ([min(o.bbox[0][i] for _, o, _ in material[p]) for i in range(3)],
                  [max(o.bbox[1][i] for _, o, _ in material[p]) for i in range(3)]) if material[p] else None
              for p in model.parts}
    key = {p: tuple(round(v, 9) for row in transforms[p][0] for v in row) + tuple(round(v, 9) for v in transforms[p][1])
           for p in model.parts}
    room = rooms(model, tol) if room is None else room
    for p, q in itertools.combinations(model.parts, 2):
        if bounds[p] is None or bounds[q] is None or \
                any(min(bounds[p][1][i], bounds[q][1][i]) - max(bounds[p][0][i], bounds[q][0][i]) <= tol for i in range(3)):
            continue
        if configuration is not None and key[p] == key[q]:
            continue  # they move together: judged as modelled
        if fixed_together(model, p, q):
            continue
        mp, mq = material[p], material[q]
        for inner, enclosing in ((p, q), (q, p)):
            cut = room.get((inner, enclosing))
            if cut:
                t = transforms[enclosing]
                extra = [Oriented(lo, hi, compose(t, rel)) for lo, hi, rel in cut]
                held = [(s, o, cavities + extra) for s, o, cavities in material[enclosing]]
                mp, mq = (mp, held) if enclosing == q else (held, mq)
        found = material_overlap(mp, mq, tol)
        if not found:
            continue
        text = "interpenetration %s: parts '%s' and '%s': %s" % (where(configuration, fraction), p, q, found[1])
        if fraction == 1.0:
            problems.append(text)
            continue
        # along a motion: the parts' own joints (those they do not share) move one against the other; where
        # both turn, print-in-place bevels each by the other's path (a warning: the print's check judges it)
        joints_p, joints_q = model.posed_joints(p, configuration), model.posed_joints(q, configuration)
        own_p = [j for j in joints_p if j not in joints_q]
        own_q = [j for j in joints_q if j not in joints_p]
        if own_p and own_q and turns_in(model, own_p, configuration) and turns_in(model, own_q, configuration):
            if warnings is not None:
                warnings.append("motion: " + text)
            continue
        problems.append("motion collision: %s (joints %s)" % (text, ", ".join("'%s'" % j for j in own_p + own_q)))


# --------------------------------------------------------------------------------------------------------
# relationships


def configuration_of(r):
    return r.get("configuration")


def rectangles_union_minus(a_rects, b_rects, tol):
    """Pieces of the union of a_rects not inside the union of b_rects (2-D, (lo, hi) pairs)."""
    pieces = []
    for r in a_rects:
        rest = [r]
        for b in b_rects:
            nxt = []
            for piece in rest:
                nxt.extend(rect_subtract(piece, b))
            rest = nxt
        pieces.extend(p for p in rest if min(p[1][0] - p[0][0], p[1][1] - p[0][1]) > tol)
    return pieces


def rect_subtract(a, c):
    lo = [max(a[0][i], c[0][i]) for i in range(2)]
    hi = [min(a[1][i], c[1][i]) for i in range(2)]
    if hi[0] <= lo[0] or hi[1] <= lo[1]:
        return [a]
    out = []
    alo, ahi = list(a[0]), list(a[1])
    for i in range(2):
        if lo[i] > alo[i]:
            plo, phi = list(alo), list(ahi)
            phi[i] = lo[i]
            out.append((plo, phi))
            alo[i] = lo[i]
        if hi[i] < ahi[i]:
            plo, phi = list(alo), list(ahi)
            plo[i] = hi[i]
            out.append((plo, phi))
            ahi[i] = hi[i]
    return out


def infer_cover_pairs(model, r, configuration):
    """The checker's own reading of a cover without pairs: facing faces within `distance`, overlapping by
    half the smaller face; a covering face linked to an opening is not linked to the wall around it; the edge of
    a board (a face less than half its cuboid's largest) covers nothing."""
    distance = float(r.get("distance", 5))
    pairs = []
    for p in r["covering"]:
        for a in model.solids(p):
            ba = model.posed(a, configuration).bbox
            size = [ba[1][i] - ba[0][i] for i in range(3)]
            areas = [size[(n + 1) % 3] * size[(n + 2) % 3] for n in range(3)]
            for sa in range(6):
                if 2 * areas[sa // 2] < max(areas):
                    continue
                found = {True: [], False: []}
                for q in r["covered"]:
                    for b in model.part_cuboids[q]:
                        sb = sa ^ 1
                        if b.cavity and not is_opening(model, b, sb, OPENING_HAIR):
                            continue
                        bb = model.posed(b, configuration).bbox
                        n = sa // 2
                        gap = abs(ba[sa % 2][n] - bb[sb % 2][n])
                        u, v = (n + 1) % 3, (n + 2) % 3
                        ou = min(ba[1][u], bb[1][u]) - max(ba[0][u], bb[0][u])
                        ov = min(ba[1][v], bb[1][v]) - max(ba[0][v], bb[0][v])
                        smaller = min((ba[1][u] - ba[0][u]) * (ba[1][v] - ba[0][v]),
                                      (bb[1][u] - bb[0][u]) * (bb[1][v] - bb[0][v]))
                        if gap <= distance and ou > 0 and ov > 0 and ou * ov > smaller / 2:
                            found[b.cavity].append(["%s.%s" % (a.name, SIDES[sa]), "%s.%s" % (b.name, SIDES[sb])])
                pairs.extend(found[True] or found[False])
    return pairs


def infer_support_pairs(model, r, configuration, tol):
    distance = float(r.get("distance", 100))
    pairs = []
    for p in r["supporting"]:
        for a in model.solids(p):
            top = model.value(a, 5, configuration)
            best = None
            for q in r["supported"]:
                for b in model.solids(q):
                    rise = model.value(b, 4, configuration) - top
                    if -tol <= rise <= distance and (best is None or rise < best[0]):
                        best = (rise, b)
            if best:
                pairs.append(["%s.top" % a.name, "%s.bottom" % best[1].name])
    return pairs


def components(pairs):
    parent = {}

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    for a, b in pairs:
        parent.setdefault(a, a)
        parent.setdefault(b, b)
        parent[root(b)] = root(a)
    groups = {}
    for a, b in pairs:
        g = groups.setdefault(root(a), ([], []))
        if a not in g[0]:
            g[0].append(a)
        if b not in g[1]:
            g[1].append(b)
    return list(groups.values())


def check_cover(model, r, tol, problems):
    k = configuration_of(r)
    name = "cover '%s' (%s)" % (r["name"], where(k))
    pairs = r.get("pairs")
    if pairs is None:
        pairs = infer_cover_pairs(model, r, k)
    for role, parts, index in (("covering", r["covering"], 0), ("covered", r["covered"], 1)):
        for p in parts:
            if not any(model.face(pair[index])[0].part == p for pair in pairs):
                problems.append("%s: %s part '%s' has no face in the cover's pairs (dropped)" % (name, role, p))
    for covering, covered in components(pairs):
        faces = [model.face(f) for f in covering + covered]
        axes = {s // 2 for _, s in faces}
        if len(axes) != 1:
            problems.append("%s: faces %s are not parallel" % (name, ", ".join(covering + covered)))
            continue
        n = axes.pop()
        u, v = (n + 1) % 3, (n + 2) % 3
        values = [model.value(c, s, k) for c, s in faces]
        if max(values) - min(values) > tol:
            problems.append("%s: faces %s are not in one plane (%s)"
                            % (name, ", ".join(covering + covered), ", ".join(fmt(x) for x in values)))
        for a in covering:
            for b in covered:
                if [a, b] in pairs and model.face(a)[1] != model.face(b)[1] ^ 1:
                    problems.append("%s: %s does not face %s" % (name, a, b))

        def rects(names):
            out = []
            for f in names:
                box = model.posed(model.face(f)[0], k).bbox
                out.append(([box[0][u], box[0][v]], [box[1][u], box[1][v]]))
            return out

        bare = rectangles_union_minus(rects(covered), rects(covering), tol)
        if bare:
            problems.append("%s: %s not covered by %s: %s %s..%s, %s %s..%s left bare"
                            % (name, ", ".join(covered), ", ".join(covering), AXES[u], fmt(bare[0][0][0]),
                               fmt(bare[0][1][0]), AXES[v], fmt(bare[0][0][1]), fmt(bare[0][1][1])))
        if r.get("just"):
            over = rectangles_union_minus(rects(covering), rects(covered), tol)
            if over:
                problems.append("%s: just, but %s reaches past %s: %s %s..%s, %s %s..%s"
                                % (name, ", ".join(covering), ", ".join(covered), AXES[u], fmt(over[0][0][0]),
                                   fmt(over[0][1][0]), AXES[v], fmt(over[0][0][1]), fmt(over[0][1][1])))


def covering_alongside(model, r, pairs, tol):
    """The drawing links a covered face to some covering faces; the cover's other covering parts help cover it
    where, solved, a face of theirs on the same side lies in its plane over it (a lid and its flap over one well,
    the flap drawn 11 mm above it: seed 7591)."""
    k = configuration_of(r)
    extra = []
    for a, b in pairs:
        covered, side = model.face(b)[0], model.face(a)[1]
        n = side // 2
        over = model.posed(covered, k).bbox
        for c in (c for p in r["covering"] for c in model.solids(p)):
            face = "%s.%s" % (c.name, SIDES[side])
            box = model.posed(c, k).bbox
            if [face, b] in pairs + extra or abs(box[side % 2][n] - model.value(covered, side ^ 1, k)) > tol:
                continue
            if all(min(box[1][u], over[1][u]) - max(box[0][u], over[0][u]) > tol for u in range(3) if u != n):
                extra.append([face, b])
    return extra


def check_cover_intent(model, drawn, r, tol, problems):
    """A cover drawn without pairs, read by the checker itself on the drawing (faces within twice the cover
    distance, a user's gap of up to 10 mm): what it links must be covered in the solved model too. Only for
    covers that are not "just" (a larger cover of the wall around an opening covers the opening as well)."""
    if "pairs" in r or r.get("just"):
        return
    mine = infer_cover_pairs(drawn, dict(r, distance=2 * float(r.get("distance", 5))), configuration_of(r))
    if not mine:
        return
    mine += covering_alongside(model, r, mine, tol)
    found = []
    check_cover(model, dict(r, pairs=mine), tol, found)
    reading = "; ".join("%s over %s" % (a, b) for a, b in mine)
    problems.extend("%s [the cover as the drawing shows it: %s]" % (p, reading) for p in found if "(dropped)" not in p)


def enclosing_box(model, part, configuration):
    boxes = [model.posed(c, configuration).bbox for c in model.solids(part)]
    return ([min(b[0][i] for b in boxes) for i in range(3)], [max(b[1][i] for b in boxes) for i in range(3)])


def check_fit_inside(model, r, tol, problems):
    k = configuration_of(r)
    name = "fit inside '%s' (%s)" % (r["name"], where(k))
    if r.get("cavity"):
        container = model.posed(model.cuboids[r["cavity"]], k).bbox
        what = "cavity '%s'" % r["cavity"]
    else:
        container = enclosing_box(model, r["enclosing"], k)
        what = "the box of '%s'" % r["enclosing"]
    if r.get("portion"):
        inner = [model.cuboids[c] for c in r["portion"]]
    else:
        inner = [c for p in r["inner"] for c in model.solids(p)]
    for c in inner:
        box = model.posed(c, k).bbox
        out = []
        for i in range(3):
            if box[0][i] < container[0][i] - tol:
                out.append("%s %s below %s" % (AXES[i], fmt(container[0][i] - box[0][i]), fmt(container[0][i])))
            if box[1][i] > container[1][i] + tol:
                out.append("%s %s past %s" % (AXES[i], fmt(box[1][i] - container[1][i]), fmt(container[1][i])))
        if out:
            problems.append("%s: '%s' sticks out of %s (%s)" % (name, c.name, what, "; ".join(out)))
    for a, axis, b in r.get("apart", []):
        i = AXES.index(axis)
        high = model.posed(model.cuboids[a], k).bbox[1][i]
        low = model.posed(model.cuboids[b], k).bbox[0][i]
        if high > low + tol:
            problems.append("%s: '%s' and '%s' not apart along %s (%s > %s)" % (name, a, b, axis, fmt(high), fmt(low)))
    for item in r.get("just", []):
        if isinstance(item, list) and len(item) == 2:
            pairs = [item]
        else:  # an axis, or {"part", "axes"}: the inner parts' extreme faces on the walls
            parts = [item["part"]] if isinstance(item, dict) else r["inner"]
            axes = item["axes"] if isinstance(item, dict) else [item]
            pairs = []
            for axis in axes:
                i = AXES.index(axis)
                for high in (0, 1):
                    cubs = [c for p in parts for c in model.solids(p)]
                    pick = (max if high else min)(cubs, key=lambda c: model.posed(c, k).bbox[high][i])
                    wall = model.cuboids[r["cavity"]] if r.get("cavity") else (max if high else min)(
                        model.solids(r["enclosing"]), key=lambda c: model.posed(c, k).bbox[high][i])
                    side = SIDES[2 * i + high]
                    pairs.append(["%s.%s" % (pick.name, side), "%s.%s" % (wall.name, side)])
        for a, b in pairs:
            va, vb = model.quantity(a, k), model.quantity(b, k)
            if abs(va - vb) > tol:
                problems.append("%s: %s (%s) does not just fit %s (%s)" % (name, a, fmt(va), b, fmt(vb)))


def check_support(model, r, tol, problems):
    k = configuration_of(r)
    name = "support '%s' (%s)" % (r["name"], where(k))
    pairs = r.get("pairs")
    if pairs is None:
        pairs = infer_support_pairs(model, r, k, tol)
    for role, parts, index in (("supporting", r["supporting"], 0), ("supported", r["supported"], 1)):
        for p in parts:
            if not any(model.face(pair[index])[0].part == p for pair in pairs):
                problems.append("%s: %s part '%s' is in no pair (dropped)" % (name, role, p))
    for top, bottom in pairs:
        a, sa = model.face(top)
        b, sb = model.face(bottom)
        if sa != 5 or sb != 4:
            problems.append("%s: pair %s, %s is not a top under a bottom" % (name, top, bottom))
            continue
        ba, bb = model.posed(a, k).bbox, model.posed(b, k).bbox
        if abs(ba[1][2] - bb[0][2]) > tol:
            problems.append("%s: %s at %s but %s at %s" % (name, top, fmt(ba[1][2]), bottom, fmt(bb[0][2])))
        for i in (0, 1):
            o = min(ba[1][i], bb[1][i]) - max(ba[0][i], bb[0][i])
            if o < model.minimum_size - tol:
                problems.append("%s: %s and %s overlap by only %s mm along %s" % (name, top, bottom, fmt(o), AXES[i]))
    only = [p for p in r["supporting"] if p not in r["supported"]]
    grounds = {p: min(model.posed(c, k).bbox[0][2] for c in model.solids(p)) for p in only}
    if grounds and max(grounds.values()) - min(grounds.values()) > tol:
        problems.append("%s: the supporting parts do not stand on one ground (%s)"
                        % (name, ", ".join("%s at %s" % (p, fmt(z)) for p, z in grounds.items())))


def check_flush(model, r, tol, problems):
    k = configuration_of(r)
    (a, sa), (b, sb) = model.face(r["faces"][0]), model.face(r["faces"][1])
    if sa // 2 != sb // 2:
        problems.append("flush '%s' (%s): faces are not parallel" % (r["name"], where(k)))
        return
    va, vb = model.value(a, sa, k), model.value(b, sb, k)
    if abs(va - vb) > tol:
        problems.append("flush '%s' (%s): %s at %s, %s at %s" % (r["name"], where(k), r["faces"][0], fmt(va),
                                                                 r["faces"][1], fmt(vb)))


def check_geometric(model, r, tol, problems):
    k = configuration_of(r)
    left = model.expression(r["left"], k)
    right = model.expression(r["right"], k) + float(r.get("offset", 0))
    relation = r.get("relation", "equal")
    bad = abs(left - right) > tol if relation == "equal" else left > right + tol
    if bad:
        problems.append("geometric '%s' (%s): %s %s %s does not hold"
                        % (r["name"], where(k), fmt(left), "=" if relation == "equal" else "<=", fmt(right)))


# --------------------------------------------------------------------------------------------------------
# openings, walls, locks, double pivots


def exempt_from_closing(model, cavity):
    """Parts meant to be in the cavity: the inner parts of a fit inside in it (or in its part's box), and parts
    that go into it in a configuration (mostly inside it there: a pocket door turned into its bay)."""
    out = set()
    for r in model.relationships:
        if r.get("type") != "fit_inside" or r.get("enclosing") != cavity.part:
            continue
        if r.get("cavity") in (None, cavity.name):
            out.update(r.get("inner", []))
    covering = {p for r in model.relationships if r.get("type") == "cover" and cavity.part in r.get("covered", [])
                for p in r.get("covering", [])}
    out.update(q for q in model.parts for p in covering if q != p and fixed_together(model, q, p))  # its knob
    room = (cavity.lo, cavity.hi)
    for part in model.parts:
        for k in model.configuration_order:
            transform = model.part_transform(part, k)
            boxes = [Oriented(c.lo, c.hi, transform).bbox for c in model.solids(part)]
            volume = sum(box_volume(b) for b in boxes)
            within = sum(box_volume(box_intersection(b, room)) for b in boxes)
            if volume > 0 and 2 * within > volume:
                out.add(part)
    return out



def check_openings_and_walls(model, original, tol, problems):
    for part in model.parts:
        for cavity in model.part_cuboids[part]:
            if not cavity.cavity:
                continue
            if cavity.solid is None:
                problems.append("cavity '%s' lies outside every solid cuboid of '%s'" % (cavity.name, part))
                continue
            solid = cavity.solid
            drawn = original.cuboids.get(cavity.name)
            for s in range(6):
                was_opening = drawn is not None and drawn.solid is not None and \
                    is_opening(original, drawn, s, OPENING_HAIR)
                skin = (cavity.side(s) - solid.side(s)) * (1 if s % 2 == 0 else -1)  # material beyond it
                if skin < -tol:
                    problems.append("cavity '%s' reaches %s mm past %s.%s" % (cavity.name, fmt(-skin), solid.name,
                                                                             SIDES[s]))
                elif was_opening:
                    if skin > tol:
                        problems.append("opening sealed: %s.%s lies %s mm inside %s.%s (was an opening)"
                                        % (cavity.name, SIDES[s], fmt(skin), solid.name, SIDES[s]))
                elif skin < MINIMUM_WALL - tol:
                    problems.append("thin wall: %s.%s leaves %s mm of %s (at least %s mm)"
                                    % (cavity.name, SIDES[s], fmt(skin), solid.name, fmt(MINIMUM_WALL)))
                if was_opening and skin <= tol:
                    check_closed(model, cavity, s, tol, problems)


def check_closed(model, cavity, s, tol, problems):
    """Another part closes an opening (as modelled) when its material crosses the opening's plane within the
    opening and lies mostly in front of it: a skin of a door sunk behind the face. Parts that belong in the
    cavity (their material mostly behind the plane, like a drawer's tray, or named inner parts of a fit
    inside in it) pass through the opening and do not close it; parts in front that only touch do not."""
    n = s // 2
    plane = cavity.side(s)
    inward = -1 if s % 2 else 1  # from the plane into the cavity
    exempt = exempt_from_closing(model, cavity)
    for q in model.parts:
        if q == cavity.part or any(fixed_together(model, q, e) for e in exempt | {cavity.part}):
            continue
        inside = outside = 0.0
        where_inside = None
        for c in model.solids(q):
            prism = ([cavity.lo[i] if i != n else -1e18 for i in range(3)],
                     [cavity.hi[i] if i != n else 1e18 for i in range(3)])
            pieces = [box_intersection((c.lo, c.hi), prism)]
            pieces = [p for p in pieces if box_thickness(p) > tol]  # within the opening
            for own in model.cavities_of(c):  # q's material: its solid minus its own cavities
                pieces = [r for piece in pieces for r in box_subtract(piece, (own.lo, own.hi), tol)]
            for lo, hi in pieces:  # a piece that crosses the plane: behind it and in front of it
                behind = max((lo[n] - plane) * inward, (hi[n] - plane) * inward)
                front = max(-(lo[n] - plane) * inward, -(hi[n] - plane) * inward)
                if behind <= tol or front <= tol:
                    continue
                depth = min(behind, cavity.hi[n] - cavity.lo[n])
                if depth > inside:
                    inside, where_inside = depth, c
                outside = max(outside, front)
        if inside > tol and outside > tol and inside < outside:
            problems.append("opening closed: '%s' (part '%s') reaches %s mm behind the opening %s.%s at %s %s"
                            % (where_inside.name, q, fmt(inside), cavity.name, SIDES[s], AXES[n], fmt(plane)))


def check_locks(model, original, problems):
    for lock in model.locks:
        try:
            c, s = model.face(lock)
            o, so = original.face(lock)
        except (KeyError, ValueError):
            problems.append("lock '%s' names no face of the model" % lock)
            continue
        moved = abs(c.side(s) - o.side(so))
        if moved > LOCK_TOLERANCE:
            residue = " (a residue)" if moved < 1e-4 else ""
            problems.append("lock '%s' moved by %.3g mm (%r -> %r)%s" % (lock, moved, o.side(so), c.side(s), residue))
    for lock in original.locks:
        if lock not in model.locks:
            problems.append("lock '%s' is missing from the solved model" % lock)


def check_structure(model, original, problems):
    for part in original.parts:
        if part not in model.part_cuboids:
            problems.append("part '%s' is missing from the solved model" % part)
    for name in original.cuboids:
        if name not in model.cuboids:
            problems.append("cuboid '%s' is missing from the solved model" % name)
    solved_names = {r.get("name") for r in model.relationships}
    for r in original.relationships:
        if r.get("name") not in solved_names:
            problems.append("relationship '%s' is missing from the solved model" % r.get("name"))
    for j in original.joints:
        if j not in model.joints:
            problems.append("joint '%s' is missing from the solved model" % j)


def joined(a, b, tol):
    """Whether two cuboids are joined face to face (or overlap): touching along one axis, overlapping along the
    other two."""
    meet = [min(a.hi[x], b.hi[x]) - max(a.lo[x], b.lo[x]) for x in range(3)]
    return min(meet) >= -tol and sorted(meet)[1] > tol


def check_one_piece(model, tol, problems):
    """Every part one piece: its solid cuboids joined face to face (or overlapping), none cut through by a
    cavity of its own."""
    for part in model.parts:
        solids = model.solids(part)
        group = list(range(len(solids)))

        def root(i):
            while group[i] != i:
                i = group[i]
            return i

        for i, j in itertools.combinations(range(len(solids)), 2):
            if joined(solids[i], solids[j], tol):
                group[root(j)] = root(i)
        pieces = len({root(i) for i in range(len(solids))})
        if pieces > 1:
            apart = min((max(max(a.lo[x] - b.hi[x], b.lo[x] - a.hi[x]) for x in range(3)), a.name, b.name)
                        for a, b in itertools.combinations(solids, 2) if root(solids.index(a)) != root(solids.index(b)))
            problems.append("part '%s' is in %d pieces ('%s' and '%s' %s mm apart)"
                            % (part, pieces, apart[1], apart[2], fmt(apart[0])))
        j = model.part_joint(part)
        if j and model.joints[j]["type"] == "fixed":  # one body with its base: joined face to face
            base = model.solids(model.joints[j]["base"])
            if not any(joined(a, b, tol) for a in solids for b in base):
                problems.append("part '%s' does not touch '%s', which fixed joint '%s' holds it to"
                                % (part, model.joints[j]["base"], j))
        for s in solids:
            for c in model.cavities_of(s):
                through = [x for x in range(3) if c.lo[x] <= s.lo[x] + tol and c.hi[x] >= s.hi[x] - tol]
                if len(through) == 2:
                    x = 3 - sum(through)
                    if c.lo[x] > s.lo[x] + tol and c.hi[x] < s.hi[x] - tol:
                        problems.append("part '%s': cavity '%s' cuts '%s' in two" % (part, c.name, s.name))


def check_double_pivots(model, tol, problems):
    for name in model.joint_order:
        j = model.joints[name]
        if j["type"] != "double_pivot":
            continue
        (a, sa), (b, sb) = model.face(j["pivot"][0]), model.face(j["base_pivot"][0])
        if sa // 2 != sb // 2 or abs(a.side(sa) - b.side(sb)) > tol:
            problems.append("double pivot '%s': %s and %s are not in one plane" % (name, j["pivot"][0],
                                                                                  j["base_pivot"][0]))
        for (c, s), point in (((a, sa), j["pivot"][1]), ((b, sb), j["base_pivot"][1])):
            for i in range(3):
                if i == s // 2:
                    continue
                if not c.lo[i] - tol <= point[i] <= c.hi[i] + tol:
                    problems.append("double pivot '%s': its pivot %s lies off %s.%s" % (name, point, c.name,
                                                                                      SIDES[s]))
                    break
        for k in model.configuration_order:
            pose = model.configurations[k].get(name)
            if pose is None:
                continue
            normal, pa, pb, pole, angle, end, link = model.pivot_geometry(j, pose)
            before, after = norm(sub(pa, pb)), norm(sub(end, pb))
            if abs(before - after) > tol:
                problems.append("double pivot '%s' (%s): the link is %s mm long but must reach %s mm"
                                % (name, where(k), fmt(before), fmt(after)))
            base = j.get("base")
            if base and any(jj in model.configurations[k] for jj in model.chain(base)):
                problems.append("double pivot '%s' (%s): its base moves" % (name, where(k)))


# --------------------------------------------------------------------------------------------------------


CHECKS = {"cover": check_cover, "fit_inside": check_fit_inside, "support": check_support, "flush": check_flush,
          "geometric": check_geometric}


def check_all(solved, original=None, tolerance=1e-4):
    """(problems, warnings) for a solved works-like model (a dict as read from JSON)."""
    problems, warnings = [], []
    model = Model(solved)
    drawn = Model(original) if original is not None else model
    if original is not None:
        check_structure(model, drawn, problems)
        check_locks(model, drawn, problems)
    room = rooms(model, tolerance)
    check_overlaps(model, None, tolerance, problems, room=room)
    for k in model.configuration_order:
        check_overlaps(model, k, tolerance, problems, room=room)
    for r in model.relationships:
        kind = r.get("type")
        if kind not in CHECKS:
            warnings.append("relationship '%s' of type '%s' is not known to the checker" % (r.get("name"), kind))
            continue
        try:
            CHECKS[kind](model, r, tolerance, problems)
        except KeyError as e:
            problems.append("%s '%s': names something the model does not have: %s" % (kind, r.get("name"), e))
    for r in drawn.relationships if original is not None else []:
        if r.get("type") == "cover":
            try:
                check_cover_intent(model, drawn, r, tolerance, problems)
            except KeyError:
                pass  # a relationship the solved model lacks: check_structure says so
    check_openings_and_walls(model, drawn, tolerance, problems)
    check_double_pivots(model, tolerance, problems)
    check_one_piece(model, tolerance, problems)
    for k in model.configuration_order:
        for i in range(1, MOTION_SAMPLES):
            check_overlaps(model, k, tolerance, problems, fraction=i / MOTION_SAMPLES, warnings=warnings, room=room)
    return dedupe(problems), dedupe(warnings)


def dedupe(items):
    """Keep the first of each message about the same parts and motion (16 poses repeat one collision)."""
    out, seen = [], set()
    for item in items:
        key = item
        if " on the way to " in item:
            head, _, rest = item.partition(" on the way to ")
            config = rest.split("'")[1]
            parts = rest.split(": parts ", 1)[1].split(":")[0] if ": parts " in rest else rest
            key = (head, config, parts)
        if key not in seen:
            seen.add(key)
            out.append(item)
    return out


def check(solved, original=None, tolerance=1e-4, warnings=None):
    """Problems found in a solved works-like model (empty: it passes). Warnings go to `warnings` if given."""
    problems, found = check_all(solved, original, tolerance)
    if warnings is not None:
        warnings.extend(found)
    return problems


def main(argv):
    if len(argv) < 2:
        print("usage: workslike_checker.py SOLVED.workslike.json [ORIGINAL.workslike.json]")
        return 2
    solved = json.load(open(argv[1]))
    original = json.load(open(argv[2])) if len(argv) > 2 else None
    problems, warnings = check_all(solved, original)
    for p in problems:
        print("PROBLEM " + p)
    for w in warnings:
        print("warning " + w)
    print("%d problems, %d warnings" % (len(problems), len(warnings)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
