#!/usr/bin/env python3
"""An independent checker for `fabguide optimise` suggestions (`*.flatpack.json`, layout JSON, summary.json).

It shares no code with FabGuide and trusts nothing the optimiser says about the suggestion: it reads the JSON
files, rebuilds every board's box from its corners, and judges the suggestion as a furniture maker with
a CNC router would, against the ORIGINAL design (docs/formats.md, *.flatpack.json and layout JSON):

- the suggestion is the same furniture: the same parts in the same order, the same quantities, every board still
  as thick as the master boards and lying the same way (its thin side along the same axis);
- it is not the original design unchanged;
- every design constraint of the original holds on the suggestion, each computed here from the boxes: equal,
  sum, fixed (value default: the original's), symmetric (about default: midway in the original), ground (level
  default: the original's lowest board), coplanar, snap, range (fraction: of the original's value), the
  settings' min_length (default 2 x the board's thickness; a side shorter than it in the original may not get shorter) and
  snap (default on: every two boards that touch in the original still touch on the same faces, faces flush in
  the original stay flush, others keep overlapping by min(original overlap, the thinner board)), the inner
  volumes (moving with the centre of the board they rest on, free of every other board) and the outer volume;
- no two boards interpenetrate (boxes overlapping by more than 0.01 mm on all three axes) unless they did in the
  original (a cross halving), and no board is below the original's lowest z;
- the layout: every placement on a master board of the design (at most `count` of each kind), inside it by the
  trim, at least kerf + spacing from every other part on the same board, its size the suggestion's board (width
  along its grain axis, else its first long axis; swapped by a quarter turn), parts with a grain ("grain": an
  axis, or follow_grain) along the board's grain, every part laid out as many times as its quantity;
- no more sheets than before and, on as many, no more waste (m² of sheets minus parts); the summary's
  sheet count and waste_m2 ("bought sheets less parts") those of the layout;
- the suggestion file reloads: `fabguide optimise SUGGESTION -o TMP --time-limit 1` exits 0.

Use: check_suggestion(original, suggestion, layout, summary_entry, before_entry, cli=..., reload=True)
-> list of problems (empty: passes). From a shell: python3 flatpack_checker.py OUTDIR ORIGINAL.flatpack.json
"""

import json
import os
import subprocess
import sys
import tempfile

AXES = "xyz"
TOL = 0.01  # mm: constraint equalities, touching, flush, interpenetration (boxes overlapping by more than this)
LAYOUT_TOL = 1e-6  # mm: gaps and margins in the layout are what the settings ask, to rounding
SIZE_TOL = 0.01  # mm: a placement's size against the suggestion's board
DISTINCT = 10.0  # mm: some board of a suggestion differs by this from every earlier suggestion (a maker sees it)
RELOAD_TIME_LIMIT = "1"
RELOAD_TIMEOUT = 120  # s


# ---------------------------------------------------------------------------------------------------- boxes


class Box:
    """A part or volume as a file writes it: "min" and "max" corners, or version 1's "position" and "size"."""

    def __init__(self, part):
        self.id = part["id"]
        if "min" in part:
            self.lo, self.hi = [float(v) for v in part["min"]], [float(v) for v in part["max"]]
            self.size = [self.hi[k] - self.lo[k] for k in range(3)]
        else:
            self.lo, self.size = [float(v) for v in part["position"]], [float(v) for v in part["size"]]
            self.hi = [self.lo[k] + self.size[k] for k in range(3)]
        self.quantity = int(part.get("quantity", 1))
        self.normal = min(range(3), key=lambda k: self.size[k])  # the thin side; x before y before z on ties

    def centre(self, k):
        return (self.lo[k] + self.hi[k]) / 2.0

    def in_plane(self):
        return [k for k in range(3) if k != self.normal]

    def grain_axis(self, part):
        """The axis the wood's grain runs along (docs/formats.md): "grain": "x"/"y"/"z", "free" (None), or the
        older follow_grain (its first long axis); None without either."""
        grain = part.get("grain")
        if grain in ("x", "y", "z"):
            return AXES.index(grain)
        if grain is None and part.get("follow_grain"):
            return self.in_plane()[0]
        return None

    def material_size(self, part=None):
        """(width, height) in material space: width along the grain axis if the part names one, else along the
        first of its two long axes (x before y before z)."""
        a, b = self.in_plane()
        g = self.grain_axis(part or {})
        if g == b:
            a, b = b, a
        return self.size[a], self.size[b]


