"""MasterBoard: a kind of sheet the boards are cut from (thesis 5.1); a leftover is just another one."""
from freecad.fabguide import preferences, properties
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

# The grain directions, as *.pack.json names them.
GRAIN = {"None": "none", "Along width": "width", "Along height": "height"}


class MasterBoard(properties.Proxy):
    TYPE, NOUN = "FabGuide::MasterBoard", QT_TRANSLATE_NOOP("FabGuide", "Master board")
    VALID = dict(Width=properties.more_than(0), Height=properties.more_than(0), Thickness=properties.more_than(0),
                 Count=properties.at_least(0, QT_TRANSLATE_NOOP("FabGuide", " (as many as needed)")),
                 Cost=properties.at_least(0, QT_TRANSLATE_NOOP("FabGuide", " (an offcut you have)")))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLength", "Width", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "Size along the layout's x axis"), 2440)
        add(obj, "App::PropertyLength", "Height", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "Size along the layout's y axis"), 1220)
        add(obj, "App::PropertyLength", "Thickness", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "Material thickness"), 18)
        add(obj, "App::PropertyInteger", "Count", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "Boards in stock; 0 = as many as needed"), 1)
        add(obj, "App::PropertyString", "Material", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "Material name for the cut list"), "plywood")
        add(obj, "App::PropertyEnumeration", "Grain", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "Direction of the wood grain; boards set to Follow grain keep their "
                                               "length along it"), list(GRAIN))
        add(obj, "App::PropertyFloat", "Cost", "Master board",
            QT_TRANSLATE_NOOP("App::Property", "What one board costs (any unit; 1 = a sheet); 0 for an offcut you "
                                               "have, which is used before new sheets"), 1.0)
        if "UsedBy" not in obj.PropertiesList:  # an output: noting the users never recomputes anything
            obj.addProperty("App::PropertyStringList", "UsedBy", "Result",
                            QT_TRANSLATE_NOOP("App::Property", "The designs and layouts cut from this master "
                                                               "board: a change reaches them all"),
                            properties.READ_ONLY | properties.OUTPUT)


def create(doc, width=None, height=None, thickness=None, count=1, material="plywood", label="MasterBoard",
           grain="none", cost=1.0):
    """A master board; `grain` as *.pack.json names it (none, width, height); `cost` 0 for an offcut. Sizes not
    given are the preferences' (a sheet of 2440 x 1220 x 18 mm until set)."""
    width = width or preferences.get("SheetWidth")
    height = height or preferences.get("SheetHeight")
    thickness = thickness or preferences.get("SheetThickness")
    obj = doc.addObject("App::FeaturePython", "MasterBoard")
    obj.Label = label
    MasterBoard(obj)
    obj.Width, obj.Height, obj.Thickness, obj.Count, obj.Material = width, height, thickness, count, material
    obj.Grain = next(name for name, value in GRAIN.items() if value == grain)
    obj.Cost = cost
    return obj


def is_master_board(obj):
    return properties.is_a(obj, MasterBoard)


def as_problem_board(obj):
    """The master board as a *.pack.json board."""
    return {"name": obj.Label, "material": obj.Material, "width": obj.Width.Value, "height": obj.Height.Value,
            "thickness": obj.Thickness.Value, "count": obj.Count if obj.Count > 0 else -1,
            "grain": GRAIN[obj.Grain], "cost": obj.Cost}


def users(obj):
    """The designs and layouts that cut from master board `obj`, by label."""
    return sorted(o.Label for o in obj.InList if obj in getattr(o, "MasterBoards", []))


def note_users(doc):
    """Each master board of `doc` shows who cuts from it (its UsedBy): called when a design or layout recomputes,
    is renamed or changes its master boards."""
    for m in doc.Objects:
        if is_master_board(m) and hasattr(m, "UsedBy") and list(m.UsedBy) != users(m):
            m.UsedBy = users(m)


def users_changed(user, prop):
    """A design's or layout's onChanged: renamed, or cut from other master boards."""
    if prop in ("Label", "MasterBoards") and not user.Document.Restoring:
        note_users(user.Document)


def shared(masters, user):
    """What the message of `user`'s failure adds when its master boards are others' too: a change made for
    another design is the likely cause."""
    others = {m.Label: [u for u in users(m) if u != user.Label] for m in masters}
    said = [translate("FabGuide", "master board '{}' is shared with {}").format(
                m, ", ".join("'{}'".format(u) for u in us))
            for m, us in others.items() if us]
    return " ({})".format("; ".join(said)) if said else ""
