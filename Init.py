"""FreeCAD application entry point (also run headless by freecadcmd).

FabGuide's document objects live in the `fabguide` package and are imported on demand,
so nothing needs to be set up here when FreeCAD starts.
"""