def boxes_of(design):
    return {p["id"]: Box(p) for p in design.get("parts", [])}


def overlap(a, b, k):
    """Length along axis k shared by boxes a and b (negative: a gap)."""
    return min(a.hi[k], b.hi[k]) - max(a.lo[k], b.lo[k])


def interpenetrate(a, b, tol=TOL):
    return all(overlap(a, b, k) > tol for k in range(3))


def thicknesses_of(design):
    return [float(b.get("thickness", 0)) for b in design.get("boards", [])]


def ref_value(boxes, ref):
    """'<part>.size|centre|center|min|max.<x|y|z>' on these boxes; the part id may itself contain dots."""
    if not isinstance(ref, str) or ref.count(".") < 2:
        raise ValueError("not a reference: %r" % (ref,))
    part, what, axis = ref.rsplit(".", 2)
    if part not in boxes:
        raise ValueError("no part %r in %r" % (part, ref))
    if axis not in AXES:
        raise ValueError("bad axis in %r" % ref)
    b, k = boxes[part], AXES.index(axis)
    if what == "size":
        return b.size[k]
    if what in ("centre", "center"):
        return b.centre(k)
    if what == "min":
        return b.lo[k]
    if what == "max":
        return b.hi[k]
    raise ValueError("bad reference kind in %r" % ref)


def fmt(v):
    return ("%.3f" % v).rstrip("0").rstrip(".")


# ---------------------------------------------------------------------------------------------- constraints


def constraint_name(c, i):
    if c.get("name"):
        return "constraints[%d] %s '%s'" % (i, c.get("kind"), c["name"])
    what = c.get("refs") or c.get("parts") or c.get("ref") or (c.get("lhs"), c.get("rhs"))
    return "constraints[%d] %s %s" % (i, c.get("kind"), json.dumps(what))


def snap_problems(label, a0, b0, a1, b1, tol=TOL):
    """Boards a and b touch in the original (a0, b0); at (a1, b1) they must still touch on the same faces, flush
    faces stay flush, other overlaps stay at least min(original overlap, the thinner board)."""
    problems = []
    for k in range(3):
        others = [j for j in range(3) if j != k]
        if abs(overlap(a0, b0, k)) > tol or any(overlap(a0, b0, j) <= tol for j in others):
            continue
        if abs(a0.hi[k] - b0.lo[k]) <= tol:
            gap = b1.lo[k] - a1.hi[k]
        else:
            gap = a1.lo[k] - b1.hi[k]
        if abs(gap) > tol:
            problems.append("%s: %s and %s no longer touch along %s (%s %s mm)" % (
                label, a0.id, b0.id, AXES[k], "gap" if gap > 0 else "overlap", fmt(abs(gap))))
        thinner = min(a0.size[a0.normal], b0.size[b0.normal])
        for j in others:
            low = abs(a0.lo[j] - b0.lo[j]) <= tol
            high = abs(a0.hi[j] - b0.hi[j]) <= tol
            if low and abs(a1.lo[j] - b1.lo[j]) > tol:
                problems.append("%s: %s and %s no longer flush at min.%s (%s vs %s)" % (
                    label, a0.id, b0.id, AXES[j], fmt(a1.lo[j]), fmt(b1.lo[j])))
            if high and abs(a1.hi[j] - b1.hi[j]) > tol:
                problems.append("%s: %s and %s no longer flush at max.%s (%s vs %s)" % (
                    label, a0.id, b0.id, AXES[j], fmt(a1.hi[j]), fmt(b1.hi[j])))
            if not low and not high:
                need = min(overlap(a0, b0, j), thinner)
                if overlap(a1, b1, j) < need - tol:
                    problems.append("%s: %s and %s overlap only %s mm along %s (need %s)" % (
                        label, a0.id, b0.id, fmt(overlap(a1, b1, j)), AXES[j], fmt(need)))
        return problems
    return problems


