#include "Printable/PrintInPlace.h"

#include "Function/DoublePivot.h"
#include "Function/Pose.h"
#include "Function/Solve.h"
#include "Printable/Motion.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fabguide::printable {

namespace {

using function::Cuboid;
using function::Joint;
using function::Model;
using function::Side;
using Coordinates = std::array<double, 6>;

constexpr double kPi = 3.14159265358979323846;

TopoDS_Shape box(const Coordinates& c)
{
    return BRepPrimAPI_MakeBox(gp_Pnt(c[0], c[2], c[4]), gp_Pnt(c[1], c[3], c[5])).Shape();
}

/// A Boolean operation of the first shape with the others, or an error naming it: OpenCASCADE reports
/// failures by flags, not exceptions. Many tools in one operation are much faster than one at a time.
template <typename Operation>
TopoDS_Shape boolean(const std::vector<TopoDS_Shape>& shapes, const char* what)
{
    if (shapes.size() < 2)
        return shapes.empty() ? TopoDS_Shape() : shapes.front();
    TopTools_ListOfShape first, rest;
    first.Append(shapes.front());
    for (size_t i = 1; i < shapes.size(); ++i)
        rest.Append(shapes[i]);
    Operation operation;
    operation.SetArguments(first);
    operation.SetTools(rest);
    operation.Build();
    if (operation.HasErrors()) {
        std::ostringstream report;
        operation.DumpErrors(report);
        std::string errors = report.str();
        while (!errors.empty() && std::isspace(static_cast<unsigned char>(errors.back())))
            errors.pop_back();
        throw std::runtime_error(std::string("geometry: a ") + what + " failed: " + errors +
                                 "; try another --gap or --scale");
    }
    return operation.Shape();
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    return a.IsNull() ? b : boolean<BRepAlgoAPI_Fuse>({a, b}, "union");
}

double volumeOf(const TopoDS_Shape& s)
{
    GProp_GProps volume;
    BRepGProp::VolumeProperties(s, volume);
    return volume.Mass();
}

/// a less the tools, in one operation (tools that touch along faces are cut more reliably so than united
/// first). A cut takes at most its tools' volume; OpenCASCADE sometimes returns a fragment without an error,
/// which is refused here rather than printed.
TopoDS_Shape cut(const TopoDS_Shape& a, const std::vector<TopoDS_Shape>& tools)
{
    std::vector<TopoDS_Shape> shapes{a};
    double held = 0;
    for (const TopoDS_Shape& tool : tools)
        if (!tool.IsNull()) {
            shapes.push_back(tool);
            held += volumeOf(tool);
        }
    const TopoDS_Shape result = boolean<BRepAlgoAPI_Cut>(shapes, "cut");
    const double before = volumeOf(a), lost = before - held - volumeOf(result);
    if (lost > 1e-6 * before + 1e-3)
        throw std::runtime_error("geometry: a cut lost " + std::to_string(lost) +
                                 " mm3 more than its tools hold (OpenCASCADE); try another --gap or --scale");
    return result;
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    return cut(a, std::vector<TopoDS_Shape>{b});
}

TopoDS_Shape compound(const std::vector<TopoDS_Shape>& shapes)
{
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    for (const TopoDS_Shape& s : shapes)
        builder.Add(c, s);
    return c;
}

TopoDS_Shape moved(const TopoDS_Shape& s, const gp_Trsf& t)
{
    return BRepBuilderAPI_Transform(s, t, true).Shape();
}

/// A cylinder of radius r around the axis `axis` through `at`, from `from` to `to` along it.
TopoDS_Shape rod(const gp_Pnt& at, int axis, double from, double to, double r)
{
    gp_Pnt start = at;
    start.SetCoord(axis + 1, from);
    return BRepPrimAPI_MakeCylinder(gp_Ax2(start, gp_Dir(axis == 0, axis == 1, axis == 2)), r, to - from)
        .Shape();
}

/// A rod of `radius` round p along normal axis n, from `from` to `to` measured from `face` in direction
/// `sign` (+1 or -1), whichever way round that puts its ends.
TopoDS_Shape rodFrom(const gp_Pnt& p, int n, double face, double sign, double from, double to, double radius)
{
    const double a = face + sign * from, b = face + sign * to;
    return rod(p, n, std::min(a, b), std::max(a, b), radius);
}

/// A cuboid's thinnest side.
double thinnest(const Cuboid& c)
{
    double side = 1e300;
    for (int a = 0; a < 3; ++a)
        side = std::min(side, c.at(static_cast<Side>(2 * a + 1)) - c.at(static_cast<Side>(2 * a)));
    return side;
}

bool movedByJoint(const Model& m, int part)
{
    return jointMoving(m, part) >= 0;
}

/// The modelled side of cuboid c that configuration k turns onto side `side` of its posed box, or -1 (a turn
/// by other than a multiple of 90° leaves no face there).
int modelledSide(const Model& m, int part, int c, int k, int side)
{
    const gp_Trsf motion = partMotion(m, part, k, 1);
    const auto& x = m.cuboids[c].coordinates;
    const double at = function::evaluate(m, function::posed(m, {c, static_cast<Side>(side)}, k));
    for (int s = 0; s < 6; ++s) {
        gp_Pnt centre((x[0] + x[1]) / 2, (x[2] + x[3]) / 2, (x[4] + x[5]) / 2);
        centre.SetCoord(s / 2 + 1, x[s]);
        centre.Transform(motion);
        if (std::abs(centre.Coord(side / 2 + 1) - at) < 1e-6) {
            gp_Vec normal(0, 0, 0);
            normal.SetCoord(s / 2 + 1, s % 2 ? 1 : -1);
            normal.Transform(motion);
            if (std::abs(normal.Coord(side / 2 + 1) - (side % 2 ? 1 : -1)) < 1e-9)
                return s;
        }
    }
    return -1;
}

/// Gaps (4.5.3): where cuboids of two parts touch, as modelled or in any configuration, the face of the one
/// that moves (or the later one) steps back by the gap; so does a solid's face lying on its cavity's wall.
std::vector<Coordinates> gapped(const Model& m, double gap)
{
    std::vector<int> partOf(m.cuboids.size());
    for (size_t p = 0; p < m.parts.size(); ++p)
        for (int c : m.parts[p].cuboids)
            partOf[c] = static_cast<int>(p);
    std::vector<std::array<bool, 6>> steps(m.cuboids.size(), std::array<bool, 6>{});
    const double hair = 1e-6;
    for (int k = -1; k < static_cast<int>(m.configurations.size()); ++k) {
        std::vector<Coordinates> posed(m.cuboids.size());
        for (size_t c = 0; c < m.cuboids.size(); ++c)
            for (int s = 0; s < 6; ++s)
                posed[c][s] =
                    function::evaluate(m, function::posed(m, {static_cast<int>(c), static_cast<Side>(s)}, k));
        for (size_t a = 0; a < m.cuboids.size(); ++a)
            for (size_t b = 0; b < m.cuboids.size(); ++b) {
                if (a == b || partOf[a] == partOf[b] || m.cuboids[a].cavity())
                    continue;
                const Coordinates &ca = posed[a], &cb = posed[b];
                const bool aSteps =
                    m.cuboids[b].cavity() ||
                    (movedByJoint(m, partOf[a]) != movedByJoint(m, partOf[b]) ? movedByJoint(m, partOf[a])
                                                                              : a > b);
                if (!aSteps)
                    continue;
                for (int axis = 0; axis < 3; ++axis) {
                    bool overlaps = true;  // across the other two axes
                    for (int o = 0; o < 3; ++o)
                        if (o != axis)
                            overlaps = overlaps && std::min(ca[2 * o + 1], cb[2 * o + 1]) -
                                                           std::max(ca[2 * o], cb[2 * o]) >
                                                       hair;
                    if (!overlaps)
                        continue;
                    for (int high : {0, 1}) {
                        const int side = 2 * axis + high;
                        // Against another solid: a's side on b's opposite side; against a cavity: on its same
                        // side.
                        const int facing = m.cuboids[b].cavity() ? side : side ^ 1;
                        const bool opening =
                            m.cuboids[b].cavity() &&  // no wall there: the cavity opens
                            std::abs(m.cuboids[b].coordinates[side] -
                                     m.cuboids[m.cuboids[b].within].coordinates[side]) < hair;
                        if (std::abs(ca[side] - cb[facing]) < hair && !opening)
                            if (const int s = modelledSide(m, partOf[a], static_cast<int>(a), k, side);
                                s >= 0)
                                steps[a][s] = true;
                    }
                }
            }
    }
    std::vector<Coordinates> out;
    for (size_t c = 0; c < m.cuboids.size(); ++c) {
        Coordinates x = m.cuboids[c].coordinates;
        for (int s = 0; s < 6; ++s)
            if (steps[c][s])
                x[s] += s % 2 ? -gap : gap;
        out.push_back(x);
    }
    // Cuboids of one part stay joined: where one face stepped back, the cuboid glued to it follows.
    for (size_t a = 0; a < m.cuboids.size(); ++a)
        for (size_t b = 0; b < m.cuboids.size(); ++b)
            for (int side = 0; side < 6 && a != b && partOf[a] == partOf[b] && !m.cuboids[a].cavity() &&
                               !m.cuboids[b].cavity();
                 ++side)
                if (std::abs(m.cuboids[a].coordinates[side] - m.cuboids[b].coordinates[side ^ 1]) < hair)
                    out[b][side ^ 1] = out[a][side];
    return out;
}

/// A part's solid cuboids, grown by `grow` all round.
std::vector<Coordinates> boxesOf(const Model& m, int part, const std::vector<Coordinates>& at,
                                 double grow = 0)
{
    std::vector<Coordinates> boxes;
    for (int c : m.parts[part].cuboids)
        if (!m.cuboids[c].cavity()) {
            Coordinates k = at[c];
            for (int i = 0; i < 6; ++i)
                k[i] += i % 2 ? grow : -grow;
            boxes.push_back(k);
        }
    return boxes;
}

TopoDS_Shape solid(const std::vector<Coordinates>& boxes)
{
    TopoDS_Shape s;
    for (const Coordinates& b : boxes)
        s = fuse(s, box(b));
    return s;
}

TopoDS_Shape solid(const Model& m, int part, const std::vector<Coordinates>& at, double grow = 0)
{
    return solid(boxesOf(m, part, at, grow));
}

/// A solid swept by a motion: the solid and what each of its faces sweeps (OpenCASCADE sweeps faces into
/// solids, not solids; faces that sweep no volume are left out).
template <typename Sweep>
TopoDS_Shape swept(const TopoDS_Shape& shape, Sweep sweepFace)
{
    TopoDS_Shape result = shape;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
        TopoDS_Shape s;
        try {
            s = sweepFace(TopoDS::Face(e.Current()));
        } catch (const Standard_Failure&) {  // a face across a hinge's axis turns in its own plane: no volume
            continue;
        }
        GProp_GProps area;
        BRepGProp::SurfaceProperties(e.Current(), area);
        // Faces along the motion sweep nothing, or a rounding error's sliver.
        if (std::abs(volumeOf(s)) > 1e-9 * area.Mass() * std::sqrt(area.Mass()))
            result = fuse(result, s);
    }
    return result;
}

