"""Documents opened in FreeCAD's GUI: FabGuide objects saved without their view providers (made by a script or in
freecadcmd, as the bundled examples are) get them, so they show their icons and open their task panels on
double-click like objects the commands made."""
import FreeCAD

from freecad import fabguide


def adopt(doc):
    """Gives every FabGuide object of `doc` without a FabGuide view provider the one it is shown with."""
    from freecad.fabguide.gui import function_viewproviders, viewproviders

    for obj in doc.Objects:
        shown = getattr(obj, "ViewObject", None)
        if shown is None or isinstance(getattr(shown, "Proxy", None), viewproviders.ViewProvider):
            continue
        cls = next((cls for test, cls in function_viewproviders.CLASSES + viewproviders.CLASSES if test(obj)), None)
        if cls is not None:
            cls(shown)
            if not hasattr(shown.Proxy, "Object"):  # FreeCAD attaches a view provider once, as it is made
                shown.Proxy.attach(shown)
                mode = getattr(shown.Proxy, "getDefaultDisplayMode", lambda: None)()
                if mode in shown.listDisplayModes():
                    shown.DisplayMode = mode


class Opened:
    """A document observer: adopts what a document holds when it becomes the active one (FreeCAD 0.20 has no
    observer slot for a finished restore; an opened document is activated once it is read)."""

    def slotActivateDocument(self, doc):
        if doc.Restoring:
            return
        try:
            adopt(doc)
        except fabguide.CoreMissing:  # the workbench says what to do when it is activated
            pass


FreeCAD.addDocumentObserver(Opened())