def touching(a, b, tol=TOL):
    for k in range(3):
        if abs(overlap(a, b, k)) <= tol and all(overlap(a, b, j) > tol for j in range(3) if j != k):
            return True
    return False


def constraint_problems(original, suggestion, tol=TOL):
    """Every design constraint of the original, evaluated on the suggestion's boxes."""
    B0, B1 = boxes_of(original), boxes_of(suggestion)
    problems = []
    if set(B0) != set(B1):
        return ["constraints not checked: the suggestion's parts are not the original's"]
    settings = original.get("settings", {})

    # settings.min_length
    for pid, b0 in B0.items():
        b1 = B1[pid]
        least = float(settings.get("min_length", 2 * b0.size[b0.normal]))
        for k in b0.in_plane():
            need = min(least, b0.size[k])
            if b1.size[k] < need - tol:
                problems.append("min_length: %s.size.%s = %s < %s" % (pid, AXES[k], fmt(b1.size[k]), fmt(need)))

    # settings.snap: every pair touching in the original
    if settings.get("snap", True):
        ids = list(B0)
        for i in range(len(ids)):
            for j in range(i + 1, len(ids)):
                a0, b0 = B0[ids[i]], B0[ids[j]]
                if touching(a0, b0, tol):
                    problems += snap_problems("snap setting", a0, b0, B1[ids[i]], B1[ids[j]], tol)

    lowest0 = min(b.lo[2] for b in B0.values())
    for i, c in enumerate(original.get("constraints", [])):
        name = constraint_name(c, i)
        kind = c.get("kind")
        try:
            if kind == "equal":
                vals = [ref_value(B1, r) for r in c["refs"]]
                if max(vals) - min(vals) > tol:
                    problems.append("%s broken: %s" % (name, ", ".join(
                        "%s=%s" % (r, fmt(v)) for r, v in zip(c["refs"], vals))))
            elif kind == "sum":
                lhs = sum(ref_value(B1, r) for r in c["lhs"])
                rhs = sum(ref_value(B1, r) for r in c["rhs"]) + float(c.get("offset", 0))
                if abs(lhs - rhs) > tol:
                    problems.append("%s broken: lhs %s != rhs + offset %s" % (name, fmt(lhs), fmt(rhs)))
            elif kind == "fixed":
                value = float(c["value"]) if "value" in c else ref_value(B0, c["ref"])
                v = ref_value(B1, c["ref"])
                if abs(v - value) > tol:
                    problems.append("%s broken: %s = %s, fixed at %s" % (name, c["ref"], fmt(v), fmt(value)))
            elif kind == "symmetric":
                r0, r1 = c["refs"]
                about = c.get("about")
                if about is None:
                    centre = (ref_value(B0, r0) + ref_value(B0, r1)) / 2.0
                elif isinstance(about, (int, float)):
                    centre = float(about)
                else:
                    centre = ref_value(B1, about)
                v0, v1 = ref_value(B1, r0), ref_value(B1, r1)
                if abs(v0 + v1 - 2 * centre) > tol:
                    problems.append("%s broken: %s=%s and %s=%s are not symmetric about %s" % (
                        name, r0, fmt(v0), r1, fmt(v1), fmt(centre)))
            elif kind == "ground":
                level = float(c.get("level", lowest0))
                for pid in c["parts"]:
                    if abs(B1[pid].lo[2] - level) > tol:
                        problems.append("%s broken: %s.min.z = %s, ground at %s" % (
                            name, pid, fmt(B1[pid].lo[2]), fmt(level)))
            elif kind == "coplanar":
                parts = c["parts"]
                n = B0[parts[0]].normal
                for pid in parts:
                    if B1[pid].normal != n:
                        problems.append("%s broken: %s is no longer parallel to %s" % (name, pid, parts[0]))
                    elif abs(B1[pid].centre(n) - B1[parts[0]].centre(n)) > tol:
                        problems.append("%s broken: %s.centre.%s = %s, %s.centre.%s = %s" % (
                            name, pid, AXES[n], fmt(B1[pid].centre(n)), parts[0], AXES[n],
                            fmt(B1[parts[0]].centre(n))))
            elif kind == "snap":
                a, b = c["parts"]
                if not touching(B0[a], B0[b], tol):
                    problems.append("%s: %s and %s do not touch in the original" % (name, a, b))
                problems += snap_problems(name, B0[a], B0[b], B1[a], B1[b], tol)
            elif kind == "range":
                v0, v = ref_value(B0, c["ref"]), ref_value(B1, c["ref"])
                f = float(c.get("fraction", 0) or 0)
                low = float(c["min"]) if "min" in c else (v0 - abs(v0) * f if f > 0 else None)
                high = float(c["max"]) if "max" in c else (v0 + abs(v0) * f if f > 0 else None)
                if low is not None and v < low - tol:
                    problems.append("%s broken: %s = %s < min %s" % (name, c["ref"], fmt(v), fmt(low)))
                if high is not None and v > high + tol:
                    problems.append("%s broken: %s = %s > max %s" % (name, c["ref"], fmt(v), fmt(high)))
            else:
                problems.append("%s: unknown constraint kind %r" % (name, kind))
        except (KeyError, ValueError, TypeError) as e:
            problems.append("%s: cannot evaluate (%s)" % (name, e))

    for i, vol in enumerate(original.get("inner_volumes", [])):
        vname = "inner volume '%s'" % vol.get("name", i + 1)
        on = vol.get("on")
        if on not in B0:
            problems.append("%s: no board %r" % (vname, on))
            continue
        v0 = Box(dict(vol, id=vname))
        # it keeps its distance from the face of its board it was drawn nearer to (the lower one on a tie)
        lo = [v0.lo[k] + (B1[on].lo[k] - B0[on].lo[k] if v0.lo[k] - B0[on].lo[k] <= B0[on].hi[k] - v0.hi[k]
                          else B1[on].hi[k] - B0[on].hi[k]) for k in range(3)]
        v = Box({"id": vname, "position": lo, "size": v0.size})
        for k in B1[on].in_plane():  # and stands on it: the board under all of it, or overhung no more than drawn
            for side, drawn, now in (("lower", B0[on].lo[k] - v0.lo[k], B1[on].lo[k] - v.lo[k]),
                                     ("upper", v0.hi[k] - B0[on].hi[k], v.hi[k] - B1[on].hi[k])):
                if now > max(0.0, drawn) + tol:
                    problems.append("%s: off %s by %s mm on its %s side along %s" % (
                        vname, on, fmt(now), side, AXES[k]))
        for pid, b in B1.items():
            if pid != on and interpenetrate(v, b, tol):
                problems.append("%s (on %s) intruded by %s by %s mm" % (
                    vname, on, pid, " x ".join(fmt(overlap(v, b, k)) for k in range(3))))

    outer = original.get("outer_volume")
    if outer:
        for pid, b in B1.items():
            for k in range(3):
                if b.lo[k] < float(outer["min"][k]) - tol:
                    problems.append("outer volume: %s.min.%s = %s < %s" % (pid, AXES[k], fmt(b.lo[k]),
                                                                           fmt(outer["min"][k])))
                if b.hi[k] > float(outer["max"][k]) + tol:
                    problems.append("outer volume: %s.max.%s = %s > %s" % (pid, AXES[k], fmt(b.hi[k]),
                                                                           fmt(outer["max"][k])))
    return problems


