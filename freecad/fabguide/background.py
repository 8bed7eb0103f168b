"""Long core calls made by a recompute (a layout's search, a print's geometry). Headless they simply run. In
FreeCAD's GUI, gui/busy.py installs RUNNER: the call runs on a thread of its own (the core releases Python's lock)
while a progress dialog keeps FreeCAD drawing, with Stop; so no recompute of a FabGuide object freezes FreeCAD."""
RUNNER = None  # run(title, work, cancel, seconds, stoppable) -> result; set by the GUI


class Cancelled(ValueError):
    """The user cancelled a call that cannot stop early: its object keeps its last result; the message says so."""


def run(title, work, seconds=None, stoppable=True):
    """work(cancel) -> result, where cancel is a fabguide_core.CancelToken the core call checks. `seconds`: the
    call's time limit, for the progress shown. Stoppable work ends early with its best result on Stop; other work
    is left to finish on its thread, unused, and Cancelled is raised."""
    from freecad.fabguide.core import fabguide_core

    cancel = fabguide_core.CancelToken()
    if RUNNER is None:
        return work(cancel)
    return RUNNER(title, work, cancel, seconds, stoppable)
