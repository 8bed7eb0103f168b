"""Make CAM Job: a layout's master boards as FreeCAD CAM jobs (the Path workbench in FreeCAD 0.20), one per
sheet, built from the parts as designed so that the tool's radius is CAM's own: stock = the sheet, the parts as
solids at board thickness, profiles in the core's cut order (holes before outlines, small parts before large),
holding tags and dogbones as CAM dressups, drilling per dowel depth, labels engraved from their strokes.
The G-code comes from FreeCAD's own post-processors."""
import contextlib
import importlib.util
import json
import os
import types

import FreeCAD
import Part

from freecad.fabguide.core import fabguide_core
from freecad.fabguide.material import layout
from freecad.fabguide.i18n import QT_TRANSLATE_NOOP, translate

FEED = 1500.0  # mm/min across the sheet: a router in plywood or MDF
PLUNGE = 300.0  # mm/min down
SPINDLE = 18000.0  # rpm
ENGRAVE_DEPTH = 0.5  # mm below the face
THROUGH = 0.2  # mm the profiles cut below the sheet, into the spoilboard, so that the parts come free
TAGS = 2  # holding tags per tabbed outline
BITS = {"end mill": "5mm_Endmill.fctb", "drill": "5mm_Drill.fctb", "v-bit": "60degree_Vbit.fctb"}


class CamError(ValueError):
    """CAM jobs that cannot be made or posted; the message says why."""


def workbench():
    """FreeCAD's CAM modules under one set of names: `Path.*` of FreeCAD 1.0's CAM workbench, else the
    `PathScripts` of 0.20's Path workbench; CamError when neither is installed."""
    try:
        from Path.Main import Job, Stock
        from Path.Op import Drilling, Engrave, Profile
        from Path.Dressup import DogboneII as Dogbone, Tags
        from Path.Tool import Bit, Controller
        import Path.Preferences as Preferences
        import Path.Tool as tools
        ToolBit = getattr(tools, "ToolBit", None)  # FreeCAD 1.1
    except ImportError:
        try:
            from PathScripts import (PathJob as Job, PathStock as Stock, PathDrilling as Drilling,
                                     PathEngrave as Engrave, PathProfile as Profile,
                                     PathDressupDogbone as Dogbone, PathDressupHoldingTags as Tags,
                                     PathToolBit as Bit, PathToolController as Controller,
                                     PathPreferences as Preferences)
            ToolBit = None
        except ImportError as error:
            raise CamError(translate("FabGuide", "FreeCAD's CAM (Path) workbench is not installed: {}").format(error))
    return types.SimpleNamespace(Job=Job, Stock=Stock, Drilling=Drilling, Engrave=Engrave, Profile=Profile,
                                 Dogbone=Dogbone, Tags=Tags, Bit=Bit, Controller=Controller,
                                 Preferences=Preferences, ToolBit=ToolBit)


def library_bits():
    """The tool bits FreeCAD ships, {file name: path}."""
    folder = os.path.join(FreeCAD.getResourceDir(), "Mod", "CAM", "Tools", "Bit")
    if not os.path.isdir(folder):
        folder = os.path.join(FreeCAD.getResourceDir(), "Mod", "Path", "Tools", "Bit")
    return {name: os.path.join(folder, name) for name in sorted(os.listdir(folder))} if os.path.isdir(folder) else {}


def bit_diameter(bit):
    """The diameter (mm) of the tool bit file `bit` (FreeCAD's *.fctb JSON, the same in 0.20 to 1.1); CamError if
    it has none."""
    try:
        with open(bit, encoding="utf-8") as f:
            return FreeCAD.Units.Quantity(json.load(f)["parameter"]["Diameter"]).Value
    except (KeyError, TypeError, ValueError, OSError) as error:
        raise CamError(translate("FabGuide", "tool bit file '{}' has no diameter ({})").format(bit, error))


def post_processors():
    return workbench().Preferences.allAvailablePostProcessors()