/// What a shape sweeps turning by `radians` about `axis`, then shifting by `by` (motions turn first, then
/// slide): a revolution, then a prism of the turned shape.
TopoDS_Shape turnedThenShifted(const TopoDS_Shape& shape, const gp_Ax1& axis, double radians,
                               const gp_Vec& by)
{
    TopoDS_Shape result = shape, turned = shape;
    if (std::abs(radians) > 1e-12) {
        result = swept(shape,
                       [&](const TopoDS_Face& f) { return BRepPrimAPI_MakeRevol(f, axis, radians).Shape(); });
        gp_Trsf turn;
        turn.SetRotation(axis, radians);
        turned = moved(shape, turn);
    }
    if (by.Magnitude() > 1e-9)
        result =
            fuse(result,
                 swept(turned, [&](const TopoDS_Face& f) { return BRepPrimAPI_MakePrism(f, by).Shape(); }));
    return result;
}

/// Boxes cut in two (or four) by the planes through `axis` along the box's sides wherever it passes through
/// one: no face of the pieces crosses the axis. A face across its axis revolves into a solid that turns
/// through itself, which OpenCASCADE cannot unite or cut reliably (parts grown by the gap reach their hinge's
/// line, small scales).
std::vector<Coordinates> splitAtAxis(const std::vector<Coordinates>& boxes, const gp_Ax1& axis)
{
    std::vector<Coordinates> pieces = boxes;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(axis.Direction().Coord(a + 1)) > 0.5)
            continue;
        const double x = axis.Location().Coord(a + 1);
        std::vector<Coordinates> split;
        for (const Coordinates& b : pieces)
            if (b[2 * a] + 1e-6 < x && x < b[2 * a + 1] - 1e-6) {
                Coordinates low = b, high = b;
                low[2 * a + 1] = high[2 * a] = x;
                split.insert(split.end(), {low, high});
            } else {
                split.push_back(b);
            }
        pieces = split;
    }
    return pieces;
}

