"""Edit mode on an object's own document. FreeCADGui.ActiveDocument can be another one: FreeCAD 1.0 re-activates
the document of the current selection after a new document is made."""
import FreeCADGui


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
