#include "Function/Solve.h"

#include "Function/Cover.h"
#include "Function/DoublePivot.h"
#include "Function/FitInside.h"
#include "Function/Pose.h"
#include "Function/Separation.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace fabguide::function {

namespace {

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
            rows.push_back({terms, -kInfinity, -model.minimumWall, "wall: " + model.cuboids[cavity].name});
    }
}

/// A part stays in one piece: each two of its solid cuboids that touch or overlap as modelled keep touching
/// along the axis they meet least on, and overlapping along the other two by as much as modelled, or the
/// minimum size ("one piece: drawer"). A drawer's tray held in its bay stays glued to its front when the
/// bay's mouth moves.
void onePiece(std::vector<LinearConstraint>& rows, const Model& model, const Part& part)
{
    for (int a : part.cuboids)
        for (int b : part.cuboids) {
            if (a >= b || model.cuboids[a].cavity() || model.cuboids[b].cavity())
                continue;
            std::array<double, 3> meet{};
            for (int axis = 0; axis < 3; ++axis)
                meet[axis] =
                    std::min(model.cuboids[a].coordinates[2 * axis + 1],
                             model.cuboids[b].coordinates[2 * axis + 1]) -
                    std::max(model.cuboids[a].coordinates[2 * axis], model.cuboids[b].coordinates[2 * axis]);
            if (*std::min_element(meet.begin(), meet.end()) < -1e-9)
                continue;  // apart as modelled
            const long touching = std::min_element(meet.begin(), meet.end()) - meet.begin();
            for (int axis = 0; axis < 3; ++axis) {
                const double least = axis == touching ? 0.0 : std::min(meet[axis], model.minimumSize);
                for (const auto& [high, low] :
                     {std::pair{a, b}, std::pair{b, a}})  // high's top past low's bottom
                    rows.push_back({{{6 * high + 2 * axis + 1, 1.0}, {6 * low + 2 * axis, -1.0}},
                                    least,
                                    kInfinity,
                                    "one piece: " + part.name});
            }
        }
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

std::string millimetres(double mm)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", mm);
    return text;
}

bool isOpening(const Model& model, int cavity, int side)
{
    if (depthInside(model, cavity, side) <= std::max(1e-6, model.minimumWall / 2))
        return true;
    const Face face{cavity, static_cast<Side>(side)};
    return std::any_of(model.cover.begin(), model.cover.end(), [&](const Cover& c) {
        return std::any_of(c.pairs.begin(), c.pairs.end(),
                           [&](const auto& pair) { return pair.second == face; });
    });
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
    for (const Joint& j : model.joints)  // a double pivot's faces stay in one plane (thesis 4.1.2)
        if (j.type == Joint::Type::DoublePivot)
            order(rows, model, j.name, -1, j.pivotFace, j.basePivotFace, true);
    for (const Lock& lock : model.locks) {
        const double value = model.cuboids[lock.face.cuboid].at(lock.face.side);
        rows.push_back({{{variable(lock.face), 1.0}}, value, value, "lock: " + faceName(model, lock.face)});
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

/// Pairs of cuboids in configurations, as keys of the separations already made.
using PairKey = std::tuple<int, int, int>;

/// The separations of the pairs that come near in `model` and have none yet (`margin` as nearPairs),
/// inferred on `arranged` (the model as its relationships arrange it). Returns how many it added.
size_t separateNear(const Model& arranged, const Model& model, double margin, std::set<PairKey>& seen,
                    std::vector<Separation>& separations)
{
    const size_t before = separations.size();
    for (int k = -1; k < static_cast<int>(model.configurations.size()); ++k)
        for (const auto& [a, b] : nearPairs(model, k, margin)) {
            if (k >= 0 && jointMovingIn(model, partOf(model, a), k) < 0 &&
                jointMovingIn(model, partOf(model, b), k) < 0)
                continue;  // neither moves there: kept apart as modelled
            if (seen.insert({a, b, k}).second)
                separations.push_back(inferSeparation(arranged, a, b, k));
        }
    return separations.size() - before;
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
            if (model.cuboids[c].cavity() && source == "wall: " + model.cuboids[c].name)
                blame(c);
    }
    return names;
}

void addNotes(std::vector<std::string>& notes, const std::string& name, const InferenceNotes& more)
{
    for (const std::string& note : more)
        notes.push_back(name + ": " + note);
}

/// Stage 1 of thesis 4.4, the least change of the coordinates, except that it does not collapse a part: the
/// least change would rather thin a part than move it (a laptop's 8 mm screen made 1 mm thick so that its
/// hinge edge moves 8 mm back; then no hinge fits it). A size it cuts to less than half of what the user drew
/// is held as drawn, all such sizes at once or, when the relationships cannot have that, one at a time (the
/// thinnest first), and the parts move instead.
LeastChangeResult leastChange(const Eigen::VectorXd& target, const std::vector<LinearConstraint>& rows,
                              const Eigen::VectorXd* start)
{
    LeastChangeResult least = solveLeastChange(target, rows, start);
    std::vector<std::pair<double, int>> collapsed;  // (size left / size drawn, the axis' low variable)
    for (int i = 0; least.solved && i + 1 < target.size(); i += 2)
        if (const double drawn = target[i + 1] - target[i], now = least.x[i + 1] - least.x[i];
            now < drawn / 2)
            collapsed.push_back({now / drawn, i});
    if (collapsed.empty())
        return least;
    std::sort(collapsed.begin(), collapsed.end());
    auto asDrawn = [&](int i) {  // the row holding the size of the axis whose low variable is i
        const double drawn = target[i + 1] - target[i];
        return LinearConstraint{{{i + 1, 1.0}, {i, -1.0}}, drawn, drawn, ""};
    };
    std::vector<LinearConstraint> all = rows;
    for (const auto& [left, i] : collapsed)
        all.push_back(asDrawn(i));
    if (LeastChangeResult kept = solveLeastChange(target, all, &least.x); kept.solved)
        return kept;
    std::vector<LinearConstraint> some = rows;
    for (const auto& [left, i] : collapsed) {
        some.push_back(asDrawn(i));
        if (LeastChangeResult kept = solveLeastChange(target, some, &least.x); kept.solved)
            least = std::move(kept);
        else
            some.pop_back();
    }
    return least;
}

}  // namespace