/// What boxes sweep turning about `axis` then shifting by `by`: the volume each piece (splitAtAxis) sweeps,
/// to cut with together; OpenCASCADE may drop a thin piece from their union.
std::vector<TopoDS_Shape> turnedThenShifted(const std::vector<Coordinates>& boxes, const gp_Ax1& axis,
                                            double radians, const gp_Vec& by)
{
    std::vector<TopoDS_Shape> swept;
    for (const Coordinates& piece : splitAtAxis(boxes, axis))
        swept.push_back(turnedThenShifted(box(piece), axis, radians, by));
    return swept;
}

/// The volume part p's boxes sweep as it moves from its modelled pose to configuration k (4.5.1), as solids
/// to cut with. Motions turn first, then slide (Motion.h), so with at most one hinge turning in p's chain the
/// sweep is exact: that hinge's revolution, then a prism along the slides' common displacement; otherwise
/// (double pivots, turns upon turns) the part at 48 poses along the motion.
std::vector<TopoDS_Shape> sweep(const Model& m, int part, int k, const std::vector<Coordinates>& boxes)
{
    int turning = -1, turns = 0;
    bool pivots = false;
    for (int j = jointMoving(m, part); j >= 0;
         j = m.joints[j].base >= 0 ? jointMoving(m, m.joints[j].base) : -1) {
        const function::JointPose* pose = poseOf(m, j, k);
        if (!pose)
            continue;
        pivots = pivots || m.joints[j].type == Joint::Type::DoublePivot;
        if (m.joints[j].turns() && std::abs(pose->angle) > 1e-9) {
            turning = j;
            ++turns;
        }
    }
    if (!pivots && turns <= 1) {
        const gp_Trsf half = partMotion(m, part, k, 0.5), whole = partMotion(m, part, k, 1);
        const gp_Vec by((whole * half.Inverted()).TranslationPart());
        if (turning < 0)
            return turnedThenShifted(boxes, gp_Ax1(), 0, by);
        return turnedThenShifted(boxes, hingeAxis(m, m.joints[turning]),
                                 poseOf(m, turning, k)->angle * kPi / 180, by);
    }
    const TopoDS_Shape shape = solid(boxes);
    std::vector<TopoDS_Shape> poses;
    for (int step = 0; step <= 48; ++step)
        poses.push_back(moved(shape, partMotion(m, part, k, step / 48.0)));
    return poses;
}

