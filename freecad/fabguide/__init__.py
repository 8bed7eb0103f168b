"""FabGuide, a FreeCAD workbench in the `freecad` namespace package (FreeCAD's module layout: this folder is
importable straight from a clone in the Mod folder).

The document objects here gather their inputs into plain core models, call the compiled core (`core.py` finds
it) once on recompute and write the results back; no algorithm lives in Python. Everything outside `gui/` can be
created and recomputed headless in `freecadcmd`.
"""
import os
import xml.etree.ElementTree as ET

from freecad.fabguide import legacy_names


def package_version():
    """The version in package.xml, beside freecad/ in a clone and as installed (the core's agrees: tested)."""
    root = ET.parse(os.path.join(os.path.dirname(__file__), "..", "..", "package.xml")).getroot()
    return root.find("{https://wiki.freecad.org/Package_Metadata}version").text


__version__ = package_version()
legacy_names.install()


class CoreMissing(ImportError):
    """The compiled core is not built for this FreeCAD's Python (core.py): the message says what to do."""