# ----------------------------------------------------------------------------------------------- 3-D checks


def structure_problems(original, suggestion):
    problems = []
    ids0 = [p["id"] for p in original.get("parts", [])]
    ids1 = [p.get("id") for p in suggestion.get("parts", [])]
    if ids0 != ids1:
        problems.append("parts: the suggestion's parts %s are not the original's %s" % (ids1[:8], ids0[:8]))
        return problems
    if suggestion.get("format") != "fabguide.flatpack":
        problems.append("format: %r is not fabguide.flatpack" % suggestion.get("format"))
    if suggestion.get("boards") != original.get("boards"):
        problems.append("boards: the master boards changed")
    for p0, p1 in zip(original["parts"], suggestion["parts"]):
        b0, b1 = Box(p0), Box(p1)
        t = b0.size[b0.normal]
        if not any(abs(t - m) < 1e-6 for m in thicknesses_of(original)):
            problems.append("%s is %s thick: no master board is" % (b0.id, fmt(t)))
        if b1.quantity != b0.quantity:
            problems.append("quantity of %s changed %d -> %d" % (b0.id, b0.quantity, b1.quantity))
        growth = float(original.get("settings", {}).get("max_growth", 1.5))
        for k in b0.in_plane():  # a batten stays a batten
            if b1.size[k] > growth * b0.size[k] + TOL:
                problems.append("%s grew along %s from %s to %s mm, more than max_growth %g times" % (
                    b0.id, AXES[k], fmt(b0.size[k]), fmt(b1.size[k]), growth))
        if min(b1.size) <= 0:
            problems.append("%s has a side of size %s" % (b1.id, fmt(min(b1.size))))
        if abs(b1.size[b0.normal] - t) > 1e-6:
            problems.append("%s is no longer %s thick along %s (size %s)" % (b1.id, fmt(t), AXES[b0.normal],
                                                                           [fmt(v) for v in b1.size]))
        elif p0.get("grain") != p1.get("grain") or bool(p0.get("follow_grain")) != bool(p1.get("follow_grain")):
            problems.append("%s: its grain changed" % b1.id)
        elif any(b1.size[k] < t - 1e-6 for k in range(3)):
            problems.append("%s has a side thinner than the board: %s" % (b1.id, [fmt(v) for v in b1.size]))
    return problems


