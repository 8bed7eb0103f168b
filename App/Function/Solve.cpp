#include "Function/Solve.h"

#include "Function/Cover.h"
#include "Function/DoublePivot.h"
#include "Function/FitInside.h"
#include "Function/Pose.h"
#include "Function/Separation.h"
#include "Geometry/Interval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace fabguide::function {

namespace {

/// The names the solve gives what it keeps besides the relationships, each written here once: a conflict
/// names them, and `typed` tells them apart by these, never by their wording.
std::string lockName(const Model& model, const Lock& lock)
{
    return "lock: " + faceName(model, lock.face);
}

std::string onePieceName(const Part& part)
{
    return "one piece: " + part.name;
}

std::string wallName(const Cuboid& cavity)
{
    return "wall: " + cavity.name;
}

std::string drawnInsideName(const Model& model, int inner, int outer)
{
    return "drawn inside: " + model.cuboids[inner].name + " in " + model.cuboids[outer].name;
}

const std::string kStillMeeting = "no overlap";  ///< parts still meeting after every round of separations

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// left − right measured in a configuration, as constraint terms and the constant that moves to the bound.
std::pair<std::vector<std::pair<int, double>>, double> difference(const Model& model, const Expression& left,
                                                                  const Expression& right, int configuration)
{
    std::vector<std::pair<int, double>> terms;
    double constant = left.constant - right.constant;
    auto add = [&](const Expression& side, double sign) {
        for (const auto& [c, face] : side.terms) {
            const Expression moved = posed(model, face, configuration);
            for (const auto& [k, f] : moved.terms)
                terms.push_back({variable(f), sign * c * k});
            constant += sign * c * moved.constant;
        }
    };
    add(left, 1);
    add(right, -1);
    return {terms, -constant};
}

/// Face `low` at most (or exactly) at face `high`, measured in a configuration.
void order(std::vector<LinearConstraint>& rows, const Model& model, const std::string& name,
           int configuration, const Face& low, const Face& high, bool equal)
{
    if (low == high)
        return;
    auto [terms, bound] = difference(model, {{{1.0, low}}, 0}, {{{1.0, high}}, 0}, configuration);
    rows.push_back({terms, equal ? bound : -kInfinity, bound, name});
}

/// A cavity stays within its solid cuboid (thesis 4.1.1), its openings on the solid's faces; its other sides
/// keep the minimum wall inside them ("wall: well", named so a conflict can blame it).
void walls(std::vector<LinearConstraint>& rows, const Model& model, int cavity, int solid)
{
    for (int k = 0; k < 6; ++k) {
        const double sign = k % 2 ? 1 : -1;  // cavity − solid, outwards
        const std::vector<std::pair<int, double>> terms{{6 * cavity + k, sign}, {6 * solid + k, -sign}};
        const bool opening = isOpening(model, cavity, k);
        rows.push_back({terms, opening ? 0 : -kInfinity, 0, ""});
        if (!opening && model.minimumWall > 0)
            rows.push_back({terms, -kInfinity, -model.minimumWall, wallName(model.cuboids[cavity])});
    }
}

/// The gaps between two boxes along each axis where they overlap (negative: apart by that much).
std::array<double, 3> meeting(const Cuboid& a, const Cuboid& b)
{
    std::array<double, 3> meet{};
    for (int axis = 0; axis < 3; ++axis)
        meet[axis] = overlapOf(along(a.coordinates, axis), along(b.coordinates, axis));
    return meet;
}

/// How far apart two boxes are along the axis they are farthest apart on (negative: they overlap).
double apart(const Cuboid& a, const Cuboid& b)
{
    const std::array<double, 3> meet = meeting(a, b);
    return -*std::min_element(meet.begin(), meet.end());
}

/// Cuboids a and b keep touching along the axis they meet least on (or overlapping), and overlapping along
/// the other two by as much as modelled, or the minimum size.
void glue(std::vector<LinearConstraint>& rows, const Model& model, int a, int b, const std::string& name)
{
    const std::array<double, 3> meet = meeting(model.cuboids[a], model.cuboids[b]);
    const long touching = std::min_element(meet.begin(), meet.end()) - meet.begin();
    for (int axis = 0; axis < 3; ++axis) {
        const double least = axis == touching ? 0.0
                             : meet[axis] > 0 ? std::min(meet[axis], model.minimumSize)
                                              : model.minimumSize;
        for (const auto& [high, low] : {std::pair{a, b}, std::pair{b, a}})  // high's top past low's bottom
            rows.push_back(
                {{{6 * high + 2 * axis + 1, 1.0}, {6 * low + 2 * axis, -1.0}}, least, kInfinity, name});
    }
}

/// A part stays in one piece: each two of its glued cuboids stay glued ("one piece: drawer"). A drawer's tray
/// held in its bay stays glued to its front when the bay's mouth moves.
void onePiece(std::vector<LinearConstraint>& rows, const Model& model, const Part& part)
{
    for (const Pieces::Glued& g : piecesOf(model, part).glued)
        glue(rows, model, g.a, g.b, onePieceName(part));
}

/// A part a fixed joint holds prints as one body with its base: its nearest cuboid and the base's stay glued
/// (a knob drawn a hair off its door ends on it; one drawn into it stays in it).
void heldFixed(std::vector<LinearConstraint>& rows, const Model& model, const Joint& joint)
{
    double nearest = std::numeric_limits<double>::infinity();
    int a = -1, b = -1;
    for (int c : model.parts[joint.part].cuboids)
        for (int d : model.parts[joint.base].cuboids)
            if (!model.cuboids[c].cavity() && !model.cuboids[d].cavity())
                if (const double by = apart(model.cuboids[c], model.cuboids[d]); by < nearest)
                    std::tie(nearest, a, b) = std::tuple{by, c, d};
    if (a >= 0)
        glue(rows, model, a, b, joint.name);
}

/// A hinge holds its part on the part it turns on: its edge stays beside that part's cuboid it was drawn
/// along (cuboidNear within twice the edge cuboid's thinnest side, the farthest the print looks), no farther
/// off it across the axis than the edge cuboid's thinnest side or as drawn, and running beside it along the
/// axis. A door whose swing met a post on the carcass's plinth had its hinge moved 269 mm off the carcass,
/// and printed without one.
void heldOnEdge(std::vector<LinearConstraint>& rows, const Model& model, const Joint& joint)
{
    const Cuboid& own = model.cuboids[joint.edgeA.cuboid];
    const std::array<Face, 2> edge{joint.edgeA, joint.edgeB};
    const int running = 3 - axisOf(edge[0].side) - axisOf(edge[1].side);
    const int base = cuboidNear(model, joint, 2 * own.thinnest());
    if (base < 0)
        return;  // the print says that nothing holds its yokes
    const Cuboid& on = model.cuboids[base];
    const double longest = overlapOf(along(on.coordinates, running), along(own.coordinates, running));
    for (const Face& f : edge) {
        const int low = 6 * base + 2 * axisOf(f.side), high = low + 1;
        rows.push_back({{{variable(f), 1.0}, {low, -1.0}},
                        -std::max(own.thinnest(), on.coordinates[low % 6] - own.at(f.side)),
                        kInfinity,
                        joint.name});
        rows.push_back({{{high, 1.0}, {variable(f), -1.0}},
                        -std::max(own.thinnest(), own.at(f.side) - on.coordinates[high % 6]),
                        kInfinity,
                        joint.name});
    }
    const double least = std::min(longest, model.minimumSize);
    for (const auto& [a, b] : {std::pair{joint.edgeA.cuboid, base}, std::pair{base, joint.edgeA.cuboid}})
        rows.push_back(
            {{{6 * a + 2 * running + 1, 1.0}, {6 * b + 2 * running, -1.0}}, least, kInfinity, joint.name});
}

/// The constraints that keep a pair clear (Separation.h), in its configuration.
void separate(std::vector<LinearConstraint>& rows, const Model& model, const Separation& s)
{
    const std::string name = separationName(model, s);
    if (s.walls.empty()) {  // a's projection on the direction at most b's
        const Expression a = projected(model, s.a, s.configuration, s.direction, true),
                         b = projected(model, s.b, s.configuration, s.direction, false);
        LinearConstraint row{{}, -kInfinity, b.constant - a.constant, name};
        for (const auto& [c, face] : a.terms)
            row.terms.push_back({variable(face), c});
        for (const auto& [c, face] : b.terms)
            row.terms.push_back({variable(face), -c});
        rows.push_back(row);
        return;
    }
    for (const Face& wall : s.walls) {
        const Face held{s.a, wall.side};
        const bool high = static_cast<int>(wall.side) % 2;
        order(rows, model, name, s.configuration, high ? held : wall, high ? wall : held, false);
    }
}

/// Whether cuboid c of an inner part must lie inside (a partial fit names the portion that must).
bool fits(const Model& model, const FitInside& f, int c)
{
    return !model.cuboids[c].cavity() &&
           (f.portion.empty() || std::find(f.portion.begin(), f.portion.end(), c) != f.portion.end());
}

/// Cover (thesis 4.2.1, eq. 4.1; packing 4.3.1): per component of M, one plane, each face set packed, the
/// covering box around (or, just, equal to) the covered box.
void coverConstraints(std::vector<LinearConstraint>& rows, const Model& model, const Cover& c)
{
    auto rule = [&](const Face& low, const Face& high, bool equal) {
        order(rows, model, c.name, c.configuration, low, high, equal);
    };
    for (const CoverComponent& component : components(c.pairs)) {
        const Face plane = component.covering.front();
        for (const auto* faces : {&component.covering, &component.covered})
            for (const Face& f : *faces)
                rule(f, plane, true);
        const Packing covering = packing(model, component.covering, c.configuration, c.distance),
                      covered = packing(model, component.covered, c.configuration, c.distance);
        for (const Packing* p : {&covering, &covered}) {
            for (const Packing::Neighbours& n : p->neighbours)  // no gap, no overlap
                rule(Face{n.a.cuboid, static_cast<Side>(2 * n.axis + 1)},
                     Face{n.b.cuboid, static_cast<Side>(2 * n.axis)}, true);
            for (const auto& [a, b] : p->aligned)  // one seam
                rule(a, b, true);
            for (int k = 0; k < 6; ++k)  // the outermost faces aligned
                for (const Face& f : p->ends[k])
                    rule(Face{f.cuboid, static_cast<Side>(k)},
                         Face{p->ends[k].front().cuboid, static_cast<Side>(k)}, true);
        }
        for (int k = 0; k < 6; ++k) {
            if (covering.ends[k].empty())
                continue;  // the plane's normal
            const Face a{covering.ends[k].front().cuboid, static_cast<Side>(k)},
                b{covered.ends[k].front().cuboid, static_cast<Side>(k)};
            if (k % 2)
                rule(b, a, c.just);
            else
                rule(a, b, c.just);
        }
    }
}

/// How far side `side` of a cavity lies inside its solid's same side (negative: beyond it).
double depthInside(const Model& model, int cavity, int side)
{
    const Cuboid& c = model.cuboids[cavity];
    return (side % 2 ? -1 : 1) * (c.coordinates[side] - model.cuboids[c.within].coordinates[side]);
}

}  // namespace

