"""Inside FreeCAD's GUI: run test steps once the main window is up, then quit with a status.

`run(steps)` schedules the steps on Qt's event loop; each step is a callable. A failing step
prints its traceback and FreeCAD exits with status 1; when all pass it exits with status 0.
"""
import os
import sys
import traceback

import FreeCADGui
from PySide import QtCore


def screenshot(name):
    """Grab the whole FreeCAD window into $FABGUIDE_SCREENSHOTS/name.png; returns the path."""
    folder = os.environ["FABGUIDE_SCREENSHOTS"]
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, name + ".png")
    FreeCADGui.updateGui()
    if not FreeCADGui.getMainWindow().grab().save(path):
        raise RuntimeError("could not save screenshot " + path)
    return path


def _run_all(steps):
    status = 0
    try:
        for step in steps:
            step()
            print("gui step passed: " + step.__name__)
    except BaseException:
        traceback.print_exc()
        status = 1
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)  # FreeCAD would otherwise keep its window open


def run(steps):
    QtCore.QTimer.singleShot(0, lambda: _run_all(steps))
