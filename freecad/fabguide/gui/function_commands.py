"""Function toolbar (thesis ch. 4): parts from boxes, joints, relationships, solve, configurations, and
*.workslike.json import/export. Commands read the 3-D selection; each is one undo step; the document objects in
freecad.fabguide.function do the work."""
import os

import FreeCAD
import FreeCADGui

from freecad.fabguide import cuboids
from freecad.fabguide.function import joints, mechanism, parts, printable, relationships, workslike_file
from freecad.fabguide.gui import editing, function_viewproviders as vp
from freecad.fabguide.gui.command_base import (Command, all_in, ask_open, ask_save, both, present, selected, selecting,
                                              tell, the_one, transaction)
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate


def picks():
    """[(object, element name or None)] in the order the user picked them."""
    return [(s.Object, sub or None) for s in FreeCADGui.Selection.getSelectionEx()
            for sub in (s.SubElementNames or [None])]


def mechanism_for(doc, objs=()):
    """The mechanism holding any of `objs`, else the document's only one, else a new one."""
    for m in all_in(doc, mechanism.is_mechanism):
        if any(o in m.Group for o in objs):
            return m
    existing = all_in(doc, mechanism.is_mechanism)
    if len(existing) == 1:
        return existing[0]
    return vp.attach(mechanism.create(doc))


def part_of(doc, box):
    """The box's FabGuide part, made (with a mechanism to hold it) if the box has none yet."""
    part = parts.part_of(doc.Objects, box)
    if part is None:
        part = vp.attach(parts.create(doc, [box]))
        add_to(mechanism_for(doc), part)
    return part


def add_to(mech, obj):
    if obj not in mech.Group:
        mech.Group = mech.Group + [obj]
    return obj


def picked_elements(kind):
    """Picked faces or edges of boxes: [(box, "Face3")]."""
    return [(o, e) for o, e in picks() if cuboids.is_box(o) and e and e.startswith(kind)]


def picked_parts(doc):
    """The parts of the picked boxes, in picking order, each once."""
    found = []
    for obj, _ in picks():
        part = obj if parts.is_part(obj) else part_of(doc, obj) if cuboids.is_box(obj) else None
        if part is not None and part not in found:
            found.append(part)
    return found


def finish(doc, obj, mech):
    """Recompute and say what the mechanism made of it."""
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    FreeCAD.Console.PrintMessage("{}: {}\n".format(mech.Label, mech.Status))


def usable(boxes):
    """The boxes, each checked to be one FabGuide can solve (CuboidError naming one that is rotated)."""
    for box in boxes:
        cuboids.coordinates(box)
    return boxes


def the_mechanism(doc, select):
    """The mechanism picked, else the document's only one; None when that is not one (the user told `select`, or
    that there is none)."""
    return the_one(doc, mechanism.is_mechanism, select,
                   translate("FabGuide", "There is no mechanism in this document yet."))


class NewMechanism(Command):
    ICON, MENU = "FabGuide_Mechanism.svg", QT_TRANSLATE_NOOP("FabGuide", "Mechanism from Boxes")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Make a mechanism; each selected box (Part::Box) becomes one of its parts")
    NEEDS = selecting(cuboids.is_box)

    def run(self, doc):
        boxes = usable([o for o in selected(cuboids.is_box) if parts.part_of(doc.Objects, o) is None])
        if not boxes:
            return tell(translate("FabGuide", "Every picked box is already in a part: pick boxes that are not."))
        with transaction(doc, "New mechanism"):
            mech = vp.attach(mechanism.create(doc))
            mech.Group = [vp.attach(parts.create(doc, [b])) for b in boxes]
            finish(doc, mech, mech)


