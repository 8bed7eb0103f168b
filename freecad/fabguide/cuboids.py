"""Native Part::Box objects as the core's axis-aligned cuboids (thesis 4.1.1): their coordinates, their faces
and edges by name, and writing solved coordinates back."""
import FreeCAD
from freecad.fabguide.i18n import translate

SIDES = ("left", "right", "near", "far", "bottom", "top")  # Part::Box Face1..Face6, x y z low/high
SIZES = ("Length", "Width", "Height")  # along x, y, z


class CuboidError(ValueError):
    """A box FabGuide cannot use as a cuboid; the message names it."""


def is_box(obj):
    return getattr(obj, "TypeId", "") == "Part::Box"


def coordinates(box):
    """[left, right, near, far, bottom, top] of an axis-aligned Part::Box."""
    placement = FreeCAD.Placement(box.Placement)  # a copy: Rotation.isSame on the property touches the box
    if not placement.Rotation.isSame(FreeCAD.Rotation(), 1e-9):
        raise CuboidError(translate("FabGuide", "'{}' is rotated: FabGuide parts are axis-aligned boxes (reset its "
                                                "Placement rotation; joints turn parts in configurations)").format(
            box.Label))
    base = placement.Base
    sizes = [getattr(box, s).Value for s in SIZES]
    if not all(abs(v) < 1e100 for v in list(base) + sizes):  # nan or inf, set from a script
        raise CuboidError(translate("FabGuide", "'{}': its Length, Width, Height and Placement must be finite "
                                                "numbers").format(box.Label))
    return [c for a in range(3) for c in (base[a], base[a] + sizes[a])]


def in_plane(sizes):
    """A board's two in-plane axes, x before y before z: all but the axis of its thinnest side."""
    thin = sizes.index(min(sizes))
    return [a for a in range(3) if a != thin]


def set_coordinates(box, values, tolerance=1e-9):
    """Moves and sizes the box to [left, right, near, far, bottom, top]; returns whether anything changed."""
    current = coordinates(box)
    if all(abs(a - b) <= tolerance for a, b in zip(current, values)):
        return False
    for a, size in enumerate(SIZES):
        setattr(box, size, values[2 * a + 1] - values[2 * a])
    box.Placement = FreeCAD.Placement(FreeCAD.Vector(values[0], values[2], values[4]), FreeCAD.Rotation())
    return True


def place(box, values):
    """set_coordinates, and when the box changed its shape at once (within the recompute that moved it), not
    marked touched; returns whether it changed."""
    if not set_coordinates(box, values):
        return False
    box.recompute()
    box.purgeTouched()
    return True


def change(label, before, after, tolerance=1e-6):
    """What a solve did to a box, [left, right, near, far, bottom, top] `before` → `after`, as the user reads
    it: "Lid: Length 120 → 115 mm, moved -2.5 mm along x"; "" when nothing changed."""
    said = []
    for a, size in enumerate(SIZES):
        was, now = before[2 * a + 1] - before[2 * a], after[2 * a + 1] - after[2 * a]
        if abs(now - was) > tolerance:
            said.append("{} {:g} → {:g} mm".format(size, round(was, 4), round(now, 4)))
    moved = [(after[2 * a] - before[2 * a], "xyz"[a]) for a in range(3)]
    said += ["moved {:+g} mm along {}".format(round(d, 4), axis) for d, axis in moved if abs(d) > tolerance]
    return "{}: {}".format(label, ", ".join(said)) if said else ""


def face_name(box, element):
    """"Face6" of a box → "Box.top" (the core's face name)."""
    if not element.startswith("Face") or not 1 <= int(element[4:]) <= 6:
        raise CuboidError(translate("FabGuide", "'{}.{}' is not a face of the box").format(box.Label, element))
    return "{}.{}".format(box.Label, SIDES[int(element[4:]) - 1])


def side_of(box, element):
    return face_name(box, element).rsplit(".", 1)[1]


def edge_sides(box, element):
    """"Edge3" → the two sides whose faces meet there, e.g. ("left", "far"), from where the edge lies."""
    if not element.startswith("Edge"):
        raise CuboidError(translate("FabGuide", "'{}.{}' is not an edge of the box").format(box.Label, element))
    centre = box.Shape.getElement(element).CenterOfMass
    bounds, sides = coordinates(box), []
    for a in range(3):
        for high in (0, 1):
            if abs(centre[a] - bounds[2 * a + high]) < 1e-6 * max(1.0, abs(bounds[2 * a + high])):
                sides.append(SIDES[2 * a + high])
    if len(sides) != 2:
        raise CuboidError(translate("FabGuide", "'{}.{}' is not an edge of the box").format(box.Label, element))
    return tuple(sides)


def edge_element(box, sides):
    """The "EdgeN" where the faces of two sides meet (inverse of edge_sides)."""
    for n in range(1, len(box.Shape.Edges) + 1):
        if set(edge_sides(box, "Edge{}".format(n))) == set(sides):
            return "Edge{}".format(n)
    raise CuboidError(translate("FabGuide", "'{}' has no edge between its {} and {} faces").format(box.Label, *sides))
