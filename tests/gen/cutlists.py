"""Shop cut lists as a cabinet maker writes them: kitchens and wardrobes of cabinets drawn from a seed,
each cabinet's carcass, shelves, rails, doors and drawer fronts; carcass parts from 18 mm white melamine
(2800 x 2070 mm, no grain), doors and fronts from 19 mm oak veneered board (2500 x 1250 mm, grain along its length)
that follow the grain (a door's length, along x, is its height: grain runs up a door). Identical parts are merged into one line with a quantity, as a cut list has them:
80-400 parts of 20-60 sizes. `problem(seed)` is a *.pack.json document; `--write DIR N` writes N of them."""
import json
import os
import random
import sys

CARCASS = {"name": "white melamine 18", "material": "melamine", "width": 2800, "height": 2070, "thickness": 18,
           "count": -1, "grain": "none"}
FRONTS = {"name": "oak veneer 19", "material": "oak", "width": 2500, "height": 1250, "thickness": 19,
          "count": -1, "grain": "width"}
WIDTHS = [300, 400, 450, 500, 600, 800, 900, 1000]


def _cabinet(rng, kind, width, parts):
    """The parts of one cabinet `width` mm wide, added to `parts` {(name, w, h, thickness, grain): quantity}."""
    def add(name, w, h, thickness=18, grain=False):
        key = (name, round(w), round(h), thickness, grain)
        parts[key] = parts.get(key, 0) + 1
    inner = width - 36
    if kind == "base":
        height, depth = 720, 560
        add("base side", depth, height)
        add("base side", depth, height)
        add("base bottom", inner, depth)
        add("base rail", inner, 100)
        add("base rail", inner, 100)
        for _ in range(rng.choice([0, 1, 1, 2])):
            add("base shelf", inner, depth - 20)
        if rng.random() < 0.4:
            for front in rng.choice([[140, 280, 280], [180, 180, 340], [355, 355]]):
                add("drawer front", width - 4, front, 19, True)
            add("drawer side", 500, 120)
        else:
            for _ in range(1 if width <= 600 else 2):
                add("base door", 716, (width - 4) / (1 if width <= 600 else 2), 19, True)
    elif kind == "wall":
        height, depth = rng.choice([600, 720, 900]), 320
        add("wall side", depth, height)
        add("wall side", depth, height)
        add("wall top", inner, depth)
        add("wall bottom", inner, depth)
        for _ in range(rng.choice([1, 2])):
            add("wall shelf", inner, depth - 20)
        for _ in range(1 if width <= 600 else 2):
            add("wall door", height - 4, (width - 4) / (1 if width <= 600 else 2), 19, True)
    else:  # wardrobe
        height, depth = rng.choice([2000, 2100, 2200]), 580
        width = rng.choice([500, 600, 800, 1000])
        inner = width - 36
        add("wardrobe side", depth, height)
        add("wardrobe side", depth, height)
        add("wardrobe top", inner, depth)
        add("wardrobe bottom", inner, depth)
        for _ in range(rng.choice([2, 3, 4])):
            add("wardrobe shelf", inner, depth - 20)
        for _ in range(1 if width <= 600 else 2):
            add("wardrobe door", height - 4, (width - 4) / (1 if width <= 600 else 2), 19, True)


def problem(seed, kerf=3.2, trim=10.0):
    """A kitchen (even seeds) or a bedroom of wardrobes with a few base units (odd seeds)."""
    rng = random.Random(seed)
    parts = {}
    if seed % 2 == 0:
        for _ in range(rng.randint(6, 22)):
            _cabinet(rng, "base", rng.choice(WIDTHS), parts)
        for _ in range(rng.randint(4, 16)):
            _cabinet(rng, "wall", rng.choice(WIDTHS), parts)
    else:
        for _ in range(rng.randint(4, 14)):
            _cabinet(rng, "wardrobe", 0, parts)
        for _ in range(rng.randint(2, 8)):
            _cabinet(rng, "base", rng.choice(WIDTHS), parts)
    listed = []
    for (name, w, h, thickness, grain), quantity in sorted(parts.items()):
        listed.append({"id": "{} {}x{}".format(name, w, h), "width": w, "height": h, "quantity": quantity,
                       "thickness": thickness, "follow_grain": grain})
    return {"format": "fabguide.pack", "version": 1,
            "settings": {"kerf": kerf, "trim": trim, "cuts": "guillotine", "stages": 3},
            "boards": [dict(CARCASS), dict(FRONTS)], "parts": listed}


def main(argv):
    folder, count = argv[argv.index("--write") + 1], int(argv[argv.index("--write") + 2])
    os.makedirs(folder, exist_ok=True)
    for seed in range(count):
        with open(os.path.join(folder, "cutlist-{}.pack.json".format(seed)), "w") as f:
            json.dump(problem(seed), f, indent=1)


if __name__ == "__main__":
    main(sys.argv)
