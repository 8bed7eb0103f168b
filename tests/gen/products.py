"""Products with known answers: a grammar that composes works-like products, each valid by
construction, then drawn roughly by a separate pass (roughen.py), a third of them made contradictory with the
conflict known (contradict.py).

A product is a carcass (a box with compartments open at the front and, perhaps, a well open at the top) and
what the compartments hold: doors hinged on either side and at any angle, flaps hinged at the bottom or the
top, drawers (a front and a tray with a well), pull-outs carrying a rack that lifts out of them, bins, pocket
doors (sliding hinges), sliding doors in one track, a lid (perhaps folding in two: a chain), knobs (fixed
joints), legs (support); or a crate: a base with boards on links (double pivots) that fold over it. Cover,
fit inside (whole and portion, just), support, flush and geometric relationships say what it must do, in two
to five configurations.

generate(seed) -> Product, whose .model is the clean design (a dict in the *.workslike.json format). Every
product is judged by the independent checker (tests/python/workslike_checker.py) before it is returned: a
design the checker rejects is drawn again from the next draw of the same seed (`redraws` counts them), so
what is returned is valid in every configuration and along every motion.
"""

import copy
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
import workslike_checker  # noqa: E402

AXES = "xyz"


def box(name, lo, hi, cavity=False):
    c = {"name": name, "min": [float(v) for v in lo], "max": [float(v) for v in hi]}
    if cavity:
        c["cavity"] = True
    return c


class Product:
    """A product as it is built: parts, joints, configurations and relationships, and what it shows."""

    def __init__(self, seed, rng):
        self.seed, self.rng = seed, rng
        self.parts, self.joints, self.relationships, self.locks = [], [], [], []
        self.configurations = []
        self.movers = []  # (joint name, [poses it may take], group): what configurations may pose
        self.features = set()
        self.redraws = 0

    # ---- building
    def part(self, name, *cuboids):
        self.parts.append({"name": name, "cuboids": list(cuboids)})
        return name

    def cuboid(self, name):
        for p in self.parts:
            for c in p["cuboids"]:
                if c["name"] == name:
                    return c
        raise KeyError(name)

    def joint(self, joint, poses=None, group=None):
        self.joints.append(joint)
        if poses:
            self.movers.append((joint["name"], poses, group or joint["name"]))
        return joint["name"]

    def relate(self, kind, name, **fields):
        self.relationships.append(dict({"type": kind, "name": name}, **fields))
        self.features.add(kind)

    @property
    def model(self):
        return {"format": "fabguide.workslike", "version": 1, "minimum_size": 1, "minimum_wall": 1,
                "description": "generated product, seed %d: %s" % (self.seed, ", ".join(sorted(self.features))),
                "parts": self.parts, "joints": self.joints, "configurations": self.configurations,
                "relationships": self.relationships, "locks": self.locks}


# --------------------------------------------------------------------------------------------------------
# the carcass and its fronts


class Bay:
    """A compartment: a cavity of the carcass open at the front (y = 0), and the room its front may take."""

    def __init__(self, name, lo, hi, room_lo, room_hi, row, column):
        self.name, self.lo, self.hi = name, lo, hi
        self.room_lo, self.room_hi = room_lo, room_hi  # x and z a front may overlay up to
        self.row, self.column = row, column

    def front(self, rng):
        """A front's x and z extents: the opening, overlaid (or not) into the room around it."""
        over = rng.choice([0.0, 0.0, 1.0])
        lo = [self.lo[i] - over * rng.uniform(0, self.lo[i] - self.room_lo[i]) for i in (0, 2)]
        hi = [self.hi[i] + over * rng.uniform(0, self.room_hi[i] - self.hi[i]) for i in (0, 2)]
        return lo, hi


def split(rng, start, end, n, divider):
    """n spans between start and end with dividers between them: [(lo, hi)]."""
    room = end - start - (n - 1) * divider
    weights = [rng.uniform(0.7, 1.3) if rng.random() < 0.5 else 1.0 for _ in range(n)]
    spans, at = [], start
    for w in weights:
        size = room * w / sum(weights)
        spans.append((at, at + size))
        at += size + divider
    return spans


def round_to(v, step=0.5):
    return round(v / step) * step


