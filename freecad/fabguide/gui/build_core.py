"""FabGuide > Build the Core: where the workbench came as a clone (FreeCAD's Addon Manager clones the repository
into the Mod folder) and has no compiled core, this builds one for this FreeCAD's Python and puts it into
freecad/fabguide/, showing the build's progress and naming what stops it; Cancel stops the build."""
import glob
import os
import re
import shutil
import subprocess
import sys

import FreeCAD
import FreeCADGui

from freecad.fabguide.gui import resources
from freecad.fabguide.i18n import translate

SOURCE = resources.ROOT
PACKAGE = os.path.join(SOURCE, "freecad", "fabguide")
PYTHON = "/usr/bin/python{}.{}".format(*sys.version_info[:2])  # the Python this FreeCAD embeds


def build_dir():
    """Kept between builds so a second one is quick; FABGUIDE_CORE_BUILD names another (the tests' build)."""
    return os.environ.get("FABGUIDE_CORE_BUILD") or os.path.join(SOURCE, "build-core")


def steps(build):
    """The programs to run, in order: configure (only a new build folder), then build the core alone."""
    configure = ["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                 "-DPython_EXECUTABLE=" + PYTHON]
    compile_core = ["cmake", "--build", build, "--target", "fabguide_core", "-j", str(os.cpu_count() or 1)]
    return ([] if os.path.isfile(os.path.join(build, "CMakeCache.txt")) else [configure]) + [compile_core]


def obstacle():
    """Why the core cannot be built here, in one sentence, or None."""
    if not os.path.isfile(os.path.join(SOURCE, "CMakeLists.txt")):
        return translate("FabGuide", "this FabGuide has no sources to build from ({}): install it again").format(SOURCE)
    if shutil.which("cmake") is None or not os.access(os.path.join(SOURCE, "tools", "install-deps"), os.X_OK):
        return translate("FabGuide", "cmake is not installed: in a terminal, run  sudo {}/tools/install-deps "
                                     "core").format(SOURCE)
    missing = subprocess.run([os.path.join(SOURCE, "tools", "install-deps"), "--missing", "core"],
                             capture_output=True, text=True).stdout.split()
    if missing:
        return translate("FabGuide", "the build needs Debian packages that are not installed ({}): in a terminal, "
                                     "run  sudo {}/tools/install-deps core").format(", ".join(missing), SOURCE)
    return None


def install_core(build):
    """Copies the built core into the package; returns its path."""
    built = glob.glob(os.path.join(build, "fabguide_core*.so"))
    if not built:
        raise RuntimeError(translate("FabGuide", "the build made no fabguide_core in {}").format(build))
    return shutil.copy2(max(built, key=os.path.getmtime), PACKAGE)


class BuildDialog:
    """Runs the steps one after the other in a QProcess (FreeCAD stays responsive), with a progress bar read from
    the build's [ NN%] lines, the output's last lines, and Cancel."""

    def __init__(self):
        from PySide import QtCore, QtGui

        self.QtCore = QtCore
        self.dialog = QtGui.QDialog(FreeCADGui.getMainWindow())
        self.dialog.setWindowTitle(translate("FabGuide", "Build FabGuide's core"))
        layout = QtGui.QVBoxLayout(self.dialog)
        self.label = QtGui.QLabel(translate("FabGuide", "Building the core for this FreeCAD (Python {}.{}) in "
                                                        "{}").format(*sys.version_info[:2], build_dir()))
        self.label.setWordWrap(True)
        self.bar = QtGui.QProgressBar()
        self.output = QtGui.QPlainTextEdit()
        self.output.setReadOnly(True)
        self.output.setMaximumBlockCount(400)
        self.button = QtGui.QPushButton("Cancel")
        self.button.clicked.connect(self.stop)
        for widget in (self.label, self.bar, self.output, self.button):
            layout.addWidget(widget)
        self.dialog.resize(640, 360)
        self.process = QtCore.QProcess(self.dialog)
        self.process.setProcessChannelMode(QtCore.QProcess.MergedChannels)
        self.process.readyReadStandardOutput.connect(self.read)
        self.process.finished.connect(self.step_done)
        self.todo = steps(build_dir())
        self.outcome = None  # None while running, then "built", "failed" or "cancelled"

    def start(self):
        self.dialog.show()
        self.next_step()

    def next_step(self):
        program, *arguments = self.todo.pop(0)
        self.output.appendPlainText("$ " + " ".join([program] + arguments))
        self.process.start(program, arguments)

    def read(self):
        text = bytes(self.process.readAllStandardOutput()).decode(errors="replace")
        self.output.appendPlainText(text.rstrip())
        percents = re.findall(r"\[\s*(\d+)%\]", text)
        if percents:
            self.bar.setValue(int(percents[-1]))

    def step_done(self, code, status=None):
        if self.outcome == "cancelled":
            return
        if code != 0:
            return self.finish("failed", translate("FabGuide", "The build stopped (exit status {}): the output above "
                                                           "names the problem.").format(code))
        if self.todo:
            return self.next_step()
        try:
            path = install_core(build_dir())
        except (OSError, RuntimeError) as error:
            return self.finish("failed", translate("FabGuide", "The core could not be put into the workbench: "
                                                           "{}").format(error))
        self.bar.setValue(100)
        self.finish("built", translate("FabGuide", "Built {}. Restart FreeCAD to use FabGuide.").format(path))

    def stop(self):
        if self.outcome is None:
            self.outcome = "cancelled"
            self.process.kill()
            self.process.waitForFinished(5000)
            self.label.setText(translate("FabGuide", "Cancelled: nothing was installed."))
            self.button.setText(translate("FabGuide", "Close"))
        else:
            self.dialog.close()

    def finish(self, outcome, message):
        self.outcome = outcome
        self.label.setText(message)
        self.button.setText(translate("FabGuide", "Close"))
        (FreeCAD.Console.PrintMessage if outcome == "built" else FreeCAD.Console.PrintError)(message + "\n")


class BuildCoreCommand:
    """Offered where the core is missing; refused in one sentence where it cannot be built."""

    def GetResources(self):
        return {"Pixmap": resources.icon("FabGuide.svg"), "MenuText": "Build the Core",
                "ToolTip": "Build FabGuide's compiled core for this FreeCAD (a few minutes), from this clone"}

    def IsActive(self):
        return True

    def Activated(self):
        from PySide import QtGui

        why_not = obstacle()
        if why_not:
            FreeCAD.Console.PrintError(translate("FabGuide", "FabGuide: the core cannot be built: {}.\n").format(
                why_not))
            QtGui.QMessageBox.warning(FreeCADGui.getMainWindow(), translate("FabGuide", "Build FabGuide's core"),
                                      translate("FabGuide", "The core cannot be built: {}.").format(why_not))
            return
        self.running = BuildDialog()
        self.running.start()
