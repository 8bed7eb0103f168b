"""Board: a planar part of one thickness (thesis 5.2), made from a sketch or face plus a thickness, or
from a thin solid whose thickness and outline are detected. Its shape is always the flat slab; the
outline the layout packs is read from the slab's largest planar face."""
import re

import FreeCAD
import Part

from freecad.fabguide import properties
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

SAMPLING = 0.05  # mm: arcs and splines become polygons deviating at most this much (thesis 5.4.1)
ROTATIONS = ("Any", "Follow grain", "Fixed")  # Follow grain: the master board's Grain decides
SIDES = ("L1", "L2", "W1", "W2")  # *.pack.json's edge_banding: along the length at its start and end, then the width


class BoardError(ValueError):
    """A board that cannot be made; the message names the board and its source."""


class Board(properties.Proxy):
    TYPE, NOUN = "FabGuide::Board", QT_TRANSLATE_NOOP("FabGuide", "Board")
    VALID = dict(Quantity=properties.at_least(1))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLinkSub", "Source", "Board",
            QT_TRANSLATE_NOOP("App::Property", "Sketch, planar face or thin solid the board is made of"))
        add(obj, "App::PropertyLength", "Thickness", "Board",
            QT_TRANSLATE_NOOP("App::Property", "Thickness of a board made from a sketch or face (detected for a "
                                               "solid)"), 18)
        add(obj, "App::PropertyInteger", "Quantity", "Board", QT_TRANSLATE_NOOP("App::Property", "How many to cut"), 1)
        add(obj, "App::PropertyEnumeration", "Rotation", "Board",
            QT_TRANSLATE_NOOP("App::Property", "Turns allowed on the master board: any, keeping its length along the "
                                               "grain, or none"), list(ROTATIONS))
        for side, tip in zip(SIDES, (
                QT_TRANSLATE_NOOP("App::Property", "Band glued on its first long edge (e.g. 'oak 1 mm'); empty: none"),
                QT_TRANSLATE_NOOP("App::Property", "Band glued on its second long edge (e.g. 'oak 1 mm'); empty: none"),
                QT_TRANSLATE_NOOP("App::Property", "Band glued on its first short edge (e.g. 'oak 1 mm'); empty: none"),
                QT_TRANSLATE_NOOP("App::Property", "Band glued on its second short edge (e.g. 'oak 1 mm'); empty: "
                                                   "none"))):  # Band Edges sets them from picked faces
            add(obj, "App::PropertyString", "Edge" + side, "Edge banding", tip, "")
        add(obj, "App::PropertyLength", "OutlineWidth", "Outline",
            QT_TRANSLATE_NOOP("App::Property", "Longest side of the outline's box"), mode=1)
        add(obj, "App::PropertyLength", "OutlineHeight", "Outline",
            QT_TRANSLATE_NOOP("App::Property", "Other side of the outline's box"), mode=1)

    def recompute(self, obj):
        slab, thickness = make_slab(obj)
        # During a recompute FreeCAD moves an assigned shape to the object's Placement: the board sits
        # where its source is, so it takes the slab's placement first.
        obj.Placement = slab.Placement
        obj.Shape = slab
        if abs(obj.Thickness.Value - thickness) > 1e-9:
            obj.Thickness = thickness
        outline = outline_of(slab)
        xs = [p[0] for p in outline["outline"]]
        ys = [p[1] for p in outline["outline"]]
        obj.OutlineWidth, obj.OutlineHeight = max(xs) - min(xs), max(ys) - min(ys)


def create(doc, source, subelement=None, thickness=18, label="Board"):
    """A board from `source` (a sketch, a solid, or with `subelement` 'FaceN' a planar face of it)."""
    obj = doc.addObject("Part::FeaturePython", "Board")
    obj.Label = label
    Board(obj)
    obj.Source = (source, [subelement] if subelement else [])
    obj.Thickness = thickness
    return obj


def is_board(obj):
    return properties.is_a(obj, Board)


def element_name(name):
    """'Face3' from a selection sub-element name, also FreeCAD 1.0's mapped ';g543;…F.Face3'."""
    match = re.search(r"(Face\d+)$", name)
    return match.group(1) if match else name


