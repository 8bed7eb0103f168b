"""Perfect packings generated from a seed: a board cut into rectangles with no waste, so its height
is the optimal strip height.

Guillotine packings cut the largest piece left straight across; pinwheel packings split it into five pieces
around a centre (a pattern no guillotine cut can make) or, one time in four, straight across. Sizes are whole
millimetres, every piece at least `smallest` on each side. Written as OR-Datasets strip instances, the format
of C1-C7 and N1-N13.

    python3 tests/bench/perfect_packings.py OUTDIR   # writes the benchmark's set (seeds 1-10)
"""
import json
import os
import random
import sys

BOARDS = [(2440, 1220), (1220, 2440), (1830, 1220), (1000, 1000), (600, 400)]
KINDS = ["guillotine", "pinwheel"]


def _cut_across(rng, piece, smallest):
    """Two pieces from one cut straight across its longer side (or the other when that is too short)."""
    x, y, w, h = piece
    sides = sorted([("x", w), ("y", h)], key=lambda s: -s[1] + rng.random() * min(w, h) * 0.5)
    for axis, length in sides:
        if length >= 2 * smallest:
            at = rng.randint(smallest, length - smallest)
            if axis == "x":
                return [(x, y, at, h), (x + at, y, w - at, h)]
            return [(x, y, w, at), (x, y + at, w, h - at)]
    return None


def _pinwheel(rng, piece, smallest):
    """Five pieces around a centre: a < b across, c < d up, each piece at least `smallest` on a side."""
    x, y, w, h = piece
    if w < 3 * smallest or h < 3 * smallest:
        return None
    a = rng.randint(smallest, w - 2 * smallest)
    b = rng.randint(a + smallest, w - smallest)
    c = rng.randint(smallest, h - 2 * smallest)
    d = rng.randint(c + smallest, h - smallest)
    return [(x, y, b, c), (x + b, y, w - b, d), (x + a, y + d, w - a, h - d), (x, y + c, a, h - c),
            (x + a, y + c, b - a, d - c)]


def perfect_packing(seed, kind, board, items, smallest=10):
    """The pieces (x, y, w, h) of `board` cut into about `items` pieces."""
    rng = random.Random(seed)
    pieces = [(0, 0) + tuple(board)]
    while len(pieces) < items:
        pieces.sort(key=lambda p: p[2] * p[3])
        largest = pieces.pop()
        split = None
        if kind == "pinwheel" and rng.random() < 0.75:
            split = _pinwheel(rng, largest, smallest)
        split = split or _cut_across(rng, largest, smallest)
        if split is None:
            pieces.append(largest)
            break
        pieces += split
    return pieces


def instance(seed, kind, board, items):
    """An OR-Datasets strip instance of the packing; rotation is allowed, as for C1-C7 and N1-N13."""
    rng = random.Random(seed * 7919)
    pieces = perfect_packing(seed, kind, board, items)
    rng.shuffle(pieces)
    return {"Name": "{}-{}".format(kind, seed),
            "Objects": [{"Length": board[0], "Height": board[1], "Stock": None, "Cost": 1}],
            "Items": [{"Length": w, "Height": h, "Demand": 1, "DemandMax": None, "Value": w * h}
                      for _, _, w, h in pieces]}


def benchmark_set(seeds=range(1, 11)):
    """The instances of `seeds` for each kind: 15-250 items, the boards in turn."""
    found = []
    for kind in KINDS:
        for seed in seeds:
            items = random.Random(seed).randint(15, 250)
            found.append(instance(seed, kind, BOARDS[(seed - 1) % len(BOARDS)], items))
    return found


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for inst in benchmark_set():
        with open(os.path.join(out, inst["Name"] + ".json"), "w") as f:
            json.dump(inst, f)


if __name__ == "__main__":
    main()
