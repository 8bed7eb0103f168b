"""Parametric flat-pack designs (thesis 5.2.1, 5.4.2.2): the boxes of a FlatpackDesign follow spreadsheet aliases
through expressions; D(X) sets the aliases, recomputes the document and reads the boards' sizes back. Suggest
changes the aliases within their ranges; the core finds the gradients by finite differences."""
import FreeCAD

from freecad.fabguide.core import fabguide_core
from freecad.fabguide import cuboids
from freecad.fabguide.material import design
from freecad.fabguide.i18n import translate


class ParameterError(ValueError):
    """A Parameters entry that cannot be used; the message names the design and the entry."""


def parameters(obj):
    """[(sheet, alias, low, high)] from the design's Parameters ("Sheet.alias min max")."""
    found = []
    for entry in obj.Parameters:
        words = entry.split()  # a sheet's label may hold spaces: the range is the last two words
        try:
            name, low, high = " ".join(words[:-2]), float(words[-2]), float(words[-1])
            sheet_name, alias = name.rsplit(".", 1)
        except (IndexError, ValueError):
            raise ParameterError(translate("FabGuide", "Design '{}': parameter '{}' must read 'Sheet.alias min "
                                                       "max'").format(obj.Label, entry))
        sheets = obj.Document.getObjectsByLabel(sheet_name) or [obj.Document.getObject(sheet_name)]
        sheet = sheets[0]
        if sheet is None or sheet.TypeId != "Spreadsheet::Sheet" or sheet.getCellFromAlias(alias) is None:
            raise ParameterError(translate("FabGuide", "Design '{}': parameter '{}': no spreadsheet '{}' with an alias "
                                                       "'{}'").format(
                obj.Label, entry, sheet_name, alias))
        if not low <= value(sheet, alias) <= high:
            raise ParameterError(translate("FabGuide", "Design '{}': parameter '{}' is {:g} now, outside its "
                                                       "range").format(
                obj.Label, entry, value(sheet, alias)))
        found.append((sheet, alias, low, high))
    return found


def value(sheet, alias):
    """The alias' number; ParameterError when its cell holds none (empty, text, an expression in error)."""
    try:
        v = sheet.get(alias)
        return float(getattr(v, "Value", v))
    except (ValueError, TypeError) as error:
        raise ParameterError(translate("FabGuide", "Spreadsheet '{}': '{}' holds no number ({})").format(
            sheet.Label, alias, str(error).splitlines()[0]))


def set_values(obj, params, values, boxes_only=False):
    """The aliases to `values`, the document recomputed (or only the sheets and boxes, while searching: the
    design's own recompute lays the boards out, which the search does itself)."""
    for (sheet, alias, _, _), v in zip(params, values):
        sheet.set(sheet.getCellFromAlias(alias), "{:.12g}".format(float(v)))
    if boxes_only:
        obj.Document.recompute(list(dict.fromkeys([p[0] for p in params])) + design.boxes(obj))
    else:
        obj.Document.recompute()


def rounded(params, values, step=0.1):
    """Values as a maker types them, to `step` mm, each kept within its parameter's range."""
    return [min(max(round(v / step) * step, low), high) for (_, _, low, high), v in zip(params, values)]


def sides(obj):
    """Each box's three sides, x, y and z: the core makes them a board's width and height, along its grain."""
    return [getattr(box, name).Value for box in design.boxes(obj) for name in cuboids.SIZES]


def optimise(obj, seed=1, time_limit=8.0, rounds=3, progress=None, cancel=None):
    """MINWASTAGE over the aliases (on this thread: D(X) recomputes this document). The aliases are back at their
    values when it returns."""
    params = parameters(obj)
    if not params:
        raise ParameterError(translate("FabGuide", "Design '{}' has no Parameters").format(obj.Label))
    data = design.flatpack(obj)
    start = [value(sheet, alias) for sheet, alias, _, _ in params]

    def sides_at(values):
        set_values(obj, params, values, boxes_only=True)
        return sides(obj)

    parts = [{"id": box.Label, "grain": getattr(box, "Grain", "Free").lower()} for box in design.boxes(obj)]
    try:
        return fabguide_core.optimise_parametric(
            parts, sides_at, start, [p[2] for p in params], [p[3] for p in params],
            {"boards": data["boards"], "settings": data["settings"]}, seed=seed, time_limit=time_limit,
            rounds=rounds, progress=progress, cancel=cancel)
    finally:
        set_values(obj, params, start)
        FreeCAD.Console.PrintLog("FabGuide: {} parameters restored\n".format(obj.Label))
