"""Suggest task panel (thesis 5.1, 5.3.3): the exploration runs in the background with a progress bar and Stop;
three suggestions appear as thumbnails (3-D view and layout) with their usage; a slider moves the design along
the chosen suggestion's path live; OK applies it as one undo step, locking the sizes of the parts ticked; "Lock
and suggest again" applies, locks and searches from there."""
import os
import tempfile
import threading

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import cuboids, messages
from freecad.fabguide.material import design, parametric
from freecad.fabguide.gui import editing, resources, viewproviders
from freecad.fabguide.i18n import translate

THUMB = QtCore.QSize(92, 70)  # two side by side fit a default-width task view
SHEET, PART, EDGE = QtGui.QColor(233, 211, 166), QtGui.QColor(61, 125, 202), QtGui.QColor(29, 63, 107)


def layout_pixmap(layout, size=THUMB):
    """The layout's master boards side by side, parts in blue, scaled into `size`."""
    boards = layout["boards"]
    gap = 10.0
    total_w = sum(b["width"] for b in boards) + gap * (len(boards) - 1)
    total_h = max(b["height"] for b in boards)
    scale = min((size.width() - 4) / total_w, (size.height() - 4) / total_h)
    pixmap = QtGui.QPixmap(size)
    pixmap.fill(QtCore.Qt.white)
    painter = QtGui.QPainter(pixmap)
    offsets, x = [], 2.0
    for b in boards:
        offsets.append(x)
        painter.fillRect(QtCore.QRectF(x, 2, b["width"] * scale, b["height"] * scale), SHEET)
        x += (b["width"] + gap) * scale
    painter.setPen(EDGE)
    for p in layout["placements"]:
        top = 2 + (boards[p["board"]]["height"] - p["y"] - p["height"]) * scale  # y up on the sheet
        rect = QtCore.QRectF(offsets[p["board"]] + p["x"] * scale, top, p["width"] * scale, p["height"] * scale)
        painter.fillRect(rect, PART)
        painter.drawRect(rect)
    painter.end()
    return pixmap


def card_text(k, suggestion, before):
    """A suggestion as a maker reads it: sheets bought, then waste against the design now."""
    change = (suggestion["waste_m2"] / before["waste_m2"] - 1) if before["waste_m2"] > 0 else 0.0
    return "{}: {} sheet(s), waste {:.2f} m² ({:+.0%})".format(k + 1, suggestion["sheets"], suggestion["waste_m2"],
                                                              change)


def driven_by_expressions(box):
    """Whether an expression sets a box's size or place: a value written there would not stay."""
    return any(path.split(".")[0].lstrip(".") in cuboids.SIZES + ("Placement",) for path, _ in box.ExpressionEngine)


def why_none(result):
    """Why no variation saved a sheet, as the core knows it (a layout attempt is not said as a proof)."""
    why = result.get("no_sheet_saved", "")
    if why == "bound":
        return translate("FabGuide", "; with every board side as short as they allow, any layout of the boards needs "
                                     "{} sheet(s)").format(result["least_sheets_bound"])
    if why == "laid_out":
        return translate("FabGuide", "; with every board as small as they allow it was laid out on {} sheet(s), though "
                                     "by their sizes they would fit on {}: more time may save one").format(
            result["least_sheets"], result["least_sheets_bound"])
    return ""