/// What a part sweeps by its own hinge (or sliding hinge) alone, in the frame of the part it turns on: the
/// revolution about the edge, then the prism along the slide.
std::vector<TopoDS_Shape> hingeSweep(const Model& m, const Joint& joint, const function::JointPose& pose,
                                     const std::vector<Coordinates>& boxes)
{
    gp_Vec by(0, 0, 0);
    if (joint.slides())
        by.SetCoord(joint.axis + 1, pose.offset);
    return turnedThenShifted(boxes, hingeAxis(m, joint), pose.angle * kPi / 180, by);
}

struct Radii {
    double outer, pin;
};

/// The sizes of a joint's round parts (4.5.2): outer radius half the thinnest attached cuboid, the pin inside
/// it with the gap and a wall around it (0.8 mm, or 30 % of the radius). Where that leaves less than the
/// least pin (0.4 mm radius), as scaled-down parts do, the round parts stand proud of the thin part, up to
/// twice its thickness, noted; thinner parts are refused.
Radii radii(const Model& m, const Joint& joint, std::initializer_list<int> cuboids, double g, Printable& out)
{
    constexpr double leastPin = 0.4, leastWall = 0.8;
    double side = 1e300;
    for (int c : cuboids)
        side = std::min(side, thinnest(m.cuboids[c]));
    const double least = leastPin + g + leastWall;
    if (side < least)
        throw std::invalid_argument("joint '" + joint.name + "': its parts are too thin (" +
                                    std::to_string(side) + " mm) for a pin and its yokes with a " +
                                    std::to_string(g) + " mm gap");
    const double outer = std::max(side / 2, least);
    if (outer > side / 2) {
        std::ostringstream note;
        note.precision(2);
        note << std::fixed << joint.name << ": its round parts are " << 2 * outer
             << " mm across, proud of its " << side << " mm thin part (the least that holds a "
             << 2 * leastPin << " mm pin with a " << g << " mm gap)";
        out.notes.push_back(note.str());
    }
    return {outer, outer - g - std::max(leastWall, 0.3 * outer)};
}

/// cuboidAtEdge within `reach` of the axis.
int cuboidNear(const Model& m, const Joint& joint, const gp_Ax1& axis, double reach)
{
    int best = -1;
    double longest = 0;
    const Cuboid& own = m.cuboids[joint.edgeA.cuboid];
    for (size_t p = 0; p < m.parts.size(); ++p) {
        if (static_cast<int>(p) == joint.part || (joint.base >= 0 && static_cast<int>(p) != joint.base))
            continue;
        for (int c : m.parts[p].cuboids) {
            if (m.cuboids[c].cavity())
                continue;
            double d2 = 0, shared = 0;  // the axis' distance from the box, and how long they run together
            for (int a = 0; a < 3; ++a) {
                const double low = m.cuboids[c].at(static_cast<Side>(2 * a)),
                             high = m.cuboids[c].at(static_cast<Side>(2 * a + 1));
                if (std::abs(axis.Direction().Coord(a + 1)) > 0.5) {
                    shared = std::min(high, own.at(static_cast<Side>(2 * a + 1))) -
                             std::max(low, own.at(static_cast<Side>(2 * a)));
                    continue;
                }
                const double x = axis.Location().Coord(a + 1);
                const double out = std::max({0.0, low - x, x - high});
                d2 += out * out;
            }
            if (std::sqrt(d2) <= reach && shared > longest) {
                longest = shared;
                best = c;
            }
        }
    }
    return best;
}

/// The solid cuboid of another part that the hinge's edge lies on, along most of its length (the part the
/// yokes hang on), or -1. An edge standing off every other part (the sofa bunk's headrest, hinged 20 mm
/// behind the seat) hangs on the nearest one within the moving cuboid's thickness; bridge() joins its yokes
/// to it.
int cuboidAtEdge(const Model& m, const Joint& joint, const gp_Ax1& axis)
{
    for (double reach : {1e-3, thinnest(m.cuboids[joint.edgeA.cuboid])})
        if (const int c = cuboidNear(m, joint, axis, reach); c >= 0)
            return c;
    return -1;
}

