"""The FabGuide workbench loads in the real FreeCAD GUI and shows its toolbars and menus."""
import os

import FreeCADGui as Gui
from PySide import QtGui

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


def about_command_is_registered():
    assert "FabGuide_About" in Gui.listCommands()


def window_screenshot_is_saved():
    path = guitest.screenshot("workbench")
    assert os.path.getsize(path) > 10000, path
    print("screenshot: " + path)


guitest.run([
    workbench_is_listed_with_its_icon,
    workbench_activates_with_function_and_material_toolbars,
    about_command_is_registered,
    window_screenshot_is_saved,
])