std::string faceName(const Model& model, const Face& face)
{
    return model.cuboids[face.cuboid].name + "." + sideName(face.side);
}

std::string millimetres(double mm, int digits)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, mm);
    return text;
}

namespace {

/// Whether a part that fits inside the cavity goes out through side `side`: in a configuration
/// where no fit of it in the cavity is measured, a cuboid of it that must fit lies at least half beyond that
/// side, across the cavity (a shelf pulled out of the oven). A part drawn out of its cavity is not (the room
/// print-in-place cuts on its way in makes its passage).
bool passedThrough(const Model& model, int cavity, int side)
{
    const auto& c = model.cuboids[cavity].coordinates;
    const int axis = side / 2;
    const auto measured = [&](int part, int k) {
        return std::any_of(model.fitInside.begin(), model.fitInside.end(), [&](const FitInside& f) {
            return f.cavity == cavity && f.configuration == k &&
                   std::find(f.inner.begin(), f.inner.end(), part) != f.inner.end();
        });
    };
    for (const FitInside& f : model.fitInside) {
        if (f.cavity != cavity)
            continue;
        for (int part : f.inner)
            for (int cuboid : model.parts[part].cuboids)
                for (int k = 0; k < static_cast<int>(model.configurations.size()) && fits(model, f, cuboid);
                     ++k) {
                    if (model.configurations[k].along >= 0 || measured(part, k))
                        continue;  // the user's configurations
                    const std::array<double, 6> box = posedBounds(model, cuboid, k);
                    const double beyond = side % 2 ? box[side] - c[side] : c[side] - box[side];
                    bool across = beyond >= (box[2 * axis + 1] - box[2 * axis]) / 2;
                    for (int o = 0; o < 3 && across; ++o)
                        across = o == axis ||
                                 std::min(box[2 * o + 1], c[2 * o + 1]) > std::max(box[2 * o], c[2 * o]);
                    if (across)
                        return true;
                }
    }
    return false;
}

}  // namespace