class Cabinet:
    """A carcass on the ground (or on legs) with a grid of bays and perhaps a top well."""

    def __init__(self, p):
        rng = self.rng = p.rng
        self.p = p
        small = rng.random() < 0.4  # a product on a desk (a toolbox, a phone) or furniture
        scale = rng.uniform(60, 250) if small else rng.uniform(350, 1000)
        self.W = round_to(scale * rng.uniform(0.8, 1.8))
        self.D = round_to(scale * rng.uniform(0.6, 1.2))
        self.H = round_to(scale * rng.uniform(0.8, 1.8))
        # Printable on a desktop printer (250 x 210 x 210 mm): walls and fronts at least 3 mm as printed,
        # the least a hinge's pin and yokes or a slide's rails hold in.
        printed = self.printed = min(1.0, 240 / self.W, 200 / self.D, 150 / self.H)
        least = 3.0 / printed
        self.t = round_to(max(least, rng.uniform(3, 6) if small else rng.uniform(12, 20)))
        self.front_t = round_to(max(least, self.t * rng.uniform(0.6, 1.1)))
        self.legs = rng.random() < 0.3
        self.z0 = round_to(rng.uniform(0.1, 0.25) * self.H) if self.legs else 0.0
        self.well = rng.random() < 0.35
        self.bays = []
        self.name = p.part("carcass", box("carcass", [0, 0, self.z0], [self.W, self.D, self.z0 + self.H]))
        self.make_bays()

    def make_bays(self):
        rng, t = self.rng, self.t
        top = self.z0 + self.H - t
        if self.well:
            self.well_depth = round_to(min(self.H * rng.uniform(0.15, 0.3), self.H - 4 * t))
            top = self.z0 + self.H - self.well_depth - t
            self.p.parts[0]["cuboids"].append(box("well", [t, t, self.z0 + self.H - self.well_depth],
                                                  [self.W - t, self.D - t, self.z0 + self.H], cavity=True))
        columns = rng.choice([1, 1, 2, 2, 3])
        rows = rng.choice([1, 1, 2, 2, 3]) if top - self.z0 > 6 * t else 1
        # a plinth: a floor thick enough for a sliding door's track (as printed)
        floor = max(t, round_to(RAILED / self.printed + 1)) if rng.random() < 0.4 else t
        xs = split(rng, t, self.W - t, columns, t)
        zs = split(rng, self.z0 + floor, top, rows, t)
        depth = self.D - t
        for r, (z0, z1) in enumerate(zs):
            for c, (x0, x1) in enumerate(xs):
                name = "bay %d" % (len(self.bays) + 1)
                room_lo = [x0 - (t if c == 0 else t / 2) + 1, 0, z0 - (floor if r == 0 else t / 2) + 1]
                room_hi = [x1 + (t if c == columns - 1 else t / 2) - 1, 0,
                           z1 + (t if r == rows - 1 and not self.well else t / 2) - 1]
                bay = Bay(name, [x0, 0.0, z0], [x1, depth, z1], room_lo, room_hi, r, c)
                bay.edge_left, bay.edge_right = c == 0, c == columns - 1
                self.bays.append(bay)
                self.p.parts[0]["cuboids"].append(box(name, bay.lo, bay.hi, cavity=True))
        self.columns, self.rows = columns, rows


ANGLES = [90, 90, 90, 90, 100, 110, 75, 120, 60, 135]
RAILED = 4.0  # mm as printed: a sliding door's thickness and the rim it runs on, room for a slide's rails


