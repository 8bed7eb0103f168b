"""Zero-waste toolbar (thesis 5.1, 5.3-5.4): flat-pack designs of Part::Box boards, their design constraints
picked from edges, faces and boxes, inner and outer volumes, and Suggest. Each command is one undo step."""
import json
import os

import FreeCADGui

from freecad.fabguide import cuboids, properties
from freecad.fabguide.material import design, master_board
from freecad.fabguide.gui import editing, viewproviders
from freecad.fabguide.gui.command_base import (Command, all_in, ask_open, ask_save, present, selected, selecting,
                                              tell, the_one, transaction)
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

AXES = "xyz"


def picked():
    """(box, sub-element) for every picked box, sub-element None when the whole box is picked."""
    return [(s.Object, sub) for s in FreeCADGui.Selection.getSelectionEx() if cuboids.is_box(s.Object)
            for sub in ([n.split(".")[-1] for n in s.SubElementNames] or [None])]


def design_of(doc, box):
    """The flat-pack design `box` belongs to, or None."""
    return next((d for d in all_in(doc, design.is_design) if box in d.Group), None)


def edge_length(box, element):
    """"Box.size.z" for an edge of a box running along z."""
    sides = cuboids.edge_sides(box, element)
    axis = ({0, 1, 2} - {cuboids.SIDES.index(s) // 2 for s in sides}).pop()
    return "{}.size.{}".format(box.Label, AXES[axis])


def length(box, ref):
    """The present value of a "Box.size.x" reference."""
    return getattr(box, cuboids.SIZES[AXES.index(ref[-1])]).Value


def face_position(box, element):
    """"Box.max.x" for the right face of a box."""
    index = cuboids.SIDES.index(cuboids.side_of(box, element))
    return "{}.{}.{}".format(box.Label, ("min", "max")[index % 2], AXES[index // 2])


def one_design(doc, boxes):
    """The one design all `boxes` belong to; tells the user otherwise."""
    designs = {design_of(doc, b) for b in boxes}
    if None in designs or len(designs) != 1:
        tell(translate("FabGuide", "Pick boxes of one flat-pack design (use Flat-pack Design from Boxes first)."))
        return None
    return designs.pop()


def add(doc, kind, boxes, label=None, **values):
    """Adds a constraint to the design of `boxes` as one undo step; refuses one the design breaks now."""
    target = one_design(doc, boxes)
    if target is None:
        return None
    with transaction(doc, "Add " + kind):
        obj = design.add_constraint(target, kind, label, **values)
        viewproviders.ViewProviderDesignConstraint(obj.ViewObject)
        doc.recompute()
    if design.broken(obj):
        tell(translate("FabGuide", "{} does not hold for the design as it is: {}").format(obj.Label, obj.Status))
    return obj


def the_design(doc, select):
    """The flat-pack design picked, else the document's only one; None when that is not one (the user told
    `select`, or that there is none)."""
    return the_one(doc, design.is_design, select,
                   translate("FabGuide", "There is no flat-pack design in this document yet."))


class DesignFromBoxes(Command):
    ICON, MENU = "FabGuide_FlatpackDesign.svg", QT_TRANSLATE_NOOP("FabGuide", "Flat-pack Design from Boxes")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Make a flat-pack design of the selected Part boxes (boards, their thinnest "
                                        "side the thickness), cut from the master boards selected with them, or a new "
                                        "one of their thickness; boxes drawn the same size stay so (delete the 'drawn "
                                        "equal' constraints to free them); its usage updates as you edit")
    NEEDS = selecting(cuboids.is_box)

    def run(self, doc):
        boxes = selected(cuboids.is_box)
        if not boxes:
            return tell(translate("FabGuide", "Select the Part boxes your furniture is made of first."))
        thickness = min(min(b.Length.Value, b.Width.Value, b.Height.Value) for b in boxes)
        try:
            with transaction(doc, "Flat-pack design"):
                # Its own master board unless the user picks one: a shared one changed for another design breaks it.
                masters = selected(master_board.is_master_board) or [master_board.create(doc, thickness=thickness)]
                obj = design.create(doc, boxes, masters)
                design.keep_drawn_equal(obj)
                decorate(obj)
                doc.recompute()
        except design.DesignError as error:
            return tell(str(error) + ".")
        if properties.failed(obj):
            tell("{}: {}".format(obj.Label, obj.Status or "see the report view"))


class ImportFlatpack(Command):
    ICON, MENU = "FabGuide_ImportFlatpack.svg", QT_TRANSLATE_NOOP("FabGuide", "Import Flat-pack Design")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Open a *.flatpack.json design: boxes, master boards, constraints and volumes")

    def run(self, doc):
        path = ask_open("Import flat-pack design", "Flat-pack designs (*.flatpack.json)")
        if not path:
            return
        try:
            with transaction(doc, "Import flat-pack design"):
                obj = design.from_file(doc, path)
                decorate(obj)
                doc.recompute()
        except (ValueError, RuntimeError, KeyError) as error:
            return tell(translate("FabGuide", "Cannot import {}: {}").format(os.path.basename(path), error))
        FreeCADGui.SendMsgToActiveView("ViewFit")


def decorate(obj):
    """View providers for a design and what it holds, its boxes in the board colour."""
    viewproviders.ViewProviderFlatpackDesign(obj.ViewObject)
    for box in design.boxes(obj):
        box.ViewObject.ShapeColor = viewproviders.BOARD_COLOUR
    for m in obj.MasterBoards:
        viewproviders.ViewProviderMasterBoard(m.ViewObject)
    for o in obj.Group:
        if design.is_constraint(o):
            viewproviders.ViewProviderDesignConstraint(o.ViewObject)
        elif design.is_volume(o):
            viewproviders.ViewProviderVolume(o.ViewObject)


class ExportFlatpack(Command):
    ICON, MENU = "FabGuide_ExportFlatpack.svg", QT_TRANSLATE_NOOP("FabGuide", "Export Flat-pack Design")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Write the selected design as *.flatpack.json (for `fabguide optimise` and bug "
                                        "reports)")
    NEEDS = present(design.is_design)

    def run(self, doc):
        chosen = the_design(doc, translate("FabGuide", "Select the flat-pack design to export."))
        if chosen is None:
            return
        path = ask_save("Export flat-pack design", chosen.Label + ".flatpack.json", "Flat-pack designs (*.flatpack.json)")
        if not path:
            return
        try:
            data = design.flatpack(chosen)
        except design.DesignError as error:
            return tell(str(error))
        with open(path, "w") as f:
            json.dump(data, f, indent=1)


class EdgesCommand(Command):
    """A constraint on the lengths of picked box edges."""
    KIND, LEAST = "equal", 2

    @property
    def NEEDS(self):
        return selecting(cuboids.is_box, "Edge", least=self.LEAST)

    def run(self, doc):
        edges = [(b, e) for b, e in picked() if e and e.startswith("Edge")]
        if len(edges) < self.LEAST:
            return tell((translate("FabGuide", "Pick an edge of a box for {}.") if self.LEAST == 1 else
                         translate("FabGuide", "Pick edges of boxes for {}.")).format(translate("FabGuide", self.MENU)))
        refs = [edge_length(b, e) for b, e in edges]
        self.make(doc, [b for b, _ in edges], refs)

    def make(self, doc, boxes, refs):
        add(doc, self.KIND, boxes, Refs=refs)


class EqualLengths(EdgesCommand):
    ICON, MENU = "FabGuide_EqualLengths.svg", QT_TRANSLATE_NOOP("FabGuide", "Equal Lengths")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "The picked edges of boards keep equal lengths")


class SumOfLengths(EdgesCommand):
    ICON, MENU = "FabGuide_SumOfLengths.svg", QT_TRANSLATE_NOOP("FabGuide", "Sum of Lengths")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "The lengths of the picked edges add up to the length of the last one picked")
    KIND = "sum"

    def make(self, doc, boxes, refs):
        add(doc, "sum", boxes, "Sum " + " + ".join(refs[:-1]) + " = " + refs[-1], Refs=refs[:-1], Rhs=refs[-1:])


class FixedLength(EdgesCommand):
    ICON, MENU = "FabGuide_FixedLength.svg", QT_TRANSLATE_NOOP("FabGuide", "Fixed Length")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Each picked edge keeps its present length")
    KIND, LEAST = "fixed", 1

    def make(self, doc, boxes, refs):
        for box, ref in zip(boxes, refs):
            add(doc, "fixed", [box], "Fixed " + ref, Refs=[ref], Value=length(box, ref))


class LengthRange(EdgesCommand):
    ICON, MENU = "FabGuide_LengthRange.svg", QT_TRANSLATE_NOOP("FabGuide", "Length Range")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Each picked edge may change by at most 25 % (edit Min and Max of the "
                                        "constraint)")
    KIND, LEAST = "range", 1

    def make(self, doc, boxes, refs):
        for box, ref in zip(boxes, refs):
            add(doc, "range", [box], "Range " + ref, Refs=[ref], Min=0.75 * length(box, ref), Max=1.25 * length(box, ref))


class EqualPosition(Command):
    ICON, MENU = "FabGuide_EqualPosition.svg", QT_TRANSLATE_NOOP("FabGuide", "Equal Position")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "The picked faces of boards stay level with each other (same coordinate along "
                                        "their normal)")
    NEEDS = selecting(cuboids.is_box, "Face", least=2)

    def run(self, doc):
        faces = [(b, f) for b, f in picked() if f and f.startswith("Face")]
        refs = [face_position(b, f) for b, f in faces]
        if len(faces) < 2 or len({r[-1] for r in refs}) != 1:
            return tell(translate("FabGuide", "Pick two or more parallel faces of boards for Equal Position."))
        add(doc, "equal", [b for b, _ in faces], "Level " + " = ".join(refs), Refs=refs)


class BoxesCommand(Command):
    """A constraint on picked boxes."""
    KIND, LEAST = "ground", 1

    @property
    def NEEDS(self):
        return selecting(cuboids.is_box, least=self.LEAST)

    def run(self, doc):
        boxes = list(dict.fromkeys(b for b, _ in picked()))
        if len(boxes) < self.LEAST:
            boards = "a board" if self.LEAST == 1 else "{} or more boards".format(self.LEAST)
            return tell(translate("FabGuide", "Pick {} for {}.").format(boards, self.MENU))
        self.make(doc, boxes)

    def make(self, doc, boxes):
        add(doc, self.KIND, boxes, Parts=boxes)


class Ground(BoxesCommand):
    ICON, MENU = "FabGuide_Ground.svg", QT_TRANSLATE_NOOP("FabGuide", "Ground Touching")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "The picked boards keep standing on the ground (their lowest face at the "
                                        "lowest board's level)")


