"""Material toolbar (thesis ch. 5): master boards, boards, layout, cut sheets. Each command is one undo
step; the work itself is done by the document objects in freecad.fabguide.material."""
import os

import FreeCAD
import FreeCADGui

from freecad.fabguide import preferences, properties
from freecad.fabguide.material import board, cam, layout, master_board, techdraw
from freecad.fabguide.gui import editing, viewproviders
from freecad.fabguide.gui.command_base import Command, all_in, present, selected, selecting, tell, the_one, transaction
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate


def first_thickness(doc):
    boards = selected(board.is_board) or all_in(doc, board.is_board)
    return boards[0].Thickness.Value if boards else None  # none: the preferences' sheet thickness


def the_layout(doc, select):
    """The layout picked, else the document's only one; None when that is not one (the user told `select`, or
    that there is none)."""
    return the_one(doc, layout.is_layout, select, translate("FabGuide", "There is no layout in this document yet."))


class NewMasterBoard(Command):
    ICON, MENU = "FabGuide_MasterBoard.svg", QT_TRANSLATE_NOOP("FabGuide", "New Master Board")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Add a master board (sheet size, thickness, stock, material) to cut boards "
                                        "from")

    def run(self, doc):
        with transaction(doc, "New master board"):
            obj = master_board.create(doc, thickness=first_thickness(doc))
            viewproviders.ViewProviderMasterBoard(obj.ViewObject)
            doc.recompute()
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(obj)


class MakeBoard(Command):
    ICON, MENU = "FabGuide_Board.svg", QT_TRANSLATE_NOOP("FabGuide", "Make Board")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Make a board from each selected sketch or planar face, as thick as the master "
                                        "boards")
    NEEDS = selecting(lambda o: hasattr(o, "Shape"))

    def run(self, doc):
        picks = [(board.whole(s.Object), sub) for s in FreeCADGui.Selection.getSelectionEx()
                 for sub in (s.SubElementNames or [None]) if sub is None or board.element_name(sub).startswith("Face")]
        if not picks:
            return tell(translate("FabGuide", "Select sketches or planar faces first."))
        masters = all_in(doc, master_board.is_master_board)
        thickness = masters[0].Thickness.Value if masters else preferences.get("SheetThickness")
        makes_boards(picks, thickness)
        with transaction(doc, "Make board"):
            made = [board.create(doc, source, board.element_name(sub) if sub else None, thickness,
                                 label=source.Label + " board") for source, sub in picks]
            finish_boards(doc, made)


class BoardsFromSolids(Command):
    ICON, MENU = "FabGuide_BoardsFromSolids.svg", QT_TRANSLATE_NOOP("FabGuide", "Boards from Solids")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Turn each selected thin solid into a board, detecting its thickness and "
                                        "outline")
    NEEDS = selecting(lambda o: hasattr(o, "Shape") and not board.is_board(o))

    def run(self, doc):
        solids = list(dict.fromkeys(board.whole(o) for o in selected(
            lambda o: hasattr(o, "Shape") and o.Shape.Solids and not board.is_board(o))))
        if not solids:
            return tell(translate("FabGuide", "Select the solids of your furniture model (flat boxes, pads, "
                                              "extrusions) first."))
        makes_boards([(solid, None) for solid in solids], 0)  # a solid's thickness is its own
        with transaction(doc, "Boards from solids"):
            made = [board.create(doc, solid, label=solid.Label + " board") for solid in solids]
            finish_boards(doc, made)
            for solid in solids:
                solid.Visibility = False


class BandEdges(Command):
    ICON, MENU = "FabGuide_BandEdges.svg", QT_TRANSLATE_NOOP("FabGuide", "Band Edges")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Glue edge banding on the picked edge faces of boards (asks for the band's "
                                        "name; empty removes it)")
    NEEDS = selecting(board.is_board, "Face")
    last = "PVC 1 mm"  # the band named last, offered again

    def run(self, doc):
        from PySide import QtGui

        picks = [(s.Object, sub) for s in FreeCADGui.Selection.getSelectionEx() if board.is_board(s.Object)
                 for sub in s.SubElementNames if board.element_name(sub).startswith("Face")]
        sides = [(obj, board.side_of(obj, sub)) for obj, sub in picks]
        if not sides or not all(side for _, side in sides):
            return tell(translate("FabGuide", "Pick the edge faces of boards (their narrow sides, not the large faces) "
                                              "first."))
        band, ok = QtGui.QInputDialog.getText(FreeCADGui.getMainWindow(), translate("FabGuide", "Band Edges"),
                                              translate("FabGuide", "Band on the {} picked edge(s) (empty: "
                                                                    "none):").format(len(sides)),
                                              text=BandEdges.last)
        if not ok:
            return
        BandEdges.last = band.strip()
        with transaction(doc, "Band edges"):
            for obj, side in sides:
                setattr(obj, "Edge" + side, BandEdges.last)
            doc.recompute()
        FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide: {} on {}\n").format(
            "'{}'".format(BandEdges.last) if BandEdges.last else "no band",
            ", ".join("{} {}".format(obj.Label, side) for obj, side in sides)))


