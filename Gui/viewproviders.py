"""View providers of FabGuide's document objects: icons, colours, and the task panels they open."""
import FreeCADGui

from fabguide import properties
from fabguide_gui import resources

SHEET_COLOUR = (0.91, 0.83, 0.65)  # the master boards in a layout: raw wood
PART_COLOUR = (0.24, 0.49, 0.79)   # the parts laid out on them
BOARD_COLOUR = (0.85, 0.70, 0.45)


class ViewProvider(properties.Stateless):
    """Shows an icon; holds no state, so saving stores nothing."""

    ICON = "FabGuide.svg"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return resources.icon(self.ICON)


class EditedByDoubleClick:
    """Mixin for view providers whose setEdit opens a task panel."""

    def doubleClicked(self, vobj):
        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name)
        return True



class ViewProviderMasterBoard(ViewProvider):
    ICON = "FabGuide_MasterBoard.svg"


class ViewProviderBoard(ViewProvider):
    ICON = "FabGuide_Board.svg"

    def attach(self, vobj):
        super().attach(vobj)
        vobj.ShapeColor = BOARD_COLOUR


class ViewProviderLayout(EditedByDoubleClick, ViewProvider):
    """Sheets in wood colour, parts in blue; double-click opens the layout's task panel."""

    ICON = "FabGuide_Layout.svg"

    def updateData(self, obj, prop):
        if prop == "Shape":
            # FreeCAD's Part view provider resets the face colours after this call when the number of
            # faces changes, so colour the faces once it is done.
            from PySide import QtCore

            QtCore.QTimer.singleShot(0, lambda: colour_layout(obj))

    def setEdit(self, vobj, mode=0):
        from fabguide_gui.layout_panel import LayoutPanel

        FreeCADGui.Control.showDialog(LayoutPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        FreeCADGui.Control.closeDialog()
        return True


def colour_layout(obj):
    """Master boards in wood colour (the first SheetCount faces), parts in blue."""
    try:
        shape, view, sheets = obj.Shape, obj.ViewObject, obj.SheetCount
    except ReferenceError:  # deleted (undone) before the timer fired
        return
    if view and not shape.isNull():
        view.DiffuseColor = [SHEET_COLOUR] * sheets + [PART_COLOUR] * (len(shape.Faces) - sheets)