class Coplanar(BoxesCommand):
    ICON, MENU = "FabGuide_Coplanar.svg", QT_TRANSLATE_NOOP("FabGuide", "Coplanar")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "The picked parallel boards stay in one plane")
    KIND, LEAST = "coplanar", 2


class Snap(BoxesCommand):
    ICON, MENU = "FabGuide_Snap.svg", QT_TRANSLATE_NOOP("FabGuide", "Snap")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Two touching boards stay touching, flush where they are flush (designs snap "
                                        "all contacts by default)")
    KIND, LEAST = "snap", 2


class Symmetric(BoxesCommand):
    ICON, MENU = "FabGuide_Symmetric.svg", QT_TRANSLATE_NOOP("FabGuide", "Symmetric")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Two boards stay mirror images about the plane midway between them (along the "
                                        "axis that separates them)")
    KIND, LEAST = "symmetric", 2

    def make(self, doc, boxes):
        a, b = boxes[:2]
        centre = [(lambda c: [(c[2 * k] + c[2 * k + 1]) / 2 for k in range(3)])(cuboids.coordinates(x)) for x in (a, b)]
        axis = max(range(3), key=lambda k: abs(centre[0][k] - centre[1][k]))
        refs = ["{}.centre.{}".format(x.Label, AXES[axis]) for x in (a, b)]
        add(doc, "symmetric", [a, b], "Symmetric " + ", ".join(refs), Refs=refs)


