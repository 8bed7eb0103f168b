"""What every FabGuide command shares: one undo step per command, telling the user about mistakes, reading
the selection."""
import contextlib
import os

import FreeCAD
import FreeCADGui

from freecad.fabguide import properties
from freecad.fabguide.gui import resources
from freecad.fabguide.i18n import translate


@contextlib.contextmanager
def transaction(doc, name):
    """One undo step, or none if the command fails."""
    doc.openTransaction(name)
    try:
        yield
    except Exception:
        doc.abortTransaction()
        raise
    doc.commitTransaction()


def tell(message):
    """A user mistake: said in the report view and in a message box."""
    from PySide import QtGui

    FreeCAD.Console.PrintWarning(translate("FabGuide", "FabGuide: {}\n").format(message))
    QtGui.QMessageBox.warning(FreeCADGui.getMainWindow(), translate("FabGuide", "FabGuide"), message)


def selected(test):
    return [s.Object for s in FreeCADGui.Selection.getSelectionEx() if test(s.Object)]


def all_in(doc, test):
    return [o for o in doc.Objects if test(o)]


class Gate:
    """A command's gate (its NEEDS), a test of the active document. An object rather than a function: as a class
    attribute, a function would be bound as a method (and a functools.partial will be, from Python 3.14)."""

    def __init__(self, test):
        self.test = test

    def __call__(self, doc):
        return self.test(doc)


def selecting(test, kind=None, least=1):
    """At least `least` picked objects passing `test`, or with `kind` ("Edge", "Face"), at least `least` picked
    elements of that kind on such objects. Cheap: FreeCAD asks often."""
    def ready(doc):
        found = 0
        for s in FreeCADGui.Selection.getSelectionEx():
            if test(s.Object):
                found += sum(1 for n in s.SubElementNames if n.startswith(kind)) if kind else 1
        return found >= least
    return Gate(ready)


def present(test):
    """The document holds an object passing `test` (the picked one, or the only one, is what the command runs on)."""
    return Gate(lambda doc: any(test(o) for o in doc.Objects))


def both(*gates):
    return Gate(lambda doc: all(gate(doc) for gate in gates))


def the_one(doc, test, select, missing):
    """The selected object of a kind, else the document's only one; when there are several, tells the user
    `select` (which to pick), when there is none `missing`, and returns None."""
    found = selected(test) or all_in(doc, test)
    if len(found) != 1:
        tell(select if found else missing)
        return None
    return found[0]


def ask_open(title, filter):
    """A file to read, or "" when the user cancels."""
    from PySide import QtGui

    return QtGui.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), title, os.path.expanduser("~"), filter)[0]


def ask_save(title, name, filter):
    """A file to write, or "" when the user cancels."""
    from PySide import QtGui

    return QtGui.QFileDialog.getSaveFileName(FreeCADGui.getMainWindow(), title, name, filter)[0]


class Group:
    """Commands behind one drop-down toolbar button (FreeCAD's Python group command), as FreeCAD's own
    workbenches group theirs; the button shows the command used last."""

    def __init__(self, menu, tip, names):
        self.menu, self.tip, self.names = menu, tip, tuple(names)

    def GetCommands(self):
        return self.names

    def GetDefaultCommand(self):
        return 0

    def GetResources(self):
        return {"MenuText": translate("Workbench", self.menu), "ToolTip": translate("FabGuide", self.tip)}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None


class Command:
    """Active with an open document whose selection or content fits NEEDS (greyed out otherwise, as FreeCAD's own
    commands are); subclasses give ICON, MENU, TIP, NEEDS and run(doc), which says in one sentence what a selection
    that passes the gate still lacks."""

    NEEDS = None  # a Gate on the active document (selecting, present, both); None: any open document

    def GetResources(self):
        return {"Pixmap": resources.icon(self.ICON), "MenuText": translate("FabGuide", self.MENU),
                "ToolTip": translate("FabGuide", self.TIP)}

    def IsActive(self):
        doc = FreeCAD.ActiveDocument
        if doc is None or self.NEEDS is None:
            return doc is not None
        return self.NEEDS(doc)

    def Activated(self):
        """Runs the command; a mistake in the model (a ValueError: FabGuide's errors, the core's FormatError; the
        core's PackingError) is told in one plain sentence, not a traceback, and so is anything unforeseen, its
        traceback kept for a bug report in FreeCAD's log only."""
        try:
            self.run(FreeCAD.ActiveDocument)
        except properties.mistakes() as error:
            tell(str(error))
        except OSError as error:  # a file picked that cannot be read or written: a folder, a missing one
            tell(translate("FabGuide", "{}: cannot use '{}': {}.").format(
                self.MENU, error.filename, error.strerror or error))
        except Exception as error:  # noqa: B902  (a user meets a sentence, whatever went wrong)
            unforeseen(self.MENU, error)


def unforeseen(what, error):
    """Something FabGuide did not foresee while doing `what`: one sentence for the user, the traceback in the
    log (FreeCAD's --log-file, Report view with logging on) for a bug report."""
    import traceback

    FreeCAD.Console.PrintLog(traceback.format_exc())
    tell(translate("FabGuide", "{} did not finish: {} ({}). Please report this, with what you did, at the FabGuide "
                               "issue tracker.").format(
        what, error, type(error).__name__))