/// The box joining a hinge's yokes to the cuboid they hang on across the stand-off, between `from` and `to`
/// along the axis: from the axis to the cuboid, r deep into it where the axis runs level with its face. Null
/// when the axis lies on the cuboid.
TopoDS_Shape bridge(const Cuboid& base, const gp_Ax1& axis, int along, double from, double to, double r)
{
    Coordinates c{};
    bool apart = false;
    for (int a = 0; a < 3; ++a) {
        const double low = base.at(static_cast<Side>(2 * a)), high = base.at(static_cast<Side>(2 * a + 1));
        const double x = axis.Location().Coord(a + 1);
        if (a == along) {
            c[2 * a] = from, c[2 * a + 1] = to;
        } else if (x > high + 1e-3 || x < low - 1e-3) {
            apart = true;
            c[2 * a] = std::min(x, high), c[2 * a + 1] = std::max(x, low);
        } else {  // level with a face or within: r of the cuboid on the side of the axis' other offset
            c[2 * a] = std::max(low, x - r), c[2 * a + 1] = std::min(high, x + r);
        }
    }
    return apart ? box(c) : TopoDS_Shape();
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

/// A rod along a hinge's axis, made a slot over a sliding hinge's travel by the rod at both ends of the
/// travel and the box between: slotted yokes and their clearances.
TopoDS_Shape slotted(const Model& m, int j, const gp_Pnt& at, int along, double from, double to, double r)
{
    const Joint& joint = m.joints[j];
    const auto [low, high] = travel(m, j);
    if (high - low < 1e-9)
        return rod(at, along, from, to, r);
    auto shifted = [&](double by) {
        return at.Translated(gp_Vec(joint.axis == 0, joint.axis == 1, joint.axis == 2) * by);
    };
    Coordinates span{};
    for (int a = 0; a < 3; ++a) {
        const double centre = at.Coord(a + 1);
        span[2 * a] = a == along ? from : a == joint.axis ? centre + low : centre - r;
        span[2 * a + 1] = a == along ? to : a == joint.axis ? centre + high : centre + r;
    }
    return fuse(fuse(rod(shifted(low), along, from, to, r), rod(shifted(high), along, from, to, r)),
                box(span));
}

/// Hinge and sliding hinge (4.5.2): a pin along the edge and a knuckle around it in the middle third on the
/// moving part, two yokes at the ends on the part the edge lies on (slotted along a sliding hinge's travel),
/// each cleared of the other by the gap.
void addHinge(const Model& m, int j, const std::vector<Coordinates>& gapped, double g,
              std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    const Joint& joint = m.joints[j];
    const gp_Ax1 axis = hingeAxis(m, joint);
    const int along = std::abs(axis.Direction().X()) > 0.5 ? 0 : std::abs(axis.Direction().Y()) > 0.5 ? 1 : 2;
    const int onEdge = cuboidAtEdge(m, joint, axis);
    if (onEdge < 0) {
        out.notes.push_back(joint.name + ": no other part along its edge to hold the yokes; no hinge made");
        return;
    }
    const int base = function::partOf(m, onEdge);
    const Radii r = radii(m, joint, {joint.edgeA.cuboid, onEdge}, g, out);
    const Coordinates& edge = gapped[joint.edgeA.cuboid];  // the pin and yokes end where the part does
    const double lo = edge[2 * along], hi = edge[2 * along + 1];
    const double yoke = (hi - lo) / 4;
    const gp_Pnt at = axis.Location();
    TopoDS_Shape& part = shapes[joint.part];
    TopoDS_Shape& other = shapes[base];
    // The moving part gives way around the yokes, the other part around the knuckle.
    // A sliding hinge's slotted yokes stay put while the part turns and slides past them: it gives way
    // around them as they stand in its own frame along the way.
    const TopoDS_Shape yokes = fuse(slotted(m, j, at, along, lo - g, lo + yoke + g, r.outer + g),
                                    slotted(m, j, at, along, hi - yoke - g, hi + g, r.outer + g));
    // In its frame they turn back about the axis, then (turned back) slide back along the turned-back axis.
    TopoDS_Shape around = yokes;
    for (size_t k = 0; k < m.configurations.size() && joint.slides(); ++k)
        if (const function::JointPose* pose = poseOf(m, j, static_cast<int>(k))) {
            gp_Trsf turnBack;
            turnBack.SetRotation(axis, -pose->angle * kPi / 180);
            gp_Vec back(0, 0, 0);
            back.SetCoord(joint.axis + 1, -pose->offset);
            around = fuse(
                around, turnedThenShifted(yokes, axis, -pose->angle * kPi / 180, back.Transformed(turnBack)));
        }
    part = cut(part, around);
    other = cut(other, slotted(m, j, at, along, lo + yoke, hi - yoke, r.outer + g));
    // The pin's hole, the gap past its ends, through the other part's corner and through each yoke, before
    // they are joined.
    const TopoDS_Shape hole = slotted(m, j, at, along, lo - g - 1, hi + g + 1, r.pin + g);
    other = fuse(cut(other, hole), fuse(cut(slotted(m, j, at, along, lo, lo + yoke, r.outer), hole),
                                        cut(slotted(m, j, at, along, hi - yoke, hi, r.outer), hole)));
    for (const auto& [from, to] : {std::pair{lo, lo + yoke}, std::pair{hi - yoke, hi}})
        if (const TopoDS_Shape b = bridge(m.cuboids[onEdge], axis, along, from, to, r.outer); !b.IsNull())
            other = fuse(other, cut(b, hole));
    part = fuse(part,
                fuse(rod(at, along, lo + yoke + g, hi - yoke - g, r.outer), rod(at, along, lo, hi, r.pin)));
}

/// Slide (4.5.2) not guided by a cavity: mated rails. A dovetail tongue on the part it rests against, along
/// the slide axis where the two meet, and the matching groove, the gap all round, cut into the moving part
/// along its travel, so it can slide but not lift off.
void addRails(const Model& m, int j, const std::vector<Coordinates>& gapped, double g,
              std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    const Joint& joint = m.joints[j];
    const int a = joint.axis;
    // The widest contact between a cuboid of the part and one of another part, across the slide axis.
    int mover = -1, base = -1, normal = -1;
    double widest = 0;
    for (int c : m.parts[joint.part].cuboids)
        for (size_t q = 0; q < m.cuboids.size(); ++q) {
            if (m.cuboids[c].cavity() || m.cuboids[q].cavity() ||
                function::partOf(m, static_cast<int>(q)) == joint.part)
                continue;
            const auto& x = m.cuboids[c].coordinates;
            const auto& y = m.cuboids[q].coordinates;
            for (int n = 0; n < 3; ++n) {
                if (n == a ||
                    (std::abs(x[2 * n] - y[2 * n + 1]) > 1e-6 && std::abs(x[2 * n + 1] - y[2 * n]) > 1e-6))
                    continue;
                double area = 1;
                for (int o = 0; o < 3; ++o)
                    if (o != n)
                        area *= std::max(0.0,
                                         std::min(x[2 * o + 1], y[2 * o + 1]) - std::max(x[2 * o], y[2 * o]));
                if (area > widest) {
                    widest = area;
                    mover = c;
                    base = static_cast<int>(q);
                    normal = n;
                }
            }
        }
    if (mover < 0) {
        out.notes.push_back(joint.name + ": slides free (no cavity guides it and it rests on no other part)");
        return;
    }
    const auto& x = m.cuboids[mover].coordinates;
    const auto& y = m.cuboids[base].coordinates;
    const int across = 3 - a - normal;
    const double dir =
        std::abs(x[2 * normal] - y[2 * normal + 1]) < 1e-6 ? 1 : -1;  // from the base to the part
    const double plane = dir > 0 ? y[2 * normal + 1] : y[2 * normal];
    const double thin = std::min(gapped[mover][2 * normal + 1] - gapped[mover][2 * normal],
                                 y[2 * normal + 1] - y[2 * normal]);
    const double h = 0.4 * thin, width = std::min(x[2 * across + 1], y[2 * across + 1]) -
                                         std::max(x[2 * across], y[2 * across]);
    const double centre =
        (std::max(x[2 * across], y[2 * across]) + std::min(x[2 * across + 1], y[2 * across + 1])) / 2;
    const double from = std::max(x[2 * a], y[2 * a]), to = std::min(x[2 * a + 1], y[2 * a + 1]);
    if (h < 2 * g || width < 6 * h || to - from < 4 * h) {
        out.notes.push_back(joint.name + ": slides free (too little contact for rails at this gap)");
        return;
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
            p.SetCoord(a + 1, start);
            p.SetCoord(across + 1, uv.X());
            p.SetCoord(normal + 1, uv.Y());
            return p;
        };
        BRepBuilderAPI_MakePolygon outline(point(0), point(1), point(2), point(3), true);
        gp_Vec along(0, 0, 0);
        along.SetCoord(a + 1, length);
        return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(outline.Wire()).Face(), along).Shape();
    };
    const auto [low, high] = travel(m, j);
    const int q = function::partOf(m, base);
    shapes[q] = fuse(shapes[q], tongue(0, from, to - from));
    // In the part's frame the tongue runs back over the travel; the groove is open at the part's ends.
    shapes[joint.part] = cut(shapes[joint.part], tongue(g, std::min(from, x[2 * a]) - high - 1,
                                                        std::max(to, x[2 * a + 1]) - from + high - low + 2));
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
    corner.SetCoord(n + 1, std::min(face + inward * depth, face + inward * (depth + thick)));
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
    out.bodies.push_back(
        {joint.name + " link", -1, j, pivotLink(pivot, base, n, face, inward, g, link, r, g)});
}

