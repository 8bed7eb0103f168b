#include "Printable/Joints.h"

#include "Function/DoublePivot.h"
#include "Function/Pose.h"
#include "Geometry/Interval.h"
#include "Printable/Motion.h"
#include "Printable/Sweeps.h"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <Bnd_Box.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Quaternion.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fabguide::printable {

namespace {

struct Radii {
    double outer, pin;
};

/// The thinnest side of the cuboids.
double thinnestOf(const Model& m, std::initializer_list<int> cuboids)
{
    double side = 1e300;
    for (int c : cuboids)
        side = std::min(side, m.cuboids[c].thinnest());
    return side;
}

constexpr double kLeastPin = 0.4, kLeastWall = 0.8, kWallShare = 0.3;

/// The outer radius of the least round parts that hold a pin with gap g: the least pin, the gap and the wall
/// sized() puts round it (its 30 % of the radius is the more from a 2.67 mm radius on, so from a 1.47 mm
/// gap).
double leastOuter(double g)
{
    return std::max(kLeastPin + g + kLeastWall, (kLeastPin + g) / (1 - kWallShare));
}

/// The sizes of a joint's round parts (4.5.2) on parts `side` thin: outer radius half of it, the pin inside
/// it with the gap and a wall around it (0.8 mm, or 30 % of the radius), or, where that leaves less than the
/// least pin (0.4 mm radius), as scaled-down parts do, the least that holds one.
Radii sized(double side, double g)
{
    const double outer = std::max(side / 2, leastOuter(g));
    return {outer, outer - g - std::max(kLeastWall, kWallShare * outer)};
}

/// sized() for a joint's cuboids: round parts that stand proud of a thin part, up to twice its thickness,
/// noted; thinner parts are refused, their thickness said to four digits (1.597 mm, not the 1.6 they need).
Radii radii(const Model& m, const Joint& joint, std::initializer_list<int> cuboids, double g, Printable& out)
{
    const double side = thinnestOf(m, cuboids);
    int thinCuboid = *cuboids.begin();
    for (int c : cuboids)
        if (m.cuboids[c].thinnest() == side)
            thinCuboid = c;
    const double least = leastOuter(g);
    if (side < least)
        throw std::invalid_argument("joint '" + joint.name + "': its parts are too thin (cuboid '" +
                                    m.cuboids[thinCuboid].name + "' is " + function::millimetres(side, 4) +
                                    " mm as printed; a pin and its yokes need " +
                                    function::millimetres(least) + " mm with a " + function::millimetres(g) +
                                    " mm gap): make it thicker, or print larger");
    const Radii r = sized(side, g);
    if (r.outer > side / 2) {
        std::ostringstream note;
        note.precision(2);
        note << std::fixed << joint.name << ": its round parts are " << 2 * r.outer
             << " mm across, proud of its " << side << " mm thin part (the least that holds a "
             << 2 * kLeastPin << " mm pin with a " << g << " mm gap)";
        out.notes.push_back(note.str());
    }
    return r;
}

/// A double pivot link's head on its pins: a third of the round parts' radius, at least 1 mm.
double head(const Radii& r)
{
    return std::max(1.0, r.outer / 3);
}

/// Bridge c, when all it meets of cuboid onEdge lies in one of its cavities or that cavity's mouth (across
/// every axis but `along`), carried on to the cavity's nearest wall that is no opening, r into it.
Coordinates overWalls(const Model& m, int onEdge, Coordinates c, int along, double r)
{
    constexpr double hair = 1e-6;
    const Coordinates& base = m.cuboids[onEdge].coordinates;
    for (size_t k = 0; k < m.cuboids.size(); ++k) {
        const Coordinates& cavity = m.cuboids[k].coordinates;
        bool inAir = m.cuboids[k].within == onEdge;
        for (int a = 0; a < 3 && inAir; ++a)  // the part of c at or in the cuboid, within the cavity
            inAir = a == along || (std::max(c[2 * a], base[2 * a]) >= cavity[2 * a] - hair &&
                                   std::min(c[2 * a + 1], base[2 * a + 1]) <= cavity[2 * a + 1] + hair);
        if (!inAir)
            continue;
        int wall = -1;
        double reach = std::numeric_limits<double>::infinity();
        for (int side = 0; side < 6; ++side)
            if (side / 2 != along && !function::isOpening(m, static_cast<int>(k), side))
                if (const double d = side % 2 ? cavity[side] + r - c[side] : c[side] - (cavity[side] - r);
                    d < reach)
                    reach = d, wall = side;
        if (wall >= 0)
            c[wall] = cavity[wall] + (wall % 2 ? r : -r);
        return c;
    }
    return c;
}

/// The box joining a hinge's yokes to the cuboid they hang on across the stand-off, between `from` and `to`
/// along the axis: from the axis to the cuboid, r deep into it where the axis runs level with its face; off
/// the cuboid's edge (standing off two faces), r past the edge along the further stand-off, so that it rests
/// on the nearer face rather than meeting the cuboid along the edge alone (one body, not a yoke in pieces).
/// None when the axis lies in the cuboid's material. Where it would meet the cuboid only in a cavity's mouth
/// (a pocket door hinged 2 mm inside its bay's side: the yokes and their bridge stood in the bay, apart from
/// the carcass), or the axis runs in a cavity's air (a pocket door hinged inside its bay's mouth), it is
/// carried across the cavity to its nearest wall (overWalls).
std::optional<Coordinates> bridge(const Model& m, int onEdge, const gp_Ax1& axis, int along, double from,
                                  double to, double r)
{
    const Cuboid& base = m.cuboids[onEdge];
    const auto low = [&](int a) { return base.at(static_cast<Side>(2 * a)); };
    const auto high = [&](int a) { return base.at(static_cast<Side>(2 * a + 1)); };
    const auto standOff = [&](int a) {
        const double x = coord(axis.Location(), a);
        return std::max(x - high(a), low(a) - x);
    };
    Coordinates c{};
    std::vector<int> off;  // the axes across which it stands off the cuboid
    for (int a = 0; a < 3; ++a) {
        const double x = coord(axis.Location(), a);
        if (a == along) {
            c[2 * a] = from, c[2 * a + 1] = to;
        } else if (standOff(a) > 1e-3) {
            c[2 * a] = std::min(x, high(a)), c[2 * a + 1] = std::max(x, low(a));
            off.push_back(a);
        } else {  // level with a face or within: r of the cuboid on the side of the axis' other offset
            c[2 * a] = std::max(low(a), x - r), c[2 * a + 1] = std::min(high(a), x + r);
        }
    }
    if (off.empty()) {
        const Coordinates carried = overWalls(m, onEdge, c, along, r);
        return carried == c ? std::nullopt : std::optional(carried);
    }
    if (off.size() == 2) {
        const int a = standOff(off[0]) > standOff(off[1]) ? off[0] : off[1];
        if (coord(axis.Location(), a) > high(a))
            c[2 * a] = std::max(low(a), high(a) - r);
        else
            c[2 * a + 1] = std::min(high(a), low(a) + r);
    }
    return overWalls(m, onEdge, c, along, r);
}

/// A sliding joint's travel: the least and greatest offset over its configurations (0 as modelled).
std::pair<double, double> travel(const Model& m, int j)
{
    double low = 0, high = 0;
    for (size_t k = 0; k < m.configurations.size() && m.joints[j].slides(); ++k)
        if (const function::JointPose* pose = poseOf(m, j, static_cast<int>(k))) {
            low = std::min(low, pose->offset);
            high = std::max(high, pose->offset);
        }
    return {low, high};
}

/// A rod along a hinge's axis, made a slot over a sliding hinge's travel (longer, where it slides along the
/// axis): slotted yokes and their clearances.
TopoDS_Shape slotted(const Model& m, int j, const gp_Pnt& at, int along, double from, double to, double r)
{
    const Joint& joint = m.joints[j];
    const auto [low, high] = travel(m, j);
    const gp_Vec axis(joint.axis == 0, joint.axis == 1, joint.axis == 2);
    return joint.axis == along
               ? rod(at, along, from + low, to + high, r)
               : slot(at.Translated(axis * low), at.Translated(axis * high), along, from, to, r);
}

/// The box round `slotted`'s solid, which sweeps take in its place: OpenCASCADE loses what the round end of a
/// slot sweeps turning about another axis (a sliding hinge's yokes as its part turns).
Coordinates slottedBox(const Model& m, int j, const gp_Pnt& at, int along, double from, double to, double r)
{
    const auto [low, high] = travel(m, j);
    Coordinates c;
    for (int a = 0; a < 3; ++a) {
        c[2 * a] = a == along ? from : coord(at, a) - r;
        c[2 * a + 1] = a == along ? to : coord(at, a) + r;
        if (a == m.joints[j].axis && m.joints[j].slides())
            c[2 * a] += low, c[2 * a + 1] += high;
    }
    return c;
}

/// How far the point on the face lies from the face's edges.
double roomOnFace(const Model& m, const function::Face& face, const gp_Pnt& p)
{
    const Cuboid& c = m.cuboids[face.cuboid];
    double room = 1e300;
    for (int a = 0; a < 3; ++a)
        if (a != axisOf(face.side))
            room = std::min({room, coord(p, a) - c.at(static_cast<Side>(2 * a)),
                             c.at(static_cast<Side>(2 * a + 1)) - coord(p, a)});
    return room;
}

/// The link between two pivots at `depth` .. `depth` + `thick` from `face` along normal n (`inward` = -1 or 1
/// the way in): a bar with round ends, a hole the gap round each pin.
TopoDS_Shape pivotLink(const gp_Pnt& pivot, const gp_Pnt& base, int n, double face, double inward,
                       double depth, double thick, const Radii& r, double g)
{
    const auto span = [&](const gp_Pnt& p, double from, double to, double radius) {
        return rodFrom(p, n, face, inward, from, to, radius);
    };
    const gp_Vec along(pivot, base);
    const gp_Dir normal(n == 0, n == 1, n == 2), x(along), y = normal.Crossed(x);
    gp_Pnt corner = pivot.Translated(gp_Vec(y) * -r.outer);
    setCoord(corner, n, std::min(face + inward * depth, face + inward * (depth + thick)));
    TopoDS_Shape bar =
        BRepPrimAPI_MakeBox(gp_Ax2(corner, normal, x), along.Magnitude(), 2 * r.outer, thick).Shape();
    bar = fuse(bar,
               fuse(span(pivot, depth, depth + thick, r.outer), span(base, depth, depth + thick, r.outer)));
    return cut(bar, fuse(span(pivot, depth - 1, depth + thick + 1, r.pin + g),
                         span(base, depth - 1, depth + thick + 1, r.pin + g)));
}

/// A double pivot whose pivot faces face each other (the sofa bunk's bunk against its ends): the link lies in
/// a round recess in the base part, the gap below its face, as deep as the link and two gaps, wide enough for
/// the link turning all the way round its base pivot; each part's pin runs through the link's end, the part's
/// stopping the gap short of the recess floor. The faces between them keep the link in.
void addRecessedPivot(const Model& m, int j, double g, std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    const Joint& joint = m.joints[j];
    const Radii r = radii(m, joint, {joint.pivotFace.cuboid, joint.basePivotFace.cuboid}, g, out);
    const int n = function::pivotPlane(m, joint).normal;
    const double face = m.cuboids[joint.basePivotFace.cuboid].at(joint.basePivotFace.side);
    const double inward = static_cast<int>(joint.basePivotFace.side) % 2 ? -1 : 1;  // into the base part
    const double link = r.outer;
    const auto [pivot, base] = pivotPoints(m, joint);
    const auto span = [&](const gp_Pnt& p, double from, double to, double radius) {
        return rodFrom(p, n, face, inward, from, to, radius);
    };
    const double reach = gp_Vec(pivot, base).Magnitude() + r.outer + g;
    shapes[joint.base] = cut(shapes[joint.base], span(base, -1, 2 * g + link, reach));
    shapes[joint.base] = fuse(shapes[joint.base], span(base, 0, 2 * g + link + 1, r.pin));
    shapes[joint.part] = fuse(shapes[joint.part], span(pivot, -1 - g, g + link, r.pin));
    out.bodies.push_back({linkName(joint), -1, j, pivotLink(pivot, base, n, face, inward, g, link, r, g)});
}

/// The nearest other hinge whose axis runs beside joint j's (parallel, overlapping along it) within `reach`
/// (two doors hinged on neighbouring edges): the distance between the axes and its index, -1 for none.
std::pair<double, int> nearestHinge(const Model& m, int j, const gp_Ax1& axis, int along, double reach)
{
    std::pair<double, int> nearest{reach, -1};
    const Cuboid& own = m.cuboids[m.joints[j].edgeA.cuboid];
    for (size_t k = 0; k < m.joints.size(); ++k) {
        const Joint& other = m.joints[k];
        if (static_cast<int>(k) == j || !other.turns())
            continue;
        const gp_Ax1 beside = hingeAxis(m, other);
        const Cuboid& its = m.cuboids[other.edgeA.cuboid];
        const double overlap =
            overlapOf(fabguide::along(own.coordinates, along), fabguide::along(its.coordinates, along));
        if (!beside.IsParallel(axis, 1e-9) || overlap <= 0)
            continue;
        gp_Vec apart(axis.Location(), beside.Location());
        setCoord(apart, along, 0);
        if (apart.Magnitude() < nearest.first)
            nearest = {apart.Magnitude(), static_cast<int>(k)};
    }
    return nearest;
}

/// Hinge k's part gives way, along [lo, hi], round its own axis out to `radius` (another hinge's round parts
/// and the gap: turning about that axis it stays clear of them) and round `bridges` (the other hinge's, grown
/// by the gap) all along its turns.
void giveWay(const Model& m, int k, int along, double lo, double hi, double radius,
             const std::vector<Coordinates>& bridges, double g, std::vector<TopoDS_Shape>& shapes)
{
    const gp_Ax1 axis = hingeAxis(m, m.joints[k]);
    std::vector<TopoDS_Shape> around{rod(axis.Location(), along, lo - g, hi + g, radius)};
    for (size_t c = 0; c < m.configurations.size(); ++c)
        if (const function::JointPose* pose = poseOf(m, k, static_cast<int>(c)))
            for (const TopoDS_Shape& swept :
                 turnedThenShifted(bridges, axis, -pose->angle * kPi / 180, {0, 0, 0}))
                around.push_back(swept);
    TopoDS_Shape& part = shapes[m.joints[k].part];
    part = cut(part, around);
}

/// A part that stands within the gap of hinge j's round parts as printed (along `span`, out to `radius` round
/// the axis, the gap included) or of the bridges that hold them off the base (`clear`, grown by the gap), not
/// only on its edge, gives way round them: where it is printed, and, when it slides past them or turns past
/// them on the base by a hinge of its own, along its motion in its own frame (their boxes where they go). A
/// drawer front just above a flap's hinge gets a groove under it, where a thinner pin could not clear (too
/// little room for the least pin and its gap); a door beside another door's hinge is trimmed along its turn
/// where the yokes stand; a pull-out's front 0.1 mm beside a door's hinge, proud of the door, is notched
/// where it stands. Noted.
void makeWayPastRoundParts(const Model& m, int j, int base, std::pair<double, double> span, double radius,
                           const std::vector<Coordinates>& clear, std::vector<TopoDS_Shape>& shapes,
                           Printable& out)
{
    const Joint& joint = m.joints[j];
    const gp_Ax1 axis = hingeAxis(m, joint);
    const int along = hingeAlong(joint);
    std::vector<Coordinates> room{Coordinates{}};
    for (int a = 0; a < 3; ++a) {
        room[0][2 * a] = a == along ? span.first : coord(axis.Location(), a) - radius;
        room[0][2 * a + 1] = a == along ? span.second : coord(axis.Location(), a) + radius;
    }
    room.insert(room.end(), clear.begin(), clear.end());
    std::vector<TopoDS_Shape> roomSolids{rod(axis.Location(), along, span.first, span.second, radius)};
    for (const Coordinates& c : clear)
        roomSolids.push_back(box(c));
    Bnd_Box reach;
    for (const TopoDS_Shape& r : roomSolids)
        BRepBndLib::Add(r, reach);
    for (int q = 0; q < static_cast<int>(shapes.size()); ++q) {
        if (q == joint.part || q == base || function::carrierOf(m, q) == joint.part ||
            (standsStill(m, q) && standsStill(m, base)))
            continue;
        Bnd_Box its;
        BRepBndLib::Add(shapes[q], its);
        if (reach.IsOut(its) ||
            std::none_of(roomSolids.begin(), roomSolids.end(), [&](const TopoDS_Shape& r) {
                return volumeOf(BRepAlgoAPI_Common(r, shapes[q]).Shape()) >= 1e-3;
            }))
            continue;
        std::vector<TopoDS_Shape> around;
        for (int k = 0; k < static_cast<int>(m.configurations.size()); ++k) {
            const auto apart = [&](double t) {
                return partMotion(m, base, k, t).Inverted() * partMotion(m, q, k, t);
            };
            // q stays with base in k or turns round the same axis (its points stay put): the round parts stay
            // put; sliding along the axis moves it past them (a sliding door under a flap's hinge).
            const gp_Trsf end = apart(1);
            if (axis.Location().Transformed(end).Distance(axis.Location()) < 1e-6 &&
                axis.Direction().Transformed(end).Angle(axis.Direction()) < 1e-9)
                continue;
            bool slides = true;
            for (int step = 1; step <= 8; ++step)
                slides = slides && std::abs(apart(step / 8.0).GetRotation().GetRotationAngle()) < 1e-12;
            if (!slides && hingeOn(m, q, base, k) < 0)
                continue;  // a groove along turns upon turns costs more cuts than a part has time for
            for (const TopoDS_Shape& swept : pathRelative(m, k, base, q, room))
                around.push_back(swept);
        }
        around.insert(around.end(), roomSolids.begin(), roomSolids.end());
        shapes[q] = cut(shapes[q], around);
        out.notes.push_back(m.parts[q].name + ": grooved to clear the round parts of '" + joint.name + "'");
    }
}

}  // namespace