def jobs_of(lay):
    """The CAM jobs made for a layout."""
    return [o for o in lay.Document.Objects if getattr(o, "FabGuideLayout", None) == lay and hasattr(o, "Operations")]


def materials(lay):
    """The materials of the layout's master boards, in their order: each may have its own feed and speed."""
    return list(dict.fromkeys(board["material"] for board in json.loads(lay.ProblemJson)["boards"]))


def for_material(value, material, what):
    """A feed or spindle speed given as one number for every material, or as {material: number}."""
    if not isinstance(value, dict):
        return float(value)
    if material not in value:
        raise CamError(translate("FabGuide", "no {} for the material '{}' (given for {})").format(
            what, material, ", ".join("'{}'".format(m) for m in value) or "none"))
    return float(value[material])


def make_jobs(lay, bit=None, post="grbl", feed=FEED, spindle=SPINDLE, through=THROUGH):
    """Replaces the layout's CAM jobs with one per master board; `bit` = a tool bit file (*.fctb) for the
    profiles (default: FreeCAD's 5 mm end mill); `feed` (mm/min) and `spindle` (rpm): one number, or one per
    material ({material: number}); `through`: mm the profiles cut below the sheet. Returns the jobs."""
    layout.current(lay)
    if not 0 <= through <= 5:
        raise CamError(translate("FabGuide", "cut through by {:g} mm: from 0 to 5 mm below the sheet").format(through))
    speeds = {m: (for_material(feed, m, "feed"), for_material(spindle, m, "spindle speed")) for m in materials(lay)}
    for material, (feeding, turning) in speeds.items():
        if not 10 <= feeding <= 50000:
            raise CamError(translate("FabGuide", "feed {:g} mm/min for '{}': from 10 to 50000 mm/min").format(
                feeding, material))
        if not 0 <= turning <= 60000:
            raise CamError(translate("FabGuide", "spindle speed {:g} rpm for '{}': from 0 to 60000 rpm").format(
                turning, material))
    cam = workbench()
    if post not in cam.Preferences.allAvailablePostProcessors():
        raise CamError(translate("FabGuide", "no post-processor '{}' in FreeCAD (there are: {})").format(
            post, ", ".join(cam.Preferences.allAvailablePostProcessors())))
    bit = bit or library_bits().get(BITS["end mill"])
    if not bit or not os.path.isfile(bit):
        raise CamError(translate("FabGuide", "tool bit file '{}' not found").format(bit))
    diameter = bit_diameter(bit)
    if lay.Kerf.Value + lay.Spacing.Value < diameter - 1e-9:
        raise CamError(translate("FabGuide", "Layout '{}': its parts are {:g} mm apart (Kerf {:g} + Spacing {:g} mm), "
                                             "too close for the {:g} mm tool: set its Kerf to the tool's "
                                             "diameter").format(
                           lay.Label, lay.Kerf.Value + lay.Spacing.Value, lay.Kerf.Value, lay.Spacing.Value, diameter))
    remove_jobs(lay)
    sheets = fabguide_core.cut_sheets(json.loads(lay.ProblemJson), json.loads(lay.LayoutJson))
    with plain_bits(cam):
        jobs = [make_job(cam, lay, number, sheet, bit, post, *speeds[sheet["material"]], through)
                for number, sheet in enumerate(sheets, 1)]
    lay.Document.recompute()
    return jobs


@contextlib.contextmanager
def plain_bits(cam):
    """FreeCAD's GUI makes each tool bit in an undo step of its own, which would split Make CAM Job into eight;
    its factory is set aside meanwhile. Its module is loaded first: loading it installs that factory (in 1.0
    only when a tool bit is first shown)."""
    if not hasattr(cam.Bit, "Factory"):  # FreeCAD 1.1 makes tool bits without a factory
        yield
        return
    if FreeCAD.GuiUp:
        try:
            import Path.Tool.Gui.Bit  # noqa: F401  (FreeCAD 1.0)
        except ImportError:
            import PathScripts.PathToolBitGui  # noqa: F401  (0.20)
    gui_factory = cam.Bit.Factory
    cam.Bit.Factory = cam.Bit.ToolBitFactory()
    try:
        yield
    finally:
        cam.Bit.Factory = gui_factory


