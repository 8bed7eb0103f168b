"""A clone of the repository in the Mod folder (what FreeCAD's Addon Manager makes) is a workbench: without its
compiled core it loads, says what to do in one warning and offers Build the Core, which builds the core (here from
the test build, so no compile runs), puts it into the clone and makes the whole workbench usable."""
import glob
import os
import time

import FreeCAD
import FreeCADGui as Gui
from PySide import QtGui

import guitest

WORKBENCH = "FabGuideWorkbench"
CLONE = os.path.join(FreeCAD.getUserAppDataDir(), "Mod", "FabGuide")
PACKAGE = os.path.join(CLONE, "freecad", "fabguide")


def the_clone_has_no_core():
    assert os.path.isfile(os.path.join(PACKAGE, "init_gui.py")) and os.path.isfile(os.path.join(CLONE, "App",
                                                                                                 "CMakeLists.txt"))
    assert not glob.glob(os.path.join(PACKAGE, "fabguide_core*.so"))


def workbench_loads_and_offers_to_build_the_core():
    from freecad import fabguide

    assert os.path.realpath(fabguide.__file__).startswith(os.path.realpath(CLONE)), fabguide.__file__
    assert WORKBENCH in Gui.listWorkbenches()
    Gui.activateWorkbench(WORKBENCH)
    assert Gui.activeWorkbench().name() == WORKBENCH
    assert "FabGuide_BuildCore" in Gui.listCommands()
    assert "FabGuide_Layout" not in Gui.listCommands()  # nothing is offered that cannot run
    try:
        from freecad.fabguide.core import fabguide_core  # noqa: F401
    except fabguide.CoreMissing as missing:
        text = str(missing)
        assert "not built for this FreeCAD" in text and "Build the Core" in text, text
    else:
        raise AssertionError("the core imported from a clone that has none")


def build_the_core_puts_it_into_the_clone():
    from freecad.fabguide.gui import build_core

    os.environ["FABGUIDE_CORE_BUILD"] = os.environ["FABGUIDE_BUILD_DIR"]
    assert build_core.obstacle() is None, build_core.obstacle()
    Gui.runCommand("FabGuide_BuildCore")
    dialog = [w for w in QtGui.QApplication.topLevelWidgets() if w.windowTitle() == "Build FabGuide's core"]
    assert dialog and dialog[0].isVisible()
    end = time.monotonic() + 600  # a bound, not a measurement: the build is up to date
    label = dialog[0].findChild(QtGui.QLabel)
    while "Restart FreeCAD" not in label.text() and "stopped" not in label.text() and time.monotonic() < end:
        guitest.settle(0.2)
    print("screenshot: " + guitest.screenshot("build_core", dialog[0]))
    assert "Restart FreeCAD" in label.text(), label.text()
    assert glob.glob(os.path.join(PACKAGE, "fabguide_core*.so"))
    from freecad.fabguide.core import fabguide_core
    from freecad.fabguide.gui import commands

    assert os.path.realpath(fabguide_core.__file__).startswith(os.path.realpath(PACKAGE)), fabguide_core.__file__
    commands.register()  # what the next start does
    assert "FabGuide_Layout" in Gui.listCommands()
    dialog[0].close()


guitest.run([
    the_clone_has_no_core,
    workbench_loads_and_offers_to_build_the_core,
    build_the_core_puts_it_into_the_clone,
])