/// Double pivot (4.5.2): a headed pin at each pivot, standing out of the two coplanar faces, and a separate
/// rigid link between them, outside the faces, with a hole round each pin.
void addDoublePivot(const Model& m, int j, double g, std::vector<TopoDS_Shape>& shapes, Printable& out)
{
    const Joint& joint = m.joints[j];
    if (joint.pivotFace.side != joint.basePivotFace.side)
        return addRecessedPivot(m, j, g, shapes, out);
    const function::PivotPlane plane = function::pivotPlane(m, joint);
    const Radii r = radii(m, joint, {joint.pivotFace.cuboid, joint.basePivotFace.cuboid}, g, out);
    const int n = plane.normal;
    const double face = m.cuboids[joint.pivotFace.cuboid].at(joint.pivotFace.side);
    const double outward = static_cast<int>(joint.pivotFace.side) % 2 ? 1 : -1;
    const double link = r.outer, head = std::max(1.0, r.outer / 3);

    // Along the normal, from the face outwards.
    const auto span = [&](const gp_Pnt& p, double from, double to, double radius) {
        return rodFrom(p, n, face, outward, from, to, radius);
    };
    const auto [pivot, base] = pivotPoints(m, joint);
    for (const auto& [p, part] : {std::pair{pivot, joint.part}, std::pair{base, joint.base}})
        shapes[part] = fuse(shapes[part], fuse(span(p, -1, 2 * g + link + head, r.pin),
                                               span(p, 2 * g + link, 2 * g + link + head, r.outer)));
    // The link: a bar with round ends between the pivots, the gap off the faces.
    out.bodies.push_back(
        {joint.name + " link", -1, j, pivotLink(pivot, base, n, face, outward, g, link, r, g)});
}