bool isOpening(const Model& model, int cavity, int side)
{
    if (depthInside(model, cavity, side) <= std::max(1e-6, model.minimumWall / 2))
        return true;
    const Face face{cavity, static_cast<Side>(side)};
    return std::any_of(model.cover.begin(), model.cover.end(),
                       [&](const Cover& c) {
                           return std::any_of(c.pairs.begin(), c.pairs.end(),
                                              [&](const auto& pair) { return pair.second == face; });
                       }) ||
           passedThrough(model, cavity, side);
}

Pieces piecesOf(const Model& model, const Part& part)
{
    Pieces out;
    std::vector<int> solids;
    for (int c : part.cuboids)
        if (!model.cuboids[c].cavity())
            solids.push_back(c);
    std::vector<int> piece(solids.size());  // union-find over the solids
    std::iota(piece.begin(), piece.end(), 0);
    const auto root = [&](size_t i) {
        while (piece[i] != static_cast<int>(i))
            i = piece[i] = piece[piece[i]];
        return i;
    };
    const auto distance = [&](size_t i, size_t k) {
        return apart(model.cuboids[solids[i]], model.cuboids[solids[k]]);
    };
    for (size_t i = 0; i < solids.size(); ++i)
        for (size_t k = i + 1; k < solids.size(); ++k)
            if (distance(i, k) <= 1e-9) {
                out.glued.push_back({solids[i], solids[k], 0});
                piece[root(k)] = static_cast<int>(root(i));
            }
    // Pieces drawn apart: the nearest two cuboids of two pieces, joined if near enough, until one is left.
    for (;;) {
        double nearest = std::numeric_limits<double>::infinity();
        size_t a = 0, b = 0;
        for (size_t i = 0; i < solids.size(); ++i)
            for (size_t k = i + 1; k < solids.size(); ++k)
                if (root(i) != root(k) && distance(i, k) < nearest)
                    std::tie(nearest, a, b) = std::tuple{distance(i, k), i, k};
        if (!std::isfinite(nearest))
            break;
        const std::string pair = "'" + model.cuboids[solids[a]].name + "' and '" +
                                 model.cuboids[solids[b]].name + "' drawn " + millimetres(nearest) +
                                 " mm apart";
        if (nearest > kInferenceDistance) {
            out.error =
                part.name + ": " + pair + ", farther than the " + millimetres(kInferenceDistance) +
                " mm within which a part's cuboids are joined: a part prints as one piece (join them, "
                "or make each its own part)";
            break;
        }
        out.glued.push_back({solids[a], solids[b], nearest});
        out.notes.push_back(part.name + ": " + pair + "; joined");
        piece[root(b)] = static_cast<int>(root(a));
    }
    return out;
}

