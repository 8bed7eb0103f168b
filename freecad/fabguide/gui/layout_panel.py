"""Task panel of a Layout: the material usage, live, and the cutting settings (thesis 5.1: the
material-space view updates as the design changes)."""
import os

import FreeCADGui
from PySide import QtCore

from freecad.fabguide import properties
from freecad.fabguide.gui import editing, resources
from freecad.fabguide.i18n import translate

SETTINGS = ("Kerf", "Spacing", "Trim")
PAUSE = 700  # ms without a change before the layout is made again: not on every keystroke


class LayoutPanel:
    def __init__(self, layout):
        self.layout = layout
        self.form = FreeCADGui.PySideUic.loadUi(os.path.join(resources.RESOURCES, "ui", "LayoutPanel.ui"))
        self.form.setWindowIcon(FreeCADGui.getIcon(resources.icon("FabGuide_Layout.svg")))
        layout.Document.openTransaction("Edit layout")
        self.pending = QtCore.QTimer()
        self.pending.setSingleShot(True)
        self.pending.setInterval(PAUSE)
        self.pending.timeout.connect(self.lay_out)
        self.bindings, self.typed_from = [], {}  # typed_from: each setting before this bout of typing
        for name in SETTINGS:  # quantity spin boxes in mm that take expressions (=), bound to the layout's lengths
            box = editing.widened(getattr(self.form, name.lower()))  # its range judged when typing pauses
            box.setProperty("rawValue", getattr(layout, name).Value)
            binding = FreeCADGui.ExpressionBinding(box)
            binding.bind(layout, name)
            binding.setAutoApply(True)
            self.bindings.append(binding)
            box.valueChanged.connect(lambda *_, name=name, box=box: self.set(name, box.property("rawValue")))
            box.textChanged.connect(lambda *_: self.pending.start())  # "1e9" is 1 on its way: judged at the pause
        for name, combo in (("Cuts", self.form.cuts), ("FirstCut", self.form.firstCut)):
            combo.addItems(layout.getEnumerationsOfProperty(name))
            combo.setCurrentText(getattr(layout, name))
            combo.currentTextChanged.connect(lambda text, name=name: self.set(name, text))
        self.form.stages.setValue(layout.Stages)
        self.form.stages.valueChanged.connect(lambda value: self.set("Stages", value))
        self.form.commonLine.setChecked(layout.CommonLine)
        self.form.commonLine.toggled.connect(lambda on: self.set("CommonLine", on))
        self.show()

    def set(self, name, value):
        """The setting at once; the layout made again once the typing pauses."""
        current = properties.number(getattr(self.layout, name))
        if (abs(current - value) > 1e-12 if isinstance(value, float) else current != value):
            self.typed_from.setdefault(name, current)
            setattr(self.layout, name, value)
            self.pending.start()
            self.form.message.setText(translate("FabGuide", "<i>The layout is made again when you pause.</i>"))

    def lay_out(self):
        """Once the typing pauses: a value typed out of range or unreadable is refused whole (the keystrokes on
        its way had set 1 of "1e9"), the setting back to what it was, said; then the layout made again."""
        self.pending.stop()
        if not editing.showing(self):  # closed meanwhile (its fields change as they go)
            return
        refused = [self.refuse(name) for name in SETTINGS
                   if not editing.readable(getattr(self.form, name.lower()))]
        self.typed_from = {}
        self.layout.Document.recompute()
        self.show()
        if refused:
            self.form.message.setText("<b>{}</b>".format(" ".join(refused)))

    def refuse(self, name):
        box = getattr(self.form, name.lower())
        kept = self.typed_from.get(name, getattr(self.layout, name).Value)
        said = translate("FabGuide", "{}: \"{}\" is not a length from {:g} to {:g} mm; it stays {:g} mm.").format(
            name, box.text(), *editing.limits(box), kept)
        setattr(self.layout, name, kept)
        box.setProperty("rawValue", kept)
        return said

    def enter(self):
        """Enter in a field: lay out now (the panel stays open)."""
        self.lay_out()

    def show(self):
        """The layout's figures, or why it could not be made."""
        layout, form = self.layout, self.form
        if properties.failed(layout):
            form.message.setText(translate("FabGuide", "<b>The layout could not be made:</b> {}").format(
                getattr(layout, "Error", "") or translate("FabGuide", "see the report view")))
            return
        form.message.setText("")
        form.usage.setText("{:.1%}".format(layout.Usage))
        form.utilisation.setText("{:.1%}".format(layout.SheetUtilisation))
        form.waste.setText("{:.3f} m²".format(layout.WasteArea.Value / 1e6))
        form.sheets.setText(str(layout.SheetCount))
        guillotine = layout.Cuts.startswith("Guillotine")
        form.sawCuts.setText("{}, {:.1f} m".format(layout.SawCuts, layout.SawCutLength.Value / 1000)
                             if guillotine else "-")
        form.cutLength.setText("-" if guillotine else translate("FabGuide", "{:.1f} m").format(
            layout.CutLength.Value / 1000) + (translate("FabGuide", " ({:.1f} m shared, cut once)").format(
                layout.CommonLineLength.Value / 1000) if layout.CommonLine else ""))
        form.stages.setEnabled(guillotine)
        form.firstCut.setEnabled(guillotine)
        form.commonLine.setEnabled(not guillotine)

    def abandon(self):
        self.pending.stop()

    def accept(self):
        if self.pending.isActive():
            self.lay_out()
        self.layout.Document.commitTransaction()
        editing.end_edit(self.layout.Document)
        return True

    def reject(self):
        self.pending.stop()
        document = self.layout.Document
        document.abortTransaction()
        document.recompute()
        editing.end_edit(document)
        return True