def add_volume(doc, target, kind, at, size, on=None):
    with transaction(doc, "Add {} volume".format(kind.lower())):
        obj = design.add_volume(target, kind, at, size, on)
        viewproviders.ViewProviderVolume(obj.ViewObject)
        doc.recompute()


class InnerVolume(Command):
    ICON, MENU = "FabGuide_InnerVolume.svg", QT_TRANSLATE_NOOP("FabGuide", "Inner Volume")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Space that must stay free, resting on the picked board (a shelf for binders); "
                                        "edit its size and place")
    NEEDS = selecting(cuboids.is_box)

    def run(self, doc):
        boxes = list(dict.fromkeys(b for b, _ in picked()))
        if len(boxes) != 1:
            return tell(translate("FabGuide", "Pick the one board the free space rests on."))
        target = one_design(doc, boxes)
        if target is None:
            return
        c = cuboids.coordinates(boxes[0])
        size = [0.6 * (c[1] - c[0]), 0.6 * (c[3] - c[2]), 100]
        at = [c[0] + 0.2 * (c[1] - c[0]), c[2] + 0.2 * (c[3] - c[2]), c[5]]
        add_volume(doc, target, "Inner", at, size, boxes[0])


class OuterVolume(Command):
    ICON, MENU = "FabGuide_OuterVolume.svg", QT_TRANSLATE_NOOP("FabGuide", "Outer Volume")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "An envelope the selected design must stay inside (its box now, 10 % larger); "
                                        "edit its size and place")
    NEEDS = present(design.is_design)

    def run(self, doc):
        target = the_design(doc, translate("FabGuide", "Select the flat-pack design."))
        if target is None:
            return
        coords = [cuboids.coordinates(b) for b in design.boxes(target)]
        if not coords:
            return tell(translate("FabGuide", "Design '{}' has no boxes to put an envelope round.").format(
                target.Label))
        low = [min(c[2 * a] for c in coords) for a in range(3)]
        high = [max(c[2 * a + 1] for c in coords) for a in range(3)]
        margin = [0.05 * (h - l) for l, h in zip(low, high)]
        at = [l - m if a < 2 else l for a, (l, m) in enumerate(zip(low, margin))]  # on the ground
        add_volume(doc, target, "Outer", at, [h - l + 2 * m if a < 2 else h - l + m
                                              for a, (l, h, m) in enumerate(zip(low, high, margin))])