std::vector<LinearConstraint> constraints(const Model& model)
{
    std::vector<LinearConstraint> rows;
    for (const Part& part : model.parts)
        onePiece(rows, model, part);
    for (int c = 0; c < static_cast<int>(model.cuboids.size()); ++c) {
        for (int a = 0; a < 3; ++a)  // right − left >= minimum size, along each axis
            rows.push_back(
                {{{6 * c + 2 * a + 1, 1.0}, {6 * c + 2 * a, -1.0}}, model.minimumSize, kInfinity, ""});
        if (const int solid = model.cuboids[c].within; solid >= 0)
            walls(rows, model, c, solid);
    }
    for (const Flush& f : model.flush) {  // thesis 4.2.4: the two faces coplanar
        if (axisOf(f.a.side) != axisOf(f.b.side))
            throw std::invalid_argument("flush '" + f.name + "': " + faceName(model, f.a) + " and " +
                                        faceName(model, f.b) + " are not parallel");
        order(rows, model, f.name, f.configuration, f.a, f.b, true);
    }
    for (const Geometric& g : model.geometric) {  // thesis 4.3.5
        auto [terms, bound] = difference(model, g.left, g.right, g.configuration);
        rows.push_back({terms, g.relation == Geometric::Relation::Equal ? bound : -kInfinity, bound, g.name});
    }
    for (const FitInside& f : model.fitInside) {  // thesis 4.2.2, eq. 4.3–4.4
        auto rule = [&](const Face& low, const Face& high, bool equal) {
            order(rows, model, f.name, f.configuration, low, high, equal);
        };
        for (int part : f.inner)
            for (int c : model.parts[part].cuboids)
                for (int k = 0; k < 6 && fits(model, f, c); ++k) {  // inside the box or cavity
                    const Side side = static_cast<Side>(k);
                    const Face w = wall(model, f.enclosing, f.cavity, side, f.configuration);
                    if (k % 2)
                        rule(Face{c, side}, w, false);
                    else
                        rule(w, Face{c, side}, false);
                }
        for (const FitInside::Apart& a : f.apart)  // the inner parts do not overlap
            rule(Face{a.a, static_cast<Side>(2 * a.axis + 1)}, Face{a.b, static_cast<Side>(2 * a.axis)},
                 false);
        for (const auto& [inner, wall] : f.just)  // just fits
            rule(inner, wall, true);
    }
    for (const Support& s : model.support) {  // thesis 4.2.3, eq. 4.5
        const double overlap = model.minimumSize;
        auto faceAt = [&](int cuboid, Side side) { return Expression{{{1.0, Face{cuboid, side}}}, 0}; };
        auto atMost = [&](const Expression& left, const Expression& right, double offset) {
            Expression shifted = right;
            shifted.constant += offset;
            auto [terms, bound] = difference(model, left, shifted, s.configuration);
            rows.push_back({terms, -kInfinity, bound, s.name});
        };
        for (const auto& [a, b] : s.pairs) {
            for (const auto& [low, high] :
                 {std::pair{Side::Left, Side::Right}, std::pair{Side::Near, Side::Far}}) {
                atMost(faceAt(a, low), faceAt(b, high),
                       -overlap);  // the faces overlap in the supporting plane
                atMost(faceAt(b, low), faceAt(a, high), -overlap);
            }
            auto [terms, bound] =
                difference(model, faceAt(a, Side::Top), faceAt(b, Side::Bottom), s.configuration);
            rows.push_back({terms, bound, bound, s.name});  // at the same height
        }
        // Parts that only support stand on one ground plane: their lowest cuboids' bottoms are equal.
        std::vector<int> grounded;
        for (int p : s.supporting)
            if (std::find(s.supported.begin(), s.supported.end(), p) == s.supported.end())
                grounded.push_back(extremeFace(model, p, Side::Bottom, s.configuration).cuboid);
        for (size_t k = 1; k < grounded.size(); ++k) {
            auto [terms, bound] = difference(model, faceAt(grounded[0], Side::Bottom),
                                             faceAt(grounded[k], Side::Bottom), s.configuration);
            rows.push_back({terms, bound, bound, s.name});
        }
    }
    for (const Cover& c : model.cover)
        coverConstraints(rows, model, c);
    for (const Joint& j : model.joints)
        if (j.type == Joint::Type::DoublePivot)  // a double pivot's faces stay in one plane (thesis 4.1.2)
            order(rows, model, j.name, -1, j.pivotFace, j.basePivotFace, true);
        else if (j.type == Joint::Type::Fixed)
            heldFixed(rows, model, j);
        else if (j.type == Joint::Type::Hinge)
            heldOnEdge(rows, model, j);
    for (const Lock& lock : model.locks) {
        const double value = model.cuboids[lock.face.cuboid].at(lock.face.side);
        rows.push_back({{{variable(lock.face), 1.0}}, value, value, lockName(model, lock)});
    }
    return rows;
}

Model scaled(Model model, double factor)
{
    for (Cuboid& c : model.cuboids)
        for (double& x : c.coordinates)
            x *= factor;
    for (Joint& j : model.joints)
        for (auto* offsets : {&j.pivot, &j.basePivot})
            for (double& x : *offsets)
                x *= factor;
    for (Configuration& c : model.configurations)
        for (JointPose& pose : c.poses) {
            pose.offset *= factor;
            for (double& x : pose.pole)
                x *= factor;
        }
    model.minimumSize *= factor;
    model.minimumWall *= factor;
    return model;
}