class MakePart(Command):
    ICON, MENU = "FabGuide_Part.svg", QT_TRANSLATE_NOOP("FabGuide", "Part from Boxes")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Make one part of the selected boxes: they move together")
    NEEDS = selecting(cuboids.is_box)

    def run(self, doc):
        boxes = usable(selected(cuboids.is_box))
        if not boxes:
            return tell(translate("FabGuide", "Select the boxes (Part::Box) the part is made of."))
        owned = [b.Label for b in boxes if parts.part_of(doc.Objects, b)]
        if owned:
            return tell(translate("FabGuide", "Already in a part: {}").format(", ".join(owned)))
        with transaction(doc, "Part from boxes"):
            part = add_to(mechanism_for(doc), vp.attach(parts.create(doc, boxes)))
            finish(doc, part, mechanism_for(doc, [part]))


class MakeCavity(Command):
    ICON, MENU = "FabGuide_Cavity.svg", QT_TRANSLATE_NOOP("FabGuide", "Cavity")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Select a box of a part, then boxes to cut out of it: openings and "
                                        "compartments")
    NEEDS = selecting(cuboids.is_box, least=2)

    def run(self, doc):
        boxes = selected(cuboids.is_box)
        if len(boxes) < 2:
            return tell(translate("FabGuide", "Select a box of the part first, then the boxes that are cavities in "
                                              "it."))
        owned = [b.Label for b in boxes[1:] if parts.part_of(doc.Objects, b)]
        if owned:
            return tell(translate("FabGuide", "Already in a part: {}").format(", ".join(owned)))
        with transaction(doc, "Cavity"):
            part = part_of(doc, boxes[0])
            part.Cavities = part.Cavities + boxes[1:]
            for b in boxes[1:]:
                vp.style_cavity(b)
            finish(doc, part, mechanism_for(doc, [part]))



def already_moved(doc, box, kind):
    """Why the part of `box` can take no `kind` joint (a part is moved by one joint, or by double pivots side by
    side), or None. A part riding on another by a fixed joint picked the wrong way round is said so."""
    part = parts.part_of(doc.Objects, box)
    moving = [j for j in all_in(doc, joints.is_joint) if part is not None and j.Part == part and
              not (kind == joints.kind(j) == "double_pivot")]
    if not moving:
        return None
    joint = moving[0]
    if joints.kind(joint) == "fixed" and kind != "fixed":
        return translate("FabGuide", "'{0}' rides on '{1}' by the fixed joint '{2}', and a part is moved by one "
                                     "joint: add this joint to '{1}' (they move together), or delete the fixed "
                                     "joint and hold '{1}' on '{0}' instead.").format(
            part.Label, joint.Base.Label, joint.Label)
    if kind == "fixed":
        return translate("FabGuide", "'{}' is already moved by joint '{}' (a part is moved by one joint): pick the "
                                     "part to hold first, then the part it rides on.").format(part.Label, joint.Label)
    return translate("FabGuide", "'{}' is already moved by joint '{}' (a part is moved by one joint).").format(
        part.Label, joint.Label)


class AddJoint(Command):
    """Hinge: pick an edge; slide: a face (its normal is the direction); sliding hinge: an edge and a face.
    A box of another part picked too is the joint's base (it carries the joint)."""

    KIND = None

    def run(self, doc):
        chosen = picks()
        edges, faces = picked_elements("Edge") if self.KIND != "slide" else [], picked_elements("Face")
        if self.KIND != "slide" and len(edges) != 1:
            return tell(translate("FabGuide", "Pick the one edge of a box the {} turns about.").format(
                self.MENU.lower()[4:]))
        if self.KIND != "hinge" and not faces:
            return tell(translate("FabGuide", "Pick a face of a box: the part slides along its normal."))
        mover = (edges or faces)[0][0]
        if said := already_moved(doc, mover, self.KIND):
            return tell(said)
        with transaction(doc, self.MENU):
            part = part_of(doc, mover)
            bases = [part_of(doc, o) for o, _ in chosen if cuboids.is_box(o) and part_of(doc, o) is not part]
            axis = "xyz"[cuboids.SIDES.index(cuboids.side_of(*faces[-1])) // 2] if faces and self.KIND != "hinge" else None
            joint = vp.attach(joints.create(doc, self.KIND, part, edge=(edges[0][0], [edges[0][1]]) if edges else None,
                                            axis=axis, base=bases[0] if bases else None))
            mech = mechanism_for(doc, [part])
            add_to(mech, joint)
            finish(doc, joint, mech)


class AddHinge(AddJoint):
    ICON, MENU, KIND = "FabGuide_Hinge.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Hinge"), "hinge"
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick an edge of a box: its part turns about it (and a box of another part it "
                                        "hangs on, if any)")
    NEEDS = selecting(cuboids.is_box, "Edge")


