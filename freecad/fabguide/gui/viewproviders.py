"""View providers of FabGuide's document objects: icons, colours, and the task panels they open."""
import FreeCADGui

from freecad.fabguide import properties
from freecad.fabguide.gui import editing, resources
from freecad.fabguide.material import board, design, layout, master_board

SHEET_COLOUR = (0.91, 0.83, 0.65)  # the master boards in a layout: raw wood
PART_COLOUR = (0.24, 0.49, 0.79)   # the parts laid out on them
BOARD_COLOUR = (0.85, 0.70, 0.45)


class ViewProvider(properties.Stateless):
    """Shows an icon, marked when the object's last recompute failed (its Error); holds no state, so saving
    stores nothing."""

    ICON = "FabGuide.svg"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        failed = getattr(getattr(self, "Object", None), "Error", "")
        return resources.icon("FabGuide_Error.svg") if failed else self.icon()

    def icon(self):
        return resources.icon(self.ICON)

    def updateData(self, obj, prop):
        if prop == "Error" and obj.ViewObject is not None:
            obj.ViewObject.signalChangeIcon()


class EditedByDoubleClick:
    """Mixin for view providers whose double-click opens their task panel, made by `panel_for(obj)`: one panel at a
    time, and its work (a pending layout, an animation and its preview) abandoned when edit mode ends, however it
    ends."""

    def doubleClicked(self, vobj):
        editing.edit(vobj.Object)
        return True

    def setEdit(self, vobj, mode=0):
        panel = editing.show(lambda: self.panel_for(vobj.Object), vobj.Object.Document)
        if panel is None:  # another panel is open: it stays the one shown
            return False
        self.panel = panel
        return True

    def unsetEdit(self, vobj, mode=0):
        if getattr(self, "panel", None) is not None:
            self.panel.abandon()  # also when edit mode ends without OK or Cancel
            self.panel = None
        FreeCADGui.Control.closeDialog()
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
        super().updateData(obj, prop)
        if prop == "Shape":
            # FreeCAD's Part view provider resets the face colours after this call when the number of
            # faces changes, so colour the faces once it is done.
            from PySide import QtCore

            QtCore.QTimer.singleShot(0, lambda: colour_layout(obj))

    def panel_for(self, obj):
        from freecad.fabguide.gui.layout_panel import LayoutPanel

        return LayoutPanel(obj)


def colour_layout(obj):
    """Master boards in wood colour (the first SheetCount faces), parts in blue."""
    try:
        shape, view, sheets = obj.Shape, obj.ViewObject, obj.SheetCount
    except ReferenceError:  # deleted (undone) before the timer fired
        return
    if view and not shape.isNull():
        view.DiffuseColor = [SHEET_COLOUR] * sheets + [PART_COLOUR] * (len(shape.Faces) - sheets)


# Zero-waste designs (thesis 5.1): the design group, its constraints by kind, its volumes.
CONSTRAINT_ICONS = {"equal": "FabGuide_EqualLengths.svg", "sum": "FabGuide_SumOfLengths.svg",
                    "fixed": "FabGuide_FixedLength.svg", "range": "FabGuide_LengthRange.svg",
                    "symmetric": "FabGuide_Symmetric.svg", "ground": "FabGuide_Ground.svg",
                    "coplanar": "FabGuide_Coplanar.svg", "snap": "FabGuide_Snap.svg"}
VOLUME_COLOURS = {"Inner": (0.30, 0.75, 0.35), "Outer": (0.80, 0.20, 0.20)}


class ViewProviderFlatpackDesign(ViewProvider):
    """Says the usage (or why an edit was absorbed or undone) in the status bar after every recompute, so the
    user sees it while editing boxes (thesis 5.1: the material usage is shown live)."""

    ICON = "FabGuide_FlatpackDesign.svg"

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop in ("Status", "Valid") and obj.Status:
            # After the recompute: its progress indicator clears the status bar when it ends.
            from PySide import QtCore

            message = "{}: {}".format(obj.Label, obj.Status)
            QtCore.QTimer.singleShot(0, lambda: FreeCADGui.getMainWindow().statusBar().showMessage(message, 15000))


class ViewProviderDesignConstraint(ViewProvider):
    def icon(self):
        return resources.icon(CONSTRAINT_ICONS.get(getattr(self.Object, "Kind", ""), "FabGuide.svg"))


class ViewProviderVolume(ViewProvider):
    """A see-through box: green for space kept free, red for the envelope; double-click drags it in place
    (FreeCAD's transform dragger); its Length, Width and Height are in the property view."""

    def doubleClicked(self, vobj):
        editing.edit(vobj.Object, 1)  # 1: Transform
        return True

    def icon(self):
        return resources.icon("FabGuide_InnerVolume.svg" if getattr(self.Object, "Kind", "") == "Inner"
                              else "FabGuide_OuterVolume.svg")

    def attach(self, vobj):
        super().attach(vobj)
        self.colour(vobj)

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop == "Kind":
            self.colour(obj.ViewObject)

    def colour(self, vobj):
        vobj.ShapeColor = VOLUME_COLOURS.get(getattr(vobj.Object, "Kind", "Inner"), VOLUME_COLOURS["Inner"])
        vobj.Transparency = 75


CLASSES = [(board.is_board, ViewProviderBoard), (master_board.is_master_board, ViewProviderMasterBoard),
           (layout.is_layout, ViewProviderLayout), (design.is_design, ViewProviderFlatpackDesign),
           (design.is_constraint, ViewProviderDesignConstraint), (design.is_volume, ViewProviderVolume)]
