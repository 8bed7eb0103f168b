"""An independent check of the G-code made for one master board: it reads the G-code as a machine would (G0-G3,
G81-G83, absolute millimetres, tool changes) and judges it against the parts as designed, knowing nothing of how
CAM made it. What matters physically:
- the mill never cuts into a part (its centre stays its radius off every part's material; dogbones may cut
  into a corner, moving along its bisector from the offset corner until the tool touches the corner);
- every contour of every part is cut through (to the sheet's underside), all round except at holding tags
  and, without dogbones, at its inside corners (with dogbones, the tool reaches each of them);
- nothing is cut below the sheet; each dowel hole is drilled where it belongs to its depth, and nowhere else;
- engraving stays on the parts' faces, at most its depth deep;
- a part's holes are cut through before its outline is.
`problems(...)` returns what is wrong, in sentences; empty when the G-code is right."""
import math
import re

import numpy as np

WORD = re.compile(r"([A-Z])\s*([-+]?\d*\.?\d+(?:[eE][-+]?\d+)?)")
TOOL_CHANGE = re.compile(r"M0?6\s*T(\d+)")


def moves(text):
    """[(tool, kind, start, end, centre, feed)] in machine order: kind 0-3 for G0-G3 (centre for arcs), 81 for a
    drill cycle (its end is the hole's bottom); feed: the F in force (mm/min), None before the first."""
    position, tool, mode, feed, result = [0.0, 0.0, 0.0], 0, 0, None, []
    for raw in text.splitlines():
        changed = TOOL_CHANGE.search(raw)
        if changed:
            tool = int(changed.group(1))
        line = re.sub(r"\(.*?\)|;.*", "", raw.upper())
        words = WORD.findall(line)
        codes = [int(float(v)) for k, v in words if k == "G"]
        values = {k: float(v) for k, v in words if k != "G"}
        feed = values.get("F", feed)
        for code in codes:
            if code in (0, 1, 2, 3, 81, 82, 83):
                mode = code
        if not any(k in values for k in "XYZ"):
            continue
        end = [values.get("X", position[0]), values.get("Y", position[1]), values.get("Z", position[2])]
        if mode in (81, 82, 83):
            result.append((tool, 81, list(position), end, None, feed))
            end = [end[0], end[1], values.get("R", position[2])]  # back to the retract plane
        elif mode in (2, 3):
            centre = (position[0] + values.get("I", 0.0), position[1] + values.get("J", 0.0))
            result.append((tool, mode, list(position), end, centre, feed))
        else:
            result.append((tool, mode, list(position), end, None, feed))
        position = end
    return result


def samples(move, step):
    """Points along a feed move, at most `step` apart (its end included)."""
    _, kind, a, b, centre, _ = move
    a, b = np.array(a), np.array(b)
    if kind in (2, 3):
        r = math.hypot(a[0] - centre[0], a[1] - centre[1])
        t0 = math.atan2(a[1] - centre[1], a[0] - centre[0])
        t1 = math.atan2(b[1] - centre[1], b[0] - centre[0])
        sweep = (t1 - t0) % (2 * math.pi) if kind == 3 else -((t0 - t1) % (2 * math.pi))
        if abs(sweep) < 1e-9 and np.allclose(a, b):
            sweep = 2 * math.pi if kind == 3 else -2 * math.pi  # a full circle
        n = max(1, int(math.ceil(abs(sweep) * r / step)))
        t = t0 + sweep * np.arange(1, n + 1) / n
        z = a[2] + (b[2] - a[2]) * np.arange(1, n + 1) / n
        return np.column_stack([centre[0] + r * np.cos(t), centre[1] + r * np.sin(t), z])
    n = max(1, int(math.ceil(np.linalg.norm(b - a) / step)))
    return a + (b - a) * (np.arange(1, n + 1) / n)[:, None]


def segments(polygon):
    p = np.array(polygon, dtype=float)
    return p, np.roll(p, -1, axis=0)


def distance_to(points, polygon):
    """Each point's distance to the polygon's boundary."""
    a, b = segments(polygon)
    d = b - a
    length2 = np.maximum((d ** 2).sum(axis=1), 1e-18)
    best = np.full(len(points), np.inf)
    for chunk in range(0, len(points), 4096):
        p = points[chunk:chunk + 4096, None, :2]
        t = np.clip(((p - a) * d).sum(axis=2) / length2, 0, 1)
        best[chunk:chunk + 4096] = np.sqrt(((a + t[..., None] * d - p) ** 2).sum(axis=2)).min(axis=1)
    return best


def inside(points, polygon):
    """Even-odd rule, per point."""
    a, b = segments(polygon)
    x, y = points[:, 0:1], points[:, 1:2]
    crosses = ((a[:, 1] > y) != (b[:, 1] > y)) & (
        x < a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / np.where(b[:, 1] != a[:, 1], b[:, 1] - a[:, 1], 1))
    return crosses.sum(axis=1) % 2 == 1


