#!/usr/bin/env python3
"""Writes the two large flat-pack designs of the suite, as a cabinet maker would lay them out cabinet by cabinet:

- kitchen-run.flatpack.json: a 2400 mm kitchen niche with four base cabinets (600 with two doors, 450 with two
  drawers, 300, 450) and a 600 mm dishwasher gap, 46 boards of 18 mm birch;
- shop-shelving.flatpack.json: garage shelving, 4 bays of 800 mm x 6 shelves, 61 boards of 18 mm birch.

Run it from anywhere: python3 tests/data/flatpack/make_large.py (the files go beside it).
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
CNC = {"resolution": 0.5, "kerf": 6, "spacing": 2, "trim": 10, "min_length": 60}


def birch18(count):
    return [{"name": "birch 18", "material": "birch plywood", "width": 2440, "height": 1220, "thickness": 18,
             "count": count}]


def corners(low, size):
    """A box's "min" and "max" from its lower corner and sizes."""
    return {"min": list(low), "max": [lo + s for lo, s in zip(low, size)]}


def part(pid, position, size):
    return dict(id=pid, **corners(position, size))


def kitchen_run():
    # number, x, width, fronts: cabinet 1 has two doors, 2 two drawers, 3 is a bottle pull-out, 4 one door
    cabinets = [(1, 0, 600, "doors"), (2, 600, 450, "drawers"), (3, 1650, 300, "door"), (4, 1950, 450, "door")]
    parts, sides, depths, constraints = [], [], [], []
    for n, x0, w, fronts in cabinets:
        c = "cab-%d-" % n
        parts += [
            part(c + "side-left", [x0, 0, 130], [18, 560, 720]),
            part(c + "side-right", [x0 + w - 18, 0, 130], [18, 560, 720]),
            part(c + "bottom", [x0 + 18, 0, 130], [w - 36, 560, 18]),
            part(c + "rail-front", [x0 + 18, 0, 832], [w - 36, 100, 18]),
            part(c + "rail-back", [x0 + 18, 460, 832], [w - 36, 100, 18]),
            part(c + "hanging-rail", [x0 + 18, 542, 732], [w - 36, 18, 100]),
        ]
        if fronts in ("doors", "door") and w > 300:  # the 300 is a bottle pull-out: no shelf
            parts.append(part(c + "shelf", [x0 + 18, 0, 450], [w - 36, 520, 18]))
            constraints.append({"kind": "range", "ref": c + "shelf.min.z", "min": 400, "max": 550})
        if fronts == "doors":
            half = (w - 6) / 2.0
            parts += [part(c + "door-left", [x0 + 1.5, -18, 131.5], [half, 18, 717]),
                      part(c + "door-right", [x0 + 4.5 + half, -18, 131.5], [half, 18, 717])]
            constraints += [
                {"kind": "equal", "refs": [c + "door-left.size.x", c + "door-right.size.x"]},
                {"kind": "sum", "lhs": [c + "door-left.size.x", c + "door-right.size.x"],
                 "rhs": [c + "bottom.size.x"], "offset": 30, "name": "cabinet %d doors cover it" % n},
            ]
        elif fronts == "door":
            parts.append(part(c + "door", [x0 + 1.5, -18, 131.5], [w - 3, 18, 717]))
            constraints.append({"kind": "sum", "lhs": [c + "door.size.x"], "rhs": [c + "bottom.size.x"],
                                "offset": 33, "name": "cabinet %d door covers it" % n})
        else:
            for k, (zf, zb) in enumerate(((131.5, 150), (491.5, 510))):
                d = c + "drawer-%d-" % (k + 1)
                parts += [
                    part(d + "front", [x0 + 1.5, -18, zf], [w - 3, 18, 357]),
                    part(d + "side-left", [x0 + 31, 0, zb], [18, 500, 250]),
                    part(d + "side-right", [x0 + w - 49, 0, zb], [18, 500, 250]),
                    part(d + "back", [x0 + 49, 482, zb], [w - 98, 18, 250]),
                    part(d + "bottom", [x0 + 49, 0, zb], [w - 98, 482, 18]),
                ]
                constraints.append({"kind": "sum", "lhs": [d + "front.size.x"], "rhs": [c + "bottom.size.x"],
                                    "offset": 33, "name": "cabinet %d drawer %d front covers it" % (n, k + 1)})
            constraints += [
                {"kind": "equal", "refs": [c + "drawer-1-front.size.z", c + "drawer-2-front.size.z"]},
                {"kind": "sum", "lhs": [c + "drawer-1-front.size.z", c + "drawer-2-front.size.z"],
                 "rhs": ["cab-1-door-left.size.z"], "offset": -3, "name": "drawer fronts line up with the doors"},
                {"kind": "equal", "refs": [c + "drawer-%d-%s.size.y" % (k, s) for k in (1, 2)
                                           for s in ("side-left", "side-right")], "name": "drawer runners"},
            ]
        parts.append(part(c + "plinth-back", [x0, 500, 0], [w, 18, 130]))
        sides += [c + "side-left.size.z", c + "side-right.size.z"]
        depths += [c + "side-left.size.y", c + "side-right.size.y"]
        constraints.append({"kind": "range", "ref": c + "bottom.size.x", "min": w - 36 - 50, "max": w - 36 + 50,
                            "name": "cabinet %d width %d +- 50" % (n, w)})
    parts += [
        part("plinth-front-a", [0, 50, 0], [1050, 18, 130]),
        part("plinth-front-b", [1650, 50, 0], [750, 18, 130]),
    ]
    volumes = [
        dict(name="dishwasher 600 x 560 x 820", on="cab-2-side-right", **corners([1050, 0, 0], [600, 560, 820])),
        dict(name="pots and pans", on="cab-1-bottom", **corners([30, 20, 148], [530, 480, 280])),
        dict(name="bottles", on="cab-3-bottom", **corners([1680, 20, 148], [230, 480, 350])),
        dict(name="cutlery trays", on="cab-2-drawer-2-bottom", **corners([660, 20, 528], [320, 440, 60])),
    ]
    constraints = [
        {"kind": "ground", "parts": ["plinth-front-a", "plinth-front-b"] +
         ["cab-%d-plinth-back" % n for n, _, _, _ in cabinets], "level": 0},
        {"kind": "equal", "refs": sides, "name": "all sides equal"},
        {"kind": "equal", "refs": depths, "name": "all sides equally deep"},
        {"kind": "equal", "refs": ["cab-1-door-left.size.z", "cab-3-door.size.z", "cab-4-door.size.z"],
         "name": "all doors equally tall"},
        {"kind": "coplanar", "parts": ["plinth-front-a", "plinth-front-b"]},
        {"kind": "range", "ref": "cab-1-side-left.max.z", "min": 850, "max": 870,
         "name": "carcass height under a 38 mm worktop"},
        {"kind": "range", "ref": "cab-1-side-left.size.y", "min": 540, "max": 580, "name": "carcass depth"},
    ] + constraints
    return {
        "format": "fabguide.flatpack", "version": 2, "title": "Kitchen run, 2400 mm niche",
        "description": "Four base cabinets and a 600 mm dishwasher gap between two walls 2400 mm apart, 46 boards "
                       "of 18 mm birch: carcasses (sides, bottom, front and back top rails, a wall-hanging rail, "
                       "a shelf), a 600 with two doors, a 450 with two drawer boxes, a 300 bottle pull-out, a "
                       "450 with one door, overlay fronts, a plinth with recessed fronts. Each cabinet may be "
                       "50 mm narrower or wider, the carcasses 850-870 tall under a 38 mm laminate worktop "
                       "(bought), 540-580 deep. The dishwasher, pots, bottles and cutlery keep their room; "
                       "nothing leaves the niche.",
        "settings": CNC, "boards": birch18(8), "parts": parts, "constraints": constraints,
        "inner_volumes": volumes,
        "outer_volume": {"min": [0, -30, 0], "max": [2400, 600, 870]},
    }