def identical(original, suggestion, tol=1e-6):
    for p0, p1 in zip(original.get("parts", []), suggestion.get("parts", [])):
        b0, b1 = Box(p0), Box(p1)
        if any(abs(a - b) > tol for a, b in zip(b0.lo + b0.hi, b1.lo + b1.hi)):
            return False
    return True


def interpenetration_problems(original, suggestion, tol=TOL):
    B0, B1 = boxes_of(original), boxes_of(suggestion)
    ids = [i for i in B0 if i in B1]
    problems = []
    for i in range(len(ids)):
        for j in range(i + 1, len(ids)):
            a, b = ids[i], ids[j]
            if interpenetrate(B1[a], B1[b], tol) and not interpenetrate(B0[a], B0[b], tol):
                problems.append("interpenetration: %s and %s overlap by %s mm (they did not in the original)" % (
                    a, b, " x ".join(fmt(overlap(B1[a], B1[b], k)) for k in range(3))))
    return problems


def ground_problems(original, suggestion, tol=TOL):
    lowest = min(b.lo[2] for b in boxes_of(original).values())
    return ["below ground: %s.min.z = %s < %s (the original's lowest)" % (b.id, fmt(b.lo[2]), fmt(lowest))
            for b in boxes_of(suggestion).values() if b.lo[2] < lowest - tol]


# --------------------------------------------------------------------------------------------------- layout