class Suggest(Command):
    ICON, MENU = "FabGuide_Suggest.svg", QT_TRANSLATE_NOOP("FabGuide", "Suggest")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Search for design variations that keep your constraints and waste less "
                                        "material (or, for a design with Parameters, spreadsheet values within their "
                                        "ranges); preview and accept")
    NEEDS = present(design.is_design)

    def run(self, doc):
        target = the_design(doc, translate("FabGuide", "Select the flat-pack design."))
        if target is None:
            return
        broken = properties.failed_inputs(target)
        if broken:
            return tell(translate("FabGuide", "Design '{}': {} could not be recomputed (see the report view). Mend "
                                              "that first: Suggest would start from their last shapes.").format(
                target.Label, ", ".join(broken)))
        from freecad.fabguide.gui import suggest_panel

        try:
            self.panel = editing.show(lambda: suggest_panel.SuggestPanel(target), target.Document)  # for scripts
        except ValueError as error:  # Parameters that do not name spreadsheet aliases
            return tell(str(error))


COMMANDS = {
    "FabGuide_DesignFromBoxes": DesignFromBoxes(),
    "FabGuide_ImportFlatpack": ImportFlatpack(),
    "FabGuide_ExportFlatpack": ExportFlatpack(),
    "FabGuide_EqualLengths": EqualLengths(),
    "FabGuide_SumOfLengths": SumOfLengths(),
    "FabGuide_FixedLength": FixedLength(),
    "FabGuide_LengthRange": LengthRange(),
    "FabGuide_EqualPosition": EqualPosition(),
    "FabGuide_Symmetric": Symmetric(),
    "FabGuide_Ground": Ground(),
    "FabGuide_Coplanar": Coplanar(),
    "FabGuide_Snap": Snap(),
    "FabGuide_InnerVolume": InnerVolume(),
    "FabGuide_OuterVolume": OuterVolume(),
    "FabGuide_Suggest": Suggest(),
}
