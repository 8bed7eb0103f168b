#include "Function/Pose.h"

#include <cmath>

namespace fabguide::function {

namespace {

constexpr double kPi = 3.14159265358979323846;

Side low(int axis)
{
    return static_cast<Side>(2 * axis);
}
Side high(int axis)
{
    return static_cast<Side>(2 * axis + 1);
}
int axisOf(Side side)
{
    return static_cast<int>(side) / 2;
}
bool isHigh(Side side)
{
    return static_cast<int>(side) % 2 == 1;
}

int partOf(const Model& model, int cuboid)
{
    for (size_t p = 0; p < model.parts.size(); ++p)
        for (int c : model.parts[p].cuboids)
            if (c == cuboid)
                return static_cast<int>(p);
    return -1;
}

/// Turning about an axis a, the plane's axes (u, w) follow a cyclically: x → (y, z), y → (z, x), z → (x, y).
/// A point (u, w) goes to (pu + (u−pu)c − (w−pw)s, pw + (u−pu)s + (w−pw)c) about the pivot (pu, pw).
Expression hinged(const Joint& joint, double degrees, const Face& face)
{
    const int a = 3 - axisOf(joint.edgeA.side) - axisOf(joint.edgeB.side);
    const int u = (a + 1) % 3, w = (a + 2) % 3;
    if (axisOf(face.side) == a)
        return {{{1.0, face}}, 0};
    const Face pu = axisOf(joint.edgeA.side) == u ? joint.edgeA : joint.edgeB;
    const Face pw = axisOf(joint.edgeA.side) == w ? joint.edgeA : joint.edgeB;
    const double c = std::cos(degrees * kPi / 180), s = std::sin(degrees * kPi / 180);
    const int c0 = face.cuboid;
    // The side wanted is a min (low side) or a max over the four corners: pick each corner coordinate
    // by the sign of its coefficient.
    const bool wantMax = isHigh(face.side);
    auto corner = [&](int axis, double coefficient) {
        const bool takeHigh = (coefficient >= 0) == wantMax;
        return Face{c0, takeHigh ? high(axis) : low(axis)};
    };
    if (axisOf(face.side) == u)  // u' = pu(1−c) + pw·s + u·c − w·s
        return {{{1 - c, pu}, {s, pw}, {c, corner(u, c)}, {-s, corner(w, -s)}}, 0};
    // w' = pw(1−c) − pu·s + u·s + w·c
    return {{{1 - c, pw}, {-s, pu}, {s, corner(u, s)}, {c, corner(w, c)}}, 0};
}

}  // namespace

Expression posed(const Model& model, const Face& face, int configuration)
{
    if (configuration < 0)
        return {{{1.0, face}}, 0};
    const int part = partOf(model, face.cuboid);
    for (const auto& [j, pose] : model.configurations[configuration].poses) {
        const Joint& joint = model.joints[j];
        if (joint.part != part)
            continue;
        if (joint.type == Joint::Type::Slide)
            return {{{1.0, face}}, axisOf(face.side) == joint.axis ? pose : 0.0};
        return hinged(joint, pose, face);
    }
    return {{{1.0, face}}, 0};
}

double evaluate(const Model& model, const Expression& expression)
{
    double value = expression.constant;
    for (const auto& [coefficient, face] : expression.terms)
        value += coefficient * model.cuboids[face.cuboid].at(face.side);
    return value;
}

}  // namespace fabguide::function
