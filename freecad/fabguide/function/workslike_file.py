"""*.workslike.json ↔ FreeCAD: import builds boxes, parts, joints, configurations and relationships in a new
Mechanism; export writes the mechanism as the core reads it (docs/formats.md)."""
import json
import os

import FreeCAD

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import cuboids, references
from freecad.fabguide.function import configuration, joints, mechanism, parts, relationships


def import_model(doc, data, label="Mechanism"):
    """A Mechanism (not yet recomputed) built from a *.workslike.json dict in its normal form (read_workslike):
    every default is the core's."""
    mech = mechanism.create(doc, label)
    mech.MinimumSize = data["minimum_size"]
    mech.MinimumWall = data["minimum_wall"]
    boxes, made_parts, made_joints, made_configurations, members = {}, {}, {}, {}, []
    for p in data["parts"]:
        for c in p["cuboids"]:
            box = doc.addObject("Part::Box", "Box")
            box.Label = c["name"]  # FreeCAD may make it unique: the links hold
            cuboids.set_coordinates(box, [v for a in range(3) for v in (c["min"][a], c["max"][a])])
            boxes[c["name"]] = box
    drawn = {boxes[c["name"]].Name: c["drawn"] for p in data["parts"] for c in p["cuboids"] if "drawn" in c}
    if drawn:  # sizes a solve wrote, and what the user drew before it
        mech.Solved = json.dumps({box.Name: cuboids.coordinates(box) for box in boxes.values()})
        mech.Drawn = json.dumps(drawn)
    for p in data["parts"]:  # FreeCAD labels are unique: a part named like its box is "… part"
        taken = doc.getObjectsByLabel(p["name"])
        made_parts[p["name"]] = parts.create(
            doc, [boxes[c["name"]] for c in p["cuboids"] if not c["cavity"]],
            label=p["name"] + " part" if taken else p["name"],
            cavities=[boxes[c["name"]] for c in p["cuboids"] if c["cavity"]])
        members.append(made_parts[p["name"]])
    doc.recompute()  # the boxes' shapes, to find their edges

    def link(name):
        """"2*lid.width" in the file → (the box made for cuboid "lid", "2*width")."""
        return references.link(boxes, name, "'{}'".format(name))

    for j in data["joints"]:
        edge = None
        if "edge" in j:
            box = boxes[j["edge"][0].rsplit(".", 1)[0]]
            edge = (box, [cuboids.edge_element(box, [f.rsplit(".", 1)[1] for f in j["edge"]])])
        pivots = None
        if j["type"] == "double_pivot":
            pivots = [box_face(boxes, j[key][0]) + (FreeCAD.Vector(*j[key][1]),) for key in ("pivot", "base_pivot")]
        made_joints[j["name"]] = joints.create(doc, j["type"], made_parts[j["part"]], edge=edge, axis=j.get("axis"),
                                               base=made_parts.get(j.get("base")), label=j["name"], pivots=pivots)
        members.append(made_joints[j["name"]])
    for c in data["configurations"]:
        poses, poles = [], []
        for name, pose in c["poses"].items():
            angle, offset = (pose["angle"], pose.get("offset", 0)) if isinstance(pose, dict) else (
                (pose, 0) if joints.turns(made_joints[name]) else (0, pose))  # a double pivot's has no offset
            poses.append((made_joints[name], angle, offset))
            poles.append(FreeCAD.Vector(*pose["pole"]) if isinstance(pose, dict) and "pole" in pose
                         else FreeCAD.Vector())
        made_configurations[c["name"]] = configuration.create(doc, c["name"], poses, poles)
        members.append(made_configurations[c["name"]])
    for r in data["relationships"]:
        members.append(relationships.create(doc, r["type"], r["name"], made_configurations.get(r.get("configuration")),
                                            **relationship_fields(r, made_parts, boxes, link)))
    mech.Locks = [link(f) for f in data["locks"]]
    mech.Group = members
    return mech


def box_face(boxes, name):
    """"lid.top" in the file → (the box made for cuboid "lid", "Face6")."""
    cuboid, side = name.rsplit(".", 1)
    return boxes[cuboid], "Face{}".format(cuboids.SIDES.index(side) + 1)


def relationship_fields(r, made_parts, boxes, link):
    """The relationship object's properties from its *.workslike.json entry."""

    def pairs(r):
        """The pairs as given (none: inferred), and how far apart inferred ones may lie."""
        return dict(Pairs=[link(face) for pair in r.get("pairs", []) for face in pair], Distance=r["distance"])

    def quantities(side):
        return [link(t["quantity"] if t["times"] == 1 else "-" + t["quantity"] if t["times"] == -1
                     else "{:g}*{}".format(t["times"], t["quantity"])) for t in side]

    kind = r["type"]
    if kind == "cover":
        return dict(Covering=[made_parts[n] for n in r["covering"]], Covered=[made_parts[n] for n in r["covered"]],
                    Just=r["just"], **pairs(r))
    if kind == "support":
        return dict(Supporting=[made_parts[n] for n in r["supporting"]],
                    Supported=[made_parts[n] for n in r["supported"]], **pairs(r))
    if kind == "fit_inside":
        just = r["just"]
        each = [a for a in just if isinstance(a, dict)]  # {"part", "axes"}: that part just fits on its own
        axes = {a if isinstance(a, str) else "xyz"[cuboids.SIDES.index(a[0].rsplit(".", 1)[1]) // 2]
                for a in just if not isinstance(a, dict)} | {a for e in each for a in e["axes"]}
        return dict(Inner=[made_parts[n] for n in r["inner"]], Enclosing=made_parts[r["enclosing"]],
                    Cavity=boxes.get(r.get("cavity")), Portion=[boxes[n] for n in r["portion"]],
                    JustEach=bool(each), **{"Just" + a.upper(): True for a in axes})
    if kind == "flush":
        return dict(Faces=[box_face(boxes, n) for n in r["faces"]])
    return dict(Left=quantities(r["left"]), Right=quantities(r["right"]), Offset=r["offset"],
                Relation="Equal" if r["relation"] == "equal" else "AtMost")


def read(doc, path):
    """A Mechanism from a file the core reads first: a file it refuses is refused with its message, which
    names the field (the file's name in front); the objects follow the file's order."""
    with open(path) as f:
        try:
            data = fabguide_core.read_workslike(json.load(f))
        except ValueError as error:
            raise ValueError("{}: {}".format(os.path.basename(path), error))
    return import_model(doc, data, label=label_of(path))


def write(mech, path):
    with open(path, "w") as f:
        json.dump(mechanism.model(mech), f, indent=2)


def label_of(path):
    name = os.path.basename(path)
    return name[:-len(".workslike.json")] if name.endswith(".workslike.json") else os.path.splitext(name)[0]
