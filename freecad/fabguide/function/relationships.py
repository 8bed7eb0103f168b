"""Functional relationships (thesis 4.2–4.3): cover, fit inside, support, flush, and geometric relations. Each
names the configuration it must hold in and shows its Status after the Mechanism solves."""
from freecad.fabguide import cuboids, properties, references
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

ARROW = " -> "  # how a pair of the corresponding-faces graph is written in Pairs


class Relationship(properties.Proxy):
    KIND = None

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLink", "Configuration", "Relationship",
            QT_TRANSLATE_NOOP("App::Property", "The configuration it must hold in; empty: as modelled"))
        add(obj, "App::PropertyString", "Status", "Relationship",
            QT_TRANSLATE_NOOP("App::Property", "Satisfied, or what it conflicts with"), mode=1)
        self.define_fields(obj, add)


class Cover(Relationship):
    TYPE, KIND = "FabGuide::Cover", "cover"

    def define_fields(self, obj, add):
        add(obj, "App::PropertyLinkList", "Covering", "Cover",
            QT_TRANSLATE_NOOP("App::Property", "Parts whose faces cover"))
        add(obj, "App::PropertyLinkList", "Covered", "Cover",
            QT_TRANSLATE_NOOP("App::Property", "Parts whose faces are covered"))
        add(obj, "App::PropertyBool", "Just", "Cover",
            QT_TRANSLATE_NOOP("App::Property", "Just cover: the covering faces no larger than the covered"))
        define_pairs(obj, add, "Cover",
                     QT_TRANSLATE_NOOP("App::Property", "Corresponding faces, two by two: 'covering -> covered' "
                                                        "(thesis 4.3.1); empty: inferred on the next solve"),
                     QT_TRANSLATE_NOOP("App::Property", "How far apart faces may be to correspond when inferring "
                                                        "the pairs"), 5)

    def fields(self, obj):
        return dict({"covering": labels(obj.Covering), "covered": labels(obj.Covered), "just": obj.Just},
                    **pairs_or_distance(obj))


class FitInside(Relationship):
    TYPE, KIND = "FabGuide::FitInside", "fit_inside"

    def define_fields(self, obj, add):
        add(obj, "App::PropertyLinkList", "Inner", "Fit inside",
            QT_TRANSLATE_NOOP("App::Property", "Parts that must fit inside"))
        add(obj, "App::PropertyLink", "Enclosing", "Fit inside",
            QT_TRANSLATE_NOOP("App::Property", "The part they fit inside"))
        add(obj, "App::PropertyLink", "Cavity", "Fit inside",
            QT_TRANSLATE_NOOP("App::Property", "A cavity of the enclosing part to fit in; empty: its box"))
        add(obj, "App::PropertyLinkList", "Portion", "Fit inside",
            QT_TRANSLATE_NOOP("App::Property", "Partial fit: the boxes of the inner parts that must fit (a drawer's "
                                               "tray, not its front); empty: all"))
        for axis, tip in zip("XYZ", (QT_TRANSLATE_NOOP("App::Property", "Just fits in width (along X)"),
                                     QT_TRANSLATE_NOOP("App::Property", "Just fits in depth (along Y)"),
                                     QT_TRANSLATE_NOOP("App::Property", "Just fits in height (along Z)"))):
            add(obj, "App::PropertyBool", "Just" + axis, "Fit inside", tip)
        add(obj, "App::PropertyBool", "JustEach", "Fit inside",
            QT_TRANSLATE_NOOP("App::Property", "Each inner part just fits on its own along the ticked axes (stacked "
                                               "trays without play), not only the inner parts taken together"))

    def fields(self, obj):
        if obj.Enclosing is None:
            raise ValueError(translate("FabGuide", "Fit inside '{}': choose the Enclosing part").format(obj.Label))
        axes = [a.lower() for a in "XYZ" if getattr(obj, "Just" + a)]
        just = [{"part": p, "axes": axes} for p in labels(obj.Inner)] if obj.JustEach and axes else axes
        out = {"inner": labels(obj.Inner), "enclosing": obj.Enclosing.Label, "just": just}
        if obj.Cavity is not None:
            out["cavity"] = obj.Cavity.Label
        if obj.Portion:
            out["portion"] = labels(obj.Portion)
        return out


class Support(Relationship):
    TYPE, KIND = "FabGuide::Support", "support"

    def define_fields(self, obj, add):
        add(obj, "App::PropertyLinkList", "Supporting", "Support",
            QT_TRANSLATE_NOOP("App::Property", "Parts that support (legs, frames)"))
        add(obj, "App::PropertyLinkList", "Supported", "Support",
            QT_TRANSLATE_NOOP("App::Property", "Parts resting on them"))
        define_pairs(obj, add, "Support",
                     QT_TRANSLATE_NOOP("App::Property", "Corresponding faces, two by two: 'supporting top -> "
                                                        "supported bottom' (thesis 4.3.3); empty: inferred on the "
                                                        "next solve"),
                     QT_TRANSLATE_NOOP("App::Property", "How far above a top face a bottom face may be when "
                                                        "inferring the pairs"), 100)

    def fields(self, obj):
        return dict({"supporting": labels(obj.Supporting), "supported": labels(obj.Supported)},
                    **pairs_or_distance(obj))