def remove_jobs(lay):
    doc = lay.Document
    for job in jobs_of(lay):
        job.Proxy.onDelete(job)  # its operations, stock, model clones and tools
        if doc.getObject(job.Name):
            doc.removeObject(job.Name)
    for obj in [o for o in doc.Objects if getattr(o, "FabGuideLayout", None) == lay and o.TypeId == "Part::Feature"]:
        doc.removeObject(obj.Name)  # the parts and labels the jobs were made from


def make_job(cam, lay, number, sheet, bit, post, feed, spindle, through):
    doc = lay.Document
    title = "{} sheet {}".format(lay.Label, number)
    parts, faces = part_solids(sheet)
    model = owned(doc.addObject("Part::Feature", "CamParts"), lay, title + " parts")
    model.Shape = Part.makeCompound(parts)
    model.Visibility = False
    job = cam.Job.Create("Job", [model])
    job.Label = title
    owned(job, lay, title)
    job.PostProcessor = post
    job.PostProcessorArgs = ""
    set_stock(cam, doc, job, sheet)
    base = job.Model.Group[0]
    mill = tool(cam, job, job.Tools.Group[0] if job.Tools.Group else None, bit, 1, feed, spindle)
    profiles(cam, job, base, sheet, faces, mill, lay, through)
    drillings(cam, job, base, sheet, feed, spindle)
    engraving(cam, job, lay, sheet, title, feed, spindle)
    return job


def owned(obj, lay, label):
    obj.Label = label
    obj.addProperty("App::PropertyLink", "FabGuideLayout", "FabGuide",
                    QT_TRANSLATE_NOOP("App::Property", "The layout this was made from"))
    obj.FabGuideLayout = lay
    return obj


def part_solids(sheet):
    """Each placed part as a solid on the sheet (z from 0 to the thickness), its dowel holes bored into the
    top face; and the bottom face name of each placement's solid in the compound."""
    thickness = sheet["thickness"]
    by_placement = {}
    for cut in sheet["cuts"]:
        outline = by_placement.setdefault(cut["placement"], {"outline": None, "holes": []})
        if cut["hole"]:
            outline["holes"].append(cut["points"])
        else:
            outline["outline"] = cut["points"]
    solids, order = [], []
    for k, outline in by_placement.items():
        face = layout.polygon_face(outline["outline"], outline["holes"])
        solid = face.extrude(FreeCAD.Vector(0, 0, thickness))
        for drill in sheet["drills"]:
            centre = FreeCAD.Vector(drill["at"][0], drill["at"][1], thickness - drill["depth"])
            if face.isInside(FreeCAD.Vector(centre.x, centre.y, 0), 1e-6, True):
                solid = solid.cut(Part.makeCylinder(drill["diameter"] / 2, drill["depth"] + 1, centre))
        solids.append(solid)
        order.append(k)
    compound = Part.makeCompound(solids)
    faces = {}
    for k, solid in zip(order, solids):
        bottom = min((f for f in solid.Faces if f.Surface.TypeId == "Part::GeomPlane"),
                     key=lambda f: (f.BoundBox.ZMax, -f.Area))
        faces[k] = "Face{}".format(1 + index_of(compound.Faces, bottom))
    return solids, faces


def index_of(faces, face):
    return next(i for i, f in enumerate(faces) if f.isSame(face))


def set_stock(cam, doc, job, sheet):
    """The stock is the master board itself, its lower-left corner at the origin like the layout's."""
    old = job.Stock
    job.Stock = cam.Stock.CreateBox(job, FreeCAD.Vector(sheet["width"], sheet["height"], sheet["thickness"]),
                                    FreeCAD.Placement())
    if old:
        doc.removeObject(old.Name)
    job.Stock.Label = job.Label + " stock"


