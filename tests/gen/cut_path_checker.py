"""Independent check of the machine's cut paths in a DXF cut sheet of rectangular parts (common-line
cutting): every edge of every part, grown by half the kerf, is cut over its whole length; no stretch is cut
twice; nothing is cut that is not some part's edge. Reads the DXF with ezdxf and the layout JSON; plain Python,
sharing nothing with the writer. `problems(...)` returns a list of problems, empty when the sheet is right."""
import ezdxf

TOLERANCE = 0.01  # mm: what no laser or router tells apart


def _lines(segments):
    """Axis-aligned segments grouped into lines: {(axis, offset): [(from, to, source)]}, axis "x" for segments
    along x at y = offset; offsets within TOLERANCE of each other form one line. Others are returned apart."""
    keyed, slanted = [], []
    for (x0, y0), (x1, y1), source in segments:
        if abs(y0 - y1) <= TOLERANCE:
            keyed.append(("x", (y0 + y1) / 2, min(x0, x1), max(x0, x1), source))
        elif abs(x0 - x1) <= TOLERANCE:
            keyed.append(("y", (x0 + x1) / 2, min(y0, y1), max(y0, y1), source))
        else:
            slanted.append(((x0, y0), (x1, y1), source))
    lines = {}
    last = None
    for axis, offset, a, b, source in sorted(keyed):
        if last is None or last[0] != axis or offset - last[1] > TOLERANCE:
            last = (axis, offset)
            lines[last] = []
        lines[last].append((a, b, source))
    return lines, slanted


def _find(lines, axis, offset):
    for (line_axis, line_offset), spans in lines.items():
        if line_axis == axis and abs(line_offset - offset) <= TOLERANCE:
            return spans
    return []


def _union(spans):
    merged = []
    for a, b in sorted(spans):
        if merged and a <= merged[-1][1] + TOLERANCE:
            merged[-1][1] = max(merged[-1][1], b)
        else:
            merged.append([a, b])
    return merged


def part_edges(layout, board, kerf):
    """The edges of each part on `board` grown by kerf/2: [((x0, y0), (x1, y1), part)]."""
    edges = []
    for p in layout["placements"]:
        if p["board"] != board:
            continue
        h = kerf / 2
        x0, y0, x1, y1 = p["x"] - h, p["y"] - h, p["x"] + p["width"] + h, p["y"] + p["height"] + h
        corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        edges += [(corners[i], corners[(i + 1) % 4], p["part"]) for i in range(4)]
    return edges


def cut_segments(dxf_path):
    """The straight segments the machine cuts: every polyline on the INNER_CUT and OUTER_CUT layers."""
    segments = []
    for n, e in enumerate(ezdxf.readfile(dxf_path).modelspace().query("LWPOLYLINE")):
        if e.dxf.layer not in ("INNER_CUT", "OUTER_CUT"):
            continue
        points = [(x, y) for x, y, *_ in e.get_points()]
        if e.closed:
            points.append(points[0])
        segments += [(points[i], points[i + 1], n) for i in range(len(points) - 1)]
    return segments


def shared_length(edges):
    """mm of part edges that lie on another part's edge (what common-line cutting cuts once)."""
    lines, _ = _lines(edges)
    total = 0.0
    for spans in lines.values():
        covered = sum(b - a for a, b in _union([(a, b) for a, b, _ in spans]))
        total += sum(b - a for a, b, _ in spans) - covered
    return total


def problems(layout, board, kerf, dxf_path, once=True):
    """What is wrong with the cuts of `board` (0-based) in `dxf_path`: an edge not cut, a stretch cut twice (only
    when `once`: common-line cutting), a cut on no part's edge."""
    found = []
    edges = part_edges(layout, board, kerf)
    cuts, slanted = _lines(cut_segments(dxf_path))
    for a, b, source in slanted:
        found.append("polyline {}: a cut from {} to {} on no part's edge (not square)".format(source, a, b))
    for (x0, y0), (x1, y1), part in edges:
        axis, offset, a, b = (("x", y0, min(x0, x1), max(x0, x1)) if abs(y0 - y1) <= TOLERANCE
                              else ("y", x0, min(y0, y1), max(y0, y1)))
        at = a
        for c, d in _union([(c, d) for c, d, _ in _find(cuts, axis, offset)]):
            if d <= at or c >= b:
                continue
            if c > at + TOLERANCE:
                break
            at = max(at, d)
        if at < b - TOLERANCE:
            found.append("part {!r}: its edge {} = {:.3f} is not cut from {:.3f} to {:.3f}".format(
                part, "y" if axis == "x" else "x", offset, at, b))
    own, _ = _lines(edges)
    for (axis, offset), spans in cuts.items():
        on_edges = _union([(a, b) for a, b, _ in _find(own, axis, offset)])
        for a, b, source in spans:
            if not any(c - TOLERANCE <= a and b <= d + TOLERANCE for c, d in on_edges):
                found.append("polyline {}: a cut on {} = {:.3f} from {:.3f} to {:.3f} is on no part's edge".format(
                    source, "y" if axis == "x" else "x", offset, a, b))
        if once:
            ordered = sorted(spans)
            for i, (a, b, source) in enumerate(ordered):
                for c, d, other in ordered[i + 1:]:
                    if c >= b - TOLERANCE:
                        break
                    found.append("polylines {} and {}: {} = {:.3f} from {:.3f} to {:.3f} is cut twice".format(
                        source, other, "y" if axis == "x" else "x", offset, c, min(b, d)))
    return found
