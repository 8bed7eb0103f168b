"""The GUI's runner for long core calls (background.py): the call runs on a thread; when it takes longer than a
moment, an application-modal progress dialog shows what runs and for how long (against its time limit if it has
one) and keeps FreeCAD drawing; Stop ends a search early with its best result, Cancel abandons other work."""
import threading
import time

import FreeCADGui
from PySide import QtCore, QtGui

from freecad.fabguide import background
from freecad.fabguide.i18n import translate

QUIET = 0.4  # seconds: calls shorter than this show no dialog


def run(title, work, cancel, seconds=None, stoppable=True):
    outcome = {}

    def call():
        try:
            outcome["result"] = work(cancel)
        except BaseException as error:  # handed to FreeCAD's thread, raised there
            outcome["error"] = error

    thread = threading.Thread(target=call, daemon=True)
    thread.start()
    thread.join(QUIET)
    if thread.is_alive() and not wait(title, thread, cancel, seconds, stoppable):
        raise background.Cancelled(translate("FabGuide", "{}: cancelled; it keeps its last result (recompute to try "
                                                         "again)").format(title))
    if "error" in outcome:
        raise outcome["error"]
    return outcome["result"]


def wait(title, thread, cancel, seconds, stoppable):
    """Shows the dialog until the thread ends; False when the user cancelled work that cannot stop early."""
    button = translate("FabGuide", "Stop") if stoppable else translate("FabGuide", "Cancel")
    dialog = QtGui.QProgressDialog(title, button, 0, 100 if seconds else 0,
                                   FreeCADGui.getMainWindow())
    dialog.setWindowTitle(translate("FabGuide", "FabGuide"))
    dialog.setWindowModality(QtCore.Qt.ApplicationModal)
    dialog.setMinimumDuration(0)
    dialog.setAutoClose(False)
    dialog.setAutoReset(False)
    started = time.monotonic()
    abandoned = False
    dialog.show()
    while thread.is_alive():
        if dialog.wasCanceled() and not cancel.cancelled:
            cancel.cancel()
            dialog.setLabelText(translate("FabGuide", "{}\nstopping: keeping the best found so far").format(title)
                                if stoppable else title)
            abandoned = not stoppable
            if abandoned:
                break
        elapsed = time.monotonic() - started
        if seconds:
            dialog.setValue(min(99, int(100 * elapsed / seconds)))
            if not cancel.cancelled:
                dialog.setLabelText(translate("FabGuide", "{}\n{:.0f} s of at most {:.0f} s").format(
                    title, elapsed, seconds))
        QtGui.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        thread.join(0.05)
    dialog.close()
    dialog.deleteLater()
    return not abandoned


background.RUNNER = run
