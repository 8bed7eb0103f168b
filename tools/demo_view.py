"""`make demo`, second half, run by FreeCAD's GUI under Xvfb: renders the solved cabinet saved by tools/demo.py,
as modelled and with its doors and flap stowed and its drawer open (thesis Fig. 4.16), into PNGs, seen from the
isometric direction. It writes to the process' own stdout and stderr: FreeCAD 1.0's GUI shows print() only in its
report view."""
import os
import traceback

import FreeCAD
import FreeCADGui as Gui
from PySide import QtCore

ROOT = os.getcwd()  # make runs it from the source folder
OUT = os.path.join(ROOT, "build", "demo", "cabinet")


def render():
    from freecad.fabguide.function import configuration, mechanism, parts
    from freecad.fabguide.gui import function_viewproviders
    from freecad.fabguide.gui.posing import Poser

    doc = FreeCAD.openDocument(os.path.join(OUT, "cabinet.FCStd"))
    mech = next(o for o in doc.Objects if mechanism.is_mechanism(o))
    cavities = [b for p in mechanism.members(mech, parts.is_part) for b in p.Cavities]
    for box in mechanism.boxes(mech):  # saved by freecadcmd, without view data: FreeCAD opens them hidden
        box.ViewObject.Visibility = box not in cavities
    carcass = doc.getObjectsByLabel("carcass")[0].ViewObject
    function_viewproviders.show_conflicts(mech)
    Gui.updateGui()
    view = Gui.getDocument(doc.Name).activeView()
    view.setAnimationEnabled(False)  # FreeCAD 1.0 animates the camera: a render would catch it half-way
    view.viewIsometric()
    view.fitAll()
    view.saveImage(os.path.join(OUT, "cabinet.png"), 1200, 900, "White")
    poses = {j.Name: (a, o, configuration.pole(c, j)) for c in mechanism.members(mech, configuration.is_configuration)
             if c.Label != "lid open" for j, a, o in configuration.poses(c)}
    poser = Poser(mech)
    poser.show(poses)
    carcass.DisplayMode = "Wireframe"  # to see the doors and the flap stowed inside
    carcass.LineWidth = 2
    view.fitAll()
    Gui.updateGui()
    view.saveImage(os.path.join(OUT, "cabinet-stowed.png"), 1200, 900, "White")
    poser.clear()
    # The printable cabinet: the bodies as printed, the carcass see-through to show the hinge yokes.
    made = next(o for o in doc.Objects if getattr(o, "Proxy", None) and o.Proxy.__class__.__name__ == "Printable")
    for o in doc.Objects:
        o.ViewObject.Visibility = o in made.Group and o.BodyName != "cavities swept"
    carcass.DisplayMode = "Flat Lines"
    printed = next(o for o in made.Group if o.BodyName == "carcass part")
    printed.ViewObject.Transparency = 50
    view.fitAll()
    Gui.updateGui()
    view.saveImage(os.path.join(OUT, "cabinet-printable.png"), 1200, 900, "White")
    os.write(1, b"wrote build/demo/cabinet/cabinet.png, cabinet-stowed.png and cabinet-printable.png\n")


def main():
    status = 0
    try:
        render()
    except BaseException:
        os.write(2, "".join("demo: " + line + "\n" for line in traceback.format_exc().splitlines()).encode())
        status = 1
    os._exit(status)


QtCore.QTimer.singleShot(0, main)