std::string linkName(const Joint& joint)
{
    const bool named = joint.name.size() >= 4 && joint.name.compare(joint.name.size() - 4, 4, "link") == 0;
    return named ? joint.name : joint.name + " link";  // "upper link", not "upper link link"
}

Model needingRoundParts(Model model, double g, double scale)
{
    const double least = leastOuter(g) / scale;
    for (const Joint& joint : model.joints) {
        if (joint.turns())
            model.cuboids[joint.edgeA.cuboid].least = least;
        if (joint.type == Joint::Type::DoublePivot)
            for (int c : {joint.pivotFace.cuboid, joint.basePivotFace.cuboid})
                model.cuboids[c].least = least;
    }
    return model;
}

int cuboidAtEdge(const Model& m, const Joint& joint)
{
    const double thin = m.cuboids[joint.edgeA.cuboid].thinnest();
    for (double reach : {1e-3, thin, 2 * thin})
        if (const int c = function::cuboidNear(m, joint, reach); c >= 0)
            return c;
    return -1;
}

void addHinge(const Model& m, int j, const std::vector<Coordinates>& gapped, double g,
              std::vector<TopoDS_Shape>& shapes, Printable& out, int place)
{
    const Joint& joint = m.joints[j];
    const gp_Ax1 axis = hingeAxis(m, joint);
    const int along = hingeAlong(joint);
    const int onEdge = cuboidAtEdge(m, joint);
    if (onEdge < 0)  // printed without a hinge, the part would come out loose
        throw std::invalid_argument(
            "joint '" + joint.name + "': no other part lies along its edge, or within " +
            function::millimetres(2 * m.cuboids[joint.edgeA.cuboid].thinnest()) +
            " mm of it, to hold the hinge's yokes: move the edge onto the part it turns on");
    const int base = function::partOf(m, onEdge);
    const Coordinates& edge = gapped[joint.edgeA.cuboid];  // the pin and yokes end where the part does
    double lo = edge[2 * along], hi = edge[2 * along + 1];
    Radii r = radii(m, joint, {joint.edgeA.cuboid, onEdge}, g, out);
    // Places 4-7 are 0-3 with round parts three quarters as thick (not below the least): a neighbour that
    // closes within the gap of the round parts (the drawer front above a flap's hinge) is cleared that way.
    const bool slim = place >= 4;
    place %= 4;
    if (slim) {
        const double least = leastOuter(g);
        if (r.outer <= least)
            throw NoRoom("joint '" + joint.name + "': its round parts are as thin as they print");
        r = sized(2 * std::max(least, 0.75 * r.outer), g);
        std::ostringstream note;
        note.precision(2);
        note << std::fixed << joint.name << ": its round parts made " << 2 * r.outer
             << " mm across to clear a neighbour";
        out.notes.push_back(note.str());
    }
    // Round parts share the room with a neighbouring hinge's (a door hinged 4 mm from the next door's
    // hinge): each takes half of it, less half the gap. Where that leaves too little for a pin, the two
    // hinges take the two halves of the length they share instead (the first joint the lower half), and each
    // door gives way round its own axis, out to the other hinge's round parts and the gap, along the other's
    // half: turning about its own axis, it stays clear of them.
    std::pair<int, double> beside{-1, 0};  // the hinge sharing the edge's length, and how far off its axis is
    if (const auto [near, k] = nearestHinge(m, j, axis, along, 2 * r.outer + g); k >= 0) {
        if ((near - g) / 2 >= leastOuter(g)) {
            r = sized(near - g, g);
        } else {
            const Coordinates& its = gapped[m.joints[k].edgeA.cuboid];
            const double mid = (std::max(lo, its[2 * along]) + std::min(hi, its[2 * along + 1])) / 2;
            if (j < k)
                hi = std::min(hi, mid - g / 2);
            else
                lo = std::max(lo, mid + g / 2);
            if (hi - lo < 4 * (r.outer + g))
                throw NoRoom("joint '" + joint.name + "': no room for its pin and yokes beside joint '" +
                             m.joints[k].name + "': their axes are " + function::millimetres(near) +
                             " mm apart as printed and share " + function::millimetres(2 * (hi - lo)) +
                             " mm along them: move the parts apart, or print larger");
            beside = {k, near};
        }
    }
    // Its place: along the whole length, or its middle, first or second half.
    const double half = (hi - lo) / 2;
    if (place > 0 && half < 4 * (r.outer + g))
        throw NoRoom("joint '" + joint.name + "': its edge is too short for its round parts in half " +
                     "its length");
    if (place == 1)
        lo += half / 2, hi -= half / 2;
    else if (place == 2)
        hi = lo + half;
    else if (place == 3)
        lo = hi - half;
    const double yoke = (hi - lo) / 4;
    const gp_Pnt at = axis.Location();
    TopoDS_Shape& part = shapes[joint.part];
    TopoDS_Shape& other = shapes[base];
    // The moving part gives way around the yokes and their bridges to a part standing off the edge, the
    // other part around the knuckle. They stay put while the part turns (and a sliding hinge's part slides)
    // past them: it gives way around them as they stand in its own frame along the way, the yokes slotted
    // along a sliding hinge's travel.
    const TopoDS_Shape yokes = fuse(slotted(m, j, at, along, lo - g, lo + yoke + g, r.outer + g),
                                    slotted(m, j, at, along, hi - yoke - g, hi + g, r.outer + g));
    std::vector<Coordinates> bridges, clear;
    for (const auto& [from, to] : {std::pair{lo, lo + yoke}, std::pair{hi - yoke, hi}})
        if (const std::optional<Coordinates> b = bridge(m, onEdge, axis, along, from, to, r.outer)) {
            bridges.push_back(*b);
            clear.push_back(*b);
            for (int i = 0; i < 6; ++i)
                clear.back()[i] += i % 2 ? g : -g;
        }
    if (beside.first >= 0)
        giveWay(m, beside.first, along, lo, hi, beside.second + r.outer + g, clear, g, shapes);
    // In its frame they turn back about the axis, then (turned back) slide back along the turned-back axis;
    // round yokes that only turn need no turning back.
    std::vector<TopoDS_Shape> around{yokes};
    std::vector<Coordinates> moving = clear;
    for (const Coordinates& c : clear)
        around.push_back(box(c));
    if (joint.slides())
        moving.insert(moving.end(), {slottedBox(m, j, at, along, lo - g, lo + yoke + g, r.outer + g),
                                     slottedBox(m, j, at, along, hi - yoke - g, hi + g, r.outer + g)});
    for (size_t k = 0; k < m.configurations.size(); ++k)
        if (const function::JointPose* pose = poseOf(m, j, static_cast<int>(k)))
            for (const TopoDS_Shape& swept : hingeSweep(m, joint, *pose, moving, -1))
                around.push_back(swept);
    part = cut(part, around);
    // The knuckle's slot, in every part it would reach: the base, and a part beside it that the round
    // reaches (a wall's next carcass, flush with the base, whose corner the knuckle would graze).
    const TopoDS_Shape slot = slotted(m, j, at, along, lo + yoke, hi - yoke, r.outer + g);
    Bnd_Box reach;
    BRepBndLib::Add(slot, reach);
    for (size_t p = 0; p < shapes.size(); ++p) {
        Bnd_Box its;
        BRepBndLib::Add(shapes[p], its);
        if (static_cast<int>(p) != joint.part && function::carrierOf(m, static_cast<int>(p)) != joint.part &&
            !reach.IsOut(its) && (static_cast<int>(p) == base || touches(slot, shapes[p])))
            shapes[p] = cut(shapes[p], slot);
    }
    // The pin's hole, the gap past its ends, through the other part's corner and through each yoke, before
    // they are joined.
    const TopoDS_Shape hole = slotted(m, j, at, along, lo - g - 1, hi + g + 1, r.pin + g);
    other = fuse(cut(other, hole), fuse(cut(slotted(m, j, at, along, lo, lo + yoke, r.outer), hole),
                                        cut(slotted(m, j, at, along, hi - yoke, hi, r.outer), hole)));
    for (const Coordinates& b : bridges)
        other = fuse(other, cut(box(b), hole));
    part = fuse(part,
                fuse(rod(at, along, lo + yoke + g, hi - yoke - g, r.outer), rod(at, along, lo, hi, r.pin)));
    makeWayPastRoundParts(m, j, base, {lo - g, hi + g}, r.outer + g, clear, shapes, out);
}