def layout_problems(design, layout):
    """The layout against the suggestion's design (its parts and sizes, settings, master boards)."""
    problems = []
    settings = design.get("settings", {})
    clearance = float(settings.get("kerf", 0)) + float(settings.get("spacing", 0))
    trim = float(settings.get("trim", 0))
    kinds = design.get("boards", [])
    used = layout.get("boards", [])
    boxes = boxes_of(design)

    # master boards: each used board is one of the design's, at most `count` of each kind
    per_kind = {}
    for n, ub in enumerate(used):
        match = [k for k, kind in enumerate(kinds)
                 if abs(float(kind["width"]) - float(ub["width"])) < 1e-6
                 and abs(float(kind["height"]) - float(ub["height"])) < 1e-6
                 and abs(float(kind.get("thickness", 0)) - float(ub.get("thickness", 0))) < 1e-6
                 and kind.get("name", "") == ub.get("name", "")]
        if not match:
            problems.append("layout board %d (%s %sx%s) is none of the design's master boards" % (
                n, ub.get("name"), fmt(ub["width"]), fmt(ub["height"])))
            continue
        per_kind[match[0]] = per_kind.get(match[0], 0) + 1
    for k, n in per_kind.items():
        count = int(kinds[k].get("count", 1))
        if count >= 0 and n > count:
            problems.append("layout uses %d of master board '%s', the design has %d" % (
                n, kinds[k].get("name"), count))

    placements = layout.get("placements", [])
    counts = {}
    rects = []
    for i, p in enumerate(placements):
        pid = p.get("part")
        counts[pid] = counts.get(pid, 0) + 1
        where = "placement %d (%s)" % (i, pid)
        bi = p.get("board")
        if not isinstance(bi, int) or not 0 <= bi < len(used):
            problems.append("%s: board %r is not one of the %d used" % (where, bi, len(used)))
            continue
        W, H = float(used[bi]["width"]), float(used[bi]["height"])
        x, y, w, h = (float(p[key]) for key in ("x", "y", "width", "height"))
        rot = int(p.get("rotation", 0)) % 360
        if x < trim - LAYOUT_TOL or y < trim - LAYOUT_TOL or x + w > W - trim + LAYOUT_TOL \
                or y + h > H - trim + LAYOUT_TOL:
            problems.append("%s: [%s, %s] .. [%s, %s] is not inside board %d (%sx%s) trimmed by %s" % (
                where, fmt(x), fmt(y), fmt(x + w), fmt(y + h), bi, fmt(W), fmt(H), fmt(trim)))
        if pid in boxes:
            part = next(q for q in design["parts"] if q["id"] == pid)
            mw, mh = boxes[pid].material_size(part)
            if rot not in (0, 90, 180, 270):
                problems.append("%s: rotation %d" % (where, rot))
            thick = min(boxes[pid].size)
            if abs(thick - float(used[bi].get("thickness", 0))) > 1e-6:
                problems.append("%s: a %s mm part on board %d, %s mm thick" % (
                    where, fmt(thick), bi, fmt(used[bi].get("thickness", 0))))
            ew, eh = (mw, mh) if rot in (0, 180) else (mh, mw)
            if abs(w - ew) > SIZE_TOL or abs(h - eh) > SIZE_TOL:
                problems.append("%s: laid out %s x %s (rotation %d), the board is %s x %s" % (
                    where, fmt(w), fmt(h), rot, fmt(ew), fmt(eh)))
            grain = used[bi].get("grain", "none")
            if boxes[pid].grain_axis(part) is not None and grain in ("width", "height"):
                along_x = rot in (0, 180)  # the part's material width (its grain) along the sheet's x
                if along_x != (grain == "width"):
                    problems.append("%s: its grain runs across the board's grain (%s)" % (where, grain))
        rects.append((bi, x, y, x + w, y + h, where))

    for pid, b in boxes.items():
        if counts.get(pid, 0) != b.quantity:
            problems.append("quantity: %s laid out %d times, the design says %d" % (pid, counts.get(pid, 0),
                                                                                   b.quantity))
    for pid in counts:
        if pid not in boxes:
            problems.append("layout places %r, which is no part of the design" % pid)

    for i in range(len(rects)):
        bi, x0, y0, x1, y1, wi = rects[i]
        for j in range(i + 1, len(rects)):
            bj, u0, v0, u1, v1, wj = rects[j]
            if bi != bj:
                continue
            gap_x = max(u0 - x1, x0 - u1)
            gap_y = max(v0 - y1, y0 - v1)
            gap = max(gap_x, gap_y)
            if gap < -LAYOUT_TOL and min(gap_x, gap_y) < -LAYOUT_TOL:
                problems.append("overlapping parts on board %d: %s and %s overlap by %s x %s mm" % (
                    bi, wi, wj, fmt(-gap_x), fmt(-gap_y)))
            elif gap < clearance - LAYOUT_TOL:
                problems.append("gap too small on board %d: %s and %s are %s mm apart, kerf + spacing is %s" % (
                    bi, wi, wj, fmt(gap), fmt(clearance)))
    return problems


# ---------------------------------------------------------------------------------------------------- reload


def default_cli():
    if os.environ.get("FABGUIDE_CLI"):
        return os.environ["FABGUIDE_CLI"]
    if os.environ.get("FABGUIDE_BUILD_DIR"):
        return os.path.join(os.environ["FABGUIDE_BUILD_DIR"], "fabguide")
    return None