class AddSlide(AddJoint):
    ICON, MENU, KIND = "FabGuide_Slide.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Slide"), "slide"
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick a face of a box: its part slides along the face's normal")
    NEEDS = selecting(cuboids.is_box, "Face")


class AddSlidingHinge(AddJoint):
    ICON, MENU, KIND = "FabGuide_SlidingHinge.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Sliding Hinge"), "sliding_hinge"
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick an edge and a face of a box: its part turns about the edge, which slides "
                                        "along the face's normal")
    NEEDS = both(selecting(cuboids.is_box, "Edge"), selecting(cuboids.is_box, "Face"))


class AddDoublePivot(Command):
    ICON, MENU = "FabGuide_DoublePivot.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Double Pivot")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick a point on a face of the moving part's box, then one on the face of the "
                                        "part it links to, in the same plane: a rigid link joins them (the solve "
                                        "places both pivots)")
    NEEDS = selecting(cuboids.is_box, "Face", least=2)

    def run(self, doc):
        points = [(s.Object, sub, point) for s in FreeCADGui.Selection.getSelectionEx() if cuboids.is_box(s.Object)
                  for sub, point in zip(s.SubElementNames, s.PickedPoints) if sub.startswith("Face")]
        if len(points) != 2 or points[0][0] is points[1][0]:
            return tell(translate("FabGuide", "Pick a point on a face of the moving part's box, then one on the face "
                                              "of the part it links to."))
        if said := already_moved(doc, points[0][0], "double_pivot"):
            return tell(said)
        with transaction(doc, self.MENU):
            part, base = part_of(doc, points[0][0]), part_of(doc, points[1][0])
            joint = vp.attach(joints.create(doc, "double_pivot", part, base=base, pivots=points))
            mech = mechanism_for(doc, [part])
            add_to(mech, joint)
            finish(doc, joint, mech)


class AddFixedJoint(Command):
    ICON, MENU = "FabGuide_Fixed.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Fixed Joint")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick a box of the part to hold, then a box of the part it rides on: it moves "
                                        "with that part and prints as one body with it")
    NEEDS = selecting(cuboids.is_box, least=2)

    def run(self, doc):
        boxes = [o for o, _ in picks() if cuboids.is_box(o)]
        if len(boxes) != 2:
            return tell(translate("FabGuide", "Pick a box of the part to hold, then a box of the part it rides on."))
        owners = [parts.part_of(doc.Objects, b) for b in boxes]
        if boxes[0] is boxes[1] or (owners[0] is not None and owners[0] is owners[1]):
            return tell(translate("FabGuide", "Both boxes are in one part: pick a box of the part to hold, then one of "
                                              "another part."))
        if owners[0] is not None and owners[1] is not None and rides_on(doc, owners[1], owners[0]):
            return tell(translate("FabGuide", "'{}' already rides on '{}': pick the part to hold first, then the part "
                                              "it rides on.")
                        .format(owners[1].Label, owners[0].Label))
        if said := already_moved(doc, boxes[0], "fixed"):
            return tell(said)
        with transaction(doc, self.MENU):
            part, base = part_of(doc, boxes[0]), part_of(doc, boxes[1])
            joint = vp.attach(joints.create(doc, "fixed", part, base=base,
                                            label="{} on {}".format(part.Label, base.Label)))
            mech = mechanism_for(doc, [part, base])
            add_to(mech, joint)
            finish(doc, joint, mech)


def rides_on(doc, part, base):
    """Whether `part` hangs on `base` through its joints, directly or through parts between (picking a fixed
    joint the other way round would close a loop)."""
    hanging = {j.Part: j.Base for j in all_in(doc, joints.is_joint) if j.Base is not None}
    seen = set()
    while part in hanging and part.Name not in seen:
        seen.add(part.Name)
        part = hanging[part]
        if part == base:
            return True
    return False


