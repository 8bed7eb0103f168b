"""Translations: every user-visible string of the workbench goes through translate() or is marked with
QT_TRANSLATE_NOOP; Resources/translations/FabGuide.ts lists exactly what the code and the panels' .ui files mark
(`make translations` updates it); each FabGuide_<language>.qm is compiled from its .ts; the German translation
covers every command, drop-down button, toolbar and menu."""
import ast
import glob
import os
import re
import subprocess
import xml.etree.ElementTree as ElementTree

import pytest

SOURCE = os.path.join(os.path.dirname(__file__), "..", "..")
PACKAGE = os.path.join(SOURCE, "freecad", "fabguide")
TRANSLATIONS = os.path.join(SOURCE, "Resources", "translations")
SAID = {"tell", "setText", "setToolTip", "setWindowTitle", "setLabelText", "QProgressDialog", "PrintMessage",
        "PrintWarning", "PrintError"}
BOXES = {"warning", "information", "question", "critical"}  # QMessageBox's: (parent, title, text)


def sources():
    return sorted(glob.glob(os.path.join(PACKAGE, "**", "*.py"), recursive=True))


def plain(node):
    """The string literal with words in it, markup aside, that `node` is or is built from (literal.format(...),
    a + b, a % b, a if c else b, an f-string), or None: a translate(...) call is not looked into."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "format":
        return plain(node.func.value)
    if isinstance(node, ast.BinOp):
        return plain(node.left) or plain(node.right)
    if isinstance(node, ast.IfExp):
        return plain(node.body) or plain(node.orelse)
    if isinstance(node, ast.JoinedStr):
        return next((plain(v) for v in node.values if plain(v)), None)
    if isinstance(node, ast.Constant) and isinstance(node.value, str) and re.search(
            "[A-Za-z]{2}", re.sub("<[^>]*>", "", node.value)):
        return node.value
    return None


def unmarked(text):
    """(line, text) of each string a user reads that bypasses translation in the Python source `text`: what is
    told, shown in a widget or the report view, raised as an error, a command's MENU and TIP, a property's
    tooltip."""
    found = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Call):
            name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if name == "run" and getattr(node.func, "value", None) and getattr(node.func.value, "id", "") == "background":
                name = "tell"  # background.run's title is shown in its progress dialog
            args = node.args[1:3] if name in BOXES else node.args[:1] if name in SAID else []
            if name == "add" and len(node.args) >= 5 and str(getattr(node.args[1], "value", "")).startswith("App::"):
                args = node.args[4:5]  # a property's tooltip: FreeCAD translates it in the context App::Property
            found += [(node.lineno, plain(a)) for a in args if plain(a)]
        elif isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call) and node.exc.args:
            name = getattr(node.exc.func, "id", getattr(node.exc.func, "attr", ""))
            if name.endswith("Error") and plain(node.exc.args[0]):
                found.append((node.lineno, plain(node.exc.args[0])))
        elif isinstance(node, ast.Assign):
            targets = [t for target in node.targets for t in getattr(target, "elts", [target])]
            values = getattr(node.value, "elts", [node.value]) if len(targets) > 1 else [node.value]
            found += [(node.lineno, v.value) for t, v in zip(targets, values)
                      if getattr(t, "id", "") in ("MENU", "TIP") and plain(v)]
    return sorted(found)


def test_every_string_a_user_reads_is_marked_for_translation():
    found = ["{}:{}: {!r}".format(os.path.relpath(path, SOURCE), line, text)
             for path in sources() for line, text in unmarked(open(path, encoding="utf-8").read())]
    assert not found, "\n".join(found)


def test_the_check_finds_what_bypasses_translation():
    assert [t for _, t in unmarked('tell("Pick a box.")\nraise BoardError("{}: no shape".format(x))\n'
                                   'background.run("Laying out " + label, work)\n'
                                   'class C:\n    ICON, MENU = "a.svg", "Make Board"\n'
                                   'add(obj, "App::PropertyLength", "Kerf", "Layout", "Width of the cut", 3)\n')] == \
        ["Pick a box.", "{}: no shape", "Laying out ", "Make Board", "Width of the cut"]
    assert unmarked('tell(translate("FabGuide", "Pick a box."))\nraise BoardError(str(error))\n'
                    'MENU = QT_TRANSLATE_NOOP("FabGuide", "Make Board")\n') == []


def messages(path):
    """{(context, source): translation or None (unfinished)} of a .ts file, obsolete entries left out."""
    result = {}
    for context in ElementTree.parse(path).getroot():
        for message in context.findall("message"):
            translation = message.find("translation")
            if translation.get("type") in ("obsolete", "vanished"):
                continue
            result[(context.findtext("name"), message.findtext("source"))] = (
                None if translation.get("type") == "unfinished" else translation.text)
    return result


def test_each_ts_lists_exactly_what_the_code_and_panels_mark(tmp_path):
    fresh = tmp_path / "FabGuide.ts"
    subprocess.run(["pylupdate5", "-noobsolete"] + sources() + sorted(
        glob.glob(os.path.join(SOURCE, "Resources", "ui", "*.ui"))) + ["-ts", str(fresh)], check=True,
        capture_output=True)
    marked = set(messages(fresh))
    for path in glob.glob(os.path.join(TRANSLATIONS, "FabGuide*.ts")):
        listed = set(messages(path))
        assert listed == marked, "{}: run `make translations`: new {}, gone {}".format(
            os.path.basename(path), sorted(marked - listed)[:5], sorted(listed - marked)[:5])


@pytest.mark.parametrize("ts", sorted(glob.glob(os.path.join(TRANSLATIONS, "FabGuide_*.ts"))),
                         ids=os.path.basename)
def test_each_qm_is_compiled_from_its_ts(tmp_path, ts):
    qm = tmp_path / "compiled.qm"
    subprocess.run(["lrelease", "-silent", ts, "-qm", str(qm)], check=True)
    with open(ts[:-3] + ".qm", "rb") as shipped:
        assert qm.read_bytes() == shipped.read(), "run `make translations`"


def test_german_names_every_command_button_toolbar_and_menu():
    """What FreeCAD shows before a user does anything: QT_TRANSLATE_NOOP's strings (MENU, TIP, the drop-down
    buttons', toolbars' and menus' names)."""
    noop = set()
    for path in sources():
        for node in ast.walk(ast.parse(open(path, encoding="utf-8").read())):
            if isinstance(node, ast.Call) and getattr(node.func, "id", "") == "QT_TRANSLATE_NOOP" and \
                    node.args[0].value in ("FabGuide", "Workbench"):
                noop.add((node.args[0].value, node.args[1].value))
    german = messages(os.path.join(TRANSLATIONS, "FabGuide_de.ts"))
    assert noop and all(german.get(key) for key in noop), sorted(key for key in noop if not german.get(key))


def test_german_translates_every_string():
    """German is kept whole (docs/decisions.md): a string added in English gets its German in the same change, so
    a German user never meets a panel or a tooltip half in English."""
    german = messages(os.path.join(TRANSLATIONS, "FabGuide_de.ts"))
    assert all(german.values()), sorted(key for key, text in german.items() if not text)[:20]
