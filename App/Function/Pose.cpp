#include "Function/Pose.h"
#include "Geometry/Interval.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fabguide::function {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// The six sides of a moved cuboid's bounding box, indexed by Side.
using Box = std::array<Expression, 6>;

/// Zero terms are left out, so a quarter turn keeps faces equal to the last bit.
Expression sum(std::initializer_list<std::pair<double, const Expression*>> parts)
{
    Expression total;
    for (const auto& [times, e] : parts) {
        for (const auto& [c, face] : e->terms)
            if (times * c != 0)
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
    const auto [c, s] = cosSin(degrees);
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

/// How a posed joint moves its part: a turn by `degrees` about the coordinate axis `a` through (pu, pw) in
/// the plane of the axes after it, then a shift along `shiftAxis` (-1: none). A hinge turns about its edge as
/// modelled; a double pivot's configuration turns the part about its pole.
struct Move {
    bool turns = false;
    int a = 0;
    Expression pu, pw;
    double degrees = 0;
    int shiftAxis = -1;
    double shift = 0;
};

Move moveOf(const Joint& joint, const JointPose& pose)
{
    Move m;
    if (joint.type == Joint::Type::DoublePivot) {
        m.turns = true;
        m.a = axisOf(joint.pivotFace.side);
        m.pu = {{}, pose.pole[(m.a + 1) % 3]};
        m.pw = {{}, pose.pole[(m.a + 2) % 3]};
    } else if (joint.turns()) {
        m.turns = true;
        m.a = 3 - axisOf(joint.edgeA.side) - axisOf(joint.edgeB.side);
        const bool aFirst = axisOf(joint.edgeA.side) == (m.a + 1) % 3;
        m.pu = {{{1.0, aFirst ? joint.edgeA : joint.edgeB}}, 0};
        m.pw = {{{1.0, aFirst ? joint.edgeB : joint.edgeA}}, 0};
    }
    m.degrees = pose.angle;
    if (joint.slides()) {
        m.shiftAxis = joint.axis;
        m.shift = pose.offset;
    }
    return m;
}

Box moved(const Move& m, Box box)
{
    if (m.turns)
        box = turned(m.a, m.pu, m.pw, m.degrees, box);
    if (m.shiftAxis >= 0) {
        box[2 * m.shiftAxis].constant += m.shift;
        box[2 * m.shiftAxis + 1].constant += m.shift;
    }
    return box;
}

/// The moves that place a cuboid's part in a configuration: its own joint's first, then its base's, out to
/// the ground (thesis 4.1.2, J(Θ)).
std::vector<Move> chain(const Model& model, int cuboid, int configuration)
{
    std::vector<Move> moves;
    if (configuration < 0)
        return moves;
    for (int j = jointMoving(model, partOf(model, cuboid)); j >= 0;
         j = model.joints[j].base < 0 ? -1 : jointMoving(model, model.joints[j].base))
        if (const JointPose* pose = poseOf(model, j, configuration))
            moves.push_back(moveOf(model.joints[j], *pose));
    return moves;
}

}  // namespace

int cuboidNear(const Model& model, const Joint& joint, double reach)
{
    const Cuboid& own = model.cuboids[joint.edgeA.cuboid];
    const int a = axisOf(joint.edgeA.side), b = axisOf(joint.edgeB.side), running = 3 - a - b;
    int best = -1;
    double longest = 0;
    for (int p = 0; p < static_cast<int>(model.parts.size()); ++p) {
        // The part it turns on: its base, or on the ground one that no joint moves (not a neighbouring door).
        if (p == joint.part ||
            (joint.base >= 0 ? p != joint.base : jointMoving(model, carrierOf(model, p)) >= 0))
            continue;
        for (int c : model.parts[p].cuboids) {
            if (model.cuboids[c].cavity())
                continue;
            double d2 = 0;  // the edge's distance from the box across the axis
            for (const Face& f : {joint.edgeA, joint.edgeB}) {
                const Interval box = along(model.cuboids[c].coordinates, axisOf(f.side));
                const double out = std::max({0.0, box.lower - own.at(f.side), own.at(f.side) - box.upper});
                d2 += out * out;
            }
            const double shared =
                overlapOf(along(model.cuboids[c].coordinates, running), along(own.coordinates, running));
            if (std::sqrt(d2) <= reach && shared > longest) {
                longest = shared;
                best = c;
            }
        }
    }
    return best;
}

std::pair<double, double> cosSin(double degrees)
{
    const double quarters = degrees / 90;
    if (std::abs(quarters) < 1e15 && quarters == static_cast<double>(static_cast<long long>(quarters))) {
        const int q = static_cast<int>(((static_cast<long long>(quarters) % 4) + 4) % 4);
        return {q == 0 ? 1 : q == 2 ? -1 : 0, q == 1 ? 1 : q == 3 ? -1 : 0};
    }
    return {std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180)};
}

int jointMoving(const Model& model, int part)
{
    if (model.jointOfPart.size() == model.parts.size())
        return model.jointOfPart[part];
    for (size_t j = 0; j < model.joints.size(); ++j)
        if (model.joints[j].part == part)
            return static_cast<int>(j);
    return -1;
}

