"""Inside FreeCAD's GUI: run test steps once the main window is up, then quit with a status.

`run(steps)` schedules the steps on Qt's event loop; each step is a callable. A failing step
prints its traceback and FreeCAD exits with status 1; when all pass it exits with status 0.
"""
import os
import sys
import time
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui


def _path(name):
    folder = os.environ["FABGUIDE_SCREENSHOTS"]
    os.makedirs(folder, exist_ok=True)
    return os.path.join(folder, name + ".png")


def settle(seconds=0.3):
    """Let Qt run its timers for a moment: the tree and property view follow the selection on one."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        QtCore.QCoreApplication.processEvents()
        time.sleep(0.01)


def new_document(name):
    """A new document, made the active one in App and Gui: FreeCAD 1.0 re-activates the document of the current
    selection on the next event loop after newDocument, so the selection is cleared and activation forced."""
    FreeCADGui.Selection.clearSelection()
    doc = FreeCAD.newDocument(name)
    settle(0.1)
    FreeCAD.setActiveDocument(doc.Name)
    FreeCADGui.setActiveDocument(doc.Name)
    return doc


def box(doc, label, low, high):
    """A Part::Box labelled `label` from corner `low` to corner `high`."""
    from freecad.fabguide import cuboids

    made = doc.addObject("Part::Box", "Box")
    made.Label = label
    cuboids.set_coordinates(made, [v for a in range(3) for v in (low[a], high[a])])
    return made


def pick(*picked):
    """The selection as a user clicks it: (object, element) pairs, element None for the whole object."""
    FreeCADGui.Selection.clearSelection()
    for obj, element in picked:
        if element:
            FreeCADGui.Selection.addSelection(obj, element)
        else:
            FreeCADGui.Selection.addSelection(obj)


def task_button(text):
    """The open task panel's button reading `text` ("OK", "Cancel"), as a user clicks it: hidden dialogs of
    FreeCAD's own (FreeCAD 1.0's document recovery) have buttons reading the same."""
    boxes = [b for b in FreeCADGui.getMainWindow().findChildren(QtGui.QDialogButtonBox) if b.isVisible()]
    return [b for box in boxes for b in box.buttons() if b.text().replace("&", "") == text][0]


def told(command):
    """Runs `command`, which should tell the user something in a message box; closes the box and returns its
    text (None when no box came)."""

    seen, running = [], [True]

    def close():
        box = QtGui.QApplication.activeModalWidget()
        if isinstance(box, QtGui.QMessageBox):
            seen.append(box.text())
            box.accept()
        elif running[0]:
            QtCore.QTimer.singleShot(20, close)

    QtCore.QTimer.singleShot(20, close)
    FreeCADGui.runCommand(command)
    running[0] = False
    return seen[0] if seen else None


class MessageBoxes:
    """Answers every message box the session raises, as a user reading it would (OK), keeping what each said in
    `told`: a session of many mistakes runs on without a box stopping it."""

    def __init__(self):
        self.told = []
        self.timer = QtCore.QTimer()
        self.timer.timeout.connect(self.answer)
        self.timer.start(50)

    def answer(self):

        box = QtGui.QApplication.activeModalWidget()
        if isinstance(box, QtGui.QMessageBox):
            self.told.append(box.text())
            box.accept()


def session(name):
    """A session of a user's mistakes begins: the workbench active, a new document `name`, every message box
    answered as a user reading it would. Returns (the document, its MessageBoxes)."""
    boxes = MessageBoxes()
    FreeCADGui.activateWorkbench("FabGuideWorkbench")
    return new_document(name), boxes


def isometric(direction="Isometric"):
    """The active 3-D view from a direction (Isometric, Right, Top, ...), fitted, with no camera animation (on by
    default in 1.0: a render right after viewIsometric would catch the camera half-way)."""
    view = FreeCADGui.activeDocument().activeView()
    view.setAnimationEnabled(False)
    getattr(view, "view" + direction)()
    view.fitAll()
    FreeCADGui.updateGui()


def screenshots_at_screen_sizes(name):
    """The FreeCAD window as users see it on a laptop (1366 x 768) and a desktop (1920 x 1080): NAME_1366.png and
    NAME_1920.png; returns their paths. The window keeps the last size."""
    window = FreeCADGui.getMainWindow()
    window.showNormal()
    paths = []
    for width, height in ((1366, 768), (1920, 1080)):
        window.setGeometry(0, 0, width, height)
        settle(0.5)
        paths.append(screenshot("{}_{}".format(name, width)))
    return paths


def show_model_tab():
    """The Model tab (tree and properties) in front of Tasks: a tab of the combo view's QTabWidget on 0.20, of
    tabified dock widgets on 1.0; both have a QTabBar."""
    for bar in FreeCADGui.getMainWindow().findChildren(QtGui.QTabBar):
        for i in range(bar.count()):
            if bar.tabText(i).replace("&", "") == "Model":
                bar.setCurrentIndex(i)
    settle()


def report_view():
    """The text of FreeCAD's report view, as the user reads it."""
    return next(w.toPlainText() for w in FreeCADGui.getMainWindow().findChildren(QtGui.QTextEdit)
                if w.metaObject().className() == "Gui::DockWnd::ReportOutput")