class Flush(Relationship):
    TYPE, KIND = "FabGuide::Flush", "flush"

    def define_fields(self, obj, add):
        add(obj, "App::PropertyLinkSubList", "Faces", "Flush",
            QT_TRANSLATE_NOOP("App::Property", "Two box faces that lie in one plane"))

    def fields(self, obj):
        faces = [cuboids.face_name(box, element) for box, elements in obj.Faces for element in elements]
        if len(faces) != 2:
            raise ValueError(translate("FabGuide", "Flush '{}': choose exactly two faces, got {}").format(
                obj.Label, len(faces)))
        return {"faces": faces}


class Geometric(Relationship):
    TYPE, KIND = "FabGuide::Geometric", "geometric"

    def define_fields(self, obj, add):
        references.define(obj, "Left", "Geometric",
                          QT_TRANSLATE_NOOP("App::Property", "Quantities summed: a box and its side or size "
                                                             "(width/depth/height), with a factor in front if not 1 "
                                                             "(the formats write 'Door.width', '2*Shelf.height', "
                                                             "'-Lid.left')"))
        add(obj, "App::PropertyEnumeration", "Relation", "Geometric",
            QT_TRANSLATE_NOOP("App::Property", "Left = or <= right + offset"),
            ["Equal", "AtMost"])
        references.define(obj, "Right", "Geometric",
                          QT_TRANSLATE_NOOP("App::Property", "Quantities summed (may be empty)"))
        add(obj, "App::PropertyDistance", "Offset", "Geometric",
            QT_TRANSLATE_NOOP("App::Property", "Added to the right side"))

    def fields(self, obj):
        return {"left": terms(obj, references.names(obj.Left)), "right": terms(obj, references.names(obj.Right)),
                "relation": "equal" if obj.Relation == "Equal" else "at_most", "offset": obj.Offset.Value}


KINDS = {cls.KIND: cls for cls in (Cover, FitInside, Support, Flush, Geometric)}


def terms(obj, texts):
    """'2*Door.width' → {"quantity": "Door.width", "times": 2}; '-Lid.left' → times -1."""
    out = []
    for text in texts:
        factor, _, quantity = text.strip().rpartition("*")
        if not factor and quantity.startswith("-"):
            factor, quantity = "-1", quantity[1:]
        try:
            out.append({"quantity": quantity.strip(), "times": float(factor) if factor else 1.0})
        except ValueError:
            raise ValueError(translate("FabGuide", "Geometric '{}': '{}' must read 'Box.side', 'Box.width' or "
                                                   "'factor*Box.width'")
                             .format(obj.Label, text))
    return out


def define_pairs(obj, add, group, pairs, distance, default):
    """The corresponding-faces graph a cover or support infers, which the user may correct; `pairs` and `distance`
    are the tooltips of Pairs and Distance."""
    references.define(obj, "Pairs", group, pairs, lambda text: text.split(ARROW.strip()))
    add(obj, "App::PropertyLength", "Distance", group, distance, default)


def labels(objs):
    return [o.Label for o in objs]


def pairs_or_distance(obj):
    if not obj.Pairs:
        return {"distance": obj.Distance.Value}
    faces = references.names(obj.Pairs)
    if len(faces) % 2:
        raise ValueError(translate("FabGuide", "{} '{}': its Pairs lost a face (a box was deleted?); re-infer them "
                                               "(clear Pairs) or correct them").format(
            type(obj.Proxy).__name__, obj.Label))
    return {"pairs": [faces[i:i + 2] for i in range(0, len(faces), 2)]}


def create(doc, kind, label=None, configuration=None, **fields):
    cls = KINDS[kind]
    obj = doc.addObject("App::FeaturePython", cls.__name__)
    cls(obj)
    obj.Label = label or cls.__name__
    obj.Configuration = configuration
    for name, value in fields.items():
        setattr(obj, name, value)
    return obj


def is_relationship(obj):
    return any(properties.is_a(obj, cls) for cls in KINDS.values())


def as_dict(obj):
    out = {"type": obj.Proxy.KIND, "name": obj.Label}
    if obj.Configuration is not None:
        out["configuration"] = obj.Configuration.Label
    out.update(obj.Proxy.fields(obj))
    return out


def keep_pairs(obj, solved, boxes):
    """After a solve, an inferred graph is written into Pairs, so it stays as the user saw it; `boxes` are the
    mechanism's by label."""
    if "Pairs" in obj.PropertiesList and not obj.Pairs and solved.get("pairs"):
        obj.Pairs = references.links(boxes, [face for pair in solved["pairs"] for face in pair], obj.Label)


def pair_texts(obj):
    """Pairs as the panel shows them: 'Lid.bottom -> Body.top'."""
    faces = references.names(obj.Pairs)
    return [ARROW.join(faces[i:i + 2]) for i in range(0, len(faces), 2)]


def pair_links(obj, texts, boxes):
    """Pairs typed as 'Box.side -> Box.side' → the property's links; ValueError naming a text that is not."""
    faces = []
    for text in texts:
        ends = [t.strip() for t in text.split(ARROW.strip())]
        if len(ends) != 2:
            raise ValueError(translate("FabGuide", "{} '{}': pair '{}' must read 'Box.side -> Box.side'").format(
                type(obj.Proxy).__name__, obj.Label, text))
        faces += ends
    return references.links(boxes, faces, "{} '{}' pairs".format(type(obj.Proxy).__name__, obj.Label))