const JointPose* poseOf(const Model& model, int joint, int configuration)
{
    if (configuration < 0)
        return nullptr;
    const Configuration& c = model.configurations[configuration];
    if (c.poseOfJoint.size() == model.joints.size())
        return c.poseOfJoint[joint] < 0 ? nullptr : &c.poses[c.poseOfJoint[joint]];
    const auto& poses = c.poses;
    const auto found =
        std::find_if(poses.begin(), poses.end(), [&](const JointPose& p) { return p.joint == joint; });
    return found == poses.end() ? nullptr : &*found;
}

int jointMovingIn(const Model& model, int part, int configuration)
{
    // The reader refuses bases that go round in a circle; the bound only guards against a half-read model.
    for (size_t step = 0; part >= 0 && step <= model.joints.size(); ++step) {
        const int j = jointMoving(model, part);
        if (j < 0)
            return -1;
        if (poseOf(model, j, configuration))
            return j;
        part = model.joints[j].base;
    }
    return -1;
}

int carrierOf(const Model& model, int part)
{
    for (size_t step = 0; step <= model.joints.size(); ++step) {  // the bound: as jointMovingIn's
        const int j = jointMoving(model, part);
        if (j < 0 || model.joints[j].type != Joint::Type::Fixed)
            return part;
        part = model.joints[j].base;
    }
    return part;
}

int partOf(const Model& model, int cuboid)
{
    if (model.partOfCuboid.size() == model.cuboids.size())
        return model.partOfCuboid[cuboid];
    for (size_t p = 0; p < model.parts.size(); ++p)
        for (int c : model.parts[p].cuboids)
            if (c == cuboid)
                return static_cast<int>(p);
    return -1;
}

std::array<Expression, 6> posedBox(const Model& model, int cuboid, int configuration)
{
    Box box;
    for (int k = 0; k < 6; ++k)
        box[k] = {{{1.0, Face{cuboid, static_cast<Side>(k)}}}, 0};
    for (const Move& m : chain(model, cuboid, configuration))
        box = moved(m, box);
    return box;
}

std::vector<int> owners(const Model& model)
{
    if (model.partOfCuboid.size() == model.cuboids.size())
        return model.partOfCuboid;
    std::vector<int> owner(model.cuboids.size(), -1);
    for (size_t p = 0; p < model.parts.size(); ++p)
        for (int c : model.parts[p].cuboids)
            owner[c] = static_cast<int>(p);
    return owner;
}

Model indexed(Model model)
{
    model.partOfCuboid.clear();  // so that owners finds them anew
    model.partOfCuboid = owners(model);
    model.jointOfPart.assign(model.parts.size(), -1);
    for (size_t j = model.joints.size(); j-- > 0;)  // the first joint of each part
        model.jointOfPart[model.joints[j].part] = static_cast<int>(j);
    for (Configuration& c : model.configurations) {
        c.poseOfJoint.assign(model.joints.size(), -1);
        for (size_t p = c.poses.size(); p-- > 0;)  // the first pose of each joint, as poseOf's search finds
            c.poseOfJoint[c.poses[p].joint] = static_cast<int>(p);
    }
    return model;
}

Expression posed(const Model& model, const Face& face, int configuration)
{
    return posedBox(model, face.cuboid, configuration)[static_cast<int>(face.side)];
}

std::array<double, 6> posedBounds(const Model& model, int cuboid, int configuration)
{
    const Box box = posedBox(model, cuboid, configuration);
    std::array<double, 6> bounds{};
    for (int k = 0; k < 6; ++k)
        bounds[k] = evaluate(model, box[k]);
    return bounds;
}

Expression projected(const Model& model, int cuboid, int configuration, Direction d, bool high)
{
    // q = T(x) = R(x − p) + p + t: q·d = x·Rᵀd − p·Rᵀd + p·d + t·d, outermost move first.
    Expression e;
    const std::vector<Move> moves = chain(model, cuboid, configuration);
    for (auto m = moves.rbegin(); m != moves.rend(); ++m) {
        if (m->shiftAxis >= 0)
            e.constant += m->shift * d[m->shiftAxis];
        if (!m->turns)
            continue;
        const int u = (m->a + 1) % 3, w = (m->a + 2) % 3;
        const auto [c, s] = cosSin(m->degrees);
        Direction back = d;
        back[u] = c * d[u] + s * d[w];
        back[w] = -s * d[u] + c * d[w];
        e = sum({{1, &e}, {d[u] - back[u], &m->pu}, {d[w] - back[w], &m->pw}});
        d = back;
    }
    for (int i = 0; i < 3; ++i)  // the cuboid as modelled: its extreme corner along d
        if (d[i] != 0)
            e.terms.push_back({d[i], Face{cuboid, static_cast<Side>(2 * i + ((d[i] > 0) == high ? 1 : 0))}});
    return e;
}

std::array<Direction, 3> posedAxes(const Model& model, int cuboid, int configuration)
{
    std::array<Direction, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (const Move& m : chain(model, cuboid, configuration)) {
        if (!m.turns)
            continue;
        const int u = (m.a + 1) % 3, w = (m.a + 2) % 3;
        const auto [c, s] = cosSin(m.degrees);
        for (Direction& v : axes) {
            const double vu = v[u], vw = v[w];
            v[u] = c * vu - s * vw;
            v[w] = s * vu + c * vw;
        }
    }
    return axes;
}

double evaluate(const Model& model, const Expression& expression)
{
    double value = expression.constant;
    for (const auto& [coefficient, face] : expression.terms)
        value += coefficient * model.cuboids[face.cuboid].at(face.side);
    return value;
}

}  // namespace fabguide::function