/// The plain hinge on which part `carried` turns on `base` in configuration k, or -1.
int hingeOn(const Model& m, int carried, int base, int k)
{
    const int j = jointMoving(m, carried);
    return j >= 0 && m.joints[j].base == base && m.joints[j].type == Joint::Type::Hinge && poseOf(m, j, k)
               ? j
               : -1;
}

/// What part a's boxes sweep in part b's frame as both move to configuration k: when one turns on the other
/// by a hinge, the revolution about it (exact); otherwise a at 32 poses while they turn (the first half) and
/// 8 while they slide.
std::vector<TopoDS_Shape> pathRelative(const Model& m, int k, int a, int b,
                                       const std::vector<Coordinates>& boxes)
{
    for (const auto& [carried, base, sign] : {std::tuple{b, a, -1}, std::tuple{a, b, 1}})
        if (const int j = hingeOn(m, carried, base, k); j >= 0)
            return turnedThenShifted(boxes, hingeAxis(m, m.joints[j]),
                                     sign * poseOf(m, j, k)->angle * kPi / 180, gp_Vec(0, 0, 0));
    const TopoDS_Shape shape = solid(boxes);
    std::vector<TopoDS_Shape> path;
    for (int step = 1; step <= 40; ++step) {
        const double t = step <= 32 ? step / 64.0 : 0.5 + (step - 32) / 16.0;
        path.push_back(moved(shape, partMotion(m, b, k, t).Inverted() * partMotion(m, a, k, t)));
    }
    return path;
}

/// In configuration k, for two parts that lie within the gap of each other as printed and both turn, each is
/// cut by the other's path relative to it, grown by the gap (pathRelative): a door's edge turning towards its
/// neighbour bevels the neighbour's edge.
void clearNeighbours(const Model& m, int k, const std::vector<Coordinates>& at, double g,
                     std::vector<TopoDS_Shape>& shapes)
{
    const int parts = static_cast<int>(m.parts.size());
    auto turns = [&](int p) {  // its own joint turns in k (carried parts turn with their carrier)
        const int j = jointMoving(m, p);
        const function::JointPose* pose = j >= 0 ? poseOf(m, j, k) : nullptr;
        return pose && std::abs(pose->angle) > 1e-9 && m.joints[j].type != Joint::Type::Slide;
    };
    for (int a = 0; a < parts; ++a)
        for (int b = 0; b < parts; ++b) {
            if (a == b || !turns(a) || !turns(b))
                continue;
            const gp_Trsf relative = partMotion(m, b, k, 1).Inverted() * partMotion(m, a, k, 1);
            if (relative.Form() == gp_Identity || relative.Form() == gp_Translation)
                continue;  // sliding past each other, the gap stays a gap
            const std::vector<Coordinates> grown = boxesOf(m, a, at, g);
            Bnd_Box near, other;
            for (const Coordinates& c : grown)
                near.Update(c[0], c[2], c[4], c[1], c[3], c[5]);
            BRepBndLib::Add(shapes[b], other);
            near.Enlarge(g);
            if (near.IsOut(other))
                continue;
            shapes[b] = cut(shapes[b], pathRelative(m, k, a, b, grown));
        }
}

}  // namespace

Model solvedToPrint(const Model& model, double scale)
{
    const function::SolveResult solved = function::solve(model);
    if (!solved.solved) {
        std::string names;
        for (const std::string& name : solved.conflict)
            names += (names.empty() ? "" : ", ") + ("'" + name + "'");
        throw std::runtime_error("the model does not solve: " + names + " cannot hold together");
    }
    return function::scaled(solved.model, scale);
}