class Boxes:
    """Suggestions as boards' sizes and places (a design of boxes with constraints)."""

    background = True  # the core search runs on its own thread
    can_lock = True

    def __init__(self, obj):
        driven = [b.Label for b in design.boxes(obj) if driven_by_expressions(b)]
        if driven:
            raise ValueError(
                translate("FabGuide", "Suggest cannot change {}: their sizes or places are set by expressions. Give "
                                      "Design '{}' the spreadsheet aliases that drive them as Parameters ('Sheet.alias "
                                      "min max'), and Suggest changes those.").format(
                    ", ".join("'{}'".format(label) for label in driven), obj.Label))
        self.obj = obj
        self.start = None

    def state(self):
        self.start = design.snapshot(self.obj)  # previews move the inner volumes from here, so they come back
        return self.start["parts"]

    def search(self, progress, cancel, **options):
        problem = design.flatpack(self.obj)
        try:
            return fabguide_core.optimise(problem, progress=progress, cancel=cancel, **options)
        except fabguide_core.FormatError as error:  # said with the boxes' labels, as the design's Status says it
            raise design.DesignError(translate("FabGuide", "Design '{}': {}").format(
                self.obj.Label, messages.in_words(str(error), problem, messages.FLATPACK)))

    def path(self, suggestion):
        return [(step["parts"], step["usage"]) for step in suggestion["design"]["path"]]

    def show(self, state):
        design.write_parts(self.obj, state, self.start)

    def apply(self, state, suggestion=None):
        design.apply_parts(self.obj, state, self.start["parts"] if self.start else None, suggestion)


class Aliases:
    """Suggestions as spreadsheet values (a parametric design, thesis 5.4.2.2)."""

    background = False  # D(X) recomputes the document, which must happen on FreeCAD's thread
    can_lock = False

    def __init__(self, obj):
        self.obj = obj
        self.params = parametric.parameters(obj)

    def state(self):
        return [parametric.value(sheet, alias) for sheet, alias, _, _ in self.params]

    def search(self, progress, cancel, threads=1, **options):
        return parametric.optimise(self.obj, progress=progress, cancel=cancel, **options)

    def path(self, suggestion):
        return [(step["parameters"], step["usage"]) for step in suggestion["path"]]

    def show(self, state):
        parametric.set_values(self.obj, self.params, parametric.rounded(self.params, state), boxes_only=True)

    def apply(self, state, suggestion=None):
        parametric.set_values(self.obj, self.params, parametric.rounded(self.params, state))


