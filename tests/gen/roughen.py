"""Drawing a product roughly, as designers draw: a pass separate from the grammar that knows only the
*.workslike.json it is given. Sizes and positions off by 1-8 mm, parts pushed into the parts they touch, the
cuboids of a part pulled up to 4 mm apart, fronts (the covering parts of a cover) off their openings by up to
7 mm: on furniture (500 mm and more); on smaller products in proportion, down to a quarter (a phone drawn 2 mm
off, not 8). Locked parts stay as drawn (a user locks what is exact). Openings stay on their
faces: a cavity side on its solid's side moves with it."""

import copy

SIDES = ("left", "right", "near", "far", "bottom", "top")


def cuboids(model):
    return [(p, c) for p in model["parts"] for c in p["cuboids"]]


def locked_parts(model):
    names = {lock.rpartition(".")[0] for lock in model.get("locks", [])}
    return {p["name"] for p in model["parts"] if any(c["name"] in names for c in p["cuboids"])}


def solid_of(part, cavity):
    """The solid cuboid of the part a cavity is cut from: the one it overlaps most."""
    def overlap(s):
        v = 1.0
        for i in range(3):
            v *= max(0.0, min(s["max"][i], cavity["max"][i]) - max(s["min"][i], cavity["min"][i]))
        return v
    solids = [c for c in part["cuboids"] if not c.get("cavity")]
    return max(solids, key=overlap)


def move(part, cuboid, axis, by, pivots):
    """Shift a cuboid (and the cavities cut from it, and pivots on it) along an axis."""
    for c in [cuboid] + [k for k in part["cuboids"] if k.get("cavity") and solid_of(part, k) is cuboid]:
        c["min"][axis] += by
        c["max"][axis] += by
    for point in pivots.get(cuboid["name"], []):
        point[axis] += by


def touching(a, b, tol=1e-6):
    """The axis and direction (a's side) along which solids a and b touch face to face, or None."""
    for axis in range(3):
        others = [i for i in range(3) if i != axis]
        if all(min(a["max"][i], b["max"][i]) - max(a["min"][i], b["min"][i]) > tol for i in others):
            if abs(a["max"][axis] - b["min"][axis]) < tol:
                return axis, 1
            if abs(b["max"][axis] - a["min"][axis]) < tol:
                return axis, -1
    return None


def inward_room(part, solid, axis, end):
    """How far a side of a solid may move in and keep half of each wall it leaves round its cavities (at least
    1 mm of each, the least wall), so that a wall stays a wall and an opening an opening."""
    room = float("inf")
    for k in part["cuboids"]:
        if k.get("cavity") and solid_of(part, k) is solid:
            wall = abs(solid[end][axis] - k[end][axis])
            if wall > 1e-9:
                room = min(room, max(0.0, wall - max(1.0, wall / 2)))
    return room


def roughen(model, rng):
    """The model drawn roughly (a new dict) and what was done to it, one line each."""
    m = copy.deepcopy(model)
    done = []
    locked = locked_parts(m)
    pivots = {}
    for j in m["joints"]:
        if j["type"] == "double_pivot":
            for key in ("pivot", "base_pivot"):
                pivots.setdefault(j[key][0].rpartition(".")[0], []).append(j[key][1])
    movers = {j["part"] for j in m["joints"]}
    free = [p for p in m["parts"] if p["name"] not in locked]
    # sizes and positions off by 1-8 mm on furniture, less on a product a hand holds (a quarter at 125 mm)
    size = max(c["max"][i] - c["min"][i] for _, c in cuboids(m) for i in range(3))
    scale = min(1.0, max(0.25, size / 500))
    for p in free:
        if rng.random() < 0.3:
            continue
        e = rng.uniform(1, 8) * scale
        solids = [c for c in p["cuboids"] if not c.get("cavity")]
        shift = [rng.uniform(-e, e) / 2 for _ in range(3)]  # a face off by at most e, moved and resized
        for axis in range(3):
            for c in solids:
                move(p, c, axis, shift[axis], pivots)
        for c in solids:
            for axis in range(3):
                size = c["max"][axis] - c["min"][axis]
                for end in ("min", "max"):
                    if rng.random() < 0.5:
                        d = rng.uniform(-1, 1) * min(e / 2, 0.2 * size, inward_room(p, c, axis, end))
                        old = c[end][axis]
                        c[end][axis] += d
                        for k in p["cuboids"]:  # openings on this side move with it, and cuboids glued to it
                            if k.get("cavity") and solid_of(p, k) is c and abs(k[end][axis] - old) < 1e-9:
                                k[end][axis] += d
                            other = "max" if end == "min" else "min"
                            if not k.get("cavity") and k is not c and abs(k[other][axis] - old) < 1e-9 and \
                                    touching(c, k, 1e-6) is None:
                                k[other][axis] += d
        done.append("%s off by up to %.1f mm" % (p["name"], e))
    # the cuboids of a part pulled apart
    for p in free:
        solids = [c for c in p["cuboids"] if not c.get("cavity")]
        if len(solids) > 1 and rng.random() < 0.4:
            c = rng.choice(solids[1:])
            for other in solids:
                t = touching(c, other, 1e-3) if other is not c else None
                if t:
                    by = t[1] * -rng.uniform(0.2, 4) * scale
                    move(p, c, t[0], by, pivots)
                    done.append("%s pulled %.1f mm off %s" % (c["name"], abs(by), other["name"]))
                    break
    # moving parts pushed into the parts they touch
    for p in free:
        if p["name"] not in movers or rng.random() < 0.7:
            continue
        for c in [c for c in p["cuboids"] if not c.get("cavity")]:
            hit = None
            for q, d in cuboids(m):
                if q is not p and not d.get("cavity"):
                    hit = touching(c, d, 1.0)
                    if hit:
                        by = hit[1] * rng.uniform(0.5, 3) * scale
                        for s in [k for k in p["cuboids"] if not k.get("cavity")]:
                            move(p, s, hit[0], by, pivots)
                        done.append("%s pushed %.1f mm into %s" % (p["name"], abs(by), q["name"]))
                        break
            if hit:
                break
    # fronts off their openings
    covering = {name for r in m["relationships"] if r["type"] == "cover" for name in r["covering"]}
    for p in free:
        if p["name"] in covering and rng.random() < 0.3:
            axis = rng.choice([0, 2])
            by = rng.uniform(-7, 7) * scale
            for c in [c for c in p["cuboids"] if not c.get("cavity")]:
                move(p, c, axis, by, pivots)
            done.append("%s %.1f mm off along %s" % (p["name"], by, "xyz"[axis]))
    for _, c in cuboids(m):
        c["min"] = [round(v, 3) for v in c["min"]]
        c["max"] = [round(v, 3) for v in c["max"]]
    for j in m["joints"]:  # a pivot stays on its face
        if j["type"] == "double_pivot":
            for key in ("pivot", "base_pivot"):
                name, _, side = j[key][0].rpartition(".")
                c = next(c for _, c in cuboids(m) if c["name"] == name)
                s = SIDES.index(side)
                point = j[key][1]
                for i in range(3):
                    point[i] = min(max(point[i], c["min"][i]), c["max"][i])
                point[s // 2] = c["max" if s % 2 else "min"][s // 2]
    return m, done
