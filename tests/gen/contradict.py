"""Making a product contradictory on purpose, with the conflict known: the parts it concerns are
drawn exactly and locked (a user's typed sizes), so no design holds, and the error must name what is in every
set of contradicting constraints (the required names), and one of each group of alternatives.

- tray: a drawer's tray (a fit inside's inner cuboid) locked wider than its locked bay;
- stop: a door that cannot open past a locked neighbour standing where it opens to;
- cover: a front locked narrower than the locked opening it must cover;
- legs: legs that support one flat carcass, their tops locked at different heights;
- flush: two fronts that must be flush, their faces locked apart.

contradict(model, rng) -> (model, {"kind", "must_name", "one_of"}) or None when the product offers none."""

import copy

SIDES = ("left", "right", "near", "far", "bottom", "top")


def find(model, name):
    for p in model["parts"]:
        for c in p["cuboids"]:
            if c["name"] == name:
                return p, c
    raise KeyError(name)


def lock(model, *faces):
    for f in faces:
        if f not in model["locks"]:
            model["locks"].append(f)


def lock_all(model, cuboid):
    lock(model, *("%s.%s" % (cuboid, s) for s in SIDES))


def tray(model, rng):
    fits = [r for r in model["relationships"] if r["type"] == "fit_inside" and r.get("cavity")
            and r["enclosing"] == "carcass"]
    if not fits:
        return None
    r = rng.choice(fits)
    inner = r["portion"][0] if r.get("portion") else next(c["name"] for c in find_part(model, r["inner"][0])["cuboids"]
                                                           if not c.get("cavity"))
    part, t = find(model, inner)
    _, bay = find(model, r["cavity"])
    by = round(rng.uniform(2, 10), 1)
    wall = {id(c): t["max"][0] - c["max"][0] for c in part["cuboids"] if c.get("cavity")}
    t["max"][0] = bay["max"][0] + by
    for c in part["cuboids"]:  # its well widens with it
        if c.get("cavity"):
            c["max"][0] = t["max"][0] - wall[id(c)]
    lock(model, inner + ".left", inner + ".right", r["cavity"] + ".left", r["cavity"] + ".right")
    return {"kind": "tray", "must_name": ["lock: %s.right" % inner],
            "one_of": [[r["name"], "no overlap: carcass, %s" % part["name"]] + covers_of(model, part["name"])]}


def find_part(model, name):
    return next(p for p in model["parts"] if p["name"] == name)


def covers_of(model, part):
    return [r["name"] for r in model["relationships"] if r["type"] == "cover" and part in r["covering"]]


def stop(model, rng):
    doors = [j for j in model["joints"] if j["type"] == "hinge" and j.get("base") is None
             and j["edge"][0].endswith((".left", ".right")) and j["edge"][1].endswith(".near")]
    posed = [(j, c) for j in doors for c in model["configurations"] if j["name"] in c["poses"]
             and abs(abs(float(c["poses"][j["name"]])) - 90) < 1e-9]
    if not posed:
        return None
    j, configuration = rng.choice(posed)
    _, door = find(model, j["part"])
    lo, hi = door["min"], door["max"]
    td, width = hi[1] - lo[1], hi[0] - lo[0]
    x = lo[0] if j["edge"][0].endswith(".left") else hi[0]
    s = max(2.0, round(td, 1))
    y = lo[1] - 0.6 * width
    model["parts"].append({"name": "stop", "cuboids": [{"name": "stop", "min": [x - 2 * s, y - s, lo[2]],
                                                        "max": [x + 2 * s, y, hi[2]]}]})
    lock_all(model, "stop")
    lock_all(model, j["part"])
    where = [c["name"] for c in model["configurations"] if j["name"] in c["poses"]]
    return {"kind": "stop", "must_name": [],
            "one_of": [["no overlap: %s, stop %s '%s'" % (j["part"], how, k) for k in where
                        for how in ("in", "on the way to")]]}


def cover(model, rng):
    covers = [r for r in model["relationships"] if r["type"] == "cover" and r.get("pairs") and len(r["covering"]) == 1
              and len(find_part(model, r["covering"][0])["cuboids"]) == 1 and r["covered"] == ["carcass"]]
    if not covers:
        return None
    r = rng.choice(covers)
    front = r["covering"][0]
    opening = r["pairs"][0][1].rpartition(".")[0]
    _, f = find(model, front)
    _, bay = find(model, opening)
    f["max"][0] = bay["max"][0] - round(rng.uniform(2, 10), 1)
    lock(model, front + ".left", front + ".right", opening + ".left", opening + ".right")
    return {"kind": "cover", "must_name": [r["name"], "lock: %s.right" % front, "lock: %s.right" % opening],
            "one_of": []}


def legs(model, rng):
    supports = [r for r in model["relationships"] if r["type"] == "support" and len(r["supporting"]) >= 2]
    if not supports:
        return None
    r = rng.choice(supports)
    a, b = rng.sample(r["supporting"], 2)
    _, leg = find(model, a)
    leg["max"][2] += round(rng.uniform(2, 10), 1)
    lock(model, a + ".top", b + ".top")
    return {"kind": "legs", "must_name": [r["name"], "lock: %s.top" % a, "lock: %s.top" % b], "one_of": []}


def flush(model, rng):
    flushes = [r for r in model["relationships"] if r["type"] == "flush"]
    if not flushes:
        return None
    r = rng.choice(flushes)
    fa, fb = r["faces"]
    name, _, side = fb.rpartition(".")
    part, c = find(model, name)
    s = SIDES.index(side)
    by = round(rng.uniform(2, 6), 1)
    for k in [k for k in part["cuboids"] if not k.get("cavity")]:  # the whole front moves out
        k["min"][s // 2] -= by
        k["max"][s // 2] -= by
    lock(model, fa, fb)
    return {"kind": "flush", "must_name": [r["name"], "lock: " + fa, "lock: " + fb], "one_of": []}


KINDS = {"tray": tray, "stop": stop, "cover": cover, "legs": legs, "flush": flush}


def contradict(model, rng):
    """The model made contradictory by one kind the product offers, and the conflict known; None if none fits."""
    kinds = list(KINDS)
    rng.shuffle(kinds)
    for kind in kinds:
        m = copy.deepcopy(model)
        m.setdefault("locks", [])
        known = KINDS[kind](m, rng)
        if known:
            m["description"] += "; contradictory: " + kind
            return m, known
    return None