def make_slab(obj):
    """(slab solid, thickness) for a board, or BoardError naming the board and its source."""
    if obj.Source is None:
        raise BoardError(translate("FabGuide", "Board '{}': no Source (select a sketch, a planar face or a thin "
                                               "solid)").format(obj.Label))
    source, subs = obj.Source
    return slab_of(source, subs[0] if subs else None, obj.Thickness.Value,
                   "Board '{}' (source '{}')".format(obj.Label, source.Label))


def slab_of(source, subelement, thickness, what):
    """(slab solid, thickness) of a board made from `source` (with `subelement`, a face of it), or BoardError
    saying why it makes none, beginning with `what`."""
    if not subelement and isinstance(getattr(source, "Proxy", None), properties.Proxy):  # a layout, a board
        raise BoardError(translate("FabGuide", "{}: is FabGuide's {}, not a part of your model (pick a sketch, a "
                                               "planar face or a thin solid)").format(
            what, translate("FabGuide", source.Proxy.NOUN)))
    shape = getattr(source, "Shape", None)
    if shape is None or shape.isNull():
        raise BoardError(translate("FabGuide", "{}: the source has no shape").format(what))
    if subelement:
        face = shape.getElement(element_name(subelement))
        return extrude(face, thickness, what), thickness
    if shape.Solids:
        if len(shape.Solids) > 1:
            raise BoardError(translate("FabGuide", "{}: the source holds {} solids; make one board per solid").format(
                what, len(shape.Solids)))
        thickness = slab_thickness(shape.Solids[0], what)
        return shape.Solids[0].copy(), thickness
    closed = [wire for wire in shape.Wires if wire.isClosed()]
    if not closed:
        raise BoardError(translate("FabGuide", "{}: needs closed wires, a planar face or a solid").format(what))
    if Part.Compound(closed).findPlane() is None:
        raise BoardError(translate("FabGuide", "{}: its closed wires do not lie in one plane, so they do not outline a "
                                               "board").format(what))
    try:
        face = Part.makeFace(closed, "Part::FaceMakerBullseye")
    except Part.OCCError as error:
        raise BoardError(translate("FabGuide", "{}: its wires do not make a planar face ({})").format(what, error))
    return extrude(face, thickness, what), thickness


def extrude(face, thickness, what):
    if not is_planar(face):
        raise BoardError(translate("FabGuide", "{}: the face is not planar").format(what))
    if thickness <= 0:
        raise BoardError(translate("FabGuide", "{}: Thickness must be greater than 0").format(what))
    return face.extrude(face.normalAt(0, 0) * thickness)


def is_planar(face):
    return face.Surface.TypeId == "Part::GeomPlane"


def largest_planar_face(shape):
    faces = [f for f in shape.Faces if is_planar(f)]
    return max(faces, key=lambda f: f.Area) if faces else None


def whole(obj):
    """What a click on `obj` means as a board's source: a PartDesign feature stands for its Body (the Body's solid
    is its tip's; a link to a feature inside a Body from outside it is out of scope for FreeCAD)."""
    body = obj.getParentGeoFeatureGroup() if hasattr(obj, "getParentGeoFeatureGroup") else None
    return body if body is not None and body.TypeId == "PartDesign::Body" else obj


def slab_thickness(solid, what):
    """Distance between the solid's largest planar face and the parallel face opposite it; the solid
    must be that face swept straight through (a flat board), else BoardError."""
    top = largest_planar_face(solid)
    if top is None:
        raise BoardError(translate("FabGuide", "{}: has no planar face, so it is not a flat board").format(what))
    normal = top.normalAt(0, 0)
    opposite = [f for f in solid.Faces if is_planar(f) and f.normalAt(0, 0).dot(normal) < -1 + 1e-9
                and abs(f.Area - top.Area) <= 1e-6 * top.Area]
    if not opposite:
        raise BoardError(translate("FabGuide", "{}: no face parallel and opposite to its largest face, so it is not a "
                                               "flat board")
                         .format(what))
    thickness = abs((opposite[0].CenterOfMass - top.CenterOfMass).dot(normal))
    if abs(solid.Volume - top.Area * thickness) > 1e-3 * solid.Volume:
        raise BoardError(translate("FabGuide", "{}: is not a flat board of one thickness (volume {:.1f} mm3, face x "
                                               "thickness {:.1f} mm3)")
                         .format(what, solid.Volume, top.Area * thickness))
    width = narrowest(solid)
    if thickness >= width - 1e-6:
        raise BoardError(translate("FabGuide", "{}: is {:.0f} mm thick and {:.0f} mm wide, a block or a post rather "
                                               "than a board (a board is thinner than it is wide)").format(
            what, thickness, width))
    return thickness


