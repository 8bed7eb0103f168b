"""MasterBoard: a kind of sheet the boards are cut from (thesis 5.1); a leftover is just another one."""
from freecad.fabguide import preferences, properties

# The grain directions, as *.pack.json names them.
GRAIN = {"None": "none", "Along width": "width", "Along height": "height"}


class MasterBoard(properties.Proxy):
    TYPE, NOUN = "FabGuide::MasterBoard", "Master board"
    VALID = dict(Width=properties.more_than(0), Height=properties.more_than(0), Thickness=properties.more_than(0),
                 Count=properties.at_least(0, " (as many as needed)"), Cost=properties.at_least(0, " (an offcut you have)"))

    def define(self, obj):
        add = properties.add
        add(obj, "App::PropertyLength", "Width", "Master board", "Size along the layout's x axis", 2440)
        add(obj, "App::PropertyLength", "Height", "Master board", "Size along the layout's y axis", 1220)
        add(obj, "App::PropertyLength", "Thickness", "Master board", "Material thickness", 18)
        add(obj, "App::PropertyInteger", "Count", "Master board", "Boards in stock; 0 = as many as needed", 1)
        add(obj, "App::PropertyString", "Material", "Master board", "Material name for the cut list", "plywood")
        add(obj, "App::PropertyEnumeration", "Grain", "Master board",
            "Direction of the wood grain; boards set to Follow grain keep their length along it", list(GRAIN))
        add(obj, "App::PropertyFloat", "Cost", "Master board",
            "What one board costs (any unit; 1 = a sheet); 0 for an offcut you have, which is used before new "
            "sheets", 1.0)


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
