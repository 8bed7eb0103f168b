"""The FabGuide workbench loads in the real FreeCAD GUI and shows its toolbars and menus."""
import os

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import guitest

WORKBENCH = "FabGuideWorkbench"


def workbench_is_listed_with_its_icon():
    listed = Gui.listWorkbenches()
    assert WORKBENCH in listed, sorted(listed)
    assert os.path.isfile(listed[WORKBENCH].Icon), listed[WORKBENCH].Icon


def workbench_activates_with_function_and_material_toolbars():
    Gui.activateWorkbench(WORKBENCH)
    assert Gui.activeWorkbench().name() == WORKBENCH
    workbench = Gui.getWorkbench(WORKBENCH)
    assert {"Function", "Material"} <= set(workbench.listToolbars()), workbench.listToolbars()
    bars = {bar.objectName() for bar in Gui.getMainWindow().findChildren(QtGui.QToolBar) if bar.isVisible()}
    assert {"Function", "Material"} <= bars, bars


def toolbars_fit_a_1366_px_screen_and_reach_every_command():
    from freecad.fabguide.gui import commands

    window = Gui.getMainWindow()
    window.showNormal()
    window.setGeometry(0, 0, 1366, 768)
    guitest.settle(0.5)
    print("screenshot: " + guitest.screenshot("workbench_1366"))
    for title in commands.TOOLBARS:
        bar = [b for b in window.findChildren(QtGui.QToolBar) if b.objectName() == title][0]
        more = bar.findChild(QtGui.QToolButton, "qt_toolbar_ext_button")
        assert bar.isVisible() and (more is None or not more.isVisible()), title + " does not fit"
    every = set(commands.function_commands.COMMANDS) | set(commands.material_commands.COMMANDS) | set(
        commands.design_commands.COMMANDS)
    shown = {n for names in commands.TOOLBARS.values() for n in names}
    shown |= {n for name in shown & set(commands.GROUPS) for n in commands.GROUPS[name].GetCommands()}
    assert every <= shown, every - shown
    assert every <= {n for _, names in commands.MENUS for n in names}


def about_command_is_registered():
    assert "FabGuide_About" in Gui.listCommands()


def preferences_page_stores_what_new_objects_start_with():
    from freecad.fabguide import preferences

    seen = {}

    def on_the_page():  # the Preferences dialog is modal: this runs from its event loop
        dialog = QtGui.QApplication.activeModalWidget()
        if dialog is None:
            return QtCore.QTimer.singleShot(100, on_the_page)
        kerf = [w for w in dialog.findChildren(QtGui.QDoubleSpinBox) if w.objectName() == "Kerf"]
        seen["kerf"] = bool(kerf)
        if kerf:
            kerf[0].setValue(0.35)
            seen["screenshot"] = guitest.screenshot("preferences", dialog)
        dialog.accept()

    QtCore.QTimer.singleShot(300, on_the_page)
    Gui.showPreferences("FabGuide", 0)
    group = FreeCAD.ParamGet(preferences.PATH)
    try:
        assert seen.get("kerf"), "the FabGuide page with its Kerf field"
        assert group.GetFloat("Kerf", 0) == 0.35 and preferences.get("Kerf") == 0.35
        print("screenshot: " + seen["screenshot"])
    finally:
        group.RemFloat("Kerf")  # the test home's user.cfg keeps what is set


def window_screenshot_is_saved():
    path = guitest.screenshot("workbench")
    assert os.path.getsize(path) > 10000, path
    print("screenshot: " + path)


def a_command_is_recorded_for_macros():
    """A FabGuide command clicked is recorded as FreeCAD records its own (Macro > Macro recording, the Python
    console): `Gui.runCommand(name, 0)`, which replays it on the selection the lines before it make."""
    doc = guitest.new_document("Recorded")
    side = doc.addObject("Part::Box", "Side")
    side.Length, side.Width, side.Height = 400, 300, 18
    doc.recompute()
    window = Gui.getMainWindow()
    console = window.findChild(QtGui.QPlainTextEdit, "Python console")
    before = len(console.toPlainText())
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(side)
    next(a for a in window.findChildren(QtGui.QAction) if a.objectName() == "FabGuide_BoardsFromSolids").trigger()
    guitest.settle(0.3)
    assert "Gui.runCommand('FabGuide_BoardsFromSolids',0)" in console.toPlainText()[before:], \
        console.toPlainText()[before:]
    assert [o.Label for o in doc.Objects if o.Label.endswith(" board")] == ["Side board"]
    FreeCAD.closeDocument(doc.Name)


guitest.run([
    workbench_is_listed_with_its_icon,
    workbench_activates_with_function_and_material_toolbars,
    toolbars_fit_a_1366_px_screen_and_reach_every_command,
    about_command_is_registered,
    preferences_page_stores_what_new_objects_start_with,
    window_screenshot_is_saved,
    a_command_is_recorded_for_macros,
])
