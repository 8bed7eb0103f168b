"""Flat-pack designs with a sheet known to be savable ("sheets first, proved"): 50-100 boards of two
thicknesses, each free to shrink within a range down to a least size. The least sizes are cut from a known
layout (a guillotine cut of whole sheets, tests/bench/perfect_packings.py, each piece shrunk by the kerf and a
slack), so every board at its least fits on `saved` sheets per thickness; the boards as drawn are grown until
their area alone needs more sheets than that. The known answer: `saved` sheets in all, where the design as
drawn needs more.

    python3 tests/gen/savable_designs.py OUTDIR [SEEDS [SLACK]]   # writes savable-SEED.flatpack.json (seeds 1-5)
"""
import json
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import perfect_packings  # noqa: E402

SHEET = (2440, 1220)
SETTINGS = {"resolution": 1, "kerf": 3.2, "spacing": 0, "trim": 10, "min_length": 40}
THICKNESSES = (18, 6)
SLACK = 0.9  # each least side is this share of its piece: room a layout search can find (0.96: 8 % of the area)


def boards_of(rng, sheets, thickness, slack):
    """The boards cut from `sheets` whole sheets: {least, drawn, thickness, at: (sheet, x, y) of the least board in
    the known layout, on the board less its trim}."""
    usable = (SHEET[0] - 2 * SETTINGS["trim"], SHEET[1] - 2 * SETTINGS["trim"])
    kerf = SETTINGS["kerf"]
    least, at = [], []
    for sheet in range(sheets):
        # Pieces of a sheet one kerf wider and higher, less a kerf each: laid as cut, a kerf apart, inside the trim.
        pieces = perfect_packings.perfect_packing(rng.randrange(10 ** 6), "guillotine",
                                                  (int(usable[0] + kerf), int(usable[1] + kerf)),
                                                  rng.randint(12, 17), smallest=150)
        least += [(round((w - kerf) * slack, 1), round((h - kerf) * slack, 1)) for _, _, w, h in pieces]
        at += [(sheet, x, y) for x, y, _, _ in pieces]
    grown = [(w, h) for w, h in least]
    area = usable[0] * usable[1] * sheets
    while sum(w * h for w, h in grown) <= 1.04 * area:  # as drawn, the area alone needs another sheet
        k = rng.randrange(len(grown))
        w, h = grown[k]
        side = rng.randrange(2)
        if grown[k][side] * 1.1 <= usable[side]:  # a board the sheet still holds
            grown[k] = (round(w * 1.1, 1), h) if side == 0 else (w, round(h * 1.1, 1))
    return [{"least": l, "drawn": g, "thickness": thickness, "at": a} for l, g, a in zip(least, grown, at)]


def design(seed, slack=SLACK):
    """A design dict (docs/formats.md, *.flatpack.json) and its known answer {saved, drawn_at_least, layout}: the
    sheets its least design fits on, the sheets the boards as drawn need at least, and the least design's layout
    that shows it, [(id, thickness, sheet, x, y, width, height)] on each board less its trim."""
    rng = random.Random(seed)
    sheets = {t: rng.randint(2, 3) for t in THICKNESSES}
    boards = [b for t in THICKNESSES for b in boards_of(rng, sheets[t], t, slack)]
    parts, constraints, x = [], [], 0.0
    for k, b in enumerate(boards):
        pid = "board {}".format(k + 1)
        w, h = b["drawn"]
        parts.append({"id": pid, "min": [x, 0, 0], "max": [x + w, h, b["thickness"]]})
        x += w + 100  # apart: nothing snaps
        for axis, low, high in (("x", b["least"][0], w), ("y", b["least"][1], h)):
            constraints.append({"kind": "range", "ref": "{}.size.{}".format(pid, axis), "min": low, "max": high})
    usable = (SHEET[0] - 2 * SETTINGS["trim"]) * (SHEET[1] - 2 * SETTINGS["trim"])
    drawn_at_least = sum(-(-sum(b["drawn"][0] * b["drawn"][1] for b in boards if b["thickness"] == t) // usable)
                         for t in THICKNESSES)
    document = {"format": "fabguide.flatpack", "version": 2, "title": "savable {}".format(seed),
                "settings": dict(SETTINGS, max_growth=1.0),
                "boards": [{"name": "{} mm".format(t), "width": SHEET[0], "height": SHEET[1], "thickness": t,
                            "count": -1} for t in THICKNESSES],
                "parts": parts, "constraints": constraints}
    layout = [("board {}".format(k + 1), b["thickness"]) + tuple(b["at"]) + tuple(b["least"])
              for k, b in enumerate(boards)]
    return document, {"saved": sum(sheets.values()), "drawn_at_least": int(drawn_at_least), "layout": layout}


def least_pack_problem(known):
    """The least design's boards, as the known layout has them, as a pack problem (docs/formats.md, *.pack.json):
    by construction they fit on known["saved"] sheets."""
    return {"format": "fabguide.pack", "version": 1,
            "settings": {k: SETTINGS[k] for k in ("resolution", "kerf", "spacing", "trim")},
            "boards": [{"name": "{} mm".format(t), "width": SHEET[0], "height": SHEET[1], "thickness": t, "count": -1}
                       for t in THICKNESSES],
            "parts": [{"id": pid, "width": w, "height": h, "thickness": t}
                      for pid, t, _, _, _, w, h in known["layout"]]}


def main(argv):
    out = argv[1]
    seeds = range(1, 6) if len(argv) < 3 else [int(s) for s in argv[2].split(",")]
    slack = float(argv[3]) if len(argv) > 3 else SLACK
    os.makedirs(out, exist_ok=True)
    for seed in seeds:
        document, known = design(seed, slack)
        with open(os.path.join(out, "savable-{}.flatpack.json".format(seed)), "w") as f:
            json.dump(document, f, indent=1)
        print(seed, len(document["parts"]), {k: v for k, v in known.items() if k != "layout"})


if __name__ == "__main__":
    main(sys.argv)
