"""Zero-waste on designs nobody tuned for: the furniture suite (tests/data/flatpack), generated designs whose
sheets are known (tests/gen/savable_designs.py, slack 0.93) and parametric designs driven by a few parameters
(stackable crates, a bookshelf), each through `fabguide optimise` (or the core's parametric search) with one time
limit. Per design: boards, thicknesses, the lower bound on sheets over every variation (FabGuide's, by area and
lines across the sheets, with the area's alone beside it where less; for the parametric ones the area's is checked
against this script's own from the parameters' least corner), the known sheets where there are, sheets and
waste before -> after, seconds, and what the independent checker says of every suggestion (constraints, volumes
on their boards, growth, layouts, reopening).

    python3 tests/bench/zero_waste_table.py [build-dir] [--seconds 8]
"""
import argparse
import json
import math
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "gen"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))
import flatpack_checker  # noqa: E402
import savable_benchmark  # noqa: E402
import savable_designs  # noqa: E402

SUITE = os.path.join(ROOT, "tests", "data", "flatpack")
SHEETS = {"boards": [{"name": "birch %d" % t, "width": 2440, "height": 1220, "thickness": t, "count": -1}
                     for t in (18, 12, 6)],
          "settings": {"resolution": 1, "kerf": 4, "spacing": 0, "trim": 5}}


# Parametric designs: (parts [{id, quantity, grain}], sides(parameters) -> [x, y, z per part], start, lower, upper).
def crates(count):
    """Stackable crates of length L, width W, height H: 12 mm sides and ends, a 6 mm bottom, 12 mm cleats."""
    parts = [{"id": "side", "quantity": 2 * count, "grain": "x"}, {"id": "end", "quantity": 2 * count, "grain": "y"},
             {"id": "bottom", "quantity": count, "grain": "free"}, {"id": "cleat", "quantity": 4 * count,
                                                                   "grain": "x"}]

    def sides(p):
        length, width, height = p
        return [length, height, 12, 12, width - 24, height, length - 24, width - 24, 6, length - 24, 40, 12]

    return parts, sides, [500, 350, 250], [400, 300, 180], [600, 400, 300]


def bookshelf():
    """A bookshelf of width W, height H and depth D: 18 mm sides, five shelves, a 6 mm back."""
    parts = [{"id": "side", "quantity": 2, "grain": "y"}, {"id": "shelf", "quantity": 5, "grain": "x"},
             {"id": "back", "quantity": 1, "grain": "free"}]

    def sides(p):
        width, height, depth = p
        return [18, height, depth, width - 36, 18, depth - 6, width, height, 6]

    return parts, sides, [800, 1800, 320], [600, 1500, 250], [900, 2000, 350]


PARAMETRIC = {"crates-x3": lambda: crates(3), "crates-x6": lambda: crates(6), "bookshelf": bookshelf}


def own_bound(parts, sides, lower):
    """Sheets by area at the parameters' least corner (every side here grows with every parameter), per thickness,
    as the core counts area: each part with kerf + spacing around it, each sheet less its trim."""
    s = SHEETS["settings"]
    gap = s["kerf"] + s["spacing"]
    at = sides(lower)
    area = {}
    for k, part in enumerate(parts):
        x, y, z = at[3 * k:3 * k + 3]
        a, b, thickness = sorted((x, y, z), reverse=True)
        area[thickness] = area.get(thickness, 0) + part["quantity"] * (a + gap) * (b + gap)
    sheet = (2440 - 2 * s["trim"] + gap) * (1220 - 2 * s["trim"] + gap)
    return sum(math.ceil(a / sheet - 1e-9) for a in area.values())


