#include "Function/Separation.h"

#include "Function/Pose.h"
#include "Geometry/Interval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace fabguide::function {

namespace {

using Box = std::array<double, 6>;  ///< by Side

Box boxOf(const Model& model, int cuboid, int configuration)
{
    return posedBounds(model, cuboid, configuration);
}

/// The poses in which print-in-place makes room for a fit inside (thesis 4.5.1): by (inner part,
/// enclosing part, pose), the configurations of the fits whose room the pose is in: the modelled pose, each
/// fit's configuration and the poses on the way to it.
using Rooms = std::map<std::tuple<int, int, int>, std::set<int>>;

Rooms rooms(const Model& model)
{
    Rooms room;
    for (const FitInside& f : model.fitInside)
        for (int p : f.inner) {
            room[{p, f.enclosing, -1}].insert(f.configuration);
            for (int k = 0; k < static_cast<int>(model.configurations.size()); ++k)
                if (f.configuration >= 0 &&
                    (k == f.configuration || model.configurations[k].along == f.configuration))
                    room[{p, f.enclosing, k}].insert(f.configuration);
        }
    return room;
}

/// The volume of box a within box b.
double common(const Box& a, const Box& b)
{
    double inside = 1;
    for (int axis = 0; axis < 3; ++axis)
        inside *= std::max(0.0, overlapOf(along(a, axis), along(b, axis)));
    return inside;
}

double volume(const Box& a)
{
    return common(a, a);
}

/// Whether box a lies at least half inside box b.
bool mostlyInside(const Box& a, const Box& b)
{
    return 2 * common(a, b) >= volume(a);
}

/// Whether solid cuboids a and b of different parts may overlap in the configuration: they are carried
/// together (one part, or held by fixed joints), or a fit inside makes room for one in the other.
/// Print-in-place cuts the room a fit's inner parts sweep (thesis 4.5.1), but only for an inner cuboid carved
/// out of an enclosing one (mostly inside it where the fit holds): one between a frame's posts stays clear of
/// them.
bool exempt(const Model& model, const Rooms& room, const std::vector<int>& owner, int a, int b,
            int configuration)
{
    for (const auto& [inner, enclosing] : {std::pair{a, b}, std::pair{b, a}}) {
        const auto found = room.find({owner[inner], owner[enclosing], configuration});
        if (found != room.end())
            for (int k : found->second)
                if (mostlyInside(boxOf(model, inner, k), boxOf(model, enclosing, k)))
                    return true;
    }
    return carrierOf(model, owner[a]) == carrierOf(model, owner[b]);
}

bool overlaps(const Box& a, const Box& b)
{
    for (int axis = 0; axis < 3; ++axis)
        if (overlapOf(along(a, axis), along(b, axis)) <= 0)
            return false;
    return true;
}

/// Whether cavity box d continues cavity box c past c's side k: it reaches beyond that side from it (touching
/// or overlapping) and overlaps c across the other two axes.
bool continues(const Box& c, const Box& d, int k)
{
    const int axis = k / 2;
    const bool beyond =
        k % 2 ? d[k] > c[k] + 1e-9 && d[k - 1] <= c[k] + 1e-9 : d[k] < c[k] - 1e-9 && d[k + 1] >= c[k] - 1e-9;
    for (int o = 0; o < 3 && beyond; ++o)
        if (o != axis && overlapOf(along(c, o), along(d, o)) <= 1e-9)
            return false;
    return beyond;
}

/// The walls that hold `inner` in the void of cavity c: c and the cavities of its solid that continue it and
/// that `inner` reaches into, each on its sides that are neither openings nor passages to another of them.
std::vector<Face> voidWalls(const Model& model, const Box& inner, int cavity, int configuration)
{
    std::vector<int> cavities{cavity};
    std::vector<Box> boxes{boxOf(model, cavity, configuration)};
    auto passage = [&](size_t i, int k) {
        for (size_t d = 0; d < cavities.size(); ++d)
            if (d != i && continues(boxes[i], boxes[d], k))
                return true;
        return false;
    };
    for (size_t i = 0; i < cavities.size(); ++i)
        for (int d = 0; d < static_cast<int>(model.cuboids.size()); ++d) {
            if (model.cuboids[d].within != model.cuboids[cavity].within ||
                std::find(cavities.begin(), cavities.end(), d) != cavities.end())
                continue;
            const Box box = boxOf(model, d, configuration);
            for (int k = 0; k < 6; ++k)
                if (overlaps(inner, box) && continues(boxes[i], box, k)) {
                    cavities.push_back(d);
                    boxes.push_back(box);
                    break;
                }
        }
    std::vector<Face> walls;
    for (size_t i = 0; i < cavities.size(); ++i)
        for (int k = 0; k < 6; ++k)
            if (!isOpening(model, cavities[i], k) && !passage(i, k))
                walls.push_back({cavities[i], static_cast<Side>(k)});
    return walls;
}

/// How far `inner` reaches past the walls.
double outside(const Model& model, const Box& inner, const std::vector<Face>& walls, int configuration)
{
    double total = 0;
    for (const Face& wall : walls) {
        const int k = static_cast<int>(wall.side);
        const double at = evaluate(model, posed(model, wall, configuration));
        total += std::max(0.0, k % 2 ? inner[k] - at : at - inner[k]);
    }
    return total;
}

Direction cross(const Direction& u, const Direction& v)
{
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

/// Of unit length, or zero when shorter than 1e-9 (parallel axes have no cross product).
Direction normalised(const Direction& d)
{
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (length < 1e-9)
        return {0, 0, 0};
    return {d[0] / length, d[1] / length, d[2] / length};
}

}  // namespace

bool exactlyPosed(const Model& model, int part, int configuration)
{
    for (int j = jointMoving(model, part); j >= 0;
         j = model.joints[j].base < 0 ? -1 : jointMoving(model, model.joints[j].base)) {
        const JointPose* pose = poseOf(model, j, configuration);
        const bool turns = model.joints[j].turns() || model.joints[j].type == Joint::Type::DoublePivot;
        if (pose && turns && std::abs(std::remainder(pose->angle, 90.0)) > 1e-9)
            return false;
    }
    return true;
}

std::vector<std::pair<int, int>> nearPairs(const Model& model, int configuration, double margin)
{
    std::vector<int> solids;
    std::vector<Box> boxes(model.cuboids.size());
    for (int c = 0; c < static_cast<int>(model.cuboids.size()); ++c)
        if (!model.cuboids[c].cavity()) {
            solids.push_back(c);
            boxes[c] = boxOf(model, c, configuration);
        }
    std::sort(solids.begin(), solids.end(), [&](int a, int b) { return boxes[a][0] < boxes[b][0]; });
    const Rooms room = rooms(model);
    const std::vector<int> owner = owners(model);
    std::vector<std::pair<int, int>> pairs;
    for (size_t i = 0; i < solids.size(); ++i)
        for (size_t k = i + 1; k < solids.size() && boxes[solids[k]][0] < boxes[solids[i]][1] + margin; ++k) {
            const int a = solids[i], b = solids[k];
            bool near = !exempt(model, room, owner, a, b, configuration);
            for (int axis = 1; axis < 3 && near; ++axis)
                near = overlapOf(along(boxes[a], axis), along(boxes[b], axis)) > -margin;
            if (near)
                pairs.push_back(std::minmax(a, b));
        }
    return pairs;
}

std::vector<std::pair<int, int>> drawnInside(const Model& model)
{
    // The volume of box `in` within the material of `solids`' solid cuboids: their boxes less their cavities.
    const auto material = [&](const Box& in, std::initializer_list<int> solids) {
        Box within = in;
        for (int s : solids) {
            const Box box = boxOf(model, s, -1);
            for (int k = 0; k < 6; ++k)
                within[k] = k % 2 ? std::min(within[k], box[k]) : std::max(within[k], box[k]);
        }
        double left = volume(within);
        for (int c = 0; c < static_cast<int>(model.cuboids.size()); ++c)
            for (int s : solids)
                if (model.cuboids[c].within == s)
                    left -= common(within, boxOf(model, c, -1));
        return std::max(0.0, left);
    };
    std::vector<std::pair<int, int>> found;
    for (const auto& [a, b] : nearPairs(model, -1, 0)) {  // overlapping pairs that nothing lets overlap
        const double both = material(boxOf(model, a, -1), {a, b});
        // The share of each within the other: the one more inside is the inner (a tray in its carcass, though
        // the carcass may be more than half within the tray's box too), when it is at least half inside.
        const auto share = [&](int inner) {
            const double own = material(boxOf(model, inner, -1), {inner});
            return own > 0 ? both / own : HUGE_VAL;
        };
        const double ofA = share(a), ofB = share(b);
        if (std::max(ofA, ofB) >= 0.5)
            found.push_back(ofB > ofA ? std::pair{b, a} : std::pair{a, b});
    }
    return found;
}

namespace {

/// Whether a change is one a rough drawing explains: at most half the size across it (the cuboid is mostly
/// there already), or less than twice the inference distance (two faces each drawn that far off).
bool nearEnough(double change, double size)
{
    return change <= size / 2 || change < 2 * kInferenceDistance;
}

/// A way of keeping a pair apart in one pose, and what it changes there (how far they overlap, or how far the
/// held cuboid reaches past the walls).
struct Option {
    Separation separation;
    double cost = 0;
    bool near = true;  ///< nearEnough: a change the drawing's roughness explains
};

/// The separating-axis test (4.2.2's packing, made exact for turned parts): the order that overlaps least.
Option keptOut(const Model& arranged, int a, int b, int configuration, const Box& boxA, const Box& boxB)
{
    Option best{{}, std::numeric_limits<double>::infinity()};
    const auto consider = [&](int low, int high, const Direction& d, double overlap) {
        if (overlap < best.cost - 1e-9)
            best = {{low, high, configuration, d, {}}, overlap};
    };
    for (int axis = 0; axis < 3; ++axis) {  // along x, y, z the posed boxes' sides are the projections
        const Direction d{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0};
        consider(a, b, d, boxA[2 * axis + 1] - boxB[2 * axis]);
        consider(b, a, d, boxB[2 * axis + 1] - boxA[2 * axis]);
    }
    if (!exactlyPosed(arranged, partOf(arranged, a), configuration) ||
        !exactlyPosed(arranged, partOf(arranged, b), configuration)) {
        const auto axesA = posedAxes(arranged, a, configuration),
                   axesB = posedAxes(arranged, b, configuration);
        std::vector<Direction> directions(axesA.begin(), axesA.end());
        directions.insert(directions.end(), axesB.begin(), axesB.end());
        for (const Direction& u : axesA)
            for (const Direction& v : axesB)
                if (const Direction n = normalised(cross(u, v)); n != Direction{0, 0, 0})
                    directions.push_back(n);
        for (const Direction& d : directions)
            for (const auto& [low, high] : {std::pair{a, b}, std::pair{b, a}})
                consider(low, high, d,
                         evaluate(arranged, projected(arranged, low, configuration, d, true)) -
                             evaluate(arranged, projected(arranged, high, configuration, d, false)));
    }
    best.cost = std::max(0.0, best.cost);
    return best;
}

/// `held` (posed in `box`) inside cavity c of the other part's cuboid (a drawer in its compartment; a door
/// turning into its bay: its box, turned by other than quarter turns, bounds it).
Option heldIn(const Model& arranged, int held, int holder, int c, int configuration, const Box& box)
{
    std::vector<Face> walls = voidWalls(arranged, box, c, configuration);
    const double cost = outside(arranged, box, walls, configuration);
    const double size = std::min({box[1] - box[0], box[3] - box[2], box[5] - box[4]});
    return {{held, holder, configuration, {}, std::move(walls)}, cost, nearEnough(cost, size)};
}

/// The cavities that could hold one of a and b (posed in boxA and boxB) in the configuration: (held, holder,
/// cavity), those of the other's cuboid that its box overlaps.
std::vector<std::array<int, 3>> holders(const Model& arranged, int a, int b, int configuration,
                                        const Box& boxA, const Box& boxB)
{
    std::vector<std::array<int, 3>> found;
    for (const auto& [held, holder, box] : {std::tuple{a, b, &boxA}, std::tuple{b, a, &boxB}}) {
        for (int c = 0; c < static_cast<int>(arranged.cuboids.size()); ++c)
            if (arranged.cuboids[c].within == holder && overlaps(*box, boxOf(arranged, c, configuration)))
                found.push_back({held, holder, c});
    }
    return found;
}

}  // namespace

Separation inferSeparation(const Model& arranged, int a, int b, int configuration)
{
    const Box boxA = boxOf(arranged, a, configuration), boxB = boxOf(arranged, b, configuration);
    Option best = keptOut(arranged, a, b, configuration, boxA, boxB);
    for (const auto& [held, holder, c] : holders(arranged, a, b, configuration, boxA, boxB))
        if (Option in = heldIn(arranged, held, holder, c, configuration, held == a ? boxA : boxB);
            in.cost < best.cost)
            best = std::move(in);
    return best.separation;
}

namespace {

/// Whether one move v of one cuboid against the other meets every demand (n, o): n·v ≥ o; Hildreth's method
/// (coordinate ascent on the dual) finds the least such move where there is one. There is none for a way that
/// keeps a pair on one side of each other in one pose and on the other side in the next, which no motion
/// does.
bool oneMoveKeeps(const std::vector<std::pair<Direction, double>>& demands)
{
    double v[3] = {0, 0, 0};
    std::vector<double> weight(demands.size(), 0.0);
    const auto shortOf = [&](const std::pair<Direction, double>& d) {
        return d.second - (d.first[0] * v[0] + d.first[1] * v[1] + d.first[2] * v[2]);
    };
    bool moved = true;  // a sweep that moves nothing has converged
    for (int sweep = 0; sweep < 1000 && moved; ++sweep) {
        moved = false;
        for (size_t k = 0; k < demands.size(); ++k) {
            const Direction& n = demands[k].first;
            const double step =
                std::max(-weight[k], shortOf(demands[k]) / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
            weight[k] += step;
            for (int i = 0; i < 3; ++i)
                v[i] += step * n[i];
            moved = moved || std::abs(step) > 1e-12;
        }
    }
    return std::all_of(demands.begin(), demands.end(), [&](const auto& d) { return shortOf(d) <= 1e-3; });
}

/// Whether two separations keep the pair on the same side (in whichever pose).
bool sameSide(const Separation& s, const Separation& t)
{
    return s.a == t.a && s.b == t.b && s.direction == t.direction && s.walls == t.walls;
}

}  // namespace

bool sameWay(const Choice& x, const Choice& y)
{
    return std::equal(x.separations.begin(), x.separations.end(), y.separations.begin(), y.separations.end(),
                      sameSide);
}

std::vector<Choice> choicesAlong(const Model& arranged, int a, int b, const std::vector<int>& poses,
                                 const std::vector<int>& judged)
{
    std::vector<Choice> choices;
    const auto consider = [&](const std::function<Option(int)>& option) {
        Choice c;
        std::vector<std::pair<Direction, double>> apart;  // b moved against a by v: n·v ≥ overlap, each pose
        for (int k : judged) {
            Option o = option(k);
            c.cost += o.cost;
            c.near = c.near && o.near;
            if (const Separation& s = o.separation; s.walls.empty())
                apart.push_back(
                    {s.a == a ? s.direction : Direction{-s.direction[0], -s.direction[1], -s.direction[2]},
                     o.cost});
            if (std::find(poses.begin(), poses.end(), k) != poses.end())
                c.separations.push_back(std::move(o.separation));
        }
        if (!oneMoveKeeps(apart))
            c.cost = std::numeric_limits<double>::infinity();  // tried last
        if (std::none_of(choices.begin(), choices.end(),
                         [&](const Choice& other) { return sameWay(c, other); }))
            choices.push_back(std::move(c));
    };
    std::map<int, std::pair<Box, Box>> at;  // the posed boxes of a and b in each pose
    for (int k : judged)
        at[k] = {boxOf(arranged, a, k), boxOf(arranged, b, k)};
    consider([&](int k) { return keptOut(arranged, a, b, k, at[k].first, at[k].second); });
    std::set<std::array<int, 3>> tried;
    for (int k : judged)
        for (const std::array<int, 3>& h : holders(arranged, a, b, k, at[k].first, at[k].second))
            if (tried.insert(h).second)
                consider([&](int pose) {
                    return heldIn(arranged, h[0], h[1], h[2], pose,
                                  h[0] == a ? at[pose].first : at[pose].second);
                });
    for (int axis = 0; axis < 3; ++axis)
        for (bool aLow : {true, false})
            consider([&](int k) {
                const Box &low = aLow ? at[k].first : at[k].second, &high = aLow ? at[k].second : at[k].first;
                const double overlap = low[2 * axis + 1] - high[2 * axis];
                const double size =
                    std::min(low[2 * axis + 1] - low[2 * axis], high[2 * axis + 1] - high[2 * axis]);
                const Direction d{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0};
                return Option{{aLow ? a : b, aLow ? b : a, k, d, {}},
                              std::max(0.0, overlap),
                              nearEnough(overlap, size)};
            });
    std::stable_sort(choices.begin(), choices.end(),
                     [](const Choice& x, const Choice& y) { return x.cost < y.cost - 1e-9; });
    return choices;
}

std::string separationName(const Model& model, const Separation& separation)
{
    const int a = partOf(model, separation.a), b = partOf(model, separation.b);
    std::string where;
    if (separation.configuration >= 0) {
        const Configuration& k = model.configurations[separation.configuration];
        where = k.along < 0 ? " in '" + k.name + "'"
                            : " on the way to '" + model.configurations[k.along].name + "'";
    }
    return "no overlap: " + model.parts[std::min(a, b)].name + ", " + model.parts[std::max(a, b)].name +
           where;
}

}  // namespace fabguide::function