def narrowest(slab):
    """The slab's face's narrower extent, along its frame (frame_of): its width."""
    face, origin, u, v = frame_of(slab)
    points = face.OuterWire.discretize(Number=64)
    return min(max(p.sub(origin).dot(axis) for p in points) - min(p.sub(origin).dot(axis) for p in points)
               for axis in (u, v))


def frame_of(slab):
    """(face, origin, u, v) of a slab: its largest face, u along that face's longest straight outer edge,
    v such that u x v points into the slab (thesis 5.2's part frame)."""
    face = largest_planar_face(slab)
    normal = face.normalAt(0, 0)
    if (slab.CenterOfMass - face.CenterOfMass).dot(normal) < 0:
        normal = -normal  # point into the slab
    lines = [e for e in face.OuterWire.Edges if e.Curve.TypeId == "Part::GeomLine"]
    if lines:
        longest = max(lines, key=lambda e: e.Length)
        u = longest.Vertexes[-1].Point - longest.Vertexes[0].Point
    else:
        u = normal.cross(FreeCAD.Vector(0, 0, 1))
        if u.Length < 1e-9:
            u = FreeCAD.Vector(1, 0, 0)
    u.normalize()
    return face, face.OuterWire.Vertexes[0].Point, u, normal.cross(u)


def outline_of(slab):
    """The slab's outline in its frame (frame_of), with the frame: {'outline': [[x, y]...], 'holes': [...],
    'origin', 'u', 'v'} in mm."""
    face, origin, u, v = frame_of(slab)

    def polygon(wire):
        points = wire.discretize(Deflection=SAMPLING)
        if len(points) > 1 and (points[0] - points[-1]).Length < 1e-9:
            points = points[:-1]
        return [[(p - origin).dot(u), (p - origin).dot(v)] for p in points]

    holes = [polygon(w) for w in face.Wires if not w.isSame(face.OuterWire)]
    return {"outline": polygon(face.OuterWire), "holes": holes, "origin": list(origin), "u": list(u), "v": list(v)}


def as_board3(obj, part_id):
    """The board in 3-D for the connectors: outline in its frame, the frame, its thickness."""
    return dict(outline_of(obj.Shape), id=part_id, thickness=obj.Thickness.Value)


def packing_of(obj):
    """How the board is packed, as *.pack.json part fields (its shape comes from the connectors' pieces);
    Follow grain leaves the turns to each master board's grain."""
    banding = {side: getattr(obj, "Edge" + side, "") for side in SIDES}
    return {"quantity": obj.Quantity, "orientations": [0] if obj.Rotation == "Fixed" else [0, 90, 180, 270],
            "follow_grain": obj.Rotation == "Follow grain", "thickness": obj.Thickness.Value,
            "edge_banding": {side: band for side, band in banding.items() if band}}


def side_of(obj, face_name):
    """The side (SIDES) of the board's outline a face of its slab lies on, or None for its two large faces."""
    slab = obj.Shape
    face = slab.getElement(element_name(face_name))
    outline = outline_of(slab)
    origin, u, v = (FreeCAD.Vector(*outline[k]) for k in ("origin", "u", "v"))
    if abs(face.normalAt(0, 0).dot(u.cross(v))) > 1e-6:
        return None  # the top or bottom face
    xs = [p[0] for p in outline["outline"]]
    ys = [p[1] for p in outline["outline"]]
    centre = face.CenterOfMass - origin
    x, y = centre.dot(u), centre.dot(v)
    distances = {"L1": abs(y - min(ys)), "L2": abs(y - max(ys)), "W1": abs(x - min(xs)), "W2": abs(x - max(xs))}
    return min(distances, key=distances.get)