def add_door(p, cab, bay, n):
    rng = p.rng
    lo, hi = bay.front(rng)
    td = cab.front_t
    name = p.part("door %d" % n, box("door %d" % n, [lo[0], -td, lo[1]], [hi[0], 0, hi[1]]))
    left = rng.random() < 0.5 if not (bay.edge_left or bay.edge_right) or cab.columns == 1 else bay.edge_left
    angle = rng.choice(ANGLES)
    edge = [name + ".left", name + ".near"] if left else [name + ".right", name + ".near"]
    p.joint({"name": name + " hinge", "type": "hinge", "part": name, "edge": edge},
            [(-angle if left else angle)] + ([-45 if left else 45] if rng.random() < 0.2 else []))
    p.features.add("door" if angle % 90 == 0 else "door at %d" % (angle // 10 * 10))
    cover_front(p, name, name, bay, lo, hi)
    return name


def cover_front(p, part, cuboid, bay, lo, hi):
    """The front covers its bay's opening: pairs written out, or left for the solve to infer."""
    just = abs(lo[0] - bay.lo[0]) < 1e-9 and abs(hi[0] - bay.hi[0]) < 1e-9 and \
        abs(lo[1] - bay.lo[2]) < 1e-9 and abs(hi[1] - bay.hi[2]) < 1e-9
    fields = {"covering": [part], "covered": ["carcass"]}
    if p.rng.random() < 0.6:
        fields["pairs"] = [[cuboid + ".far", bay.name + ".near"]]
    if just and p.rng.random() < 0.5:
        fields["just"] = True
        p.features.add("just cover")
    p.relate("cover", part + " covers " + bay.name, **fields)


def add_flap(p, cab, bay, n):
    rng = p.rng
    lo, hi = bay.front(rng)
    td = cab.front_t
    name = p.part("flap %d" % n, box("flap %d" % n, [lo[0], -td, lo[1]], [hi[0], 0, hi[1]]))
    down = rng.random() < 0.5
    angle = rng.choice([90, 90, 80, 100]) if down else rng.choice([90, 90, 80, 100, 110])
    edge = [name + ".bottom", name + ".near"] if down else [name + ".top", name + ".near"]
    p.joint({"name": name + " hinge", "type": "hinge", "part": name, "edge": edge}, [angle if down else -angle])
    p.features.add("flap down" if down else "flap up")
    cover_front(p, name, name, bay, lo, hi)
    return name


def add_drawer(p, cab, bay, n, pull_out=False):
    rng = p.rng
    lo, hi = bay.front(rng)
    td = cab.front_t
    name = "pull-out %d" % n if pull_out else "drawer %d" % n
    play = round_to(rng.uniform(0.5, 3))
    head = round_to((bay.hi[2] - bay.lo[2]) * (rng.uniform(0.3, 0.45) if pull_out else rng.uniform(0.05, 0.2)))
    tray_lo = [bay.lo[0] + play, 0.0, bay.lo[2]]
    tray_hi = [bay.hi[0] - play, bay.hi[1] - round_to(rng.uniform(1, 0.1 * bay.hi[1])), bay.hi[2] - head]
    wall = round_to(max(1.5, min(cab.t / 2, (tray_hi[0] - tray_lo[0]) / 6)))
    well = box(name + " well", [tray_lo[0] + wall, wall, tray_lo[2] + wall], [tray_hi[0] - wall, tray_hi[1] - wall,
                                                                                tray_hi[2]], cavity=True)
    p.part(name, box(name + " front", [lo[0], -td, lo[1]], [hi[0], 0, hi[1]]), box(name + " tray", tray_lo, tray_hi),
           well)
    depth = tray_hi[1]
    p.joint({"name": name + " slide", "type": "slide", "part": name, "axis": "y"},
            [-round_to(depth * rng.uniform(0.4, 0.9)), -round_to(depth * rng.uniform(0.2, 0.5))], group=name)
    p.relate("fit_inside", name + " fits " + bay.name, inner=[name], enclosing="carcass", cavity=bay.name,
             portion=[name + " tray"])
    p.features.add("pull-out" if pull_out else "drawer")
    cover_front(p, name, name + " front", bay, lo, hi)
    if pull_out:
        add_rack(p, name, well, head)
    return name


def add_rack(p, pull_out, well, head):
    """A rack in the pull-out's well that lifts out of it: a slide on a slide (a chain)."""
    rng = p.rng
    lo, hi = well["min"], well["max"]
    play = 0.5
    rack_lo = [lo[0] + play, lo[1] + play, lo[2]]
    rack_hi = [hi[0] - play, hi[1] - play, hi[2] - round_to(rng.uniform(0, 0.3) * (hi[2] - lo[2]))]
    name = p.part(pull_out + " rack", box(pull_out + " rack", rack_lo, rack_hi))
    lift = round_to(min(head - 1, (rack_hi[2] - rack_lo[2]) * rng.uniform(0.3, 0.8)))
    if lift < 2:
        p.parts.pop()
        return None
    p.joint({"name": name + " lift", "type": "slide", "part": name, "axis": "z", "base": pull_out}, [lift])
    p.relate("fit_inside", name + " fits " + pull_out, inner=[name], enclosing=pull_out, cavity=pull_out + " well")
    p.features.add("chain")
    return name


def add_bin(p, cab, bay, n):
    """A bin that slides out of an open bay; it fits inside the bay (whole), perhaps just across."""
    rng = p.rng
    just = rng.random() < 0.4
    play = 0.0 if just else round_to(rng.uniform(0.5, 3))
    pulled = rng.random() < 0.35
    lo = [bay.lo[0] + play, 0.0 if pulled else round_to(rng.uniform(0, 5)), bay.lo[2]]
    hi = [bay.hi[0] - play, bay.hi[1] - round_to(rng.uniform(1, 10)),
          bay.hi[2] - round_to(rng.uniform(0.05, 0.3) * (bay.hi[2] - bay.lo[2]))]
    wall = round_to(max(1.5, min(cab.t / 2, (hi[0] - lo[0]) / 6)))
    name = p.part("bin %d" % n, box("bin %d" % n, lo, hi),
                  box("bin %d well" % n, [lo[0] + wall, lo[1] + wall, lo[2] + wall], [hi[0] - wall, hi[1] - wall, hi[2]],
                      cavity=True))
    p.joint({"name": name + " slide", "type": "slide", "part": name, "axis": "y"},
            [-round_to(hi[1] * rng.uniform(0.5, 1.0) + 1)])
    fields = {"just": ["x"]} if just else {}
    p.relate("fit_inside", name + " fits " + bay.name, inner=[name], enclosing="carcass", cavity=bay.name, **fields)
    p.features.add("bin")
    if pulled:
        add_pull(p, bay, name, lo, hi)
    return name


def add_pull(p, bay, bin_, lo, hi):
    """A pull bar fixed across a bin's face, wider than its bay: it rests on the carcass' face when the bin is
    in (a toaster's knob on its lever, a drawer's stop)."""
    k = round_to(max(2, min(20, (hi[2] - lo[2]) / 4)))
    z = round_to((lo[2] + hi[2]) / 2 - k / 2)
    x0 = round_to((bay.lo[0] + bay.room_lo[0]) / 2)
    x1 = round_to((bay.hi[0] + bay.room_hi[0]) / 2)
    name = p.part(bin_ + " pull", box(bin_ + " pull", [x0, -k, z], [x1, 0, z + k]))
    p.joint({"name": name + " fixed", "type": "fixed", "part": name, "base": bin_})
    p.features.add("pull")


def add_pocket_doors(p, cab, bay, n):
    """Pocket doors (sliding hinges): one or two doors that turn into the bay and slide back into it."""
    rng = p.rng
    td = cab.front_t
    width = bay.hi[0] - bay.lo[0]
    pair = rng.random() < 0.5
    door = width / 2 if pair else width
    spare = td * td / door + 1.0  # the corner sweeps sqrt(door^2 + td^2) from the axis
    door = round_to(door - spare, 0.5)
    depth = bay.hi[1]
    if door + 5 > depth or door < 10:
        return []
    names = []
    for k, left in enumerate([True, False] if pair else [rng.random() < 0.5]):
        name = "pocket door %d%s" % (n, "ab"[k] if pair else "")
        x0 = bay.lo[0] if left else bay.hi[0] - door
        p.part(name, box(name, [x0, -td, bay.lo[2]], [x0 + door, 0, bay.hi[2]]))
        edge = [name + (".left" if left else ".right"), name + ".far"]
        slide = round_to(rng.uniform(0.3, 1.0) * (depth - door - 1))
        p.joint({"name": name + " hinge", "type": "sliding_hinge", "part": name, "edge": edge, "axis": "y"},
                [{"angle": 90 if left else -90, "offset": slide}], group="pocket %d" % n)
        p.relate("geometric", name + " as tall as " + bay.name, relation="equal", left=name + ".height",
                 right=bay.name + ".height")
        names.append(name)
    p.features.add("pocket doors" if pair else "pocket door")
    return names


def add_slider(p, cab, bay, n):
    """A sliding door that runs in a track across the front, off the carcass' side: it overlays the rims above
    and below its opening, where print-in-place puts its rails."""
    rng = p.rng
    lo, hi = bay.front(rng)
    lo[1], hi[1] = bay.room_lo[2], bay.room_hi[2]
    td = max(cab.front_t, round_to(RAILED / cab.printed))
    name = p.part("slider %d" % n, box("slider %d" % n, [lo[0], -td, lo[1]], [hi[0], 0, hi[1]]))
    width = hi[0] - lo[0]
    leftwards = bay.edge_left
    by = -(lo[0] + width + 2) if leftwards else cab.W - lo[0] + 2
    p.joint({"name": name + " track", "type": "slide", "part": name, "axis": "x"}, [round_to(by)])
    p.features.add("sliding door")
    cover_front(p, name, name, bay, lo, hi)
    # the rim its rails run on, kept as a designer keeps it: the wider one it overlays, by RAILED at least
    rail = RAILED / cab.printed
    if hi[1] - bay.hi[2] >= bay.lo[2] - lo[1]:
        p.relate("geometric", name + " rides on the rim above " + bay.name, relation="at_most",
                 left=bay.name + ".top", right=name + ".top", offset=-rail)
    else:
        p.relate("geometric", name + " rides on the rim below " + bay.name, relation="at_most",
                 left=name + ".bottom", right=bay.name + ".bottom", offset=-rail)
    return name


def add_knob(p, front, cuboid, n, along_x):
    """A knob fixed on a front, near its free edge."""
    c = p.cuboid(cuboid)
    lo, hi = c["min"], c["max"]
    k = round_to(max(2, min(25, (hi[2] - lo[2]) / 6, (hi[0] - lo[0]) / 6)))
    if along_x is None:
        x = (lo[0] + hi[0]) / 2 - k / 2
    else:
        x = hi[0] - 2 * k if along_x == "right" else lo[0] + k
    z = (lo[2] + hi[2]) / 2 - k / 2
    name = p.part("knob %d" % n, box("knob %d" % n, [x, lo[1] - k, z], [x + k, lo[1], z + k]))
    p.joint({"name": name + " fixed", "type": "fixed", "part": name, "base": front})
    p.features.add("knob")
    return name


def add_lid(p, cab):
    """A lid over the top well, hinged at the back, perhaps folding in two (its front half on its back half)."""
    rng = p.rng
    t = cab.front_t
    z = cab.z0 + cab.H
    fold = rng.random() < 0.4
    y_mid = round_to(cab.D * rng.uniform(0.35, 0.5))
    lid_lo = [0.0, y_mid if fold else 0.0, z]
    name = p.part("lid", box("lid", lid_lo, [cab.W, cab.D, z + t]))
    angle = rng.choice([90, 90, 100, 110, 80])
    p.joint({"name": "lid hinge", "type": "hinge", "part": name, "edge": ["lid.far", "lid.bottom"]}, [-angle])
    covering = ["lid"]
    pairs = [["lid.bottom", "well.top"]]
    if fold:
        flap = p.part("lid flap", box("lid flap", [0, 0, z], [cab.W, y_mid, z + t]))
        p.joint({"name": "lid fold", "type": "hinge", "part": flap, "base": name, "edge": ["lid flap.far", "lid flap.top"]},
                [-180, -90])
        covering.append(flap)
        pairs.append(["lid flap.bottom", "well.top"])
        p.features.add("folding lid")
    fields = {"covering": covering, "covered": ["carcass"]}
    if rng.random() < 0.6:
        fields["pairs"] = pairs
    p.relate("cover", "lid covers the well", **fields)
    p.features.add("lid")
    return covering


def add_legs(p, cab):
    rng = p.rng
    s = round_to(max(cab.t, min(cab.W, cab.D) * rng.uniform(0.06, 0.12)))
    inset = round_to(rng.uniform(0, 2 * cab.t))
    legs = []
    for k, (x, y) in enumerate([(inset, inset), (cab.W - inset - s, inset), (inset, cab.D - inset - s),
                                (cab.W - inset - s, cab.D - inset - s)]):
        legs.append(p.part("leg %d" % (k + 1), box("leg %d" % (k + 1), [x, y, 0], [x + s, y + s, cab.z0])))
    fields = {"supporting": legs, "supported": ["carcass"]}
    if rng.random() < 0.6:
        fields["pairs"] = [["%s.top" % leg, "carcass.bottom"] for leg in legs]
    p.relate("support", "legs support the carcass", **fields)
    p.features.add("legs")
    return legs


def relate_fronts(p, fronts):
    """Fronts side by side in a row: flush, and as wide as each other where drawn so."""
    by_row = {}
    for part, cuboid, bay in fronts:
        by_row.setdefault(bay.row, []).append((part, cuboid, bay))
    for row in by_row.values():
        if len(row) < 2:
            continue
        (a, ca, _), (b, cb, _) = row[0], row[1]
        if p.rng.random() < 0.6:
            p.relate("flush", "%s flush with %s" % (a, b), faces=[ca + ".near", cb + ".near"])
        wa = p.cuboid(ca)["max"][0] - p.cuboid(ca)["min"][0]
        wb = p.cuboid(cb)["max"][0] - p.cuboid(cb)["min"][0]
        if abs(wa - wb) < 1e-9 and p.rng.random() < 0.7:
            p.relate("geometric", "%s as wide as %s" % (a, b), relation="equal", left=ca + ".width",
                     right=cb + ".width")


def cabinet(p):
    rng = p.rng
    cab = Cabinet(p)
    fronts = []  # (part, front cuboid, bay) of fronts in the carcass' face
    knobs = 0
    for n, bay in enumerate(cab.bays, 1):
        width, height = bay.hi[0] - bay.lo[0], bay.hi[2] - bay.lo[2]
        kinds = ["door", "door", "flap", "drawer", "drawer", "bin", "open"]
        if height > 2 * cab.front_t:
            kinds.append("pull-out")
        if bay.hi[1] > width / 2 + 10:
            kinds.append("pocket")
        if (bay.edge_left or bay.edge_right) and cab.columns <= 2 and \
                max(bay.lo[2] - bay.room_lo[2], bay.room_hi[2] - bay.hi[2]) >= RAILED / cab.printed:
            kinds.append("slider")
        kind = rng.choice(kinds)
        if kind == "door":
            name = add_door(p, cab, bay, n)
            fronts.append((name, name, bay))
            knob_on = (name, name)
        elif kind == "flap":
            name = add_flap(p, cab, bay, n)
            fronts.append((name, name, bay))
            knob_on = (name, name)
        elif kind in ("drawer", "pull-out"):
            name = add_drawer(p, cab, bay, n, pull_out=kind == "pull-out")
            fronts.append((name, name + " front", bay))
            knob_on = (name, name + " front")
        elif kind == "bin":
            add_bin(p, cab, bay, n)
            knob_on = None
        elif kind == "pocket":
            add_pocket_doors(p, cab, bay, n)
            knob_on = None
        elif kind == "slider":
            name = add_slider(p, cab, bay, n)
            fronts.append((name, name, bay))
            knob_on = None
        else:
            knob_on = None
        if knob_on and rng.random() < 0.3:
            knobs += 1
            joint = next(j for j in p.joints if j["part"] == knob_on[0])
            side = None
            if joint["type"] == "hinge" and joint["edge"][0].endswith((".left", ".right")):
                side = "right" if joint["edge"][0].endswith(".left") else "left"
            add_knob(p, knob_on[0], knob_on[1], knobs, side)
    relate_fronts(p, fronts)
    if cab.well:
        add_lid(p, cab)
    if cab.legs:
        add_legs(p, cab)
    if rng.random() < 0.25:
        p.locks.extend("carcass." + s for s in ("left", "right", "near", "far", "bottom", "top"))
        p.features.add("locked carcass")
    return p


# --------------------------------------------------------------------------------------------------------
# a crate: boards on links (double pivots) folding over a base


def crate(p):
    rng = p.rng
    W = round_to(rng.uniform(200, 1200))
    D = round_to(rng.uniform(1.2, 2.2) * W)
    Hb = round_to(rng.uniform(0.15, 0.35) * W)
    t = round_to(max(2.4 / min(1.0, 200 / (D + 60), 200 / W), rng.uniform(10, 30)))  # printable: as Cabinet's
    well = round_to(min(Hb / 2, rng.uniform(0.3, 0.6) * Hb))
    p.part("base", box("base", [0, 0, 0], [W, D, Hb]), box("base well", [t, t, Hb - well], [W - t, D - t, Hb], cavity=True))
    boards = []
    for end in (["head", "foot"] if rng.random() < 0.6 else [rng.choice(["head", "foot"])]):
        # the board stands at the end of the base; folded, it lies on the base's top
        height = round_to(rng.uniform(0.3, 0.45) * D)
        z0 = round_to(rng.uniform(0, 0.05) * Hb)
        if end == "head":
            lo, hi = [0, D, z0], [W, D + t, z0 + height]
            angle, pole = 90, [0, D + (z0 - Hb) / 2, (z0 + Hb) / 2]
        else:
            lo, hi = [0, -t, z0], [W, 0, z0 + height]
            angle, pole = -90, [0, -(z0 - Hb) / 2, (z0 + Hb) / 2]
        name = p.part(end + "board", box(end + "board", lo, hi))
        doubled = rng.random() < 0.6
        sides = ["left", "right"] if doubled else [rng.choice(["left", "right"])]
        for a, b in pivot_candidates(p, lo, hi, angle, pole, D, Hb):
            links = [{"name": "%s link %s" % (end, side), "type": "double_pivot", "part": name, "base": "base",
                      "pivot": ["%s.%s" % (name, side), [0 if side == "left" else W, a[0], a[1]]],
                      "base_pivot": ["base.%s" % side, [0 if side == "left" else W, b[0], b[1]]]} for side in sides]
            poses = {link["name"]: {"angle": angle, "pole": [0] + pole[1:]} for link in links}
            trial = dict(p.model, joints=links, configurations=[{"name": "fold", "poses": poses}])
            if valid(trial)[0]:
                break
        else:
            return None
        for link in links:
            p.joint(link, [poses[link["name"]]], group="fold " + end)
        boards.append(name)
        p.features.add("links doubled" if doubled else "link")
    p.relate("geometric", "boards as wide as the base", relation="equal", left=boards[0] + ".width", right="base.width")
    if len(boards) == 2 and rng.random() < 0.5:
        p.relate("geometric", "boards equally thick", relation="equal", left=boards[0] + ".depth",
                 right=boards[1] + ".depth")
    return p


def pivot_candidates(p, lo, hi, angle, pole, D, Hb):
    """Pivots on the board and on the base at equal distance from the board's pivot in both poses (the base's
    on the perpendicular bisector of the board's pivot and its folded place, within the base's side) along
    whose motion the board clears the base in the plane of the links (a quick test before the checker's)."""
    rng = p.rng
    for _ in range(3000):
        a = [(lo[1] + hi[1]) / 2, rng.uniform(lo[2], hi[2])]  # mid-thickness, where a link's pin holds
        c, s = workslike_checker.cos_sin(angle)
        v, w = a[0] - pole[1], a[1] - pole[2]
        folded = [pole[1] + c * v - s * w, pole[2] + s * v + c * w]
        mid = [(a[0] + folded[0]) / 2, (a[1] + folded[1]) / 2]
        along = [a[1] - folded[1], folded[0] - a[0]]
        k = rng.uniform(-3, 3)
        b = [mid[0] + k * along[0], mid[1] + k * along[1]]
        if 0.02 * D < b[0] < 0.98 * D and 0.05 * Hb < b[1] < 0.95 * Hb and \
                clears_in_plane(lo, hi, a, b, angle, pole, D, Hb):
            yield [round(a[0], 6), round(a[1], 6)], [round(b[0], 6), round(b[1], 6)]


def clears_in_plane(lo, hi, a, b, angle, pole, D, Hb, steps=24):
    """Whether the board's rectangle (y, z) stays clear of the base's [0, D] x [0, Hb] along the link's motion:
    the link turning about b the shorter way, the board about a by the rest of the angle."""
    def turn(point, centre, degrees):
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        v, w = point[0] - centre[0], point[1] - centre[1]
        return [centre[0] + c * v - s * w, centre[1] + s * v + c * w]
    end = turn(a, pole[1:], angle)
    link = math.degrees(math.atan2(end[1] - b[1], end[0] - b[0]) - math.atan2(a[1] - b[1], a[0] - b[0]))
    link = (link + 180.0) % 360.0 - 180.0
    corners = [[y, z] for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
    for step in range(1, steps):
        f = step / steps
        moved = [turn(turn(q, a, (angle - link) * f), b, link * f) for q in corners]
        ys, zs = [q[0] for q in moved], [q[1] for q in moved]
        if min(ys) < D - 1e-6 and max(ys) > 1e-6 and min(zs) < Hb - 1e-6:  # its box meets the base's
            # separating axes: the base's (y, z) and the board's two edge directions
            e1, e2 = [moved[2][0] - moved[0][0], moved[2][1] - moved[0][1]], [moved[1][0] - moved[0][0],
                                                                              moved[1][1] - moved[0][1]]
            base = [[0, 0], [D, 0], [0, Hb], [D, Hb]]
            apart = False
            for n in (e1, e2):
                pb = [n[0] * q[0] + n[1] * q[1] for q in moved]
                pa = [n[0] * q[0] + n[1] * q[1] for q in base]
                if max(pb) <= min(pa) + 1e-6 or max(pa) <= min(pb) + 1e-6:
                    apart = True
            if not apart:
                return False
    return True


# --------------------------------------------------------------------------------------------------------
# configurations and the whole


def configure(p, count):
    """count configurations (2 to 5), each posing some movers; every mover posed somewhere."""
    rng = p.rng
    groups = {}
    for joint, poses, group in p.movers:
        groups.setdefault(group, []).append((joint, poses))
    names = list(groups)
    rng.shuffle(names)
    configurations = [{"name": "open %d" % (k + 1), "poses": {}} for k in range(count)]
    for i, g in enumerate(names):
        chosen = {i % count} | ({rng.randrange(count)} if rng.random() < 0.4 else set())
        for k in chosen:
            for joint, poses in groups[g]:
                configurations[k]["poses"][joint] = copy.deepcopy(rng.choice(poses))
    # a chained joint is posed with its base where the base is posed somewhere (a rack lifted out of its pull-out)
    bases = {j["name"]: j.get("base") for j in p.joints}
    moving = {j["part"]: j["name"] for j in p.joints if j["type"] != "fixed"}
    for c in configurations:
        for joint in list(c["poses"]):
            base = bases.get(joint)
            if base in moving and moving[base] not in c["poses"]:
                carrier = next(poses for jn, poses, _ in p.movers if jn == moving[base])
                c["poses"][moving[base]] = copy.deepcopy(carrier[0])
    p.configurations = [c for c in configurations if c["poses"]]
    p.features.add("%d configurations" % len(p.configurations))


def valid(model):
    problems, warnings = workslike_checker.check_all(model, model)
    return not problems and not warnings, problems + warnings


def prune(p):
    """Drop what the checker finds invalid: a configuration that fails is split into one per group of movers,
    and a group that fails on its own is removed with its parts; None when nothing valid is left."""
    ok, _ = valid(p.model)
    if ok:
        return p
    configurations = []
    for c in p.configurations:
        trial = copy.copy(p)
        trial.configurations = [c]
        if valid(trial.model)[0]:
            configurations.append(c)
            continue
        for joint, pose in c["poses"].items():
            trial.configurations = [{"name": c["name"] + " " + joint, "poses": {joint: pose}}]
            if valid(trial.model)[0]:
                configurations.append(trial.configurations[0])
    p.configurations = configurations
    ok, problems = valid(p.model)
    return p if ok and configurations else None


def generate(seed, families=("cabinet", "cabinet", "cabinet", "crate")):
    """The product for a seed, valid by construction (checked), with its features."""
    for draw in range(50):
        rng = random.Random(seed * 1000 + draw)
        p = Product(seed, rng)
        family = rng.choice(families)
        made = cabinet(p) if family == "cabinet" else crate(p)
        if made is None or not p.movers:
            continue
        configure(p, rng.randint(2, 5))
        made = prune(p)
        if made is not None:
            made.redraws = draw
            made.features.add(family)
            return made
    raise RuntimeError("seed %d: no valid product in 50 draws" % seed)
