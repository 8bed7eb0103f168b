"""Task panel of Make CAM Job: the user's tool bit, post-processor, feed and spindle speed per material (each
remembered), how far the profiles cut into the spoilboard, and where the G-code goes. OK
makes one CAM job per master board of the layout (one undo step) and posts each; a refusal is said in the panel,
which stays open to change what it names."""
import json
import os

import FreeCAD
import FreeCADGui

from freecad.fabguide import preferences
from freecad.fabguide.material import cam, layout
from freecad.fabguide.gui import editing, resources
from freecad.fabguide.gui.command_base import transaction
from freecad.fabguide.i18n import translate

PROFILE_SHAPES = ("endmill.fcstd", "bullnose.fcstd")  # bits that cut a flat-bottomed profile


class CamJobPanel:
    def __init__(self, lay):
        self.layout = lay
        self.form = FreeCADGui.PySideUic.loadUi(os.path.join(resources.RESOURCES, "ui", "CamJobPanel.ui"))
        self.form.setWindowIcon(FreeCADGui.getIcon(resources.icon("FabGuide_CamJob.svg")))
        for name, path in cam.library_bits().items():
            if shape_of(path) in PROFILE_SHAPES:
                self.form.bit.addItem(os.path.splitext(name)[0].replace("_", " "), path)
        self.form.bit.setCurrentIndex(max(0, self.form.bit.findData(cam.library_bits().get(cam.BITS["end mill"]))))
        self.form.post.addItems(cam.post_processors())
        self.form.post.setCurrentText("grbl")
        self.materials = cam.materials(lay)
        self.show_speeds()
        self.form.through.setValue(cam.THROUGH)
        doc = lay.Document
        self.form.folder.setText(os.path.dirname(doc.FileName) if doc.FileName else os.path.expanduser("~"))
        editing.on_click(self.form.browseBit, self.browse_bit)
        editing.on_click(self.form.browseFolder, self.browse_folder)

    def show_speeds(self):
        """A row per material: its feed and spindle speed, as last used for it."""
        from PySide import QtGui

        table = self.form.speeds
        table.setRowCount(len(self.materials))
        table.setVerticalHeaderLabels(self.materials)
        self.boxes = []  # [feed, spindle] per row, held here: cellWidget() may give back a bare QWidget
        for row, material in enumerate(self.materials):
            speeds = preferences.cam_speeds(material, (cam.FEED, cam.SPINDLE))
            self.boxes.append([])
            for column, (value, least, most, step) in enumerate(zip(speeds, (10, 0), (50000, 60000), (100, 1000))):
                box = QtGui.QDoubleSpinBox()  # the unit is the column's: a narrow panel shows the whole number
                box.setDecimals(0)
                box.setRange(least, most)
                box.setSingleStep(step)
                box.setValue(value)
                table.setCellWidget(row, column, box)
                self.boxes[row].append(box)
        across, down = (editing.typed(h, QtGui.QHeaderView) for h in (table.horizontalHeader(), table.verticalHeader()))
        across.setSectionResizeMode(QtGui.QHeaderView.Stretch)  # no scrolling sideways
        table.setFixedHeight(across.sizeHint().height() + down.length() + 2 * table.frameWidth())  # as tall as its rows

    def speeds(self, column):
        """{material: value} of the table's `column` (0 feed, 1 spindle speed)."""
        return {m: self.boxes[row][column].value() for row, m in enumerate(self.materials)}

    def browse_bit(self):
        from PySide import QtGui

        path = QtGui.QFileDialog.getOpenFileName(self.form, translate("FabGuide", "Tool bit"), os.path.expanduser("~"),
                                                 translate("FabGuide", "FreeCAD tool bits (*.fctb)"))[0]
        if path:
            self.form.bit.addItem(os.path.basename(path), path)
            self.form.bit.setCurrentIndex(self.form.bit.count() - 1)

    def browse_folder(self):
        from PySide import QtGui

        folder = QtGui.QFileDialog.getExistingDirectory(self.form, translate("FabGuide", "Folder for the G-code"),
                                                    self.form.folder.text())
        if folder:
            self.form.folder.setText(folder)

    def accept(self):
        lay, doc = self.layout, self.layout.Document
        feeds, spindles = self.speeds(0), self.speeds(1)
        try:
            with transaction(doc, "Make CAM Job"):
                jobs = cam.make_jobs(lay, bit=self.form.bit.currentData(), post=self.form.post.currentText(),
                                     feed=feeds, spindle=spindles,
                                     through=self.form.through.value())
            written = (cam.write_gcode(jobs, self.form.folder.text(), layout.file_stem(lay.Label))
                       if self.form.gcodeBox.isChecked() else [])
        except (cam.CamError, layout.LayoutError, OSError) as error:
            self.form.message.setText(translate("FabGuide", "<b>No CAM job made:</b> {}").format(error))
            FreeCAD.Console.PrintWarning(translate("FabGuide", "FabGuide: {}\n").format(error))
            return False
        for material in self.materials:
            preferences.remember_cam_speeds(material, feeds[material], spindles[material])
        FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide: {} CAM job(s) for '{}'{}\n").format(
            len(jobs), lay.Label, "; wrote:\n  " + "\n  ".join(written) if written else ""))
        FreeCADGui.Control.closeDialog()
        return True

    def reject(self):
        FreeCADGui.Control.closeDialog()
        return True


def shape_of(bit_file):
    try:
        with open(bit_file) as source:
            return os.path.basename(json.load(source).get("shape", ""))
    except (OSError, ValueError):
        return ""
