"""Independent check of a layout of irregular parts against its *.pack.json problem, on the parts' real outlines
(not their bounding boxes): every unit placed once, each part inside its board's trim, and no two parts'
material closer than the clearance (kerf + spacing); a part may lie in another's hole, clear of its edge. Plain
Python geometry, sharing nothing with the layout engine. Returns a list of problems, empty when valid."""
import itertools
import math


def placed(part, placement):
    """The part's rings (outer first, then holes) turned by the placement's rotation and moved so the bounding box
    of its outer ring has its lower-left corner at (x, y)."""
    degrees = placement["rotation"] % 360
    rings = [part["outline"]] + part.get("holes", [])

    def turn(x, y):
        if degrees % 90 == 0:  # quarter turns exactly
            for _ in range(degrees // 90):
                x, y = -y, x
            return x, y
        a = math.radians(degrees)
        return x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)
    rings = [[turn(x, y) for x, y in ring] for ring in rings]
    low_x = min(x for x, _ in rings[0])
    low_y = min(y for _, y in rings[0])
    return [[(x - low_x + placement["x"], y - low_y + placement["y"]) for x, y in ring] for ring in rings]


def inside(ring, point):
    x, y = point
    found = False
    for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            found = not found
    return found


def in_material(rings, point):
    return inside(rings[0], point) and not any(inside(hole, point) for hole in rings[1:])


def cross(o, p, q):
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


def cross_through(a, b, c, d, eps=1e-9):
    """Whether segments ab and cd cross, each passing through the other (touching does not count)."""
    return cross(a, b, c) * cross(a, b, d) < -eps and cross(c, d, a) * cross(c, d, b) < -eps


def segment_distance(a, b, c, d):
    if cross_through(a, b, c, d, 0.0):
        return 0.0

    def to_segment(p, s, t):
        dx, dy = t[0] - s[0], t[1] - s[1]
        length = dx * dx + dy * dy
        u = 0.0 if length == 0 else max(0.0, min(1.0, ((p[0] - s[0]) * dx + (p[1] - s[1]) * dy) / length))
        return math.hypot(p[0] - s[0] - u * dx, p[1] - s[1] - u * dy)
    return min(to_segment(a, c, d), to_segment(b, c, d), to_segment(c, a, b), to_segment(d, a, b))


def edges(rings):
    for ring in rings:
        yield from zip(ring, ring[1:] + ring[:1])


def overlap(a, b, eps=1e-6):
    """Whether two placed parts share material: a vertex of one deeper than eps in the other's material, or edges
    crossing through each other (parts that only touch do not overlap)."""
    def deep(rings, point):
        return in_material(rings, point) and min(segment_distance(point, point, p, q) for p, q in edges(rings)) > eps
    return any(deep(b, v) for v in a[0]) or any(deep(a, v) for v in b[0]) or \
        any(cross_through(p, q, r, s) for p, q in edges(a) for r, s in edges(b))


def bounds(rings):
    xs = [x for x, _ in rings[0]]
    ys = [y for _, y in rings[0]]
    return min(xs), min(ys), max(xs), max(ys)


def problems(layout, problem, eps=1e-6, rotation_step=None):
    """`rotation_step`: the free rotation the layout was asked for, when not the problem's settings.rotation_step."""
    settings = problem.get("settings", {})
    clearance = settings.get("kerf", 0) + settings.get("spacing", 0)
    trim = settings.get("trim", 0)
    parts = {p["id"]: p for p in problem["parts"]}
    found = []
    count = {}
    shapes = []
    for n, p in enumerate(layout["placements"]):
        count[p["part"]] = count.get(p["part"], 0) + 1
        step, part = rotation_step or settings.get("rotation_step", 0), parts[p["part"]]
        allowed = part.get("orientations", [0, 90, 180, 270])
        free = step and not part.get("follow_grain") and all(r in allowed for r in (0, 90, 180, 270))
        if p["rotation"] % 360 not in allowed and not (free and p["rotation"] % step == 0):
            found.append("placement {}: {!r} turned {} degrees, which it may not".format(n, p["part"], p["rotation"]))
        rings = placed(part, p)
        board = layout["boards"][p["board"]]
        low_x, low_y, high_x, high_y = bounds(rings)
        if low_x < trim - eps or low_y < trim - eps or high_x > board["width"] - trim + eps or \
                high_y > board["height"] - trim + eps:
            found.append("placement {}: {!r} leaves board {}".format(n, p["part"], p["board"]))
        shapes.append((n, p["board"], rings, (low_x, low_y, high_x, high_y)))
    for part in problem["parts"]:
        if count.get(part["id"], 0) != part.get("quantity", 1):
            found.append("part {!r}: placed {} times, demand {}".format(part["id"], count.get(part["id"], 0),
                                                                        part.get("quantity", 1)))
    for (i, board_a, a, box_a), (j, board_b, b, box_b) in itertools.combinations(shapes, 2):
        if board_a != board_b or box_a[2] + clearance <= box_b[0] or box_b[2] + clearance <= box_a[0] or \
                box_a[3] + clearance <= box_b[1] or box_b[3] + clearance <= box_a[1]:
            continue
        if overlap(a, b):
            found.append("placements {} and {} overlap".format(i, j))
            continue
        nearest = min(segment_distance(p, q, r, s) for p, q in edges(a) for r, s in edges(b))
        if nearest < clearance - 1e-3:
            found.append("placements {} and {} are {:.3f} mm apart, less than {}".format(i, j, nearest, clearance))
    return found
