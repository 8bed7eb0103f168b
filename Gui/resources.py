"""Paths of the files installed under the workbench's Resources/ folder."""
import os

RESOURCES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Resources")


def icon(name):
    """Absolute path of an SVG icon in Resources/icons."""
    return os.path.join(RESOURCES, "icons", name)
