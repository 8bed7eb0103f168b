#include "Printable/Motion.h"

#include "Function/DoublePivot.h"
#include "Printable/Solids.h"

#include <gp_Ax1.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <array>
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

gp_Trsf shift(int axis, double by)
{
    gp_Trsf t;
    t.SetTranslation(gp_Vec(axis == 0 ? by : 0, axis == 1 ? by : 0, axis == 2 ? by : 0));
    return t;
}

/// A double pivot's turns a fraction `along` of the way to its pose: about its base pivot (the link) and its
/// own pivot (the part).
struct FourBar {
    gp_Ax1 link, part;
    double linkDegrees, partDegrees;
};

/// A four-bar's links follow their linkage (function::fourBarPath, as the solve checked it); a lone link
/// turns evenly.
FourBar fourBar(const Model& model, int j, const JointPose& pose, int configuration, double along)
{
    const Joint& joint = model.joints[j];
    const auto [pivot, base] = pivotPoints(model, joint);
    const int n = function::pivotPlane(model, joint).normal;
    const gp_Dir normal(n == 0, n == 1, n == 2);
    const auto [link, part] = function::linkAngles(model, joint, pose);
    FourBar even{gp_Ax1(base, normal), gp_Ax1(pivot, normal), along * link, along * part};
    const Joint* partner = function::fourBarPartner(model, joint);
    if (!partner || along <= 0)
        return even;
    const bool first = &joint < partner;
    const int steps = static_cast<int>(std::ceil(64 * along));
    const std::vector<function::FourBarTurns> path = function::fourBarPath(
        model, first ? joint : *partner, first ? *partner : joint, configuration, along, steps);
    if (static_cast<int>(path.size()) < steps)
        return even;  // it comes apart on the way: the solve refused it already
    const double own = first ? path.back().first : path.back().second;
    return {even.link, even.part, own, path.back().part - own};
}

}  // namespace

std::pair<gp_Pnt, gp_Pnt> pivotPoints(const Model& model, const Joint& joint)
{
    const function::PivotPlane plane = function::pivotPlane(model, joint);
    const double n = model.cuboids[joint.pivotFace.cuboid].at(joint.pivotFace.side);
    auto point = [&](const std::array<double, 2>& uw) {
        gp_Pnt p;
        setCoord(p, plane.normal, n);
        setCoord(p, plane.u, uw[0]);
        setCoord(p, plane.w, uw[1]);
        return p;
    };
    return {point(plane.pivot), point(plane.basePivot)};
}

int hingeAlong(const Joint& joint)
{
    return 3 - function::axisOf(joint.edgeA.side) - function::axisOf(joint.edgeB.side);
}

gp_Ax1 hingeAxis(const Model& model, const Joint& joint)
{
    const auto& c = model.cuboids[joint.edgeA.cuboid];
    const int a = function::axisOf(joint.edgeA.side), b = function::axisOf(joint.edgeB.side);
    const int along = hingeAlong(joint);
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
            return turn(hingeAxis(model, joint), function::turnedAt(t) * pose->angle);
        case Joint::Type::Slide:
            return shift(joint.axis, function::slidAt(t) * pose->offset);
        case Joint::Type::SlidingHinge:
            return shift(joint.axis, function::slidAt(t) * pose->offset) *
                   turn(hingeAxis(model, joint), function::turnedAt(t) * pose->angle);
        case Joint::Type::DoublePivot: {
            const FourBar f = fourBar(model, j, *pose, configuration, function::turnedAt(t));
            return turn(f.link, f.linkDegrees) * turn(f.part, f.partDegrees);
        }
        case Joint::Type::Fixed:  // no poses: it rides on its base
            return {};
    }
    return {};
}

bool standsStill(const Model& model, int part)
{
    return jointMoving(model, function::carrierOf(model, part)) < 0;
}

namespace {

/// Whether solid cuboid c touches part q's material as modelled: a solid cuboid of q where the two meet
/// outside both parts' cavities, or, from inside one of q's cavities, one of its walls (a side that is no
/// opening): a shelf against a cupboard's sides, an insert on a well's floor.
bool touchesMaterial(const Model& m, int c, int q)
{
    constexpr double hair = 1e-6;
    const auto& a = m.cuboids[c].coordinates;
    const auto within = [&](const auto& inner, const auto& outer) {
        for (int s = 0; s < 6; ++s)
            if (s % 2 ? inner[s] > outer[s] + hair : inner[s] < outer[s] - hair)
                return false;
        return true;
    };
    for (int d : m.parts[q].cuboids) {
        const auto& b = m.cuboids[d].coordinates;
        if (!m.cuboids[d].cavity()) {
            std::array<double, 6> meet{};
            bool apart = false;
            for (int axis = 0; axis < 3; ++axis) {
                meet[2 * axis] = std::max(a[2 * axis], b[2 * axis]);
                meet[2 * axis + 1] = std::min(a[2 * axis + 1], b[2 * axis + 1]);
                apart = apart || meet[2 * axis + 1] - meet[2 * axis] < -hair;
            }
            const auto inCavityOf = [&](int part) {
                return std::any_of(m.parts[part].cuboids.begin(), m.parts[part].cuboids.end(), [&](int k) {
                    return m.cuboids[k].cavity() && within(meet, m.cuboids[k].coordinates);
                });
            };
            const bool inCavity = inCavityOf(q) || inCavityOf(function::partOf(m, c));
            if (!apart && !inCavity)
                return true;
        } else if (within(a, b)) {
            for (int s = 0; s < 6; ++s)
                if (std::abs(a[s] - b[s]) < hair && !function::isOpening(m, d, s))
                    return true;
        }
    }
    return false;
}

}  // namespace

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
    const auto touch = [&](int p, int q) {
        for (int c : model.parts[p].cuboids)
            if (!model.cuboids[c].cavity() && touchesMaterial(model, c, q))
                return true;
        for (int d : model.parts[q].cuboids)
            if (!model.cuboids[d].cavity() && touchesMaterial(model, d, p))
                return true;
        return false;
    };
    for (const Joint& joint : model.joints)  // a fixed part is one body with its base
        if (joint.type == Joint::Type::Fixed)
            body[root(joint.part)] = root(joint.base);
    for (int p = 0; p < parts; ++p)
        for (int q = p + 1; q < parts; ++q)
            if (standsStill(model, p) && standsStill(model, q) && touch(p, q))
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
        const FourBar f = fourBar(model, j, *pose, configuration, function::turnedAt(t));
        own = turn(f.link, f.linkDegrees);
    }
    return partMotion(model, joint.base, configuration, t) * own;
}

}  // namespace fabguide::printable
