"""Paths of the files in the workbench's Resources/ folder (beside `freecad/`, in a clone as installed)."""
import os

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))  # the clone, or Mod/FabGuide
RESOURCES = os.path.join(ROOT, "Resources")


def icon(name):
    """Absolute path of an SVG icon in Resources/icons."""
    return os.path.join(RESOURCES, "icons", name)
