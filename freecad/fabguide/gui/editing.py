"""Task panels and edit mode on an object's own document. FreeCADGui.ActiveDocument can be another one: FreeCAD 1.0
re-activates the document of the current selection after a new document is made."""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui
from freecad.fabguide.i18n import translate

# A task panel's OK and Cancel buttons as the number FreeCAD takes: PySide6 (FreeCAD 1.1) makes the flags an enum
# that int() refuses.
OK_CANCEL = QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel
OK_CANCEL = int(getattr(OK_CANCEL, "value", OK_CANCEL))


def edit(obj, mode=0):
    """Opens obj's edit mode (its view provider's setEdit: a task panel, or 1: the transform dragger)."""
    FreeCADGui.getDocument(obj.Document.Name).setEdit(obj.Name, mode)


def end_edit(doc):
    """Leaves edit mode in App document doc; True if it was in edit mode."""
    gui = FreeCADGui.getDocument(doc.Name)
    if gui is None or not gui.getInEdit():
        return False
    gui.resetEdit()
    return True


def close_panel(doc):
    """Leaves edit mode in doc if the panel came from there (its unsetEdit closes the dialog), else closes it."""
    if not end_edit(doc):
        FreeCADGui.Control.closeDialog()


def show(make, doc):
    """Makes a task panel with `make()` and shows it; it works on App document `doc`. Returns the panel, or None
    when another task panel is open (said to the user; FreeCAD shows one at a time, and the panel is not made, so
    nothing it would begin is left half done). Enter in its fields never accepts it (the panel's `enter()`, if it
    has one, runs instead: a half-typed value is not a choice). It closes when the document closes (nothing is
    left to work on) or an undo or redo changes the document under it (it would show what is no longer there);
    its `abandon()`, if it has one, stops what it runs first."""
    if FreeCADGui.Control.activeDialog():
        from freecad.fabguide.gui.command_base import tell

        tell(translate("FabGuide", "Another task panel is open: finish it with OK or Cancel first."))
        return None
    panel = make()
    panel.enter_keys = EnterKeys(panel)
    FreeCADGui.Control.showDialog(panel)
    FreeCAD.addDocumentObserver(Watch(panel, doc.Name))
    return panel


class EnterKeys(QtCore.QObject):
    """Return and Enter in a panel's fields call its `enter()` instead of reaching the task view, which would
    accept the whole panel."""

    def __init__(self, panel):
        super().__init__()
        self.panel = panel
        forms = panel.form if isinstance(panel.form, (list, tuple)) else [panel.form]
        for form in forms:
            for field in form.findChildren(QtGui.QAbstractSpinBox) + form.findChildren(QtGui.QLineEdit):
                field.installEventFilter(self)

    def eventFilter(self, watched, event):
        if event.type() == QtCore.QEvent.KeyPress and event.key() in (QtCore.Qt.Key_Return, QtCore.Qt.Key_Enter):
            getattr(self.panel, "enter", lambda: None)()
            return True
        return False


def typed(widget, kind):
    """`widget` as a `kind` (a QHeaderView, say): shiboken can hand back a wrapper of a base class (a bare QWidget)
    when it reuses the one it made for an earlier widget at the same address."""
    if isinstance(widget, kind):
        return widget
    try:
        import shiboken6 as shiboken  # FreeCAD 1.1
    except ImportError:
        import shiboken2 as shiboken
    return shiboken.wrapInstance(shiboken.getCppPointer(widget)[0], kind)


def on_click(button, slot):
    """Calls `slot` when a .ui form's `button` is clicked, whatever wrapper shiboken hands back for it (typed)."""
    typed(button, QtGui.QAbstractButton).clicked.connect(slot)


def widened(box):
    """Lets a quantity spin box take any number as it is typed, its range kept as its "limits" for `readable` to
    judge the whole value once typed: a box held to its range drops the keystroke that leaves it ("-400" shows
    -40, "1e9" shows "1e"), and a value passing through 1 on its way to "1e9" would be applied."""
    low, high = box.property("minimum"), box.property("maximum")
    box.setProperty("limits", [low, high])
    box.setProperty("minimum", -1e12 if low < 0 else low)
    box.setProperty("maximum", 1e12)
    return box


def limits(box):
    """(low, high): the range a `widened` box's value must be in."""
    return tuple(box.property("limits") or (box.property("minimum"), box.property("maximum")))


def readable(box, unit="Length"):
    """Whether a quantity spin box holds a quantity of `unit` (FreeCAD.Units' name; a plain number is in the
    box's unit) within its `limits`, or an expression (FreeCAD judges those). The box's own validity flag calls a
    plain "0.3" unfinished."""
    text = box.text().strip()
    if text.startswith("="):
        return True
    try:
        typed = FreeCAD.Units.Quantity(text)
    except ValueError:  # "1e", "abc"
        return False
    if typed.Unit not in (FreeCAD.Units.Unit(), getattr(FreeCAD.Units, unit)):  # "2 kg"
        return False
    low, high = limits(box)
    return low <= typed.Value <= high


def showing(panel):
    try:
        return bool(panel.form and panel.form.isVisible())
    except RuntimeError:  # its form is deleted: the panel closed
        return False


class Watch:
    """A document observer for one panel; it goes once the panel has closed or been closed."""

    def __init__(self, panel, name):
        self.panel, self.name = panel, name

    def slotDeletedDocument(self, doc):
        self.check(doc, closing=True)

    def slotUndoDocument(self, doc):
        self.check(doc)

    def slotRedoDocument(self, doc):
        self.check(doc)

    def check(self, doc, closing=False):
        if doc.Name != self.name:
            return
        QtCore.QTimer.singleShot(0, lambda: FreeCAD.removeDocumentObserver(self))  # not while FreeCAD calls it
        if not showing(self.panel):
            return
        getattr(self.panel, "abandon", lambda: None)()
        if closing:  # its GUI document goes with it: no edit mode to leave
            FreeCADGui.Control.closeDialog()
        else:
            close_panel(doc)
        FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide: the task panel closed: its document {}\n").format(
            translate("FabGuide", "closed") if closing else translate("FabGuide", "changed by undo or redo")))
