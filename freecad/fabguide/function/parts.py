"""A works-like part (thesis 4.1.1): one or more native Part::Box objects moving together."""
from freecad.fabguide import properties
from freecad.fabguide import cuboids
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate


class FunctionalPart(properties.Proxy):
    TYPE, NOUN = "FabGuide::Part", QT_TRANSLATE_NOOP("FabGuide", "Part")
    VALID = dict(Cuboids=properties.links(cuboids.is_box, QT_TRANSLATE_NOOP("FabGuide", "Part::Box objects")),
                 Cavities=properties.links(cuboids.is_box, QT_TRANSLATE_NOOP("FabGuide", "Part::Box objects")))

    def define(self, obj):
        properties.add(obj, "App::PropertyLinkList", "Cuboids", "Part",
                       QT_TRANSLATE_NOOP("App::Property", "The axis-aligned boxes (Part::Box) the part is made of"))
        properties.add(obj, "App::PropertyLinkList", "Cavities", "Part",
                       QT_TRANSLATE_NOOP("App::Property", "Boxes cut out of it: openings and compartments that can be "
                                                          "covered or fitted into"))

    def recompute(self, obj):
        as_dict(obj)  # says which box is unusable


def create(doc, boxes, label=None, cavities=()):
    obj = doc.addObject("App::FeaturePython", "FunctionalPart")
    FunctionalPart(obj)
    obj.Cuboids = list(boxes)
    obj.Cavities = list(cavities)
    obj.Label = label or boxes[0].Label + " part"  # its box keeps its label: no FreeCAD "001" suffix
    return obj


def is_part(obj):
    return properties.is_a(obj, FunctionalPart)


def as_dict(obj):
    """The part as *.workslike.json names it: cuboids named by their boxes' labels."""
    if not obj.Cuboids:
        raise cuboids.CuboidError(translate("FabGuide", "Part '{}' has no boxes: add a Part::Box to its "
                                                        "Cuboids").format(obj.Label))
    out = []
    for box in list(obj.Cuboids) + list(obj.Cavities):
        if not cuboids.is_box(box):
            raise cuboids.CuboidError(translate("FabGuide", "Part '{}': '{}' is not a Part::Box").format(
                obj.Label, box.Label))
        c = cuboids.coordinates(box)
        out.append({"name": box.Label, "min": c[0::2], "max": c[1::2]})
        if box in obj.Cavities:
            out[-1]["cavity"] = True
    return {"name": obj.Label, "cuboids": out}


def boxes(obj):
    return list(obj.Cuboids) + list(obj.Cavities)


def part_of(doc_objects, box):
    """The FabGuide part among `doc_objects` that holds `box`, if any."""
    return next((p for p in doc_objects if is_part(p) and box in boxes(p)), None)
