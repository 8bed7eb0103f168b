#include "Printable/Motion.h"

#include "Function/DoublePivot.h"

#include <gp_Ax1.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>

namespace fabguide::printable {

namespace {

using function::Joint;
using function::JointPose;
using function::Model;
using function::Side;

constexpr double kPi = 3.14159265358979323846;

gp_Trsf turn(const gp_Pnt& through, int axis, double degrees)
{
    gp_Trsf t;
    t.SetRotation(gp_Ax1(through, gp_Dir(axis == 0, axis == 1, axis == 2)), degrees * kPi / 180);
    return t;
}

gp_Trsf shift(int axis, double by)
{
    gp_Trsf t;
    t.SetTranslation(gp_Vec(axis == 0 ? by : 0, axis == 1 ? by : 0, axis == 2 ? by : 0));
    return t;
}

/// A hinge's edge: the point where its two faces meet (at the low end of the third axis) and that axis.
std::pair<gp_Pnt, int> edge(const Model& model, const Joint& joint)
{
    const gp_Ax1 axis = hingeAxis(model, joint);
    return {axis.Location(), std::abs(axis.Direction().X()) > 0.5   ? 0
                             : std::abs(axis.Direction().Y()) > 0.5 ? 1
                                                                    : 2};
}

/// A double pivot's pivot (on the part) and base pivot as 3-D points, and the pivot plane's normal axis.
struct Pivots {
    gp_Pnt pivot, base;
    int normal;
    double link, part;  ///< the four-bar's turns (degrees)
};

Pivots pivots(const Model& model, const Joint& joint, const JointPose& pose)
{
    const function::PivotPlane plane = function::pivotPlane(model, joint);
    const double n = model.cuboids[joint.pivotFace.cuboid].at(joint.pivotFace.side);
    auto point = [&](const std::array<double, 2>& uw) {
        double p[3];
        p[plane.normal] = n;
        p[plane.u] = uw[0];
        p[plane.w] = uw[1];
        return gp_Pnt(p[0], p[1], p[2]);
    };
    const auto [link, part] = function::linkAngles(model, joint, pose);
    return {point(plane.pivot), point(plane.basePivot), plane.normal, link, part};
}

}  // namespace

const JointPose* poseOf(const Model& model, int j, int configuration)
{
    if (configuration < 0)
        return nullptr;
    const auto& poses = model.configurations[configuration].poses;
    const auto found =
        std::find_if(poses.begin(), poses.end(), [&](const JointPose& p) { return p.joint == j; });
    return found == poses.end() ? nullptr : &*found;
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

int jointMoving(const Model& model, int part)
{
    for (size_t j = 0; j < model.joints.size(); ++j)
        if (model.joints[j].part == part)
            return static_cast<int>(j);
    return -1;
}

gp_Trsf jointMotion(const Model& model, int j, int configuration, double t)
{
    const JointPose* pose = poseOf(model, j, configuration);
    if (!pose)
        return {};
    const Joint& joint = model.joints[j];
    const double turning = std::min(1.0, 2 * t),
                 sliding = std::max(0.0, 2 * t - 1);  // turns first, then slides
    switch (joint.type) {
        case Joint::Type::Hinge: {
            const auto [through, axis] = edge(model, joint);
            return turn(through, axis, turning * pose->angle);
        }
        case Joint::Type::Slide:
            return shift(joint.axis, sliding * pose->offset);
        case Joint::Type::SlidingHinge: {
            const auto [through, axis] = edge(model, joint);
            return shift(joint.axis, sliding * pose->offset) * turn(through, axis, turning * pose->angle);
        }
        case Joint::Type::DoublePivot: {
            const Pivots p = pivots(model, joint, *pose);
            return turn(p.base, p.normal, turning * p.link) * turn(p.pivot, p.normal, turning * p.part);
        }
    }
    return {};
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
        const Pivots p = pivots(model, joint, *pose);
        own = turn(p.base, p.normal, std::min(1.0, 2 * t) * p.link);
    }
    return partMotion(model, joint.base, configuration, t) * own;
}

}  // namespace fabguide::printable