std::vector<RailPlace> railPlaces(const Model& m, int j)
{
    const int a = m.joints[j].axis;
    std::vector<RailPlace> places;
    for (int c : m.parts[m.joints[j].part].cuboids)
        for (size_t q = 0; q < m.cuboids.size(); ++q) {
            if (m.cuboids[c].cavity() || m.cuboids[q].cavity() ||
                function::partOf(m, static_cast<int>(q)) == m.joints[j].part)
                continue;
            const auto& x = m.cuboids[c].coordinates;
            const auto& y = m.cuboids[q].coordinates;
            for (int n = 0; n < 3; ++n) {
                const int face = std::abs(x[2 * n] - y[2 * n + 1]) < 1e-6 ? 2 * n + 1
                                 : std::abs(x[2 * n + 1] - y[2 * n]) < 1e-6
                                     ? 2 * n
                                     : -1;  // q's face the part rests on
                if (n == a || face < 0)
                    continue;
                const int across = 3 - a - n;
                const double from = std::max(x[2 * a], y[2 * a]), to = std::min(x[2 * a + 1], y[2 * a + 1]);
                // The contact across the axis, less the cavities of q that open under it (a pencil case's
                // well).
                std::vector<std::pair<double, double>> strips{
                    {std::max(x[2 * across], y[2 * across]), std::min(x[2 * across + 1], y[2 * across + 1])}};
                for (const Cuboid& hollow : m.cuboids) {
                    const auto& h = hollow.coordinates;
                    if (hollow.within != static_cast<int>(q) || std::abs(h[face] - y[face]) > 1e-6 ||
                        overlapOf({from, to}, along(h, a)) <= 1e-9)
                        continue;
                    std::vector<std::pair<double, double>> left;
                    for (const auto& [low, high] : strips)
                        for (const auto& [l, r] : {std::pair{low, std::min(high, h[2 * across])},
                                                   std::pair{std::max(low, h[2 * across + 1]), high}})
                            if (r - l > 1e-9)
                                left.emplace_back(l, r);
                    strips = left;
                }
                for (const auto& [low, high] : strips)
                    if (high - low > 1e-9 && to - from > 1e-9)
                        places.push_back({c, static_cast<int>(q), n, across, face % 2 ? 1.0 : -1.0, y[face],
                                          from, to, low, high});
            }
        }
    std::stable_sort(places.begin(), places.end(), [](const RailPlace& p, const RailPlace& q) {
        return (p.high - p.low) * (p.to - p.from) > (q.high - q.low) * (q.to - q.from);
    });
    return places;
}

