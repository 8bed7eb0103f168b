"""Relationship task panel: its status (conflicts in red), and for cover and support the corresponding faces
(thesis 4.3.1, 4.3.3), which the user can correct; while it is open the faces are coloured, covering or
supporting in blue, covered or supported in red."""
import os

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from freecad.fabguide import cuboids, references
from freecad.fabguide.function import mechanism, parts, relationships
from freecad.fabguide.gui import editing, resources
from freecad.fabguide.gui.function_commands import picked_elements
from freecad.fabguide.i18n import translate

BLUE, RED = (0.24, 0.49, 0.79), (0.85, 0.33, 0.31)


class FacesOfBoxes:
    """A selection gate while pairs are edited: only faces of boxes can be picked, as the pairs need."""

    def allow(self, doc, obj, sub):
        return cuboids.is_box(obj) and sub.startswith("Face")


class RelationshipPanel:
    def __init__(self, rel):
        self.rel, self.coloured, self.changes = rel, set(), []
        self.form = FreeCADGui.PySideUic.loadUi(os.path.join(resources.RESOURCES, "ui", "RelationshipPanel.ui"))
        self.form.setWindowTitle(rel.Label)
        self.status, self.pairs = self.form.status, None
        self.form.pairsBox.setVisible("Pairs" in rel.PropertiesList)
        if "Pairs" in rel.PropertiesList:
            self.pairs = self.form.pairs
            for button, slot in ((self.form.add, self.add_pair), (self.form.remove, self.remove_pair),
                                 (self.form.infer, self.infer)):
                editing.on_click(button, slot)
            self.pairs.itemChanged.connect(self.colour)
            self.gate = FacesOfBoxes()
            FreeCADGui.Selection.addSelectionGate(self.gate)
        rel.Document.openTransaction("Edit " + rel.Label)
        self.fill()

    def fill(self):
        status = self.rel.Status or "Not solved yet"
        colour = "#b22222" if status.startswith("Conflict") else "#2e7d32"
        changed = "".join("<br>{}".format(c) for c in self.changes)
        self.status.setText(translate("FabGuide", "<b style='color:{}'>{}</b>{}").format(
            colour, status, translate("FabGuide", "<br>The solve changed:{}").format(changed) if changed else ""))
        if self.pairs is not None:
            self.pairs.blockSignals(True)
            self.pairs.clear()
            for text in relationships.pair_texts(self.rel):
                item = QtGui.QListWidgetItem(text)
                item.setFlags(item.flags() | QtCore.Qt.ItemIsEditable)
                self.pairs.addItem(item)
            self.pairs.blockSignals(False)
        self.colour()

    def texts(self):
        return [self.pairs.item(i).text() for i in range(self.pairs.count())]

    def add_pair(self):
        """The two faces picked in the 3-D view, first → second, as a new pair."""
        faces = picked_elements("Face")
        if len(faces) != 2:
            self.status.setText(translate("FabGuide", "<b>Pick two faces of boxes in the 3-D view</b> (the first, then "
                                                      "the second of the pair) and press Add; {} picked.").format(
                len(faces)))
            return
        item = QtGui.QListWidgetItem(relationships.ARROW.join(cuboids.face_name(*face) for face in faces))
        item.setFlags(item.flags() | QtCore.Qt.ItemIsEditable)
        self.pairs.addItem(item)
        FreeCADGui.Selection.clearSelection()
        self.colour()

    def remove_pair(self):
        for item in self.pairs.selectedItems():
            self.pairs.takeItem(self.pairs.row(item))
        self.colour()

    def infer(self):
        self.rel.Pairs = []
        self.solve()

    def solve(self):
        """Solves the mechanism again; the panel then lists what the solve changed."""
        mechs = [m for m in self.rel.InList if mechanism.is_mechanism(m)]
        for m in mechs:  # its solve writes its Changes, an empty list when it changed nothing
            m.touch()
        self.rel.Document.recompute()
        self.changes = [c for m in mechs for c in m.Changes]
        self.fill()

    def colour(self, *args):
        """The faces of the pairs (or the parts of the relationship) in blue and red."""
        self.uncolour()
        by_label = {b.Label: b for b in self.rel.Document.Objects if cuboids.is_box(b)}
        faces = []
        if self.pairs is not None:
            for text in self.texts():
                ends = [t.strip() for t in text.split(relationships.ARROW.strip())]
                faces += [(end, colour) for end, colour in zip(ends, (BLUE, RED))]
        elif "Faces" in self.rel.PropertiesList:
            faces = [(cuboids.face_name(b, e), c) for (b, es), c in zip(self.rel.Faces, (BLUE, RED)) for e in es]
        for name, colour in faces:
            label, _, side = name.rpartition(".")
            box = by_label.get(label)
            if box is None or side not in cuboids.SIDES or box.ViewObject is None:
                continue
            colours = list(box.ViewObject.DiffuseColor)
            if len(colours) != 6:
                colours = [box.ViewObject.ShapeColor] * 6
            colours[cuboids.SIDES.index(side)] = colour
            box.ViewObject.DiffuseColor = colours
            self.coloured.add(box)
        for name, colour in (("Inner", RED), ("Enclosing", BLUE)):
            value = getattr(self.rel, name, None)
            for part in value if isinstance(value, list) else [value]:
                for box in parts.boxes(part) if part is not None else []:
                    if box.ViewObject is not None:
                        box.ViewObject.DiffuseColor = [colour] * 6
                        self.coloured.add(box)

    def uncolour(self):
        for box in self.coloured:
            try:
                box.ViewObject.DiffuseColor = [box.ViewObject.ShapeColor] * 6
            except (ReferenceError, AttributeError):
                pass
        self.coloured = set()

    def abandon(self):
        if self.pairs is not None:
            FreeCADGui.Selection.removeSelectionGate()

    def accept(self):
        if self.pairs is not None and self.texts() != relationships.pair_texts(self.rel):
            try:
                self.rel.Pairs = relationships.pair_links(self.rel, self.texts(),
                                                          references.boxes_by_label(self.rel.Document))
            except ValueError as error:  # a pair mistyped: say which, keep the panel open
                self.status.setText(translate("FabGuide", "<b style='color:#b22222'>{}</b>").format(error))
                return False
            self.solve()
        self.abandon()
        self.uncolour()
        self.rel.Document.commitTransaction()
        editing.close_panel(self.rel.Document)
        FreeCAD.Console.PrintMessage("{}: {}\n".format(self.rel.Label, self.rel.Status))
        return True

    def reject(self):
        self.abandon()
        self.uncolour()
        self.rel.Document.abortTransaction()
        self.rel.Document.recompute()
        editing.close_panel(self.rel.Document)
        return True

    def getStandardButtons(self):
        return editing.OK_CANCEL