def reload_problems(suggestion, cli, suggestion_path=None, cost=None):
    """Problems of the suggestion read back by `fabguide optimise`: refused, or (given the `cost` of the boards its
    layout was found on) laid out again on boards that cost more."""
    if not cli or not os.access(cli, os.X_OK):
        return ["reload not checked: no fabguide command-line tool at %r" % (cli,)]
    with tempfile.TemporaryDirectory(prefix="flatpack-reload-") as tmp:
        path = suggestion_path
        if path is None:
            path = os.path.join(tmp, "suggestion.flatpack.json")
            with open(path, "w") as f:
                json.dump(suggestion, f)
        try:
            run = subprocess.run([cli, "optimise", path, "-o", os.path.join(tmp, "out"), "--time-limit",
                                  RELOAD_TIME_LIMIT, "--threads", "1", "--seed", "1"],
                                 capture_output=True, text=True, timeout=RELOAD_TIMEOUT)
        except subprocess.TimeoutExpired:
            return ["reload refused: `fabguide optimise SUGGESTION --time-limit 1` ran over %d s" % RELOAD_TIMEOUT]
        if run.returncode != 0:
            err = (run.stderr.strip().splitlines() or [""])[-1]
            return ["reload refused: `fabguide optimise SUGGESTION` exits %d: %s" % (run.returncode, err[:300])]
        with open(os.path.join(tmp, "out", "before.layout.json")) as f:
            reopened = bought_of(json.load(f))[1]
    if cost is not None and reopened > cost + 1e-9:
        return ["reopened on boards that cost %g, found on %g" % (reopened, cost)]
    return []


# ------------------------------------------------------------------------------------------------------ all


def bought_of(layout):
    """(boards bought, their cost) of a layout: boards of cost 0 are offcuts already owned."""
    costs = [float(b.get("cost", 1)) for b in layout.get("boards", [])]
    return sum(1 for c in costs if c > 0), sum(costs)


def waste_of(layout):
    """m² of master boards the layout uses minus the area of the parts laid out on them (computed here)."""
    bought = sum(float(b["width"]) * float(b["height"]) for b in layout.get("boards", []))
    parts = sum(float(p["width"]) * float(p["height"]) for p in layout.get("placements", []))
    return (bought - parts) / 1e6


def check_suggestion(original_design_dict, suggestion_design_dict, layout_dict, summary_entry, before_entry,
                     cli=None, reload=True, suggestion_path=None, before_layout=None):
    """Problems of one suggestion (empty list: it passes). summary_entry: its entry in summary.json's
    "suggestions"; before_entry: summary.json's "before". cli: the fabguide tool for the reload check (default
    $FABGUIDE_CLI or $FABGUIDE_BUILD_DIR/fabguide); reload=False leaves that check out. before_layout: the
    layout JSON of the original design; with it, waste is compared as computed here (sheets bought minus parts),
    else as the summary reports it."""
    original, suggestion, layout = original_design_dict, suggestion_design_dict, layout_dict
    problems = structure_problems(original, suggestion)
    if problems and problems[0].startswith("parts:"):
        return problems
    if identical(original, suggestion):
        problems.append("unchanged: the suggestion is the original design")
    problems += constraint_problems(original, suggestion)
    problems += interpenetration_problems(original, suggestion)
    problems += ground_problems(original, suggestion)
    problems += layout_problems(suggestion, layout)

    sheets_layout = len({p.get("board") for p in layout.get("placements", [])})
    if len(layout.get("boards", [])) != sheets_layout:
        problems.append("layout lists %d boards but places parts on %d" % (len(layout.get("boards", [])),
                                                                           sheets_layout))
    bought, cost = bought_of(layout)
    before_sheets = (before_entry or {}).get("sheets")
    before_cost = bought_of(before_layout)[1] if before_layout is not None else \
        (before_entry or {}).get("cost", before_sheets)
    if isinstance(before_sheets, int) and isinstance(before_cost, (int, float)):
        if cost > before_cost + 1e-9:
            problems.append("costs more: boards costing %s, %s before" % (fmt(cost), fmt(before_cost)))
        elif cost == before_cost and bought > before_sheets:
            problems.append("more sheets: %d sheets, %d before" % (bought, before_sheets))
    else:
        problems.append("summary: before has no sheet count")
    if (summary_entry or {}).get("sheets") != bought:
        problems.append("summary says %r sheets, the layout buys %d" % ((summary_entry or {}).get("sheets"), bought))
    # summary.json's waste_m2 is "bought sheets less parts" (docs/formats.md): the layout's, computed here
    reported = (summary_entry or {}).get("waste_m2")
    if not isinstance(reported, (int, float)):
        problems.append("summary: no waste_m2")
    elif abs(reported - waste_of(layout)) > 1e-3:
        problems.append("summary waste_m2 %.4f is not the sheets bought less the parts, %.4f m2" % (
            reported, waste_of(layout)))
    # Wastes less, as a maker counts it: fewer sheets, or as many and no more waste.
    if before_layout is not None:
        w1, w0 = waste_of(layout), waste_of(before_layout)
    else:
        w1, w0 = (summary_entry or {}).get("waste_m2"), (before_entry or {}).get("waste_m2")
    if isinstance(before_sheets, int) and cost == before_cost and bought == before_sheets \
            and isinstance(w1, (int, float)) and isinstance(w0, (int, float)) and w1 > w0 + 1e-4:
        problems.append("wastes more: %d sheets as before, %.4f m2 waste, %.4f m2 before" % (bought, w1, w0))
    if reload:
        problems += reload_problems(suggestion, cli or default_cli(), suggestion_path, cost)
    return problems


