"""References from FabGuide objects to boxes, kept as FreeCAD links: renaming a box keeps them, deleting one
warns as FreeCAD does, and save/reload keeps them. A property of references is an App::PropertyLinkSubList of
(box, what): `what` is the model formats' name after the box's label ("top", "width", "size.x"), with a factor in
front for a geometric term ("2*width", "-left"); the formats and the messages read "2*Door.width"."""
import FreeCAD

from freecad.fabguide.properties import add
from freecad.fabguide.i18n import translate


class BrokenReference(ValueError):
    """A reference that names no box, or a property of references in a shape FabGuide cannot read."""


def define(obj, name, group, doc, split=lambda text: [text]):
    """Adds property `name` as references; an older document's string list of names is turned into links
    (migration 1: labels to links), each old string `split` into names."""
    if name in obj.PropertiesList and obj.getTypeIdOfProperty(name) in ("App::PropertyStringList",
                                                                         "App::PropertyString"):
        value = getattr(obj, name)
        texts, by_label, kept = [value] if isinstance(value, str) else list(value), boxes_by_label(obj.Document), []
        obj.removeProperty(name)
        add(obj, "App::PropertyLinkSubList", name, group, doc)
        for piece in (piece for text in filter(None, texts) for piece in split(text)):
            try:
                kept.append(link(by_label, piece, "{} of '{}'".format(name, obj.Label)))
            except BrokenReference as error:
                FreeCAD.Console.PrintWarning(translate("FabGuide", "{}; left out when opening the document\n").format(
                    error))
        setattr(obj, name, kept)
    add(obj, "App::PropertyLinkSubList", name, group, doc)


def name(box, what):
    """(Door, "2*width") → "2*Door.width"."""
    factor, star, what = what.rpartition("*")
    sign = "-" if what.startswith("-") else ""
    return "{}{}{}{}.{}".format(factor, star, sign, box.Label, what[len(sign):])


def names(value):
    """A property of references as the formats name them."""
    return [name(box, what) for box, whats in value for what in (whats if isinstance(whats, (list, tuple))
                                                                   else [whats])]


def link(by_label, text, field):
    """"2*Door.width" → (the box labelled Door, "2*width"); `field` names where the text came from."""
    factor, star, rest = text.strip().rpartition("*")
    sign = "-" if rest.startswith("-") else ""
    label, dot, what = rest[len(sign):].partition(".")
    box = by_label.get(label)
    while box is None and dot and "." in what:  # a label with a dot: "Shelf.2.size.x"
        more, _, what = what.partition(".")
        label += "." + more
        box = by_label.get(label)
    if box is None or not what:
        raise BrokenReference(translate("FabGuide", "{}: '{}' names no box (write 'Box label.{}')").format(
            field, text, what or "side"))
    return box, "{}{}{}{}".format(factor.strip(), star, sign, what)


def links(by_label, texts, field):
    return [link(by_label, text, "{} {}".format(field, i + 1)) for i, text in enumerate(texts)]


def boxes_by_label(doc):
    return {o.Label: o for o in doc.Objects if getattr(o, "TypeId", "") == "Part::Box"}