class SuggestPanel:
    def __init__(self, design_obj):
        self.design = design_obj
        self.doc = design_obj.Document
        self.target = Aliases(design_obj) if design_obj.Parameters else Boxes(design_obj)
        self.original = self.target.state()
        self.closed = False
        self.result, self.error, self.thread, self.token = None, None, None, None
        self.progress = (0.0, 0.0)
        self.chosen = None
        self.form = self.build()
        self.timer = QtCore.QTimer()
        self.timer.timeout.connect(self.poll)
        if self.target.background:
            self.start()
        else:  # once the panel shows: the search then runs on FreeCAD's thread
            QtCore.QTimer.singleShot(0, self.start)

    # --- the form -------------------------------------------------------------------------------------
    def build(self):
        form = FreeCADGui.PySideUic.loadUi(os.path.join(resources.RESOURCES, "ui", "SuggestPanel.ui"))
        form.setWindowIcon(QtGui.QIcon(resources.icon("FabGuide_Suggest.svg")))
        for name in ("now", "seconds", "threads", "seed", "bar", "message", "grid", "slider", "step", "locks",
                     "again"):
            setattr(self, name, getattr(form, name))
        self.run_button, self.stop_button = form.run, form.stop
        self.now.setText(translate("FabGuide", "Usage now: {:.3f}").format(self.design.Usage))
        self.threads.setMaximum(max(1, os.cpu_count() or 1))
        self.threads.setValue(min(2, self.threads.maximum()))
        editing.on_click(self.run_button, self.start)
        editing.on_click(self.stop_button, self.stop)
        self.cards = QtGui.QButtonGroup(form)
        self.cards.setExclusive(True)
        (getattr(self.cards, "idClicked", None) or self.cards.buttonClicked[int]).connect(self.choose)
        self.slider.valueChanged.connect(self.slide)
        for box in design.boxes(self.design):
            item = QtGui.QListWidgetItem(box.Label)
            item.setFlags(item.flags() | QtCore.Qt.ItemIsUserCheckable)
            item.setCheckState(QtCore.Qt.Unchecked)
            self.locks.addItem(item)
        form.locksLabel.setVisible(self.target.can_lock)
        self.locks.setVisible(self.target.can_lock)
        editing.on_click(self.again, self.apply_and_again)
        return form

    # --- the search -----------------------------------------------------------------------------------
    def start(self):
        if self.thread and self.thread.is_alive():
            return
        self.clear_cards()
        self.result, self.error, self.progress = None, None, (0.0, self.design.Usage)
        self.token, self.stopped = fabguide_core.CancelToken(), False
        options = dict(seed=self.seed.value(), threads=self.threads.value(), time_limit=self.seconds.value())

        def work(progress):
            try:
                self.result = self.target.search(progress, self.token, **options)
            except Exception as error:  # shown to the user by poll()
                self.error = error

        self.run_button.setEnabled(False)
        self.stop_button.setEnabled(True)
        self.message.setText(translate("FabGuide", "Searching for designs that waste less..."))
        if self.target.background:
            self.thread = threading.Thread(target=work, args=(self.report,), daemon=True)
            self.thread.start()
            self.timer.start(100)
        else:
            work(self.pump)
            self.poll()

    def report(self, done, best):
        self.progress = (done, best)  # on the search's thread: poll() shows it

    def pump(self, done, best):
        """Progress of a search on FreeCAD's own thread: shown, and Stop kept clickable."""
        self.report(done, best)
        self.bar.setValue(int(100 * done))
        QtGui.QApplication.processEvents()

    def stop(self):
        if self.token:
            self.stopped = True  # by the user: its time limit ending a search is not "stopped"
            self.token.cancel()

    def wait(self):
        """Blocks until the running search ends (scripts and tests)."""
        while self.result is None and self.error is None and not (self.thread and self.thread.is_alive()):
            QtGui.QApplication.processEvents()  # a search on FreeCAD's thread starts from the event loop
        if self.thread:
            self.thread.join()
        self.poll()

    def poll(self):
        done, best = self.progress
        self.bar.setValue(int(100 * done))
        if self.thread and self.thread.is_alive():
            self.message.setText(translate("FabGuide", "Searching... best usage so far {:.3f}").format(best))
            return
        self.timer.stop()
        self.run_button.setEnabled(True)
        self.stop_button.setEnabled(False)
        if self.closed:
            return
        if self.error is not None:
            self.message.setText(translate("FabGuide", "<b>No suggestions:</b> {}").format(self.error))
        elif self.result is not None and not self.cards.buttons():
            self.show_results()

    # --- results --------------------------------------------------------------------------------------
    def clear_cards(self):
        for button in self.cards.buttons():
            self.cards.removeButton(button)
            button.deleteLater()
        self.chosen = None
        self.slider.setEnabled(False)
        self.again.setEnabled(False)

    def show_results(self):
        result = self.result
        suggestions = result["suggestions"]
        self.bar.setValue(100)
        stopped = translate("FabGuide", " (stopped)") if self.stopped else ""
        if not suggestions:
            why = why_none(result)
            self.message.setText(translate("FabGuide", "No variation of this design wastes less within its "
                                                       "constraints{}{}.").format(
                why, stopped))
            return
        self.message.setText(translate("FabGuide", "{} suggestion(s) in {:.1f} s{}. Pick one; slide along its path; OK "
                                                   "applies it.").format(
            len(suggestions), result["seconds"], stopped))
        views = self.view_thumbnails([self.target.path(s)[-1][0] for s in suggestions])
        for k, s in enumerate(suggestions):
            button = QtGui.QToolButton()
            button.setCheckable(True)
            button.setToolButtonStyle(QtCore.Qt.ToolButtonTextUnderIcon)
            icon = QtGui.QPixmap(THUMB.width() * 2 + 4, THUMB.height())
            icon.fill(QtCore.Qt.white)
            painter = QtGui.QPainter(icon)
            if views[k] is not None:
                painter.drawPixmap(0, 0, views[k])
            painter.drawPixmap(THUMB.width() + 4, 0, layout_pixmap(s["layout"]))
            painter.end()
            button.setIcon(QtGui.QIcon(icon))
            button.setIconSize(icon.size())
            button.setText(card_text(k, s, result["before"]))
            button.setToolTip(translate("FabGuide", "Suggestion {}: {} sheet(s) (now {}), waste {:.3f} m² (now "
                                                    "{:.3f}), largest offcut {:.0f} x {:.0f} mm, usage {:.3f} (now "
                                                    "{:.3f})").format(
                                  k + 1, s["sheets"], result["before"]["sheets"], s["waste_m2"],
                                  result["before"]["waste_m2"], *s["largest_offcut"], s["usage"],
                                  result["usage_before"]))
            self.cards.addButton(button, k)
            self.grid.addWidget(button, k, 0)
        self.cards.button(0).setChecked(True)
        self.choose(0)

    def view_thumbnails(self, designs):
        """The 3-D view of each suggested design (None without a 3-D view)."""
        view = getattr(FreeCADGui.getDocument(self.doc.Name), "ActiveView", None)
        if view is None or not hasattr(view, "saveImage"):
            return [None] * len(designs)
        images = []
        with tempfile.TemporaryDirectory() as folder:
            for k, parts in enumerate(designs):
                self.preview(parts)
                path = os.path.join(folder, "view{}.png".format(k))
                view.saveImage(path, THUMB.width(), THUMB.height(), "White")
                images.append(QtGui.QPixmap(path))
        self.preview(self.original)
        return images

    def choose(self, k):
        self.chosen = k
        path = self.target.path(self.result["suggestions"][k])
        self.slider.blockSignals(True)
        self.slider.setRange(0, len(path) - 1)
        self.slider.setValue(len(path) - 1)
        self.slider.blockSignals(False)
        self.slider.setEnabled(True)
        self.again.setEnabled(True)
        self.slide(len(path) - 1)

    def current(self):
        """The design (parts or parameter values) and usage at the slider's place on the chosen path."""
        return self.target.path(self.result["suggestions"][self.chosen])[self.slider.value()]

    def slide(self, _value):
        parts, usage = self.current()
        self.step.setText(translate("FabGuide", "usage {:.3f}").format(usage))
        self.preview(parts)

    def preview(self, state):
        """Shows a design in the 3-D view without touching the document's history."""
        self.target.show(state)
        FreeCADGui.updateGui()

    # --- applying -------------------------------------------------------------------------------------
    def apply(self):
        """The design at the slider as one undo step, with the ticked parts' sizes locked."""
        state, _ = self.current()
        at_end = self.slider.value() == self.slider.maximum()
        self.preview(self.original)
        self.doc.openTransaction("Accept suggestion")
        self.target.apply(state, self.result["suggestions"][self.chosen] if at_end else None)
        if self.target.can_lock:
            self.lock(state)
        self.doc.recompute()
        self.doc.commitTransaction()
        self.original = self.target.state()
        self.now.setText(translate("FabGuide", "Usage now: {:.3f}").format(self.design.Usage))

    def lock(self, parts):
        by_id = {p["id"]: p for p in parts}
        for row in range(self.locks.count()):
            item = self.locks.item(row)
            if item.checkState() != QtCore.Qt.Checked:
                continue
            box = self.doc.getObjectsByLabel(item.text())[0]
            size = design.sizes(by_id[item.text()])
            for axis in cuboids.in_plane(size):
                ref = "{}.size.{}".format(item.text(), "xyz"[axis])
                obj = design.add_constraint(self.design, "fixed", "Locked " + ref, Refs=[ref], Value=size[axis])
                viewproviders.ViewProviderDesignConstraint(obj.ViewObject)
            item.setCheckState(QtCore.Qt.Unchecked)
            FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide: locked the size of {}\n").format(box.Label))

    def apply_and_again(self):
        if self.chosen is None:
            return
        self.apply()
        self.start()

    def end_search(self):
        """Stops the search and waits for it: the panel is going."""
        self.closed = True
        self.stop()
        if self.thread:
            self.thread.join()
        self.timer.stop()  # its form goes with the panel

    def abandon(self):
        """Its document closes or changes under it: the search stops, nothing is applied or previewed."""
        self.end_search()

    def accept(self):
        self.end_search()
        if self.chosen is not None:
            self.apply()
        FreeCADGui.Control.closeDialog()
        return True

    def reject(self):
        self.end_search()
        self.preview(self.original)
        FreeCADGui.Control.closeDialog()
        return True