def in_material(points, part):
    result = inside(points, part["outline"])
    for hole in part["holes"]:
        result &= ~inside(points, hole)
    return result


def along(points, step, closed=True):
    """Points every `step` mm along a polyline: closed, back to its first point; open, its last point included."""
    p = np.array(points, dtype=float)
    a, b = segments(p) if closed else (p[:-1], p[1:])
    out = []
    for s, e in zip(a, b):
        n = max(1, int(math.ceil(np.linalg.norm(e - s) / step)))
        out.append(s + (e - s) * (np.arange(n) / n)[:, None])
    return np.vstack(out + ([] if closed else [p[-1:]]))


def first_reach(targets, centres, order, reach):
    """For each target point, the order index of the first centre within `reach` (inf: none)."""
    cell = max(reach, 1e-3)
    grid = {}
    for i, (x, y) in enumerate(centres[:, :2]):
        grid.setdefault((int(x // cell), int(y // cell)), []).append(i)
    result = np.full(len(targets), np.inf)
    for j, (x, y) in enumerate(targets):
        cx, cy = int(x // cell), int(y // cell)
        near = [i for dx in (-1, 0, 1) for dy in (-1, 0, 1) for i in grid.get((cx + dx, cy + dy), ())]
        if near:
            near = np.array(near)
            close = near[np.hypot(centres[near, 0] - x, centres[near, 1] - y) <= reach]
            if len(close):
                result[j] = order[close].min()
    return result


def problems(gcode, parts, thickness, radius, mill=1, drill_tools=(), engrave_tool=None, drills=(), strokes=(),
             tabbed=(), tab_width=0.0, tags=2, dogbones=False, engrave_depth=0.5, through=0.0, feed=None, tol=0.025,
             step=0.5):
    """What is wrong with the G-code of one sheet. parts: [{'id', 'outline', 'holes'}] as designed, in sheet
    millimetres; tabbed: ids of parts whose outline may keep `tags` holding tags at most tab_width (plus the
    tool) long; drills: [{'at', 'diameter', 'depth'}]; strokes: the labels' strokes to engrave, [[(x, y)...]].
    through: how far below the sheet the profiles must cut, and the mill may go. feed: the mm/min every move of the
    mill across the sheet (Z unchanged) must be fed at, if given. tol: CAM's geometry tolerance
    (a job's default 0.01 mm) on the model and on the path, and the G-code's rounding."""
    found = []
    all_moves = moves(gcode)
    cut = [(i, m) for i, m in enumerate(all_moves) if m[0] == mill and m[1] in (1, 2, 3)]
    if not cut:
        return ["no feed moves of the mill (T{})".format(mill)]
    points = np.vstack([samples(m, step) for _, m in cut])
    order = np.concatenate([np.full(len(samples(m, step)), i) for i, m in cut])
    across = [m[5] for _, m in cut if abs(m[3][2] - m[2][2]) < 1e-9 and (m[1] != 1 or m[3][:2] != m[2][:2])]
    if feed is not None and any(f is None or abs(f - feed) > 0.5 for f in across):
        found.append("the mill is fed at {} mm/min across the sheet, not {:g}".format(
            sorted({f for f in across if f is None or abs(f - feed) > 0.5}, key=str), feed))
    if points[:, 2].min() < -through - tol:
        found.append("the mill cuts {:.3f} mm below the sheet".format(-points[:, 2].min()))
    in_board = points[:, 2] < thickness - tol
    for part in parts:
        contours = [part["outline"]] + list(part["holes"])
        near = np.min([distance_to(points, c) for c in contours], axis=0)
        gouge = in_board & (in_material(points, part) | (near < radius - tol))
        if dogbones:
            corners = np.vstack([np.array(c, dtype=float) for c in contours])
            to_corner = np.sqrt(((points[:, None, :2] - corners[None]) ** 2).sum(axis=2)).min(axis=1)
            gouge &= to_corner > radius * math.sqrt(2) + tol  # a bone runs from the corner's offset to it
        if gouge.any():
            k = int(np.argmax(gouge))
            found.append("part '{}': the mill cuts into it at ({:.2f}, {:.2f}, {:.2f}), {:.3f} mm too close".format(
                part["id"], *points[k], radius - near[k]))
    cut_through = points[:, 2] <= -through + tol
    deep, deep_order = points[cut_through], order[cut_through]
    for part in parts:
        completed, corners = [], inside_corners(part)
        for n, contour in enumerate([part["outline"]] + list(part["holes"])):
            name = "part '{}' {}".format(part["id"], "outline" if n == 0 else "hole {}".format(n))
            targets = along(contour, step)
            reached = first_reach(targets, deep, deep_order, radius + tol + step)
            missed = ~np.isfinite(reached)
            if not dogbones and len(corners):  # a round tool leaves inside corners round
                missed &= np.hypot(*(targets[:, None, :] - corners[None]).transpose(2, 0, 1)).min(axis=1) > \
                    radius * math.sqrt(2) + step
            gaps = runs(missed)
            allowed = tags if n == 0 and part["id"] in tabbed else 0
            long_gaps = [g for g in gaps if g * step > tab_width + 2 * radius + 2 * step]
            if len(gaps) > allowed or long_gaps:
                found.append("{} is not cut through all round: {} stretch(es) left, longest {:.1f} mm".format(
                    name, len(gaps), max(gaps) * step))
            completed.append(reached[np.isfinite(reached)].max() if np.isfinite(reached).any() else np.inf)
        if len(completed) > 1 and max(completed[1:]) > completed[0]:
            found.append("part '{}': its outline is cut through before its holes".format(part["id"]))
        if dogbones and len(corners):
            missed = ~np.isfinite(first_reach(corners, deep, deep_order, radius + tol))
            if missed.any():
                found.append("part '{}': {} inside corner(s) left round, first at ({:.2f}, {:.2f})".format(
                    part["id"], int(missed.sum()), *corners[int(np.argmax(missed))]))
    found += drill_problems(all_moves, drill_tools, drills, thickness, tol)
    if engrave_tool is not None:
        found += engrave_problems(all_moves, engrave_tool, parts, strokes, thickness, engrave_depth, tol, step)
    return found


def inside_corners(part, turn=60.0):
    """The corners of the part's material that a round tool leaves round: reflex corners of its outline and
    convex corners of its holes, turning by `turn` degrees or more."""
    result = []
    for n, contour in enumerate([part["outline"]] + list(part["holes"])):
        p = np.array(contour, dtype=float)
        area = (p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1]).sum()
        if area < 0:
            p = p[::-1]  # counter-clockwise
        a, b = p - np.roll(p, 1, axis=0), np.roll(p, -1, axis=0) - p
        cross = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
        angle = np.degrees(np.abs(np.arctan2(cross, (a * b).sum(axis=1))))
        inward = cross < 0 if n == 0 else cross > 0
        result += list(p[inward & (angle >= turn)])
    return np.array(result).reshape(-1, 2)


def runs(flags):
    """Lengths of the runs of True in a cyclic sequence."""
    if flags.all():
        return [len(flags)]
    start = int(np.argmin(flags))  # a False: no run wraps past it
    rolled = np.roll(flags, -start)
    lengths, current = [], 0
    for f in rolled:
        if f:
            current += 1
        elif current:
            lengths.append(current)
            current = 0
    return lengths + ([current] if current else [])


def drill_problems(all_moves, drill_tools, drills, thickness, tol):
    """Each dowel hole plunged once or more at its centre to its depth; no plunge elsewhere."""
    plunges = [m[3] for m in all_moves if m[0] in drill_tools and (m[1] == 81 or (m[1] == 1 and m[3][2] < m[2][2]
                                                                                  and m[3][2] < thickness - tol))]
    found, used = [], set()
    for d in drills:
        want = thickness - d["depth"]
        hits = [i for i, p in enumerate(plunges) if math.hypot(p[0] - d["at"][0], p[1] - d["at"][1]) < tol]
        used.update(hits)
        if not hits or abs(min(plunges[i][2] for i in hits) - want) > tol:
            found.append("dowel hole at ({:.2f}, {:.2f}) not drilled {:g} mm deep".format(*d["at"], d["depth"]))
    stray = [p for i, p in enumerate(plunges) if i not in used]
    if stray:
        found.append("{} plunge(s) of a drill where no hole is, first at ({:.2f}, {:.2f})".format(
            len(stray), *stray[0]))
    return found


def engrave_problems(all_moves, tool, parts, strokes, thickness, depth, tol, step):
    """Every stroke engraved, all of it; nothing engraved deeper than `depth` or off the parts."""
    cuts = [m for m in all_moves if m[0] == tool and m[1] in (1, 2, 3)]
    if not cuts:
        return ["no engraving (T{})".format(tool)]
    points = np.vstack([samples(m, step / 4) for m in cuts])
    points = points[points[:, 2] < thickness - tol]
    found = []
    for stroke in strokes:
        targets = along(stroke, step / 2, closed=False)
        reached = first_reach(targets, points, np.arange(len(points)), tol + step / 2)
        if not np.isfinite(reached).all():
            k = int(np.argmin(np.isfinite(reached)))
            found.append("label stroke not engraved at ({:.2f}, {:.2f})".format(*targets[k]))
            break
    if len(points) and points[:, 2].min() < thickness - depth - tol:
        found.append("engraving {:.2f} mm deep".format(thickness - points[:, 2].min()))
    on_part = np.zeros(len(points), dtype=bool)
    for part in parts:
        on_part |= in_material(points, part)
    if not on_part.all():
        k = int(np.argmin(on_part))
        found.append("engraving off the parts at ({:.2f}, {:.2f})".format(*points[k, :2]))
    return found
