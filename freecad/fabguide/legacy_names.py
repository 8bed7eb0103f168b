"""Documents saved by FabGuide 0.1 name their objects' classes by the module layout of that version
(`fabguide.material.board`, `fabguide_gui.viewproviders`): FreeCAD imports those names when it opens the file.
Each is answered by a stand-in module that hands out the attributes of today's module (the same classes), imported
when first asked; saved again, the objects name today's modules (migration 3, docs/decisions.md)."""
import importlib
import os
import sys
import types

HERE = os.path.dirname(os.path.abspath(__file__))
OLD_PACKAGES = {"fabguide_gui": "freecad.fabguide.gui", "fabguide": "freecad.fabguide"}


class StandIn(types.ModuleType):
    """A 0.1 module name whose attributes are those of today's module `target`."""

    def __init__(self, name, target):
        super().__init__(name)
        self.__path__ = []  # a package, so that its 0.1 submodules import through it
        self.__target = target

    def __getattr__(self, attribute):
        return getattr(importlib.import_module(self.__target), attribute)


def todays_modules():
    """Today's module names under freecad.fabguide, from the files (nothing is imported)."""
    for folder, _, files in os.walk(HERE):
        if "__init__.py" not in files:
            continue
        relative = os.path.relpath(folder, HERE)
        package = "freecad.fabguide" + ("" if relative == "." else "." + relative.replace(os.sep, "."))
        yield package
        yield from (package + "." + name[:-3] for name in files if name.endswith(".py") and name != "__init__.py")


def old_name(new):
    for old, today in OLD_PACKAGES.items():
        if new == today or new.startswith(today + "."):
            return old + new[len(today):]
    return None


def install():
    for new in todays_modules():
        old = old_name(new)
        if old and old not in sys.modules:
            sys.modules[old] = StandIn(old, new)