def check_output(outdir, original, cli=None, reload=True):
    """Every suggestion in an optimise output folder: {file: problems}."""
    with open(os.path.join(outdir, "summary.json")) as f:
        summary = json.load(f)
    results, suggestions = {}, []
    for entry in summary.get("suggestions", []):
        with open(os.path.join(outdir, entry["file"])) as f:
            suggestion = json.load(f)
        suggestions.append(suggestion)
        with open(os.path.join(outdir, entry["layout"])) as f:
            layout = json.load(f)
        before_layout = None
        if summary.get("before", {}).get("layout"):
            with open(os.path.join(outdir, summary["before"]["layout"])) as f:
                before_layout = json.load(f)
        results[entry["file"]] = check_suggestion(original, suggestion, layout, entry, summary.get("before"),
                                                  cli=cli, reload=reload, before_layout=before_layout,
                                                  suggestion_path=os.path.join(outdir, entry["file"]))
    results["suggestions together"] = alike_problems(suggestions)
    return results


def drawn_equal_problems(original, suggestion, tol=TOL):
    """Boards the original draws the same size (every side within 1e-4 mm) that the suggestion sizes apart: asked
    for by `optimise --keep-drawn-equal` and by the designs FreeCAD makes from boxes."""
    sizes = {p["id"]: Box(p).size for p in suggestion.get("parts", [])}
    groups = {}
    for p in original.get("parts", []):
        groups.setdefault(tuple(round(v / 1e-4) for v in Box(p).size), []).append(p["id"])
    problems = []
    for ids in groups.values():
        for other in ids[1:]:
            if max(abs(a - b) for a, b in zip(sizes[ids[0]], sizes[other])) > tol:
                problems.append("drawn equal: %s %s and %s %s" % (ids[0], sizes[ids[0]], other, sizes[other]))
    return problems


def alike_problems(suggestions):
    """Suggestions (designs, in order) with no board that differs by DISTINCT from an earlier one's."""
    problems = []
    for k, later in enumerate(suggestions):
        sizes = {p["id"]: Box(p).size for p in later["parts"]}
        for j, earlier in enumerate(suggestions[:k]):
            if max(abs(a - b) for p in earlier["parts"] for a, b in zip(Box(p).size, sizes[p["id"]])) < DISTINCT - TOL:
                problems.append("suggestion %d: no board differs by %g mm from suggestion %d" % (k + 1, DISTINCT,
                                                                                                j + 1))
    return problems


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[-1])
        return 2
    with open(argv[2]) as f:
        original = json.load(f)
    failed = False
    for name, problems in check_output(argv[1], original).items():
        print("%s: %d problems" % (name, len(problems)))
        for p in problems:
            print("  " + p)
        failed = failed or bool(problems)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
