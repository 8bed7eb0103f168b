"""FabGuide in German: with FreeCAD's language set to German before the workbench first loads, its
toolbars, drop-down buttons, commands and their tips, what a command tells the user, task panels and property
tooltips come from Resources/translations/FabGuide_de.qm; screenshots of the German workbench at 1366 and 1920 px."""
import os

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import guitest


def the_toolbars_and_commands_speak_german():
    Gui.setLocale("German")
    Gui.activateWorkbench("FabGuideWorkbench")
    guitest.settle(0.3)
    window = Gui.getMainWindow()
    titles = {bar.objectName(): bar.windowTitle() for bar in window.findChildren(QtGui.QToolBar)}
    assert (titles.get("Function"), titles.get("Zero waste")) == ("Funktion", "Kein Verschnitt"), titles
    texts = {action.text() for action in window.findChildren(QtGui.QAction)}
    for german in ("Platte erstellen", "Zuschnitt", "Scharnier hinzufügen", "Gelenke", "Vorschlagen"):
        assert german in texts, (german, sorted(t for t in texts if t)[:40])
    tips = {action.toolTip() for action in window.findChildren(QtGui.QAction)}
    assert any(t.startswith("Aus jeder gewählten Skizze oder ebenen Fläche eine Platte") for t in tips)
    for path in guitest.screenshots_at_screen_sizes("german"):
        print("screenshot: " + path)


def a_mistake_is_told_in_german():
    doc = guitest.new_document("Deutsch")
    empty = doc.addObject("Part::Feature", "Empty")
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(empty)
    said = guitest.told("FabGuide_BoardsFromSolids")
    assert said == ("Wählen Sie zuerst die Körper Ihres Möbelmodells (flache Quader, Aufpolsterungen, "
                    "Extrusionen)."), said
    FreeCAD.closeDocument(doc.Name)


def panels_and_property_tooltips_speak_german():
    # A task panel as FreeCAD loads it (its texts translated in the .ui's own context), and a property's tooltip
    # as the property editor asks for it.
    from freecad.fabguide.gui import resources
    panel = Gui.PySideUic.loadUi(os.path.join(resources.RESOURCES, "ui", "LayoutPanel.ui"))
    assert (panel.usageBox.title(), panel.commonLine.text()) == ("Materialnutzung",
                                                                 "Gemeinsame Linien einmal schneiden")
    assert QtCore.QCoreApplication.translate("App::Property", "Width of the cut") == "Breite des Schnitts"
    Gui.setLocale("English")


guitest.run([
    the_toolbars_and_commands_speak_german,
    a_mistake_is_told_in_german,
    panels_and_property_tooltips_speak_german,
])