def makes_boards(picks, thickness):
    """Before anything is made: each picked (object, face or None) makes a board, or BoardError says which
    do not and why."""
    reasons = []
    for source, subelement in picks:
        try:
            board.slab_of(source, subelement, thickness, "'{}'".format(source.Label))
        except board.BoardError as error:
            reasons.append(str(error))
    if reasons:
        raise board.BoardError(translate("FabGuide", "Nothing made: {}.").format("; ".join(reasons)))


def finish_boards(doc, made):
    for obj in made:
        viewproviders.ViewProviderBoard(obj.ViewObject)
    doc.recompute()
    failed = [obj.Label for obj in made if properties.failed(obj)]
    if failed:
        FreeCAD.Console.PrintWarning(translate("FabGuide", "FabGuide: see the messages above for {}\n").format(
            ", ".join(failed)))


class MakeLayout(Command):
    ICON, MENU = "FabGuide_Layout.svg", QT_TRANSLATE_NOOP("FabGuide", "Layout")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Lay the selected (or all) boards out on the master boards and show the "
                                        "material usage")
    NEEDS = present(board.is_board)

    def run(self, doc):
        boards = selected(board.is_board) or all_in(doc, board.is_board)
        if not boards:
            return tell(translate("FabGuide", "There are no boards yet: use Boards from Solids or Make Board first."))
        with transaction(doc, "Layout"):
            masters = selected(master_board.is_master_board) or all_in(doc, master_board.is_master_board)
            if not masters:
                masters = [master_board.create(doc, thickness=boards[0].Thickness.Value)]
                viewproviders.ViewProviderMasterBoard(masters[0].ViewObject)
            obj = layout.create(doc, boards, masters)
            viewproviders.ViewProviderLayout(obj.ViewObject)
            doc.recompute()
        editing.edit(obj)


class ExportCutSheets(Command):
    ICON, MENU = "FabGuide_ExportCutSheets.svg", QT_TRANSLATE_NOOP("FabGuide", "Export Cut Sheets")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Write SVG and DXF cut sheets per master board, a CSV cut list, the shop's PDF "
                                        "report and part labels for the selected layout")
    NEEDS = present(layout.is_layout)

    def run(self, doc):
        from PySide import QtGui

        chosen = the_layout(doc, translate("FabGuide", "Select the layout to export."))
        if chosen is None:
            return
        start = os.path.dirname(doc.FileName) if doc.FileName else os.path.expanduser("~")
        folder = QtGui.QFileDialog.getExistingDirectory(FreeCADGui.getMainWindow(),
                                                        translate("FabGuide", "Folder for the cut sheets"),
                                                        start)
        if not folder:
            return
        try:
            written = layout.export_cut_sheets(chosen, folder)
        except (layout.LayoutError, ValueError, RuntimeError) as error:
            return tell(str(error))
        FreeCAD.Console.PrintMessage(translate("FabGuide", "FabGuide wrote:\n  {}\n").format("\n  ".join(written)))


class TechDrawPages(Command):
    ICON, MENU = "FabGuide_TechDrawPages.svg", QT_TRANSLATE_NOOP("FabGuide", "TechDraw Pages")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Make TechDraw pages of the selected layout's shop report: a page per master "
                                        "board (parts numbered and sized, grain, edge banding, saw cuts), then the cut "
                                        "list and the totals")
    NEEDS = present(layout.is_layout)

    def IsActive(self):
        return ExportCutSheets.IsActive(self)

    def run(self, doc):
        chosen = the_layout(doc, translate("FabGuide", "Select the layout to draw."))
        if chosen is None:
            return
        try:
            with transaction(doc, "TechDraw pages"):
                pages = techdraw.make_pages(chosen)
        except layout.LayoutError as error:
            return tell(str(error))
        pages[0].ViewObject.doubleClicked()


class MakeCamJob(Command):
    ICON, MENU = "FabGuide_CamJob.svg", QT_TRANSLATE_NOOP("FabGuide", "Make CAM Job")
    TIP = QT_TRANSLATE_NOOP("FabGuide", "Make a FreeCAD CAM job per master board of the selected layout (profiles, "
                                        "tags, dogbones, drilling, engraved labels) with your tool and post-processor, "
                                        "and write its G-code")
    NEEDS = present(layout.is_layout)

    def IsActive(self):
        return ExportCutSheets.IsActive(self)

    def run(self, doc):
        chosen = the_layout(doc, translate("FabGuide", "Select the layout to machine."))
        if chosen is None:
            return
        from freecad.fabguide.gui import cam_panel

        try:
            layout.current(chosen)
            self.panel = editing.show(lambda: cam_panel.CamJobPanel(chosen), chosen.Document)  # for scripts
        except (layout.LayoutError, cam.CamError) as error:  # in error, or no CAM workbench in this FreeCAD
            return tell(str(error))


COMMANDS = {
    "FabGuide_NewMasterBoard": NewMasterBoard(),
    "FabGuide_BoardsFromSolids": BoardsFromSolids(),
    "FabGuide_MakeBoard": MakeBoard(),
    "FabGuide_BandEdges": BandEdges(),
    "FabGuide_Layout": MakeLayout(),
    "FabGuide_ExportCutSheets": ExportCutSheets(),
    "FabGuide_TechDrawPages": TechDrawPages(),
    "FabGuide_MakeCamJob": MakeCamJob(),
}