def tool(cam, job, controller, bit_file, number, feed, spindle, diameter=None):
    """A tool controller of the job with the bit of `bit_file` (its diameter changed to `diameter` if given)."""
    bit = tool_bit(cam, job.Document, bit_file)
    if diameter:
        bit.Diameter = diameter
        bit.Label = "{:g} mm drill".format(diameter)
    if controller is None:
        controller = cam.Controller.Create("TC: {}".format(bit.Label), bit, number)
        job.Proxy.addToolController(controller)
    else:
        old = controller.Tool
        controller.Tool = bit
        if old and job.Document.getObject(old.Name):
            job.Document.removeObject(old.Name)
    controller.Label = "TC: {}".format(bit.Label)
    controller.ToolNumber = number
    controller.HorizFeed = "{} mm/min".format(feed)
    controller.VertFeed = "{} mm/min".format(PLUNGE)
    controller.SpindleSpeed = spindle
    if getattr(bit, "ViewObject", None):
        bit.ViewObject.Visibility = False
    return controller


def tool_bit(cam, doc, bit_file):
    """The tool bit document object of `bit_file`: by FreeCAD 0.20's and 1.0's factory, or 1.1's ToolBit asset."""
    if hasattr(cam.Bit, "Factory"):
        return cam.Bit.Factory.CreateFrom(bit_file)
    return cam.ToolBit.from_file(bit_file).attach_to_doc(doc=doc)


def profiles(cam, job, base, sheet, faces, mill, lay, through):
    """One profile per part outline, and one for each part's holes, in the core's cut order; the cut goes
    through the board, `through` mm below it; holding tags and dogbones dress them as the layout asks."""
    previous = None
    for cut in sheet["cuts"]:
        key = (cut["placement"], cut["hole"])
        if key == previous:
            continue  # the part's other holes: one profile cuts them all
        previous = key
        op = cam.Profile.Create("Profile", parentJob=job)
        op.Label = "{} {}".format(cut["part"], "holes" if cut["hole"] else "outline")
        op.Base = [(base, [faces[cut["placement"]]])]
        op.ToolController = mill
        op.Side = "Outside"  # holes: inside, as CAM profiles them
        op.processHoles, op.processPerimeter = cut["hole"], not cut["hole"]
        op.processCircles = cut["hole"]
        op.UseComp = True
        depth(op, sheet["thickness"], -through)
        dressed = op
        if lay.Dogbone.Value > 0:
            job.Document.recompute()
            dressed = dressup(job, cam.Dogbone.Create(dressed), dressed, op.Label + " dogbones")
        if cut["tabbed"] and not cut["hole"]:
            job.Document.recompute()
            tags(dressup(job, cam.Tags.Create(dressed), dressed, op.Label + " tags"), lay.TabWidth.Value)


def dressup(job, made, base, label):
    """A dressup takes its base's place among the job's operations; the base becomes its child, posted
    through it (as FreeCAD's dressup commands leave them)."""
    group = [op for op in job.Operations.Group if op != made]
    group[group.index(base)] = made
    job.Operations.Group = group
    made.Label = label
    return made


def depth(op, start, final):
    for name, value in (("StartDepth", start), ("FinalDepth", final)):
        op.setExpression(name, None)
        setattr(op, name, value)


def tags(tagged, width):
    """CAM's own holding tags, two as the core's tabs (CutSheet.tabs), placed by CAM on the longest straight
    stretches of the tool path; the core's own places can fall on a finger joint's notch, where CAM drops them."""
    tagged.Width = width
    tagged.Proxy.generateTags(tagged, TAGS)