void addRails(const Model& m, int j, const std::vector<Coordinates>& gapped, double g,
              std::vector<TopoDS_Shape>& shapes, int place)
{
    const Joint& joint = m.joints[j];
    const int a = joint.axis;
    const std::vector<RailPlace> places = railPlaces(m, j);
    if (places.empty())  // printed without rails, the part would come out loose
        throw std::invalid_argument("joint '" + joint.name + "': nothing guides part '" +
                                    m.parts[joint.part].name +
                                    "' (no cavity of another part holds it and it rests on no other part): "
                                    "put it in a cavity or against the part it slides on");
    const RailPlace& at = places[std::min(static_cast<size_t>(place), places.size() - 1)];
    const auto& x = m.cuboids[at.mover].coordinates;
    const auto& y = m.cuboids[at.base].coordinates;
    const int normal = at.normal, across = at.across;
    const double dir = at.dir, plane = at.plane, from = at.from, to = at.to;
    const double thin = std::min(gapped[at.mover][2 * normal + 1] - gapped[at.mover][2 * normal],
                                 y[2 * normal + 1] - y[2 * normal]);
    // The tongue (0.4 of the thinner part deep, from 2 to 3 times that wide) stands on the strip's material,
    // its groove (the gap all round) a wall inside the part's sides: the deepest that fits, as near the
    // strip's middle as that allows (a pencil case's lid on its 4 mm wall: 1.1 mm deep, the wall's inner
    // half).
    const double sideLow = gapped[at.mover][2 * across] + kLeastWall,
                 sideHigh = gapped[at.mover][2 * across + 1] - kLeastWall;
    const auto centres = [&](double depth) {  // the lowest and highest centre a tongue this deep fits at
        const double foot = depth + 0.5 * depth / (depth + 1), groove = 1.5 * depth + 1.5 * g;
        return std::pair{std::max(at.low + foot, sideLow + groove),
                         std::min(at.high - foot, sideHigh - groove)};
    };
    const auto fits = [&](double depth) { return centres(depth).first <= centres(depth).second; };
    double h = 0.4 * thin;
    if (!fits(h)) {
        double deeper = h;
        h = 0;
        for (int step = 0; step < 40; ++step)
            (fits((h + deeper) / 2) ? h : deeper) = (h + deeper) / 2;
    }
    const double width = at.high - at.low,
                 centre = std::clamp((at.low + at.high) / 2, centres(h).first, centres(h).second);
    if (h < 2 * g || !fits(h) || to - from < 4 * h) {
        // What the least rails (2g deep) need here: the strip as much wider as their centres are short of
        // room, 4 depths long, on parts 2.5 depths thick.
        const double wider = std::max(0.0, centres(2 * g).first - centres(2 * g).second);
        throw NoRoom("joint '" + joint.name + "': part '" + m.parts[joint.part].name + "' rests on '" +
                     m.cuboids[at.base].name + "' over " + function::millimetres(width) + " x " +
                     function::millimetres(to - from) + " mm of material, too little for rails " +
                     function::millimetres(h) + " mm deep at a " + function::millimetres(g) +
                     " mm gap (the least rails, " + function::millimetres(2 * g) + " mm deep, need " +
                     function::millimetres(width + wider) + " x " + function::millimetres(8 * g) +
                     " mm here, and parts " + function::millimetres(5 * g) +
                     " mm thick): widen the contact, or print larger");
    }
    // The dovetail's cross-section (across, normal), narrow at the base (1 mm into it), wide at the top; the
    // groove's is the same offset outwards by the gap, edge by edge.
    auto tongue = [&](double grow, double start, double length) {
        const gp_XY corners[4] = {{centre - h, plane - dir},
                                  {centre + h, plane - dir},
                                  {centre + 1.5 * h, plane + dir * h},
                                  {centre - 1.5 * h, plane + dir * h}};
        auto offsetLine = [&](int i) {  // edge i moved out by `grow`: a point on it and its direction
            const gp_XY d = (corners[(i + 1) % 4] - corners[i]).Normalized();
            gp_XY out(d.Y(), -d.X());  // outward for the corners' winding when dir > 0
            if ((out * (corners[i] - gp_XY(centre, plane + dir * h / 2))) < 0)
                out.Reverse();
            return std::pair{corners[i] + out * grow, d};
        };
        auto point = [&](int i) {  // where the offset edges i − 1 and i meet
            const auto [p1, d1] = offsetLine((i + 3) % 4);
            const auto [p2, d2] = offsetLine(i);
            const double t = ((p2 - p1) ^ d2) / (d1 ^ d2);
            const gp_XY uv = p1 + d1 * t;
            gp_Pnt p;
            setCoord(p, a, start);
            setCoord(p, across, uv.X());
            setCoord(p, normal, uv.Y());
            return p;
        };
        BRepBuilderAPI_MakePolygon outline(point(0), point(1), point(2), point(3), true);
        gp_Vec along(0, 0, 0);
        setCoord(along, a, length);
        return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(outline.Wire()).Face(), along).Shape();
    };
    const auto [low, high] = travel(m, j);
    const int q = function::partOf(m, at.base);
    shapes[q] = fuse(shapes[q], tongue(0, from, to - from));
    // In the part's frame the tongue runs back over the travel; the groove is open at the part's ends.
    shapes[joint.part] = cut(shapes[joint.part], tongue(g, std::min(from, x[2 * a]) - high - 1,
                                                        std::max(to, x[2 * a + 1]) - from + high - low + 2));
}