namespace {

Model withCoordinates(Model model, const Eigen::VectorXd& x)
{
    for (size_t c = 0; c < model.cuboids.size(); ++c)
        for (int k = 0; k < 6; ++k)
            model.cuboids[c].coordinates[k] = x[6 * c + k];
    return model;
}

/// The pairs kept apart: by (cuboid a, cuboid b, the configuration whose motion), the poses where they came
/// near (the configuration's, those on the way to it; -1 for the modelled pose alone), those its ways are
/// judged in, the ways of keeping them apart there (choicesAlong) and the one chosen.
struct Apart {
    using Key = std::tuple<int, int, int>;
    std::map<Key, std::vector<int>> poses, judged;
    std::map<Key, std::vector<Choice>> choices;
    std::map<Key, size_t> chosen;
    std::set<Key> drawnWays;  ///< the pairs whose ways near as drawn are among their choices
    /// The pair's ways near as the user drew the parts (`drawn`) count as near too, those the arrangement did
    /// not find tried after its own (a jewellery box's lid turned past upright drawn behind the casket,
    /// arranged over it by a limit on how far behind it goes). Found once a pair's ways are revised: a
    /// conflict's cost.
    void addDrawnWays(const Model& drawn, const Key& key)
    {
        if (!drawnWays.insert(key).second)
            return;
        std::vector<Choice>& ways = choices[key];
        for (const Choice& d :
             choicesAlong(drawn, std::get<0>(key), std::get<1>(key), poses[key], judged[key])) {
            if (!d.near)
                continue;
            const auto same =
                std::find_if(ways.begin(), ways.end(), [&](const Choice& w) { return sameWay(d, w); });
            if (same == ways.end())
                ways.push_back(d);
            else
                same->near = true;
        }
    }
    std::vector<Separation> all() const
    {
        std::vector<Separation> out;
        for (const auto& [key, ways] : choices) {
            const std::vector<Separation>& some = ways[chosen.at(key)].separations;
            out.insert(out.end(), some.begin(), some.end());
        }
        return out;
    }
    /// The pairs whose separations a conflict names.
    std::vector<Key> named(const Model& model, const std::vector<std::string>& conflict) const
    {
        std::vector<Key> keys;
        for (const auto& [key, ways] : choices)
            for (const Separation& s : ways[chosen.at(key)].separations)
                if (std::find(conflict.begin(), conflict.end(), separationName(model, s)) != conflict.end()) {
                    keys.push_back(key);
                    break;
                }
        return keys;
    }
};

/// Whether parts p and q each turn by a joint of their own in configuration k (not one that carries both).
bool turnEach(const Model& model, int p, int q, int k)
{
    const auto turning = [&](int part) {
        const int j = jointMovingIn(model, part, k);
        const JointPose* pose = j >= 0 ? poseOf(model, j, k) : nullptr;
        return pose && (model.joints[j].turns() || model.joints[j].type == Joint::Type::DoublePivot) &&
                       pose->angle != 0
                   ? j
                   : -1;
    };
    const int jp = turning(p), jq = turning(q);
    return jp >= 0 && jq >= 0 && jp != jq;
}

/// Adds the pairs that come near in `model` (`margin` as nearPairs), in the modelled pose and configurations
/// [0, `configurations`), to those kept apart, each pair's ways along a motion found anew on `arranged` (the
/// model as its relationships arrange it) when it gains a pose. Returns how many poses it added.
size_t separateNear(const Model& arranged, const Model& model, double margin, int configurations,
                    Apart& apart)
{
    std::set<Apart::Key> grown;
    size_t added = 0;
    const std::vector<int> partOf = owners(model);
    for (int k = -1; k < configurations; ++k)
        for (const auto& [a, b] : nearPairs(model, k, margin)) {
            if (k >= 0 && jointMovingIn(model, partOf[a], k) < 0 && jointMovingIn(model, partOf[b], k) < 0)
                continue;  // neither moves there: kept apart as modelled
            const int along =
                k >= 0 && model.configurations[k].along >= 0 ? model.configurations[k].along : k;
            if (along != k && turnEach(model, partOf[a], partOf[b], k))
                continue;  // two doors meeting as they swing: print-in-place bevels each by the other's path
            std::vector<int>& poses = apart.poses[{a, b, along}];
            if (std::find(poses.begin(), poses.end(), k) == poses.end()) {
                poses.push_back(k);
                grown.insert({a, b, along});
                ++added;
            }
        }
    for (const auto& key : grown) {
        const auto& [a, b, along] = key;
        std::vector<int> judged = apart.poses[key];  // and the rest of the motion where they are kept apart
        for (int k = 0; along >= 0 && k < static_cast<int>(model.configurations.size()); ++k)
            if ((k == along ||
                 (model.configurations[k].along == along && !turnEach(model, partOf[a], partOf[b], k))) &&
                std::find(judged.begin(), judged.end(), k) == judged.end())
                judged.push_back(k);
        apart.choices[key] = choicesAlong(arranged, a, b, apart.poses[key], judged);
        apart.judged[key] = std::move(judged);
        apart.drawnWays.erase(key);
        apart.chosen[key] = 0;
    }
    return added;
}

/// The parts that the overlaps and walls in a conflict concern, each named once.
std::vector<std::string> blamedParts(const Model& model, const std::vector<Separation>& separations,
                                     const std::vector<std::string>& conflict)
{
    std::vector<std::string> names;
    auto blame = [&](int cuboid) {
        const std::string& name = model.parts[partOf(model, cuboid)].name;
        if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    };
    for (const std::string& source : conflict) {
        for (const Separation& s : separations)
            if (separationName(model, s) == source) {
                blame(s.a);
                blame(s.b);
            }
        for (int c = 0; c < static_cast<int>(model.cuboids.size()); ++c)
            if (model.cuboids[c].cavity() && source == wallName(model.cuboids[c]))
                blame(c);
    }
    return names;
}

void addNotes(std::vector<std::string>& notes, const std::string& name, const InferenceNotes& more)
{
    for (const std::string& note : more)
        notes.push_back(name + ": " + note);
}

/// For each fit inside in a conflict whose enclosing part has no cavity: the inner parts may lie in its solid
/// (4.2.2) but never move through it; the note says what to make.
void cavityNotes(const Model& model, const std::vector<std::string>& conflict,
                 std::vector<std::string>& notes)
{
    for (const FitInside& f : model.fitInside) {
        const Part& enclosing = model.parts[f.enclosing];
        if (std::find(conflict.begin(), conflict.end(), f.name) == conflict.end() ||
            std::any_of(enclosing.cuboids.begin(), enclosing.cuboids.end(),
                        [&](int c) { return model.cuboids[c].cavity(); }))
            continue;
        std::string inner;
        for (int p : f.inner)
            inner += (inner.empty() ? "'" : ", '") + model.parts[p].name + "'";
        notes.push_back(f.name + ": '" + enclosing.name + "' has no cavity for " + inner +
                        " to move in; make a cavity in '" + enclosing.name + "' where it goes");
    }
}

/// `least` (a least change under `rows`) with `holds` added to `rows` where the relationships allow them: all
/// at once or, when they cannot have that, one at a time in their order.
LeastChangeResult heldWhereAllowed(const Eigen::VectorXd& target, std::vector<LinearConstraint>& rows,
                                   LeastChangeResult least, const std::vector<LinearConstraint>& holds)
{
    if (holds.empty())
        return least;
    std::vector<LinearConstraint> all = rows;
    all.insert(all.end(), holds.begin(), holds.end());
    if (LeastChangeResult kept = solveLeastChange(target, all, &least.x); kept.solved) {
        rows = std::move(all);
        return kept;
    }
    for (const LinearConstraint& hold : holds) {
        rows.push_back(hold);
        if (LeastChangeResult kept = solveLeastChange(target, rows, &least.x); kept.solved)
            least = std::move(kept);
        else
            rows.pop_back();
    }
    return least;
}

/// The row holding the size of the axis whose low variable is i to `size`.
LinearConstraint sizeHeld(int i, double size)
{
    return {{{i + 1, 1.0}, {i, -1.0}}, size, size, ""};
}

/// What the solve holds the least change to, where the relationships allow (leastChange).
struct Drawing {
    std::vector<double> sizes;               ///< what the user drew: a size per axis of each cuboid
    std::vector<double> least;               ///< what a joint's geometry needs of each cuboid (Cuboid::least)
    std::vector<std::pair<int, int>> twins;  ///< cuboids that stay alike
};

/// Sizes the least change `x` cuts to less than half of the larger of what the user drew and what they are
/// now, or below what a joint's geometry on them needs (Cuboid::least) where they are not below it now, the
/// thinnest first, each held as it is now.
std::vector<LinearConstraint> collapsed(const Eigen::VectorXd& target, const Drawing& drawing,
                                        const Eigen::VectorXd& x)
{
    std::vector<std::pair<double, int>> thinned;  // (size left / size drawn, the axis' low variable)
    for (int i = 0; i + 1 < target.size(); i += 2) {
        const double size = target[i + 1] - target[i], was = std::max(drawing.sizes[i / 2], size),
                     now = x[i + 1] - x[i], least = drawing.least[i / 6];
        if (now < was / 2 || (now < least - 1e-9 && least <= size))
            thinned.push_back({now / was, i});
    }
    std::sort(thinned.begin(), thinned.end());
    std::vector<LinearConstraint> holds;
    for (const auto& [left, i] : thinned)
        holds.push_back(sizeHeld(i, target[i + 1] - target[i]));
    return holds;
}

/// Pairs of cuboids alike now (the same three sizes, to 1e-6 mm: a pair of doors, a row of shelves) that one
/// relationship names both of (its rows touch both). A relationship that names one of them only (a's width
/// 25) may set them apart.
std::vector<std::pair<int, int>> twins(const Model& model, const std::vector<LinearConstraint>& rows)
{
    std::set<std::string> relationships;
    const auto named = [&](const auto& all) {
        for (const auto& r : all)
            relationships.insert(r.name);
    };
    named(model.flush), named(model.geometric), named(model.support), named(model.fitInside),
        named(model.cover);
    std::map<std::string, std::set<int>> touched;  // relationship → the cuboids its rows touch
    for (const LinearConstraint& row : rows)
        if (relationships.count(row.source))
            for (const auto& [variable, coefficient] : row.terms)
                touched[row.source].insert(variable / 6);
    std::set<std::pair<int, int>> pairs;
    for (const auto& [name, cuboids] : touched) {
        std::map<std::array<long long, 3>, int> first;  // sizes to 1e-6 mm → the first cuboid that has them
        for (int c : cuboids) {
            const auto& k = model.cuboids[c].coordinates;
            const auto [at, fresh] =
                first.insert({{std::llround(1e6 * (k[1] - k[0])), std::llround(1e6 * (k[3] - k[2])),
                               std::llround(1e6 * (k[5] - k[4]))},
                              c});
            if (!fresh)
                pairs.insert({at->second, c});
        }
    }
    return {pairs.begin(), pairs.end()};
}

/// Rows holding each twin's size to its first one's along the axes where the least change `x` sizes them
/// apart.
std::vector<LinearConstraint> twinsApart(const std::vector<std::pair<int, int>>& twins,
                                         const Eigen::VectorXd& x)
{
    std::vector<LinearConstraint> holds;
    for (const auto& [c, d] : twins)
        for (int a = 0; a < 3; ++a)
            if (const int i = 6 * c + 2 * a, j = 6 * d + 2 * a;
                std::abs((x[j + 1] - x[j]) - (x[i + 1] - x[i])) > 1e-6)
                holds.push_back({{{j + 1, 1.0}, {j, -1.0}, {i + 1, -1.0}, {i, 1.0}}, 0, 0, ""});
    return holds;
}

/// Stage 1 of thesis 4.4, the least change of the coordinates, except that it does not collapse a part, nor
/// tell twins apart. The least change would rather thin a part than move it (a laptop's 8 mm screen made 1 mm
/// thick so that its hinge edge moves 8 mm back; then no hinge fits it): a size it cuts to less than half of
/// what the user drew is held as it was before this solve, and the parts move instead. What the user drew is
/// `drawn`, so that successive solves cannot halve a size again and again (a door 20 mm, then 10.2,
/// then 5.1). Nor does it thin a part below what a joint's geometry on it needs (Cuboid::least: a lid pushed
/// into its carcass moves up rather than thin below its hinge's pin). Twins stay alike (the left door
/// thinned, the right not). All where the relationships allow.
LeastChangeResult leastChange(const Eigen::VectorXd& target, const Drawing& drawing,
                              const std::vector<LinearConstraint>& rows, const Eigen::VectorXd* start)
{
    LeastChangeResult least = solveLeastChange(target, rows, start);
    if (!least.solved)
        return least;
    std::vector<LinearConstraint> held = rows;
    const std::vector<LinearConstraint> thinned = collapsed(target, drawing, least.x);
    least = heldWhereAllowed(target, held, std::move(least), thinned);
    const std::vector<LinearConstraint> twins = twinsApart(drawing.twins, least.x);
    return heldWhereAllowed(target, held, std::move(least), twins);
}

/// The least change that keeps the pairs apart as chosen, from `start` (kept when it does already). Where
/// that conflicts, a pair the conflict names is kept apart its other ways that are near (Choice::near, as
/// arranged or as drawn in `moving`: Apart::addDrawnWays), one try at a time while `tries` last, and a way
/// kept when it solves or leaves that pair out of the conflict (a door and a drawer front side by side in one
/// plane, not one in front of the other: the least overlap as drawn chose wrong). When no way is kept, the
/// conflict names what each way tried conflicts with: the pair is kept apart no way because of all of them (a
/// lid turned past upright is held over the casket by the cover and behind it by a limit on how far behind it
/// goes; the limit is part of why).
LeastChangeResult keptApart(const Eigen::VectorXd& target, const Drawing& drawing,
                            const std::vector<LinearConstraint>& relationships, const Model& moving,
                            Apart& apart, const Eigen::VectorXd& start, int& tries)
{
    const auto solveApart = [&] {
        std::vector<LinearConstraint> rows = relationships;
        for (const Separation& s : apart.all())
            separate(rows, moving, s);
        if (violation(start, rows) <= 1e-6)
            return LeastChangeResult{true, start, violation(start, rows), {}};
        return leastChange(target, drawing, rows, &start);
    };
    LeastChangeResult r = solveApart();
    std::vector<std::string> because = r.conflict;
    for (bool revised = true; !r.solved && revised;) {
        revised = false;
        for (const Apart::Key& key : apart.named(moving, r.conflict)) {
            apart.addDrawnWays(moving, key);
            const size_t was = apart.chosen[key];
            for (size_t way = was + 1; way < apart.choices[key].size() && tries > 0 && !revised; ++way) {
                if (!apart.choices[key][way].near)
                    continue;  // another way only where the drawing is near it
                --tries;
                apart.chosen[key] = way;
                LeastChangeResult t = solveApart();
                const std::vector<Apart::Key> still = apart.named(moving, t.conflict);
                if (t.solved || std::find(still.begin(), still.end(), key) == still.end()) {
                    r = std::move(t);
                    revised = true;
                } else {
                    for (const std::string& name : t.conflict)
                        if (std::find(because.begin(), because.end(), name) == because.end())
                            because.push_back(name);
                }
            }
            if (revised)
                break;
            apart.chosen[key] = was;
        }
        if (revised)
            because = r.conflict;
    }
    if (!r.solved)
        r.conflict = because;
    return r;
}

/// How many poses along each motion the solve keeps parts apart at (the checker's: tests/python).
constexpr int kMotionSamples = 64;
/// How many rounds of constraint generation the solve may take, and how many other ways of keeping a pair
/// apart it may try where the first ones conflict.
constexpr int kRounds = 100, kRevisions = 32;

/// The model with each configuration's motion sampled: the poses a fraction i / kMotionSamples of
/// the way there, turns in the first half and slides in the second (as print-in-place moves the parts),
/// appended after the model's configurations, each `along` its own. Only fractions where something moves: no
/// turning half without a turn, no sliding half without a slide; the turning half of a configuration that
/// poses a double pivot is stage 2's (its path depends on where the pivots go).
Model motionSampled(Model model)
{
    const int count = static_cast<int>(model.configurations.size());
    for (int k = 0; k < count; ++k) {
        bool turns = false, slides = false, pivots = false;
        for (const JointPose& pose : model.configurations[k].poses) {
            const Joint& joint = model.joints[pose.joint];
            turns = turns || ((joint.turns() || joint.type == Joint::Type::DoublePivot) && pose.angle != 0);
            slides = slides || (joint.slides() && pose.offset != 0);
            pivots = pivots || joint.type == Joint::Type::DoublePivot;
        }
        for (int i = 1; i < kMotionSamples; ++i) {
            const double t = static_cast<double>(i) / kMotionSamples;
            if (t < 0.5 ? !turns || pivots : !slides)
                continue;
            Configuration on = model.configurations[k];
            on.along = k;
            for (JointPose& pose : on.poses) {
                pose.angle *= turnedAt(t);
                pose.offset *= slidAt(t);
            }
            model.configurations.push_back(on);
        }
    }
    return indexed(std::move(model));
}

/// A double pivot's pivots keep their places on their faces as the solve resizes the cuboids under them: each
/// offset scaled with its face's size.
void keepPivotsOnFaces(const Model& before, Model& after)
{
    for (Joint& j : after.joints)
        if (j.type == Joint::Type::DoublePivot)
            for (auto [face, offsets] :
                 {std::pair{j.pivotFace, &j.pivot}, std::pair{j.basePivotFace, &j.basePivot}})
                for (int k = 0; k < 2; ++k) {
                    const int a = (axisOf(face.side) + 1 + k) % 3;
                    const auto &was = before.cuboids[face.cuboid].coordinates,
                               &now = after.cuboids[face.cuboid].coordinates;
                    if (const double size = was[2 * a + 1] - was[2 * a]; size > 0)
                        (*offsets)[k] *= (now[2 * a + 1] - now[2 * a]) / size;
                }
}

/// Parts drawn inside others (Separation.h's drawnInside), refused with what to do; empty when there are
/// none.
SolveResult refusedDrawnInside(const Model& model)
{
    SolveResult refused{false, model, {}, 0, {}, {}, {}};
    const std::vector<int> owner = owners(model);
    for (const auto& [inner, outer] : drawnInside(model)) {
        const std::string &a = model.cuboids[inner].name, &b = model.cuboids[outer].name;
        refused.conflict.push_back(drawnInsideName(model, inner, outer));
        refused.notes.push_back(refused.conflict.back() + ": nothing lets them overlap; make a cavity in '" +
                                b + "' where '" + a + "' goes (or move it out); nothing was changed");
        for (int c : {inner, outer})
            if (const std::string& part = model.parts[owner[c]].name;
                std::find(refused.parts.begin(), refused.parts.end(), part) == refused.parts.end())
                refused.parts.push_back(part);
    }
    return refused;
}

/// `result` with its conflict typed (SolveResult::conflicts): each name matched against the names the solve
/// gives what it keeps in `model`, with the `separations` it kept parts apart by.
SolveResult typed(const Model& model, const std::vector<Separation>& separations, SolveResult result)
{
    std::vector<Conflict> known;
    const auto relationships = [&](ConflictKind kind, const auto& list) {
        for (const auto& r : list)
            known.push_back({kind, r.name, r.name});
    };
    relationships(ConflictKind::Cover, model.cover);
    relationships(ConflictKind::FitInside, model.fitInside);
    relationships(ConflictKind::Support, model.support);
    relationships(ConflictKind::Flush, model.flush);
    relationships(ConflictKind::Geometric, model.geometric);
    for (const Joint& j : model.joints)  // a double pivot's pivots, a fixed joint's hold
        known.push_back({ConflictKind::Joint, j.name, j.name});
    for (const Lock& lock : model.locks)
        known.push_back({ConflictKind::Lock, lockName(model, lock), faceName(model, lock.face)});
    for (const Part& part : model.parts)
        known.push_back({ConflictKind::OnePiece, onePieceName(part), part.name});
    for (const Cuboid& c : model.cuboids)
        if (c.cavity())
            known.push_back({ConflictKind::Wall, wallName(c), c.name});
    for (const Separation& s : separations) {
        const int a = partOf(model, s.a), b = partOf(model, s.b);
        known.push_back({ConflictKind::NoOverlap, separationName(model, s),
                         model.parts[std::min(a, b)].name + ", " + model.parts[std::max(a, b)].name});
    }
    known.push_back({ConflictKind::NoOverlap, kStillMeeting, ""});
    for (const auto& [inner, outer] : drawnInside(model))
        known.push_back({ConflictKind::DrawnInside, drawnInsideName(model, inner, outer),
                         model.cuboids[inner].name + " in " + model.cuboids[outer].name});
    for (const std::string& name : result.conflict)
        for (const Conflict& k : known)
            if (k.name == name) {
                result.conflicts.push_back(k);
                break;
            }
    return result;
}

}  // namespace

