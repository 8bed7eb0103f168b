"""TechDraw pages of a layout's cut sheets: one A3 page per master board, the cut sheet (cut paths,
drill holes, labels) drawn to scale, for printing and the shop. The SVG and DXF files stay the input
for the machine; a page is a snapshot of the layout, made again by running the command again."""
import json
import os

import FreeCAD

import fabguide_core
from fabguide.material import layout

TEMPLATE = ("Mod", "TechDraw", "Templates", "A3_Landscape_blank.svg")
PAGE = (420.0, 297.0)  # A3 landscape, mm
MARGIN = 15.0
LINE = 0.35  # mm on paper


def scale(sheet):
    """The drawing scale that fits a master board on the page."""
    return min((PAGE[0] - 2 * MARGIN) / sheet["width"], (PAGE[1] - 3 * MARGIN) / sheet["height"])


def pages_of(lay):
    """The TechDraw pages made for a layout."""
    return [o for o in lay.Document.Objects
            if o.TypeId == "TechDraw::DrawPage" and getattr(o, "FabGuideLayout", None) == lay]


def make_pages(lay):
    """Replaces the layout's pages with one page per master board; returns the pages."""
    import TechDraw  # noqa: F401  (registers the TechDraw document objects)

    if not lay.LayoutJson:
        raise layout.LayoutError("Layout '{}' has not been computed yet: recompute it first".format(lay.Label))
    doc = lay.Document
    for page in pages_of(lay):
        names = [view.Name for view in page.Views] + [page.Name] + ([page.Template.Name] if page.Template else [])
        for name in names:  # removing a page may take its template with it
            if doc.getObject(name):
                doc.removeObject(name)
    result = json.loads(lay.LayoutJson)
    problem = json.loads(lay.ProblemJson)
    template_path = os.path.join(FreeCAD.getResourceDir(), *TEMPLATE)
    pages = []
    scales = [scale(sheet) for sheet in result["boards"]]
    svgs = fabguide_core.cut_sheet_svgs(problem, result, stroke=LINE / min(scales))  # lines >= LINE on paper
    for number, (sheet, text) in enumerate(zip(result["boards"], svgs), start=1):
        page = doc.addObject("TechDraw::DrawPage", "CutSheetPage")
        page.Label = "{} sheet {}".format(lay.Label, number)
        page.addProperty("App::PropertyLink", "FabGuideLayout", "FabGuide", "The layout this page draws")
        page.FabGuideLayout = lay
        template = doc.addObject("TechDraw::DrawSVGTemplate", "CutSheetTemplate")
        template.Template = template_path
        page.Template = template
        drawing = doc.addObject("TechDraw::DrawViewSymbol", "CutSheet")
        drawing.Symbol = text
        drawing.ScaleType = "Custom"
        drawing.Scale = scales[number - 1]
        drawing.X, drawing.Y = PAGE[0] / 2, PAGE[1] / 2 + MARGIN / 2
        drawing.Caption = "Sheet {} of {}: {} {:g} x {:g} x {:g} mm, scale 1:{:.0f}".format(
            number, len(svgs), sheet["material"] or sheet["name"], sheet["width"], sheet["height"],
            sheet["thickness"], 1 / drawing.Scale)
        page.addView(drawing)
        pages.append(page)
    doc.recompute()
    return pages
