"""Task panels close with their document and on undo, and stop what they run: no panel is left working on a closed
document, no search or timer outlives it."""
import os
import time

import FreeCAD
import FreeCADGui as Gui
from PySide import QtGui

import guitest

ROOT = os.environ["FABGUIDE_SOURCE_DIR"]


def no_panel_open():
    guitest.settle(0.3)
    return not Gui.Control.activeDialog()


def opened_layout():
    """The bundled bookshelf, saved by freecadcmd without view providers: opened, its objects get FabGuide's."""
    doc = FreeCAD.openDocument(os.path.join(ROOT, "examples", "bookshelf.FCStd"))
    lay = next(o for o in doc.Objects if hasattr(o, "LayoutJson"))
    assert type(lay.ViewObject.Proxy).__name__ == "ViewProviderLayout", lay.ViewObject.Proxy
    doc.recompute()
    Gui.setActiveDocument(doc.Name)
    lay = next(o for o in doc.Objects if hasattr(o, "LayoutJson"))
    Gui.getDocument(doc.Name).setEdit(lay.Name)
    guitest.settle(0.3)
    assert Gui.Control.activeDialog() and kerf_field(), "the layout panel is open"
    return doc, lay


def kerf_field():
    return [w for w in QtGui.QApplication.allWidgets() if w.objectName() == "kerf"]


def layout_panel_closes_with_its_document():
    doc, _ = opened_layout()
    FreeCAD.closeDocument(doc.Name)
    assert no_panel_open(), "the panel outlived its document"


def layout_panel_closes_on_undo():
    doc, lay = opened_layout()
    kerf_field()[0].setProperty("rawValue", 1.0)  # an edit in the panel's transaction, laid out after the pause
    doc.commitTransaction()
    doc.undo()
    assert no_panel_open(), "the panel shows a layout undo changed"
    assert not Gui.getDocument(doc.Name).getInEdit()
    FreeCAD.closeDocument(doc.Name)


def suggest_stops_when_its_document_closes():
    from freecad.fabguide.material import design

    Gui.activateWorkbench("FabGuideWorkbench")
    doc = guitest.new_document("Suggesting")
    design.from_file(doc, os.path.join(ROOT, "examples", "parrot-shelf.flatpack.json"))
    doc.recompute()
    Gui.runCommand("FabGuide_Suggest")
    guitest.settle(0.5)
    assert Gui.Control.activeDialog(), "the Suggest panel is open"
    from freecad.fabguide.gui import design_commands

    suggest = design_commands.COMMANDS["FabGuide_Suggest"].panel
    FreeCAD.closeDocument(doc.Name)
    end = time.monotonic() + 30  # a bound: the search stops within a step
    while suggest.thread and suggest.thread.is_alive() and time.monotonic() < end:
        guitest.settle(0.1)
    assert not (suggest.thread and suggest.thread.is_alive()), "the search outlived its document"
    assert not suggest.timer.isActive() and no_panel_open()
    guitest.settle(0.5)  # a poll timer left running would raise here, on a deleted form


guitest.run([
    layout_panel_closes_with_its_document,
    layout_panel_closes_on_undo,
    suggest_stops_when_its_document_closes,
])
