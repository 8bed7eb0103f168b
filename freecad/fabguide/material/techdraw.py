"""TechDraw pages of a layout's shop report: an A4 page per master board (its parts numbered with their sizes,
the grain, the edge banding, the saw cuts in order), then the cut list and the totals, as the PDF report has
them. The SVG and DXF files stay the input for the machine; a page is a snapshot of the layout, made again by
running the command again."""
import json
import os

import FreeCAD

from freecad.fabguide.core import fabguide_core
from freecad.fabguide.material import layout

# TechDraw's blank A4 page: in Templates/ up to FreeCAD 1.0, in Templates/ISO/ from 1.1.
TEMPLATES = (("Mod", "TechDraw", "Templates", "A4_Landscape_blank.svg"),
             ("Mod", "TechDraw", "Templates", "ISO", "A4_Landscape_blank.svg"))
PAGE = (297.0, 210.0)  # A4 landscape, mm: the report's pages


def pages_of(lay):
    """The TechDraw pages made for a layout."""
    return [o for o in lay.Document.Objects
            if o.TypeId == "TechDraw::DrawPage" and getattr(o, "FabGuideLayout", None) == lay]


def make_pages(lay):
    """Replaces the layout's pages with the report's: one per master board, then the cut list; returns them."""
    import TechDraw  # noqa: F401  (registers the TechDraw document objects)

    if not lay.LayoutJson:
        raise layout.LayoutError("Layout '{}' has not been computed yet: recompute it first".format(lay.Label))
    doc = lay.Document
    for page in pages_of(lay):
        names = [view.Name for view in page.Views] + [page.Name] + ([page.Template.Name] if page.Template else [])
        for name in names:  # removing a page may take its template with it
            if doc.getObject(name):
                doc.removeObject(name)
    template_path = next((path for path in (os.path.join(FreeCAD.getResourceDir(), *t) for t in TEMPLATES)
                          if os.path.isfile(path)), None)
    if template_path is None:
        raise layout.LayoutError("TechDraw's blank A4 template is not installed with this FreeCAD")
    svgs = fabguide_core.report_svgs(json.loads(lay.ProblemJson), json.loads(lay.LayoutJson), lay.Label)
    pages = []
    for number, text in enumerate(svgs, start=1):
        page = doc.addObject("TechDraw::DrawPage", "ReportPage")
        page.Label = "{} report {}".format(lay.Label, number)
        page.addProperty("App::PropertyLink", "FabGuideLayout", "FabGuide", "The layout this page draws")
        page.FabGuideLayout = lay
        template = doc.addObject("TechDraw::DrawSVGTemplate", "ReportTemplate")
        template.Template = template_path
        page.Template = template
        drawing = doc.addObject("TechDraw::DrawViewSymbol", "Report")
        drawing.Symbol = text
        drawing.ScaleType = "Custom"
        drawing.Scale = 1.0
        drawing.X, drawing.Y = PAGE[0] / 2, PAGE[1] / 2
        page.addView(drawing)
        pages.append(page)
    doc.recompute()
    return pages
