"""View providers of the works-like objects: icons, parts holding their boxes in the tree, joint axes drawn
in the 3-D view, conflicting parts shown in red, and the task panels opened by double-click."""
from freecad.fabguide import cuboids
from freecad.fabguide.function import configuration, joints, mechanism, parts, printable, relationships
from freecad.fabguide.gui import editing
from freecad.fabguide.gui.viewproviders import EditedByDoubleClick, ViewProvider

CONFLICT_COLOUR = (0.85, 0.2, 0.2)
AXIS_COLOUR = (1.0, 0.6, 0.1)


class ViewProviderMechanism(EditedByDoubleClick, ViewProvider):
    """Double-click: the configurations panel. After a solve, parts in conflict turn red."""

    ICON = "FabGuide_Mechanism.svg"

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        if prop == "Status":
            show_conflicts(obj)
            for j in mechanism.members(obj, joints.is_joint):
                if j.ViewObject and hasattr(j.ViewObject.Proxy, "redraw"):
                    j.ViewObject.Proxy.redraw()

    def panel_for(self, obj):
        from freecad.fabguide.gui.configurations_panel import ConfigurationsPanel

        return ConfigurationsPanel(obj)


class ViewProviderPart(ViewProvider):
    """Holds its boxes and cavities in the tree."""

    ICON = "FabGuide_Part.svg"

    def claimChildren(self):
        return [b for b in parts.boxes(self.Object) if cuboids.is_box(b)]


class ViewProviderConfiguration(ViewProvider):
    ICON = "FabGuide_Configuration.svg"

    def doubleClicked(self, vobj):
        from freecad.fabguide.gui.configurations_panel import ConfigurationsPanel

        mech = next((m for m in vobj.Object.InList if mechanism.is_mechanism(m)), None)
        if mech is not None:
            editing.show(lambda: ConfigurationsPanel(mech, vobj.Object), mech.Document)
        return True


