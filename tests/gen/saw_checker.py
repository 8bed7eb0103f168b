"""Independent check of a guillotine layout: on each sheet, the listed saw cuts, made in their order,
each run straight from edge to edge of the one piece it lies in, their kerf touches no part, their stages are
as listed and within the limit (a trim one stage past it only parts one part from waste), and every part ends in
a piece of its own no larger than the part and half the clearance round it. The layout's own validity (demand,
boards, overlaps) is layout_check's. `problems(layout, problem)` returns a list of problems, empty when valid."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import layout_check  # noqa: E402

EPS = 1e-6


def _demand(problem):
    return {p["id"]: (p["width"], p["height"], p.get("quantity", 1)) for p in problem["parts"]}


def _sheet_problems(n, board, parts, cuts, s):
    """Problems of sheet n: board {width, height}, parts [(x0, y0, x1, y1)], cuts as the layout lists them."""
    kerf, half = s.get("kerf", 0), (s.get("kerf", 0) + s.get("spacing", 0)) / 2
    limit = s.get("stages", 0) or float("inf")
    found = []
    # A piece: [x0, y0, x1, y1, level, direction of the cut that made it]
    pieces = [[0.0, 0.0, board["width"], board["height"], 0, None]]
    inside = lambda r, p: r[0] >= p[0] - EPS and r[1] >= p[1] - EPS and r[2] <= p[2] + EPS and r[3] <= p[3] + EPS
    for c in cuts:
        name = "sheet {} cut {}".format(n + 1, c["number"])
        (ax, ay), (bx, by) = c["from"], c["to"]
        if abs(ax - bx) > EPS and abs(ay - by) > EPS:
            found.append(name + ": not straight along an edge")
            continue
        d = 0 if abs(ax - bx) <= EPS else 1  # 0: a line x = const
        at = ax if d == 0 else ay
        lo, hi = (min(ay, by), max(ay, by)) if d == 0 else (min(ax, bx), max(ax, bx))
        holder = None
        for p in pieces:
            span = (p[1], p[3]) if d == 0 else (p[0], p[2])
            across = (p[0], p[2]) if d == 0 else (p[1], p[3])
            if abs(span[0] - lo) <= 1e-3 and abs(span[1] - hi) <= 1e-3 and across[0] < at < across[1]:
                holder = p
                break
        if holder is None:
            found.append(name + ": does not run from edge to edge of any piece")
            continue
        band = (at - kerf / 2, lo, at + kerf / 2, hi) if d == 0 else (lo, at - kerf / 2, hi, at + kerf / 2)
        for r in parts:
            if band[0] < r[2] - EPS and r[0] < band[2] - EPS and band[1] < r[3] - EPS and r[1] < band[3] - EPS:
                found.append(name + ": its kerf cuts into a part at ({:.1f}, {:.1f})".format(r[0], r[1]))
        first, second = list(holder), list(holder)
        first[2 + d], second[d] = at, at
        held = [[r for r in parts if inside(r, q)] for q in (first, second)]
        if c["stage"] == 0:  # edge trim: takes off a margin with no part in it
            if held[0] and held[1]:
                found.append(name + ": an edge trim with parts on both sides")
            level, made = holder[4], holder[5]
        else:
            level = holder[4] if d == holder[5] else holder[4] + 1
            made = d
            if level != c["stage"]:
                found.append(name + ": listed stage {}, its stage is {}".format(c["stage"], level))
            if level > limit:
                alone = sorted(len(h) for h in held) == [0, 1] and sum(len(h) for h in held) == 1
                if not (c.get("trim") and level == limit + 1 and alone):
                    found.append(name + ": stage {} past the limit {}".format(level, limit))
        pieces.remove(holder)
        pieces += [first[:4] + [level, made], second[:4] + [level, made]]
    for r in parts:
        holders = [p for p in pieces if inside(r, p)]
        if len(holders) != 1:
            found.append("sheet {}: the part at ({:.1f}, {:.1f}) is not inside one piece".format(n + 1, r[0], r[1]))
            continue
        p = holders[0]
        if sum(1 for q in parts if inside(q, p)) > 1:
            found.append("sheet {}: the part at ({:.1f}, {:.1f}) shares its piece".format(n + 1, r[0], r[1]))
        elif max(r[0] - p[0], r[1] - p[1], p[2] - r[2], p[3] - r[3]) > half + 1e-3:
            found.append("sheet {}: the part at ({:.1f}, {:.1f}) is not cut free (waste left on it)".format(
                n + 1, r[0], r[1]))
    return found


def problems(layout, problem):
    s = problem.get("settings", {})
    boards = layout["boards"]
    found = layout_check.problems(layout, _demand(problem),
                                  lambda i: (boards[i]["width"], boards[i]["height"], s.get("trim", 0)),
                                  s.get("kerf", 0) + s.get("spacing", 0))
    cuts = layout.get("saw_cuts")
    if cuts is None or len(cuts) != len(boards):
        return found + ["saw_cuts: not one list per board"]
    for n, board in enumerate(boards):
        parts = [(p["x"], p["y"], p["x"] + p["width"], p["y"] + p["height"])
                 for p in layout["placements"] if p["board"] == n]
        found += _sheet_problems(n, board, parts, cuts[n], s)
    return found


def least_sheets(problem):
    """The least number of sheets any layout could use: per thickness, the parts' area over a sheet's."""
    import math
    total = 0
    for board in problem["boards"]:
        area = sum(p["width"] * p["height"] * p.get("quantity", 1) for p in problem["parts"]
                   if p.get("thickness", 0) in (0, board.get("thickness", 0)))
        total += math.ceil(area / (board["width"] * board["height"]) - 1e-9)
    return total