void addDoublePivot(const Model& m, int j, double g, std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    const Joint& joint = m.joints[j];
    if (joint.pivotFace.side != joint.basePivotFace.side)
        return addRecessedPivot(m, j, g, shapes, out);
    const function::PivotPlane plane = function::pivotPlane(m, joint);
    const auto [pivot, base] = pivotPoints(m, joint);
    Radii r = radii(m, joint, {joint.pivotFace.cuboid, joint.basePivotFace.cuboid}, g, out);
    // Round parts no wider than the faces they stand on round the pivots: a pivot 6 mm under a crate base's
    // top had a pin 18 mm across standing above the top, in the way of the board folding over it.
    if (const double room =
            std::min(roomOnFace(m, joint.pivotFace, pivot), roomOnFace(m, joint.basePivotFace, base));
        room < r.outer)
        r = sized(2 * std::max(room, leastOuter(g)), g);
    const int n = plane.normal;
    const double face = m.cuboids[joint.pivotFace.cuboid].at(joint.pivotFace.side);
    const double outward = static_cast<int>(joint.pivotFace.side) % 2 ? 1 : -1;
    const double link = r.outer;
    // The link's layer: the gap off the faces; a four-bar's second link on the same faces beyond the first
    // one's heads, so the two may cross (the solve keeps each off the other's pins).
    double depth = g;
    if (const Joint* first = function::fourBarPartner(m, joint);
        first && first < &joint && first->pivotFace.side == joint.pivotFace.side) {
        const Radii under = sized(thinnestOf(m, {first->pivotFace.cuboid, first->basePivotFace.cuboid}), g);
        depth += 2 * g + under.outer + head(under);
    }
    // Along the normal, from the face outwards.
    const auto span = [&](const gp_Pnt& p, double from, double to, double radius) {
        return rodFrom(p, n, face, outward, from, to, radius);
    };
    const double top = depth + link + g;  // where the head starts
    for (const auto& [p, part] : {std::pair{pivot, joint.part}, std::pair{base, joint.base}})
        shapes[part] =
            fuse(shapes[part], fuse(span(p, -1, top + head(r), r.pin), span(p, top, top + head(r), r.outer)));
    // The link: a bar with round ends between the pivots.
    out.bodies.push_back(
        {linkName(joint), -1, j, pivotLink(pivot, base, n, face, outward, depth, link, r, g)});
}

}  // namespace fabguide::printable