def drillings(cam, job, base, sheet, feed, spindle):
    """A drilling operation per dowel diameter and depth, with a drill of that diameter."""
    groups = {}
    for drill in sheet["drills"]:
        groups.setdefault((drill["diameter"], drill["depth"]), []).append(drill)
    holes = [(i, f) for i, f in enumerate(base.Shape.Faces, 1) if f.Surface.TypeId == "Part::GeomCylinder"]
    drills = {}
    for (diameter, deep), group in sorted(groups.items()):
        if diameter not in drills:
            drills[diameter] = tool(cam, job, None, library_bits()[BITS["drill"]], 2 + len(drills), feed, spindle,
                                    diameter)
        names = []
        for drill in group:
            names += ["Face{}".format(i) for i, f in holes
                      if abs(f.Surface.Radius - diameter / 2) < 1e-6
                      and abs(f.Surface.Center.x - drill["at"][0]) < 1e-6
                      and abs(f.Surface.Center.y - drill["at"][1]) < 1e-6]
        op = job.Document.addObject("Path::FeaturePython", "Drilling")  # not Create: it looks for holes itself
        op.Proxy = cam.Drilling.ObjectDrilling(op, "Drilling", job)
        op.Label = "Drill {:g} mm, {:g} deep".format(diameter, deep)
        op.Base = [(base, names)]
        op.ToolController = drills[diameter]
        depth(op, sheet["thickness"], sheet["thickness"] - deep)


def engraving(cam, job, lay, sheet, title, feed, spindle):
    """The labels' strokes engraved ENGRAVE_DEPTH into the face with a V-bit."""
    strokes = [stroke for label in sheet["lettering"] for stroke in label if len(stroke) > 1]
    if not strokes:
        return
    z = sheet["thickness"]
    wires = [Part.makePolygon([FreeCAD.Vector(x, y, z) for x, y in stroke]) for stroke in strokes]
    labels = owned(job.Document.addObject("Part::Feature", "CamLabels"), lay, title + " labels")
    labels.Shape = Part.makeCompound(wires)
    labels.Visibility = False
    vbit = tool(cam, job, None, library_bits()[BITS["v-bit"]], 10, feed, spindle)
    op = cam.Engrave.Create("Engrave", parentJob=job)
    op.Label = "Labels"
    op.BaseShapes = [labels]
    op.ToolController = vbit
    depth(op, z, z - ENGRAVE_DEPTH)


def write_gcode(jobs, folder, stem):
    """Posts each job into FOLDER/STEM-sheet-N.nc; returns the paths."""
    os.makedirs(folder, exist_ok=True)
    paths = [os.path.join(folder, "{}-sheet-{}.nc".format(stem, n)) for n in range(1, len(jobs) + 1)]
    for job, path in zip(jobs, paths):
        post(job, path)
    return paths


def post(job, filename):
    """Writes the job's G-code with its post-processor (FreeCAD's own script of that name); returns it."""
    name = job.PostProcessor + "_post.py"
    scripts = [os.path.join(folder, name) for folder in workbench().Preferences.searchPathsPost()]
    script = next((path for path in scripts if os.path.isfile(path)), None)
    if script is None:
        raise CamError(translate("FabGuide", "Job '{}': post-processor '{}' not found").format(
            job.Label, job.PostProcessor))
    spec = importlib.util.spec_from_file_location(job.PostProcessor + "_post", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if os.path.exists(filename):
        os.remove(filename)
    args = job.PostProcessorArgs
    if "--no-show-editor" in str(getattr(module, "TOOLTIP_ARGS", "")):
        args += " --no-show-editor"  # the G-code goes to its file, not to a dialog in the way
    module.export(postables(job), filename, args)  # some return the text, all write it
    if not os.path.isfile(filename):
        raise CamError(translate("FabGuide", "Job '{}': the post-processor '{}' wrote nothing").format(
            job.Label, job.PostProcessor))
    with open(filename) as written:
        return written.read()


def postables(job):
    """What a post-processor writes, in order: each active operation, after its tool controller whenever the
    tool changes (as FreeCAD's Post command orders them without splitting)."""
    result, current = [], None
    for op in job.Operations.Group:
        if not getattr(op, "Active", True):
            continue
        controller = tool_controller(op)
        if controller is not None and controller != current:
            result.append(controller)
            current = controller
        result.append(op)
    return result


def tool_controller(op):
    while op is not None and not hasattr(op, "ToolController"):
        op = getattr(op, "Base", None)
    return op.ToolController if op is not None else None