def shop_shelving():
    bays, levels = 4, 6
    parts = [part("upright-%d" % (i + 1), [i * 818, 0, 0], [18, 400, 1800]) for i in range(bays + 1)]
    shelves = []
    for b in range(bays):
        x0 = b * 818 + 18
        for k in range(levels):
            z = 100 + 320 * k
            parts += [part("bay-%d-shelf-%d" % (b + 1, k + 1), [x0, 0, z], [800, 382, 18]),
                      part("bay-%d-stiffener-%d" % (b + 1, k + 1), [x0, 0, z - 60], [800, 18, 60])]
            shelves.append("bay-%d-shelf-%d" % (b + 1, k + 1))
        parts += [part("bay-%d-brace-low" % (b + 1), [x0, 382, 100], [800, 18, 120]),
                  part("bay-%d-brace-top" % (b + 1), [x0, 382, 1598], [800, 18, 120])]
    constraints = [
        {"kind": "ground", "parts": ["upright-%d" % (i + 1) for i in range(bays + 1)], "level": 0},
        {"kind": "equal", "refs": ["upright-%d.size.z" % (i + 1) for i in range(bays + 1)]},
        {"kind": "equal", "refs": [s + ".size.x" for s in shelves], "name": "all bays equally wide"},
        {"kind": "equal", "refs": [s + ".size.y" for s in shelves], "name": "all shelves equally deep"},
        {"kind": "equal", "refs": ["bay-%d-stiffener-%d.size.z" % (b + 1, k + 1) for b in range(bays)
                                   for k in range(levels)], "name": "stiffeners equal"},
    ] + [
        {"kind": "coplanar", "parts": ["bay-%d-shelf-%d" % (b + 1, k + 1) for b in range(bays)],
         "name": "level %d lines up" % (k + 1)} for k in range(levels)
    ] + [
        {"kind": "sum", "lhs": ["bay-1-shelf-%d.min.z" % (k + 2)] * 2,
         "rhs": ["bay-1-shelf-%d.min.z" % (k + 1), "bay-1-shelf-%d.min.z" % (k + 3)],
         "name": "level %d evenly spaced" % (k + 2)} for k in range(levels - 2)
    ] + [
        {"kind": "range", "ref": "bay-1-shelf-1.size.x", "min": 760, "max": 840, "name": "bay width"},
        {"kind": "range", "ref": "bay-1-shelf-1.size.y", "min": 350, "max": 420, "name": "shelf depth"},
        {"kind": "range", "ref": "upright-1.size.z", "min": 1700, "max": 1850, "name": "under the garage door rail"},
        {"kind": "range", "ref": "bay-1-stiffener-1.size.z", "min": 50, "max": 80},
        {"kind": "range", "ref": "bay-1-shelf-1.min.z", "min": 80, "max": 150},
    ]
    volumes = [dict(name="storage bins, bay %d" % (b + 1), on="bay-%d-shelf-1" % (b + 1),
                    **corners([b * 818 + 38, 20, 118], [600, 340, 290])) for b in range(bays)]
    return {
        "format": "fabguide.flatpack", "version": 2, "title": "Garage shelving, 4 bays x 6 shelves",
        "description": "Workshop shelving along a 3400 mm garage wall in 18 mm birch: five uprights, 24 shelves "
                       "with front stiffeners, a low and a top back brace per bay. Bays 760-840 wide, shelves "
                       "350-420 deep, uprights 1700-1850 under the door rail; every level lines up across the "
                       "bays and the bottom shelves keep room for storage bins.",
        "settings": CNC, "boards": birch18(8), "parts": parts, "constraints": constraints,
        "inner_volumes": volumes,
        "outer_volume": {"min": [-10, -10, 0], "max": [3400, 450, 1900]},
    }


def dump(design):
    """One part, constraint or volume a line, like the examples."""
    lines = ["{"]
    keys = list(design)
    for i, key in enumerate(keys):
        value, comma = design[key], "," if i < len(keys) - 1 else ""
        if isinstance(value, list) and value and isinstance(value[0], dict):
            lines.append("  %s: [" % json.dumps(key))
            lines += ["    " + json.dumps(v) + ("," if j < len(value) - 1 else "") for j, v in enumerate(value)]
            lines.append("  ]" + comma)
        else:
            lines.append("  %s: %s%s" % (json.dumps(key), json.dumps(value), comma))
    return "\n".join(lines + ["}"]) + "\n"


DESIGNS = {"kitchen-run": kitchen_run, "shop-shelving": shop_shelving}

if __name__ == "__main__":
    for name, make in DESIGNS.items():
        design = make()
        with open(os.path.join(HERE, name + ".flatpack.json"), "w") as f:
            f.write(dump(design))
        print("%s: %d boards" % (name, len(design["parts"])))