SolveResult solve(const Model& model)
{
    std::vector<std::string> pieceNotes;
    for (const Part& part : model.parts) {
        Pieces pieces = piecesOf(model, part);
        if (!pieces.error.empty())
            return typed(model, {}, {false, model, {onePieceName(part)}, 0, {pieces.error}, {part.name}, {}});
        pieceNotes.insert(pieceNotes.end(), pieces.notes.begin(), pieces.notes.end());
    }
    if (SolveResult inside = refusedDrawnInside(model); !inside.conflict.empty())
        return typed(model, {}, inside);
    Eigen::VectorXd target(6 * model.cuboids.size());
    Drawing drawing;
    for (size_t c = 0; c < model.cuboids.size(); ++c) {
        for (int k = 0; k < 6; ++k)
            target[6 * c + k] = model.cuboids[c].coordinates[k];
        for (int a = 0; a < 3; ++a)
            drawing.sizes.push_back(model.cuboids[c].drawn[a]);
        drawing.least.push_back(model.cuboids[c].least);
    }
    const std::vector<LinearConstraint> relationships = constraints(model);
    drawing.twins = twins(model, relationships);
    LeastChangeResult r = leastChange(target, drawing, relationships, nullptr);
    // Parts kept apart: each pair of parts that come near keeps the side (or the cavity) it takes
    // in that solution, the arrangement the relationships give; pairs the solve then brings together are
    // added round by round (constraint generation: the pairs stay few).
    // They are kept apart along every motion too, at the poses on the way (motionSampled) where they meet.
    const Model moving = motionSampled(model);
    const int configurations = static_cast<int>(moving.configurations.size());
    const Model arranged = r.solved ? withCoordinates(moving, r.x) : moving;
    Apart apart;
    separateNear(arranged, arranged, model.minimumSize, static_cast<int>(model.configurations.size()), apart);
    int tries = kRevisions;
    for (int round = 0; r.solved; ++round) {
        r = keptApart(target, drawing, relationships, moving, apart, r.x, tries);
        if (!r.solved ||
            separateNear(arranged, withCoordinates(moving, r.x), -1e-6, configurations, apart) == 0)
            break;
        // Every round adds poses where parts still meet: a bound, never reached so far.
        if (round == kRounds) {
            r = {false, target, r.violation, {kStillMeeting}};
            break;
        }
    }
    const std::vector<Separation> separations = apart.all();
    SolveResult result{r.solved,   r.solved ? withCoordinates(model, r.x) : model, r.conflict, r.violation,
                       pieceNotes, blamedParts(moving, separations, r.conflict),   {}};
    for (const Cover& c : model.cover)
        addNotes(result.notes, c.name, c.notes);
    for (const Support& s : model.support)
        addNotes(result.notes, s.name, s.notes);
    if (!r.solved) {
        cavityNotes(model, r.conflict, result.notes);
        return typed(moving, separations, result);
    }
    // Stage 2 (thesis 4.4): the double pivots' pivots, with the cuboids fixed.
    keepPivotsOnFaces(model, result.model);
    const std::vector<Unplaced> unplaced = placePivots(result.model);
    if (unplaced.empty())
        return result;
    SolveResult failed{false, model, {}, r.violation, result.notes, {}, {}};
    for (const Unplaced& u : unplaced) {
        failed.conflict.push_back(u.joint);
        failed.notes.push_back(u.joint + ": " + u.reason);
    }
    return typed(model, {}, failed);
}

}  // namespace fabguide::function