Printable makePrintable(const Model& m, const Printer& printer)
{
    Printable out;
    const double g = printer.gap;
    const std::vector<Coordinates> at = gapped(m, g);
    std::vector<TopoDS_Shape> shapes;
    for (size_t p = 0; p < m.parts.size(); ++p) {
        TopoDS_Shape s = solid(m, static_cast<int>(p), at);
        for (int c : m.parts[p].cuboids)
            if (m.cuboids[c].cavity())
                s = cut(s, box(m.cuboids[c].coordinates));
        shapes.push_back(s);
    }
    // Cavities (4.5.1): what each inner part sweeps, with its clearance, leaves the enclosing part.
    for (const function::FitInside& f : m.fitInside) {
        if (f.configuration < 0)
            continue;
        for (int p : f.inner) {
            const std::vector<TopoDS_Shape> swept = sweep(m, p, f.configuration, boxesOf(m, p, at, g));
            out.sweeps.push_back(compound(swept));
            shapes[f.enclosing] = cut(shapes[f.enclosing], swept);
        }
    }
    // Likewise a part turning on a hinge clears the part its yokes sit on: a thick lid's edge below the axis
    // sweeps a quarter round into the body.
    for (size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& joint = m.joints[j];
        const int other = joint.turns() ? cuboidAtEdge(m, joint, hingeAxis(m, joint)) : -1;
        for (size_t k = 0; k < m.configurations.size() && other >= 0; ++k)
            if (const function::JointPose* pose = poseOf(m, static_cast<int>(j), static_cast<int>(k)))
                shapes[function::partOf(m, other)] =
                    cut(shapes[function::partOf(m, other)],
                        hingeSweep(m, joint, *pose, boxesOf(m, joint.part, at, g)));
    }
    // Two neighbours that both move (doors meeting in the middle) clear what each sweeps past the other.
    for (size_t k = 0; k < m.configurations.size(); ++k)
        clearNeighbours(m, static_cast<int>(k), at, g, shapes);
    for (size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& joint = m.joints[j];
        if (joint.turns())
            addHinge(m, static_cast<int>(j), at, g, shapes, out);
        else if (joint.type == Joint::Type::DoublePivot)
            addDoublePivot(m, static_cast<int>(j), g, shapes, out);
        else if (std::none_of(m.fitInside.begin(), m.fitInside.end(), [&](const function::FitInside& f) {
                     return f.cavity >= 0 &&
                            std::find(f.inner.begin(), f.inner.end(), joint.part) != f.inner.end();
                 }))
            addRails(m, static_cast<int>(j), at, g, shapes, out);
    }
    for (size_t p = 0; p < m.parts.size(); ++p) {
        ShapeUpgrade_UnifySameDomain unify(shapes[p], true, true, false);
        unify.Build();
        int pieces = 0;
        for (TopExp_Explorer e(unify.Shape(), TopAbs_SOLID); e.More(); e.Next())
            ++pieces;
        if (pieces == 0 || volumeOf(unify.Shape()) < 1e-6)  // OpenCASCADE lost it without an error
            throw std::runtime_error(
                "geometry: nothing is left of part '" + m.parts[p].name +
                "' after its cavities and joints were cut; try another --gap or --scale");
        if (pieces > 1)  // a sweep cut through it: a joint turning the wrong way round, or a part in the way
            out.notes.push_back(m.parts[p].name + ": falls apart into " + std::to_string(pieces) +
                                " pieces; check which way its neighbours' joints turn");
        out.bodies.insert(out.bodies.begin() + static_cast<long>(p),
                          {m.parts[p].name, static_cast<int>(p), -1, unify.Shape()});
    }
    return out;
}

Size sizeOf(const Printable& printable)
{
    Bnd_Box bounds;
    for (const Body& b : printable.bodies)
        BRepBndLib::AddOptimal(b.shape, bounds, false, false);
    if (bounds.IsVoid())
        return {0, 0, 0};
    double x0, y0, z0, x1, y1, z1;
    bounds.Get(x0, y0, z0, x1, y1, z1);
    return {x1 - x0, y1 - y0, z1 - z0};
}

Fitted fitted(const Model& solved, const Size& volume, const Printer& printer)
{
    // First as large as the cuboids allow, then smaller by what joints and links add beyond them.
    Size extent{0, 0, 0};
    for (int a = 0; a < 3; ++a) {
        double low = 1e300, high = -1e300;
        for (const Cuboid& c : solved.cuboids) {
            low = std::min(low, c.at(static_cast<Side>(2 * a)));
            high = std::max(high, c.at(static_cast<Side>(2 * a + 1)));
        }
        extent[a] = high - low;
    }
    // How much larger it could be, 0.01 mm short of each side (meshes are written to a micrometre).
    auto room = [&](const Size& size) {
        double r = 1e300;
        for (int a = 0; a < 3; ++a)
            r = std::min(r, (volume[a] - 0.01) / std::max(size[a], 1e-9));
        return r;
    };
    Fitted f;
    f.scale = std::min(1.0, room(extent));
    for (int attempt = 0; attempt < 4; ++attempt) {
        f.model = function::scaled(solved, f.scale);
        try {
            f.printable = makePrintable(f.model, printer);
        } catch (const std::invalid_argument& e) {
            std::ostringstream what;
            what << e.what() << " at scale " << f.scale << ", which fits " << volume[0] << " x " << volume[1]
                 << " x " << volume[2] << " mm";
            throw std::invalid_argument(what.str());
        }
        const double r = room(sizeOf(f.printable));
        if (r >= 1 - 1e-9)
            return f;
        f.scale *= r * (1 - 1e-4);
    }
    std::ostringstream what;
    what << "the print does not fit the build volume " << volume[0] << " x " << volume[1] << " x "
         << volume[2] << " mm at any scale tried (down to " << f.scale << ")";
    throw std::runtime_error(what.str());
}

Fitted printed(const Model& model, const Printer& printer, double scale, const std::optional<Size>& fit)
{
    if (fit)
        return fitted(solvedToPrint(model, 1), *fit, printer);
    Fitted f{scale, solvedToPrint(model, scale), {}};
    f.printable = makePrintable(f.model, printer);
    return f;
}

}  // namespace fabguide::printable