SolveResult solve(const Model& model)
{
    Eigen::VectorXd target(6 * model.cuboids.size());
    for (size_t c = 0; c < model.cuboids.size(); ++c)
        for (int k = 0; k < 6; ++k)
            target[6 * c + k] = model.cuboids[c].coordinates[k];
    const std::vector<LinearConstraint> relationships = constraints(model);
    LeastChangeResult r = leastChange(target, relationships, nullptr);
    // Parts kept apart (issue 13): each pair of parts that come near keeps the side (or the cavity) it takes
    // in that solution, the arrangement the relationships give; pairs the solve then brings together are
    // added round by round (constraint generation: the pairs stay few).
    const Model arranged = r.solved ? withCoordinates(model, r.x) : model;
    std::set<PairKey> seen;
    std::vector<Separation> separations;
    separateNear(arranged, arranged, model.minimumSize, seen, separations);
    for (int round = 0; r.solved && round < 8; ++round) {
        std::vector<LinearConstraint> rows = relationships;
        for (const Separation& s : separations)
            separate(rows, model, s);
        if (violation(r.x, rows) > 1e-6)
            r = leastChange(target, rows, &r.x);
        if (!r.solved || separateNear(arranged, withCoordinates(model, r.x), -1e-6, seen, separations) == 0)
            break;
    }
    SolveResult result{r.solved, r.solved ? withCoordinates(model, r.x) : model, r.conflict, r.violation,
                       {},       blamedParts(model, separations, r.conflict)};
    for (const Cover& c : model.cover)
        addNotes(result.notes, c.name, c.notes);
    for (const Support& s : model.support)
        addNotes(result.notes, s.name, s.notes);
    if (!r.solved)
        return result;
    // Stage 2 (thesis 4.4): the double pivots' pivots, with the cuboids fixed.
    const std::vector<Unplaced> unplaced = placePivots(result.model);
    if (unplaced.empty())
        return result;
    SolveResult failed{false, model, {}, r.violation, result.notes, {}};
    for (const Unplaced& u : unplaced) {
        failed.conflict.push_back(u.joint);
        failed.notes.push_back(u.joint + ": " + u.reason);
    }
    return failed;
}

}  // namespace fabguide::function