class AddRelationship(Command):
    """Pick boxes of the parts in order; the last picked is the covered / enclosing / supported part. The
    relationship holds in the configuration the mechanism shows (see Configurations)."""
    KIND = None
    NEEDS = selecting(lambda o: cuboids.is_box(o) or parts.is_part(o), least=2)

    def check(self):
        """What is wrong with the selection, or None."""
        boxes = {o.Name for o, _ in picks() if cuboids.is_box(o) or parts.is_part(o)}
        if len(boxes) < 2:
            return translate("FabGuide", self.TOO_FEW)

    def run(self, doc):
        mistake = self.check()
        if mistake:
            return tell(mistake)
        with transaction(doc, self.MENU):
            found = picked_parts(doc)
            mech = mechanism_for(doc, found)
            fields = self.fields(doc, found)
            rel = vp.attach(relationships.create(doc, self.KIND, self.MENU[4:], mech.ShownConfiguration, **fields))
            add_to(mech, rel)
            finish(doc, rel, mech)
        if rel.Status != mechanism.SATISFIED:
            tell("{}: {}".format(rel.Label, rel.Status or mech.Status))


class AddCover(AddRelationship):
    ICON, MENU, KIND = "FabGuide_Cover.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Cover"), "cover"
    TOO_FEW = QT_TRANSLATE_NOOP("FabGuide", "Pick boxes of at least two parts; the last one picked is the covered "
                                            "part.")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "These parts cover that one (picked last): faces in one plane, packed, "
                                        "covering its faces or openings")

    def fields(self, doc, found):
        return {"Covering": found[:-1], "Covered": found[-1:]}


def portion(inner):
    """The boxes that must fit (thesis 4.2.2's partial fit) when a box was picked of a part of several, as picked:
    the tray of a drawer, not its front; every box of the other inner parts. Empty (the whole parts) otherwise."""
    picked = [o for o, _ in picks()[:-1]]
    boxes = [o for o in picked if cuboids.is_box(o)]
    partial = [p for p in inner if p not in picked and set(p.Cuboids) - set(boxes) and set(p.Cuboids) & set(boxes)]
    if not partial:
        return []
    return [b for p in inner for b in p.Cuboids if p not in partial or b in boxes]


class AddFitInside(AddRelationship):
    ICON, KIND = "FabGuide_FitInside.svg", "fit_inside"
    TOO_FEW = QT_TRANSLATE_NOOP("FabGuide", "Pick boxes of at least two parts; the last one picked is the enclosing "
                                            "part.")
    MENU = QT_TRANSLATE_NOOP("FabGuide", "Add Fit Inside")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "These parts fit inside that one (picked last; pick one of its cavities to fit "
                                        "in it)")

    def fields(self, doc, found):
        last = picks()[-1][0]
        cavity = last if any(last in p.Cavities for p in found[-1:]) else None
        return {"Inner": found[:-1], "Enclosing": found[-1], "Cavity": cavity, "Portion": portion(found[:-1])}


class AddSupport(AddRelationship):
    ICON, KIND = "FabGuide_Support.svg", "support"
    TOO_FEW = QT_TRANSLATE_NOOP("FabGuide", "Pick boxes of at least two parts; the last one picked is the supported "
                                            "part.")
    MENU = QT_TRANSLATE_NOOP("FabGuide", "Add Support")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "These parts support that one (picked last): it rests on their tops; they "
                                        "stand on one ground")

    def fields(self, doc, found):
        return {"Supporting": found[:-1], "Supported": found[-1:]}


class AddFlush(AddRelationship):
    ICON, MENU, KIND = "FabGuide_Flush.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Flush"), "flush"
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick two faces of boxes: they lie in one plane")
    NEEDS = selecting(cuboids.is_box, "Face", least=2)

    def check(self):
        faces = picked_elements("Face")
        if len(faces) != 2:
            return translate("FabGuide", "Pick exactly two faces of boxes.")
        if faces[0][0] == faces[1][0]:
            return translate("FabGuide", "Pick faces of two different boxes: two faces of one box never lie in one "
                                         "plane.")

    def fields(self, doc, found):
        return {"Faces": picked_elements("Face")}


