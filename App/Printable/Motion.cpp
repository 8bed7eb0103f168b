#include "Printable/Motion.h"

#include "Function/DoublePivot.h"

#include <gp_Ax1.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fabguide::printable {

namespace {

using function::Joint;
using function::JointPose;
using function::Model;
using function::Side;

constexpr double kPi = 3.14159265358979323846;

gp_Trsf turn(const gp_Ax1& axis, double degrees)
{
    gp_Trsf t;
    t.SetRotation(axis, degrees * kPi / 180);
    return t;
}

/// Turns happen in the first half of a motion, slides in the second.
double turning(double t)
{
    return std::min(1.0, 2 * t);
}
double sliding(double t)
{
    return std::max(0.0, 2 * t - 1);
}

gp_Trsf shift(int axis, double by)
{
    gp_Trsf t;
    t.SetTranslation(gp_Vec(axis == 0 ? by : 0, axis == 1 ? by : 0, axis == 2 ? by : 0));
    return t;
}

/// A double pivot's four-bar: the turns about its base pivot (the link) and its own pivot (the part).
struct FourBar {
    gp_Ax1 link, part;
    double linkDegrees, partDegrees;
};

FourBar fourBar(const Model& model, const Joint& joint, const JointPose& pose)
{
    const auto [pivot, base] = pivotPoints(model, joint);
    const int n = function::pivotPlane(model, joint).normal;
    const gp_Dir normal(n == 0, n == 1, n == 2);
    const auto [link, part] = function::linkAngles(model, joint, pose);
    return {gp_Ax1(base, normal), gp_Ax1(pivot, normal), link, part};
}

}  // namespace

std::pair<gp_Pnt, gp_Pnt> pivotPoints(const Model& model, const Joint& joint)
{
    const function::PivotPlane plane = function::pivotPlane(model, joint);
    const double n = model.cuboids[joint.pivotFace.cuboid].at(joint.pivotFace.side);
    auto point = [&](const std::array<double, 2>& uw) {
        gp_Pnt p;
        p.SetCoord(plane.normal + 1, n);
        p.SetCoord(plane.u + 1, uw[0]);
        p.SetCoord(plane.w + 1, uw[1]);
        return p;
    };
    return {point(plane.pivot), point(plane.basePivot)};
}

gp_Ax1 hingeAxis(const Model& model, const Joint& joint)
{
    const auto& c = model.cuboids[joint.edgeA.cuboid];
    const int a = static_cast<int>(joint.edgeA.side) / 2, b = static_cast<int>(joint.edgeB.side) / 2;
    const int along = 3 - a - b;
    double p[3];
    p[a] = c.at(joint.edgeA.side);
    p[b] = c.at(joint.edgeB.side);
    p[along] = c.at(static_cast<Side>(2 * along));
    return gp_Ax1(gp_Pnt(p[0], p[1], p[2]), gp_Dir(along == 0, along == 1, along == 2));
}

gp_Trsf jointMotion(const Model& model, int j, int configuration, double t)
{
    const JointPose* pose = poseOf(model, j, configuration);
    if (!pose)
        return {};
    const Joint& joint = model.joints[j];
    switch (joint.type) {
        case Joint::Type::Hinge:
            return turn(hingeAxis(model, joint), turning(t) * pose->angle);
        case Joint::Type::Slide:
            return shift(joint.axis, sliding(t) * pose->offset);
        case Joint::Type::SlidingHinge:
            return shift(joint.axis, sliding(t) * pose->offset) *
                   turn(hingeAxis(model, joint), turning(t) * pose->angle);
        case Joint::Type::DoublePivot: {
            const FourBar f = fourBar(model, joint, *pose);
            return turn(f.link, turning(t) * f.linkDegrees) * turn(f.part, turning(t) * f.partDegrees);
        }
    }
    return {};
}

bool standsStill(const Model& model, int part)
{
    return jointMoving(model, part) < 0;
}

std::vector<std::vector<int>> rigidBodies(const Model& model)
{
    const int parts = static_cast<int>(model.parts.size());
    std::vector<int> body(parts);  // union-find: the first part of each one's body
    std::iota(body.begin(), body.end(), 0);
    const auto root = [&](int p) {
        while (body[p] != p)
            p = body[p] = body[body[p]];
        return p;
    };
    const auto touch = [&](int c, int d) {  // solid cuboids touching or overlapping as modelled
        const auto &a = model.cuboids[c].coordinates, &b = model.cuboids[d].coordinates;
        for (int axis = 0; axis < 3; ++axis)
            if (std::min(a[2 * axis + 1], b[2 * axis + 1]) - std::max(a[2 * axis], b[2 * axis]) < -1e-6)
                return false;
        return !model.cuboids[c].cavity() && !model.cuboids[d].cavity();
    };
    for (int p = 0; p < parts; ++p)
        for (int q = p + 1; q < parts; ++q)
            if (standsStill(model, p) && standsStill(model, q))
                for (int c : model.parts[p].cuboids)
                    for (int d : model.parts[q].cuboids)
                        if (touch(c, d))
                            body[root(q)] = root(p);
    std::vector<std::vector<int>> bodies;
    std::vector<int> index(parts, -1);
    for (int p = 0; p < parts; ++p) {
        int& i = index[root(p)];
        if (i < 0) {
            i = static_cast<int>(bodies.size());
            bodies.emplace_back();
        }
        bodies[i].push_back(p);
    }
    return bodies;
}

gp_Trsf partMotion(const Model& model, int part, int configuration, double t)
{
    gp_Trsf total;
    std::vector<int> seen;
    for (int j = jointMoving(model, part); j >= 0 && std::find(seen.begin(), seen.end(), j) == seen.end();) {
        seen.push_back(j);
        total = jointMotion(model, j, configuration, t) * total;
        const int base = model.joints[j].base;
        j = base >= 0 ? jointMoving(model, base) : -1;
    }
    return total;
}

gp_Trsf linkMotion(const Model& model, int j, int configuration, double t)
{
    const Joint& joint = model.joints[j];
    gp_Trsf own;
    if (const JointPose* pose = poseOf(model, j, configuration)) {
        const FourBar f = fourBar(model, joint, *pose);
        own = turn(f.link, turning(t) * f.linkDegrees);
    }
    return partMotion(model, joint.base, configuration, t) * own;
}

}  // namespace fabguide::printable
