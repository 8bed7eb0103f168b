#include "Function/Pose.h"

#include <cmath>

namespace fabguide::function {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The six sides of a moved cuboid's bounding box, indexed by Side.
using Box = std::array<Expression, 6>;

int axisOf(Side side)
{
    return static_cast<int>(side) / 2;
}

Expression sum(std::initializer_list<std::pair<double, const Expression*>> parts)
{
    Expression total;
    for (const auto& [times, e] : parts) {
        for (const auto& [c, face] : e->terms)
            total.terms.push_back({times * c, face});
        total.constant += times * e->constant;
    }
    return total;
}

/// Turning about an axis a, the plane's axes (u, w) follow a cyclically: x → (y, z), y → (z, x),
/// z → (x, y). A point (u, w) goes to (pu + (u−pu)c − (w−pw)s, pw + (u−pu)s + (w−pw)c) about the pivot
/// (pu, pw). A low side is the least over the box's corners, a high side the greatest: each corner
/// coordinate is picked by the sign of its coefficient.
Box turned(int a, const Expression& pu, const Expression& pw, double degrees, const Box& box)
{
    const int u = (a + 1) % 3, w = (a + 2) % 3;
    const double c = std::cos(degrees * kPi / 180), s = std::sin(degrees * kPi / 180);
    Box result = box;
    for (bool high : {false, true}) {
        auto corner = [&](int axis, double coefficient) {
            return &box[2 * axis + ((coefficient >= 0) == high ? 1 : 0)];
        };
        result[2 * u + high] = sum({{1 - c, &pu}, {s, &pw}, {c, corner(u, c)}, {-s, corner(w, -s)}});
        result[2 * w + high] = sum({{1 - c, &pw}, {-s, &pu}, {s, corner(u, s)}, {c, corner(w, c)}});
    }
    return result;
}

/// A hinge turns about its edge as modelled; a double pivot's configuration turns the part about its pole.
Box moved(const Joint& joint, const JointPose& pose, Box box)
{
    if (joint.type == Joint::Type::DoublePivot) {
        const int a = axisOf(joint.pivotFace.side);
        return turned(a, {{}, pose.pole[(a + 1) % 3]}, {{}, pose.pole[(a + 2) % 3]}, pose.angle, box);
    }
    if (joint.turns()) {
        const int a = 3 - axisOf(joint.edgeA.side) - axisOf(joint.edgeB.side);
        const Face& fu = axisOf(joint.edgeA.side) == (a + 1) % 3 ? joint.edgeA : joint.edgeB;
        const Face& fw = axisOf(joint.edgeA.side) == (a + 2) % 3 ? joint.edgeA : joint.edgeB;
        box = turned(a, {{{1.0, fu}}, 0}, {{{1.0, fw}}, 0}, pose.angle, box);
    }
    if (joint.slides()) {
        box[2 * joint.axis].constant += pose.offset;
        box[2 * joint.axis + 1].constant += pose.offset;
    }
    return box;
}

const Joint* jointMoving(const Model& model, int part)
{
    for (const Joint& joint : model.joints)
        if (joint.part == part)
            return &joint;
    return nullptr;
}

}  // namespace

int partOf(const Model& model, int cuboid)
{
    for (size_t p = 0; p < model.parts.size(); ++p)
        for (int c : model.parts[p].cuboids)
            if (c == cuboid)
                return static_cast<int>(p);
    return -1;
}

Expression posed(const Model& model, const Face& face, int configuration)
{
    Box box;
    for (int k = 0; k < 6; ++k)
        box[k] = {{{1.0, Face{face.cuboid, static_cast<Side>(k)}}}, 0};
    if (configuration < 0)
        return box[static_cast<int>(face.side)];
    // The part's own joint first, then its base's, out to the ground (thesis 4.1.2, J(Θ)).
    for (const Joint* joint = jointMoving(model, partOf(model, face.cuboid)); joint;
         joint = joint->base < 0 ? nullptr : jointMoving(model, joint->base)) {
        const int j = static_cast<int>(joint - model.joints.data());
        for (const JointPose& pose : model.configurations[configuration].poses)
            if (pose.joint == j)
                box = moved(*joint, pose, box);
    }
    return box[static_cast<int>(face.side)];
}

double evaluate(const Model& model, const Expression& expression)
{
    double value = expression.constant;
    for (const auto& [coefficient, face] : expression.terms)
        value += coefficient * model.cuboids[face.cuboid].at(face.side);
    return value;
}

}  // namespace fabguide::function
