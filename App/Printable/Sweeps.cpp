#include "Printable/Sweeps.h"

#include "Printable/Motion.h"

#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Quaternion.hxx>

#include <cmath>
#include <tuple>

namespace fabguide::printable {

namespace {

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

/// Boxes cut in two (or four) by the planes through `axis` along the box's sides wherever it passes through
/// one: no face of the pieces crosses the axis. A face across its axis revolves into a solid that turns
/// through itself, which OpenCASCADE cannot unite or cut reliably (parts grown by the gap reach their hinge's
/// line, small scales).
std::vector<Coordinates> splitAtAxis(const std::vector<Coordinates>& boxes, const gp_Ax1& axis)
{
    std::vector<Coordinates> pieces = boxes;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(coord(axis.Direction(), a)) > 0.5)
            continue;
        const double x = coord(axis.Location(), a);
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

}  // namespace

int hingeOn(const Model& m, int carried, int base, int k)
{
    const int j = jointMoving(m, function::carrierOf(m, carried));
    const bool onBase =
        j >= 0 && (m.joints[j].base == base || (m.joints[j].base < 0 && standsStill(m, base)));
    const bool hinge = j >= 0 && m.joints[j].turns() && m.joints[j].type != Joint::Type::DoublePivot;
    return onBase && hinge && poseOf(m, j, k) ? j : -1;
}

std::vector<TopoDS_Shape> turnedThenShifted(const std::vector<Coordinates>& boxes, const gp_Ax1& axis,
                                            double radians, const gp_Vec& by)
{
    std::vector<TopoDS_Shape> swept;
    for (const Coordinates& piece : splitAtAxis(boxes, axis))
        swept.push_back(turnedThenShifted(box(piece), axis, radians, by));
    return swept;
}

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

std::vector<TopoDS_Shape> hingeSweep(const Model& m, const Joint& joint, const function::JointPose& pose,
                                     const std::vector<Coordinates>& boxes, int direction)
{
    const gp_Ax1 axis = hingeAxis(m, joint);
    const double radians = direction * pose.angle * kPi / 180;
    gp_Vec by(0, 0, 0);
    if (joint.slides())
        setCoord(by, joint.axis, pose.offset);
    if (direction < 0) {  // undone: turned back, then shifted back along the slide turned back
        gp_Trsf back;
        back.SetRotation(axis, radians);
        by = -by.Transformed(back);
    }
    return turnedThenShifted(boxes, axis, radians, by);
}

std::vector<TopoDS_Shape> pathRelative(const Model& m, int k, int a, int b,
                                       const std::vector<Coordinates>& boxes)
{
    for (const auto& [carried, base, sign] : {std::tuple{b, a, -1}, std::tuple{a, b, 1}})
        if (const int j = hingeOn(m, carried, base, k); j >= 0)
            return hingeSweep(m, m.joints[j], *poseOf(m, j, k), boxes, sign);
    const TopoDS_Shape shape = solid(boxes);
    const auto relative = [&](double t) {
        return partMotion(m, b, k, t).Inverted() * partMotion(m, a, k, t);
    };
    // The first half turns: a pose on every 64th of the way, none repeated while nothing turns (the last is
    // the prism's start).
    const auto same = [](const gp_Trsf& x, const gp_Trsf& y) {
        const gp_Trsf d = x.Inverted() * y;
        return d.TranslationPart().Modulus() < 1e-9 && std::abs(d.GetRotation().GetRotationAngle()) < 1e-12;
    };
    std::vector<TopoDS_Shape> path;
    for (int step = 1; step < 32; ++step)
        if (!same(relative(step / 64.0), relative((step + 1) / 64.0)))
            path.push_back(moved(shape, relative(step / 64.0)));
    // The second half only slides, so relative to b, a shifts in a straight line: the prism it sweeps.
    const gp_Vec by((relative(1) * relative(0.5).Inverted()).TranslationPart());
    path.push_back(turnedThenShifted(moved(shape, relative(0.5)), gp_Ax1(), 0, by));
    return path;
}

}  // namespace fabguide::printable