def screenshot(name, window=None):
    """Grab the FreeCAD window (panels, toolbars, and the 3-D view as users see it), or another top-level
    `window` (a dialog), into $FABGUIDE_SCREENSHOTS/name.png; returns the path. With no task panel open, the Model
    tab is shown."""
    path = _path(name)
    if window is None and not FreeCADGui.Control.activeDialog():
        show_model_tab()  # FreeCAD 1.0 leaves the empty Tasks tab in front when a panel closes
    settle()
    FreeCADGui.updateGui()
    grabbed = (window or FreeCADGui.getMainWindow()).grab()
    if window is None:
        with_3d_view(grabbed, path)
    if not grabbed.save(path):
        raise RuntimeError("could not save screenshot " + path)
    return path


def with_3d_view(grabbed, scratch):
    """The active 3-D view drawn into a grab of the main window where it lies: a window grab leaves OpenGL
    blank, so the view renders itself (saveImage, as view_image) and is painted over its place."""
    document = FreeCADGui.activeDocument()
    view = document.activeView() if document else None
    if not hasattr(view, "saveImage"):
        return
    main = FreeCADGui.getMainWindow()
    gl = [w for w in main.findChildren(QtGui.QWidget)
          if w.metaObject().className() in ("QOpenGLWidget", "QGLWidget", "Gui::View3DInventorViewer")
          and w.isVisible() and w.width() > 50]
    if not gl:
        return
    widget = max(gl, key=lambda w: w.width() * w.height())
    rendered = scratch + ".view.png"
    view.saveImage(rendered, widget.width(), widget.height(), "Current")
    image = QtGui.QImage(rendered)
    os.remove(rendered)
    if image.isNull():
        return
    painter = QtGui.QPainter(grabbed)
    painter.drawImage(widget.mapTo(main, QtCore.QPoint(0, 0)), image)
    painter.end()


REFERENCES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference")
TOLERANCE = 0.02  # mean difference of the channels, of their range, between a view and its reference


def view_image(name, width=1200, height=900, compared=True):
    """Render the active 3-D view into $FABGUIDE_SCREENSHOTS/name.png and, when `compared`, check it against its
    reference image of this FreeCAD version (tests/gui/reference/<major.minor>/name.png; as freecad.gears'
    visual tests do); FABGUIDE_UPDATE_REFERENCES=1 writes the reference instead. Returns the path."""
    path = _path(name)
    view = FreeCADGui.activeDocument().activeView()
    view.setAnimationEnabled(False)
    FreeCADGui.updateGui()
    view.saveImage(path, width, height, "White")
    if not os.path.isfile(path):
        raise RuntimeError("could not save 3-D view " + path)
    if compared:
        looks_like_its_reference(path, name)
    return path


def looks_like_its_reference(path, name):
    """Both images scaled to 160 × 120 (small shifts and antialiasing average out), their mean channel
    difference at most TOLERANCE; AssertionError saying by how much otherwise."""
    import shutil


    reference = os.path.join(REFERENCES, ".".join(FreeCAD.Version()[:2]), name + ".png")
    if os.environ.get("FABGUIDE_UPDATE_REFERENCES") == "1":
        os.makedirs(os.path.dirname(reference), exist_ok=True)
        shutil.copyfile(path, reference)
        return
    assert os.path.isfile(reference), "no reference image " + reference + " (FABGUIDE_UPDATE_REFERENCES=1 makes it)"

    def small(file):
        image = QtGui.QImage(file).scaled(160, 120, QtCore.Qt.IgnoreAspectRatio, QtCore.Qt.SmoothTransformation)
        return image.convertToFormat(QtGui.QImage.Format_RGB32)

    a, b = small(path), small(reference)
    total = 0
    for y in range(120):
        for x in range(160):
            p, q = a.pixel(x, y), b.pixel(x, y)
            total += sum(abs((p >> shift & 255) - (q >> shift & 255)) for shift in (0, 8, 16))
    difference = total / (160 * 120 * 3 * 255)
    assert difference <= TOLERANCE, "{} differs from {} by {:.1%} (tolerance {:.0%})".format(
        path, reference, difference, TOLERANCE)


def keys(widget, text="", key=None):
    """Types `text` into `widget` key by key as a user does (each keystroke its own events), then presses `key`
    (QtCore.Qt.Key_Return, ...) if given. Debian's PySide has no QtTest."""

    strokes = [(ord(ch.upper()), ch) for ch in text] + ([(key, "")] if key is not None else [])
    for code, ch in strokes:
        for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
            QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, code, QtCore.Qt.NoModifier, ch))
        QtCore.QCoreApplication.processEvents()


def with_file_dialog(name, path, command):
    """Runs FreeCAD command `command` with QFileDialog.`name` (getOpenFileName, getSaveFileName) answering
    `path`, as if the user had picked it (a modal dialog would stop the test)."""

    original = getattr(QtGui.QFileDialog, name)
    setattr(QtGui.QFileDialog, name, staticmethod(lambda *args, **kwargs: (path, "")))
    try:
        FreeCADGui.runCommand(command)
    finally:
        setattr(QtGui.QFileDialog, name, original)


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
