"""Task panels and edit mode on an object's own document. FreeCADGui.ActiveDocument can be another one: FreeCAD 1.0
re-activates the document of the current selection after a new document is made."""
import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

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


def show(panel, doc):
    """Shows task panel `panel`, which works on App document `doc`. It closes when the document closes (nothing is
    left to work on) or an undo or redo changes the document under it (it would show what is no longer there);
    its `abandon()`, if it has one, stops what it runs first."""
    FreeCADGui.Control.showDialog(panel)
    FreeCAD.addDocumentObserver(Watch(panel, doc.Name))


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
        FreeCAD.Console.PrintMessage("FabGuide: the task panel closed: its document {}\n".format(
            "closed" if closing else "changed by undo or redo"))