class AddGeometric(AddRelationship):
    ICON, MENU, KIND = "FabGuide_Geometric.svg", QT_TRANSLATE_NOOP("FabGuide", "Add Geometric"), "geometric"
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pick two edges of boxes: their lengths stay equal (one edge: its length stays "
                                        "as it is now)")
    NEEDS = selecting(cuboids.is_box, "Edge")

    def check(self):
        if len(picked_elements("Edge")) not in (1, 2) or any(not (e or "").startswith("Edge") for _, e in picks()):
            return translate("FabGuide", "Pick one or two edges of boxes, and nothing else (a face or a whole box says "
                                         "no length).")

    def fields(self, doc, found):
        edges = picked_elements("Edge")
        sizes = []
        for box, edge in edges:
            along = set("xyz") - {"xyz"[cuboids.SIDES.index(s) // 2] for s in cuboids.edge_sides(box, edge)}
            sizes.append((box, {"x": "width", "y": "depth", "z": "height"}[along.pop()]))
        if len(sizes) == 2:
            return {"Left": sizes[:1], "Right": sizes[1:]}
        return {"Left": sizes, "Right": [], "Offset": edges[0][0].Shape.getElement(edges[0][1]).Length}


class Solve(Command):
    ICON, MENU = "FabGuide_Solve.svg", QT_TRANSLATE_NOOP("FabGuide", "Solve")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Solve the selected (or every) mechanism: the least change that makes its "
                                        "relationships hold")
    NEEDS = present(mechanism.is_mechanism)

    def run(self, doc):
        mechs = selected(mechanism.is_mechanism) or all_in(doc, mechanism.is_mechanism)
        if not mechs:
            return tell(translate("FabGuide", "There is no mechanism yet: use Mechanism from Boxes first."))
        with transaction(doc, "Solve"):
            for m in mechs:
                m.touch()
            doc.recompute()
        for m in mechs:
            FreeCAD.Console.PrintMessage("{}: {}\n".format(m.Label, m.Status))


class Configurations(Command):
    ICON, MENU = "FabGuide_Configurations.svg", QT_TRANSLATE_NOOP("FabGuide", "Configurations")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Pose the joints: name configurations and move the mechanism between them")
    NEEDS = present(mechanism.is_mechanism)

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and bool(all_in(FreeCAD.ActiveDocument, mechanism.is_mechanism))

    def run(self, doc):
        mech = the_mechanism(doc, translate("FabGuide", "Select the mechanism to pose."))
        if mech is not None:
            editing.edit(mech)


class ImportWorkslike(Command):
    ICON, MENU = "FabGuide_Import.svg", QT_TRANSLATE_NOOP("FabGuide", "Import Works-like Model")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Build a mechanism from a *.workslike.json file")

    def run(self, doc):
        path = ask_open("Works-like model", "Works-like models (*.workslike.json)")
        if path:
            with transaction(doc, "Import works-like model"):
                mech = import_file(doc, path)
            FreeCADGui.SendMsgToActiveView("ViewFit")
            FreeCAD.Console.PrintMessage("{}: {}\n".format(mech.Label, mech.Status))


def import_file(doc, path):
    """Imports, attaches view providers, solves."""
    mech = workslike_file.read(doc, path)
    for obj in [mech] + mech.Group:
        vp.attach(obj)
        for box in parts.boxes(obj) if parts.is_part(obj) else []:
            if box in obj.Cavities:
                vp.style_cavity(box)
    doc.recompute()
    return mech


class ExportWorkslike(Command):
    ICON, MENU = "FabGuide_Export.svg", QT_TRANSLATE_NOOP("FabGuide", "Export Works-like Model")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Write the selected mechanism as a *.workslike.json file (the CLI's fabguide "
                                        "solve reads it)")
    NEEDS = present(mechanism.is_mechanism)

    def IsActive(self):
        return Configurations.IsActive(self)

    def run(self, doc):
        mech = the_mechanism(doc, translate("FabGuide", "Select the mechanism to export."))
        if mech is None:
            return
        path = ask_save("Works-like model", mech.Label + ".workslike.json", "Works-like models (*.workslike.json)")
        if path:
            try:
                workslike_file.write(mech, path)
            except ValueError as error:
                return tell(str(error))
            FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide wrote {}\n").format(path))


class MakePrintable(Command):
    ICON, MENU = "FabGuide_Printable.svg", QT_TRANSLATE_NOOP("FabGuide", "Make Printable")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Print-in-place bodies of the selected (or only) mechanism: gaps, cavities, "
                                        "hinge pins and yokes, pivot links; checked along every motion")
    NEEDS = present(mechanism.is_mechanism)

    def IsActive(self):
        return Configurations.IsActive(self)

    def run(self, doc):
        mech = the_mechanism(doc, translate("FabGuide", "Select the mechanism to print."))
        if mech is None:
            return
        existing = [p for p in all_in(doc, printable.is_printable) if p.Mechanism == mech]
        with transaction(doc, self.MENU):
            made = existing[0] if existing else vp.attach(printable.create(doc, mech))
            added = printable.sync(made) if existing else [c for c in made.Group]
            vp.colour_bodies(made, added)
            mech.ViewObject.Visibility = False
            doc.recompute()
        if not made.Error:  # a failure or a cancel was said by the recompute
            FreeCAD.Console.PrintMessage(translate("FabGuide", "{}: least clearance {:.3f} mm ({})\n").format(
                made.Label, made.MinimumClearance.Value, made.ClearanceAt))