def parametric_row(core, name, seconds):
    """(boards, thicknesses, summary, wall seconds, problems) of the core's parametric search: suggestions within the parameters' box, their layouts
    checked as plain designs' are, and the bound against this script's own."""
    parts, sides, start, lower, upper = PARAMETRIC[name]()
    began = time.monotonic()
    result = core.optimise_parametric(parts, sides, start, lower, upper, SHEETS, time_limit=seconds)
    wall = time.monotonic() - began
    problems = []
    if result["least_sheets_by_area"] != own_bound(parts, sides, lower):
        problems.append("bound {} where the least corner's area needs {}".format(
            result["least_sheets_by_area"], own_bound(parts, sides, lower)))
    for k, s in enumerate(result["suggestions"]):
        p = s["parameters"]
        if not all(lo - 1e-6 <= v <= hi + 1e-6 for v, lo, hi in zip(p, lower, upper)):
            problems.append("suggestion {}: parameters {} outside their box".format(k + 1, p))
        at = sides(p)
        design = {"boards": SHEETS["boards"], "settings": SHEETS["settings"],
                  "parts": [dict(id=part["id"], quantity=part["quantity"], grain=part["grain"],
                                 min=[0, 0, 0], max=at[3 * i:3 * i + 3]) for i, part in enumerate(parts)]}
        problems += ["suggestion {}: {}".format(k + 1, q) for q in flatpack_checker.layout_problems(design,
                                                                                                  s["layout"])]
        if s["sheets"] > result["before"]["sheets"]:
            problems.append("suggestion {}: more sheets than as drawn".format(k + 1))
    summary = dict(result, suggestions=[{"sheets": s["sheets"], "waste_m2": s["waste_m2"]}
                                        for s in result["suggestions"]])
    boards = sum(p["quantity"] for p in parts)
    thicknesses = sorted({sorted(sides(start)[3 * i:3 * i + 3])[0] for i in range(len(parts))})
    return boards, thicknesses, summary, wall, problems


def thicknesses_of(document):
    return sorted({min(p["size"]) for p in document["parts"]})


def boards_of(document):
    return sum(p.get("quantity", 1) for p in document["parts"])


def bound_of(summary):
    """The lower bound, and the area's alone where it is less."""
    bound, area = summary["least_sheets_bound"], summary["least_sheets_by_area"]
    return "none" if not bound else str(bound) if bound == area else "{} (area {})".format(bound, area)


def line(name, boards, thicknesses, summary, known, wall, problems):
    before = summary["before"]
    best = min(summary["suggestions"], key=lambda s: (s["sheets"], s["waste_m2"]), default=before)
    return "| {} | {} | {} | {} | {} | {} -> {} | {:.3f} -> {:.3f} | {:.1f} | {} |".format(
        name, boards, " + ".join("%g" % t for t in thicknesses), bound_of(summary),
        known if known is not None else "", before["sheets"], best["sheets"], before["waste_m2"], best["waste_m2"],
        wall, "; ".join(problems[:2]) or "pass ({} suggestions)".format(len(summary["suggestions"])))


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"))
    parser.add_argument("--seconds", type=float, default=8)
    args = parser.parse_args(argv[1:])
    cli = os.path.join(args.build, "fabguide")
    sys.path.insert(0, args.build)
    import fabguide_core
    print("| design | boards | mm | lower bound (sheets) | known sheets | sheets | waste m² | seconds | checker |")
    print("|---|---|---|---|---|---|---|---|---|")
    rows = []
    designs = [(name[:-len(".flatpack.json")], json.load(open(os.path.join(SUITE, name))), None)
               for name in sorted(os.listdir(SUITE)) if name.endswith(".flatpack.json")]
    for seed in range(1, 6):
        document, known = savable_designs.design(seed, 0.93)
        designs.append(("generated-%d" % seed, document, known["saved"]))
    for name, document, known in designs:
        summary, problems, wall = savable_benchmark.run(cli, document, args.seconds, reload=True)
        if summary is None:
            print("| {} | {} | | | | | | {:.1f} | error: {} |".format(name, boards_of(document), wall,
                                                                   problems[0][:80]))
            continue
        rows.append((summary, known, problems))
        print(line(name, boards_of(document), thicknesses_of(document), summary, known, wall, problems), flush=True)
    for name in PARAMETRIC:
        boards, thicknesses, summary, wall, problems = parametric_row(fabguide_core, name, args.seconds)
        rows.append((summary, None, problems))
        print(line(name, boards, thicknesses, summary, None, wall, problems), flush=True)
    after = [min([s["sheets"] for s in summary["suggestions"]] + [summary["before"]["sheets"]])
             for summary, _, _ in rows]
    bounds = [summary["least_sheets_bound"] for summary, _, _ in rows]
    known = [(a, k) for a, (_, k, _) in zip(after, rows) if k is not None]
    print("\n{} designs; the checker passes {}; on the sheets the bound allows: {}; known sheets reached: {} of {}; "
          "a sheet saved on {} of the {} drawn on more sheets than the bound".format(
              len(rows), sum(not problems for _, _, problems in rows), sum(a == b for a, b in zip(after, bounds)),
              sum(a <= k for a, k in known), len(known),
              sum(a < r[0]["before"]["sheets"] for a, r in zip(after, rows)),
              sum(r[0]["before"]["sheets"] > b for r, b in zip(rows, bounds))))

if __name__ == "__main__":
    main(sys.argv)
