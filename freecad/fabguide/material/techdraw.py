"""TechDraw pages of a layout's shop report: an A4 page per master board (its parts numbered with their sizes,
the grain, the edge banding, the saw cuts in order), then the cut list and the totals, as the PDF report has
them. The SVG and DXF files stay the input for the machine; a page is a snapshot of the layout, made again by
running the command again."""
import json
import os

import FreeCAD

from freecad.fabguide.core import fabguide_core
from freecad.fabguide.material import layout
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

# TechDraw's blank A4 page: in Templates/ up to FreeCAD 1.0, in Templates/ISO/ from 1.1.
TEMPLATES = (("Mod", "TechDraw", "Templates", "A4_Landscape_blank.svg"),
             ("Mod", "TechDraw", "Templates", "ISO", "A4_Landscape_blank.svg"))
PAGE = (297.0, 210.0)  # A4 landscape, mm: the report's pages


def pages_of(lay):
    """The TechDraw pages made for a layout."""
    return [o for o in lay.Document.Objects
            if o.TypeId == "TechDraw::DrawPage" and getattr(o, "FabGuideLayout", None) == lay]


def make_pages(lay):
    """The layout's pages made the report's, one per master board, then the cut list: pages made before are
    kept and redrawn one for one (an open page stays open, showing what it shows now), extra ones removed.
    Returns them."""
    import TechDraw  # noqa: F401  (registers the TechDraw document objects)

    layout.current(lay)
    svgs = fabguide_core.report_svgs(json.loads(lay.ProblemJson), json.loads(lay.LayoutJson), lay.Label)
    made = pages_of(lay)
    for page in made[len(svgs):]:
        remove(page)
    pages = made[:len(svgs)] + [new_page(lay) for _ in range(len(svgs) - len(made))]
    for number, (page, text) in enumerate(zip(pages, svgs), start=1):
        page.Label = "{} report {}".format(lay.Label, number)
        next(view for view in page.Views if view.TypeId == "TechDraw::DrawViewSymbol").Symbol = text
    lay.Document.recompute()
    return pages


def remove(page):
    doc = page.Document
    names = [view.Name for view in page.Views] + [page.Name] + ([page.Template.Name] if page.Template else [])
    for name in names:  # removing a page may take its template with it
        if doc.getObject(name):
            doc.removeObject(name)


def new_page(lay):
    """A blank A4 page of the layout's, holding one drawing at scale 1."""
    template_path = next((path for path in (os.path.join(FreeCAD.getResourceDir(), *t) for t in TEMPLATES)
                          if os.path.isfile(path)), None)
    if template_path is None:
        raise layout.LayoutError(translate("FabGuide", "TechDraw's blank A4 template is not installed with this "
                                                       "FreeCAD"))
    doc = lay.Document
    page = doc.addObject("TechDraw::DrawPage", "ReportPage")
    page.addProperty("App::PropertyLink", "FabGuideLayout", "FabGuide",
                     QT_TRANSLATE_NOOP("App::Property", "The layout this page draws"))
    page.FabGuideLayout = lay
    template = doc.addObject("TechDraw::DrawSVGTemplate", "ReportTemplate")
    template.Template = template_path
    page.Template = template
    drawing = doc.addObject("TechDraw::DrawViewSymbol", "Report")
    drawing.ScaleType = "Custom"
    drawing.Scale = 1.0
    drawing.X, drawing.Y = PAGE[0] / 2, PAGE[1] / 2
    page.addView(drawing)
    return page
