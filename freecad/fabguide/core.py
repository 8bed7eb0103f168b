"""The one place Python finds FabGuide's compiled core, `fabguide_core`: built into this folder (`make install`,
or the workbench's *Build the Core* command on a clone), or installed for the system's Python by the Debian
package. Without it the workbench still loads and says what to do (gui/build_core.py)."""
import importlib
import sys

from freecad.fabguide import CoreMissing
from freecad.fabguide.i18n import translate


def missing_message(cause=None):
    return translate("FabGuide", "FabGuide's compiled core is not built for this FreeCAD (Python {}.{}){}: choose "
                                 "FabGuide > Build the Core, or install the fabguide Debian package (README.md, "
                                 "Install).").format(
        *sys.version_info[:2],
        translate("FabGuide", " (the one there does not load: {})").format(cause) if cause else "")


# Where the core is looked for: built into this folder; installed for the system's Python (the Debian package).
PLACES = ("freecad.fabguide.fabguide_core", "fabguide_core")


def load():
    """The first core found; CoreMissing says why none loads (none there, or the one there fails to load)."""
    causes = []
    for name in PLACES:
        try:
            return importlib.import_module(name)
        except ModuleNotFoundError:
            continue
        except ImportError as error:  # there, but it does not load (a library missing, built for another FreeCAD)
            causes.append(str(error))
    raise CoreMissing(missing_message(causes[0] if causes else None))


fabguide_core = load()