class ViewProviderJoint(ViewProvider):
    """Draws the joint in orange: a hinge's edge, a slide's direction through its part, a double pivot's link, a
    fixed joint's hold from its part to its base."""

    ICONS = {"hinge": "FabGuide_Hinge.svg", "slide": "FabGuide_Slide.svg", "sliding_hinge": "FabGuide_SlidingHinge.svg",
             "double_pivot": "FabGuide_DoublePivot.svg", "fixed": "FabGuide_Fixed.svg"}

    def icon(self):
        from freecad.fabguide.gui import resources

        obj = getattr(self, "Object", None)
        return resources.icon(self.ICONS[joints.kind(obj)] if obj is not None else "FabGuide_Hinge.svg")

    def attach(self, vobj):
        from pivy import coin

        super().attach(vobj)
        self.coordinates = coin.SoCoordinate3()
        self.lines = coin.SoLineSet()
        style, colour = coin.SoDrawStyle(), coin.SoBaseColor()
        style.lineWidth = 5
        colour.rgb = AXIS_COLOUR
        root = coin.SoSeparator()
        for node in (colour, style, self.coordinates, self.lines):
            root.addChild(node)
        vobj.addDisplayMode(root, "Axis")
        self.redraw()

    def getDisplayModes(self, vobj):
        return ["Axis"]

    def getDefaultDisplayMode(self):
        return "Axis"

    def updateData(self, obj, prop):
        super().updateData(obj, prop)
        self.redraw()

    def redraw(self, motions=None):
        """Draws the joint as modelled, or posed by motions {part label: Placement} (the Configurations preview):
        each point moves with the part that carries it."""
        import FreeCAD

        motions = motions or {}
        points = [motions.get(rider.Label, FreeCAD.Placement()).multVec(p) if rider is not None else p
                  for p, rider in axis_points(self.Object)]
        if hasattr(self, "coordinates"):
            self.coordinates.point.setValues(0, len(points), [tuple(p) for p in points])
            self.coordinates.point.setNum(len(points))
            self.lines.numVertices.setValues(0, len(points) // 2, [2] * (len(points) // 2))
            self.lines.numVertices.setNum(len(points) // 2)


class ViewProviderRelationship(ViewProvider):
    """Double-click: the relationship panel (its status, its corresponding faces, coloured)."""

    ICONS = {"cover": "FabGuide_Cover.svg", "fit_inside": "FabGuide_FitInside.svg", "support": "FabGuide_Support.svg",
             "flush": "FabGuide_Flush.svg", "geometric": "FabGuide_Geometric.svg"}

    def icon(self):
        from freecad.fabguide.gui import resources

        obj = getattr(self, "Object", None)
        return resources.icon(self.ICONS[obj.Proxy.KIND] if obj is not None else "FabGuide_Cover.svg")

    def doubleClicked(self, vobj):
        from freecad.fabguide.gui.relationship_panel import RelationshipPanel

        editing.show(lambda: RelationshipPanel(vobj.Object), vobj.Object.Document)
        return True


class ViewProviderPrintable(ViewProvider):
    ICON = "FabGuide_Printable.svg"


def axis_points(joint):
    """Pairs of points of the lines that show a joint, each with the part that carries it (None: the ground):
    the hinge's edge (points on it stay on it as the part turns), the slide's axis through its part, the double
    pivot's link (a pivot on each part), the fixed joint's hold."""
    import FreeCAD
    import Part

    points = []
    try:
        part, base = joint.Part, joint.Base
        if joints.turns(joint) and joint.Edge:
            edge = joint.Edge[0].Shape.getElement(joint.Edge[1][0])
            points += [(edge.Vertexes[0].Point, part), (edge.Vertexes[-1].Point, part)]
        if joints.slides(joint) and part and part.Cuboids:
            box = part.Cuboids[0].Shape.BoundBox
            direction = FreeCAD.Vector(*[1 if joint.Axis == a else 0 for a in "xyz"])
            half = direction * (0.75 * max(box.XLength, box.YLength, box.ZLength))
            points += [(box.Center - half, part), (box.Center + half, part)]
        if joints.kind(joint) == "double_pivot":
            points += [(joint.Pivot, part), (joint.BasePivot, base)]
        if joints.kind(joint) == "fixed" and part and base:  # from the part to what holds it
            points += [(part.Cuboids[0].Shape.BoundBox.Center, part), (base.Cuboids[0].Shape.BoundBox.Center, base)]
    except (AttributeError, IndexError, ValueError, ReferenceError, Part.OCCError):  # half-made, deleted, no such edge
        return []
    return points


def show_conflicts(mech):
    """Boxes of the parts named by conflicting relationships, or blamed by the conflict (parts that would
    overlap, walls too thin), in red; all others in their own colour."""
    red = set()
    for rel in mechanism.members(mech, relationships.is_relationship):
        if mechanism.in_conflict(rel):
            red.update(b.Name for p in relationship_parts(rel) for b in parts.boxes(p))
    blamed = set(getattr(mech, "Blamed", []))  # overlapping parts, thin walls
    red.update(b.Name for p in mechanism.members(mech, parts.is_part) if p.Label in blamed for b in parts.boxes(p))
    for box in mechanism.boxes(mech):
        if box.ViewObject:
            colour = CONFLICT_COLOUR if box.Name in red else box.ViewObject.ShapeColor[:3]
            box.ViewObject.DiffuseColor = [colour] * max(1, len(box.Shape.Faces))


def relationship_parts(rel):
    found = []
    for name in ("Covering", "Covered", "Inner", "Supporting", "Supported"):
        found += list(getattr(rel, name, []))
    if getattr(rel, "Enclosing", None) is not None:
        found.append(rel.Enclosing)
    for box, _ in getattr(rel, "Faces", []):
        part = parts.part_of(box.InList, box)
        if part is not None:
            found.append(part)
    return found


CLASSES = [(mechanism.is_mechanism, ViewProviderMechanism), (parts.is_part, ViewProviderPart),
           (printable.is_printable, ViewProviderPrintable),
           (joints.is_joint, ViewProviderJoint), (configuration.is_configuration, ViewProviderConfiguration),
           (relationships.is_relationship, ViewProviderRelationship)]


def attach(obj):
    """Gives a works-like object its view provider (when there is a GUI); returns the object."""
    if getattr(obj, "ViewObject", None) is not None:
        for test, cls in CLASSES:
            if test(obj):
                cls(obj.ViewObject)
    return obj


def colour_bodies(made, bodies):
    """Each printed body in its part's colour; the swept cavities see-through."""
    colours = {p.Label: p.Cuboids[0].ViewObject.ShapeColor for p in mechanism.members(made.Mechanism, parts.is_part)
               if p.Cuboids and p.Cuboids[0].ViewObject}
    for body in bodies:
        if body.ViewObject is None:
            continue
        if body.BodyName == printable.CAVITIES:
            body.ViewObject.Transparency = 80
            body.ViewObject.ShapeColor = (1.0, 0.6, 0.1)
        else:
            body.ViewObject.ShapeColor = colours.get(body.BodyName, AXIS_COLOUR)


def style_cavity(box):
    """Cavities are see-through, so the part around them shows."""
    if box.ViewObject is not None:
        box.ViewObject.Transparency = 75
        box.ViewObject.ShapeColor = (1.0, 1.0, 1.0)