class ExportPrintable(Command):
    ICON, MENU = "FabGuide_ExportPrintable.svg", QT_TRANSLATE_NOOP("FabGuide", "Export Printable")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Write the selected printable as STL, 3MF and STEP: the assembly and one file "
                                        "per body")
    NEEDS = present(printable.is_printable)

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and bool(all_in(FreeCAD.ActiveDocument, printable.is_printable))

    def run(self, doc):
        from PySide import QtGui

        made = the_one(doc, printable.is_printable, translate("FabGuide", "Select the printable to export."),
                        translate("FabGuide", "There is no printable in this document yet."))
        if made is None:
            return
        folder = QtGui.QFileDialog.getExistingDirectory(FreeCADGui.getMainWindow(),
                                                        translate("FabGuide", "Folder for the print files"),
                                                        os.path.expanduser("~"))
        if folder:
            doc.recompute()  # what is written is what the Printable shows, made from the mechanism as it is
            try:
                written = printable.export(made, folder)
            except (ValueError, RuntimeError) as error:
                return tell(str(error))
            FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide wrote:\n  {}\n").format("\n  ".join(written)))


COMMANDS = {
    "FabGuide_NewMechanism": NewMechanism(),
    "FabGuide_MakePart": MakePart(),
    "FabGuide_MakeCavity": MakeCavity(),
    "FabGuide_AddHinge": AddHinge(),
    "FabGuide_AddSlide": AddSlide(),
    "FabGuide_AddSlidingHinge": AddSlidingHinge(),
    "FabGuide_AddDoublePivot": AddDoublePivot(),
    "FabGuide_AddFixedJoint": AddFixedJoint(),
    "FabGuide_AddCover": AddCover(),
    "FabGuide_AddFitInside": AddFitInside(),
    "FabGuide_AddSupport": AddSupport(),
    "FabGuide_AddFlush": AddFlush(),
    "FabGuide_AddGeometric": AddGeometric(),
    "FabGuide_Solve": Solve(),
    "FabGuide_Configurations": Configurations(),
    "FabGuide_ImportWorkslike": ImportWorkslike(),
    "FabGuide_ExportWorkslike": ExportWorkslike(),
    "FabGuide_MakePrintable": MakePrintable(),
    "FabGuide_ExportPrintable": ExportPrintable(),
}
