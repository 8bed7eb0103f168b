#include "Function/DoublePivot.h"

#include "Function/Pose.h"
#include "Geometry/Interval.h"

#include <libalglib/optimization.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace fabguide::function {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// A link turning more than this either way turns half a turn the way its part turns (the checker's rule).
constexpr double kHalfTurn = 180 - 1e-3;

using Point = std::array<double, 2>;

/// p turned about centre by the angle whose cosine and sine are c and s.
Point turn(const Point& p, const Point& centre, double c, double s)
{
    const double du = p[0] - centre[0], dw = p[1] - centre[1];
    return {centre[0] + du * c - dw * s, centre[1] + du * s + dw * c};
}

Point turn(const Point& p, const Point& centre, double degrees)
{
    const auto [c, s] = cosSin(degrees);
    return turn(p, centre, c, s);
}

/// Rounded to the nanometre, as the cuboids are (no 1e-12 residue on a pivot placed at a face's edge).
double nanometres(double mm)
{
    return std::round(mm * 1e9) / 1e9;
}

double squared(const Point& a, const Point& b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

/// The in-plane axis (0: u, 1: w) along which a cuboid is longest: where its pivot may move (thesis 4.3.6).
int longest(const Cuboid& c, const PivotPlane& plane)
{
    const double eu = c.at(static_cast<Side>(2 * plane.u + 1)) - c.at(static_cast<Side>(2 * plane.u));
    const double ew = c.at(static_cast<Side>(2 * plane.w + 1)) - c.at(static_cast<Side>(2 * plane.w));
    return eu >= ew ? 0 : 1;
}

/// One double pivot's stage-2 problem: offsets (a, b) of the part's and the base's pivots along their axes.
struct Placement {
    const Model& model;
    const Joint& joint;
    PivotPlane plane;
    int axisA = 0, axisB = 0;
    std::vector<JointPose> poses;
    std::vector<int> configurations;  ///< of each pose

    Point pivotA(double a) const
    {
        Point p = plane.pivot;
        p[axisA] += a;
        return p;
    }
    Point pivotB(double b) const
    {
        Point p = plane.basePivot;
        p[axisB] += b;
        return p;
    }
    Point pole(const JointPose& pose) const { return {pose.pole[plane.u], pose.pole[plane.w]}; }
    /// Position constraint (4.3.6.1) for one pose: the link keeps its length, |x_k^A − x^B|² − |x^A − x^B|².
    double position(const JointPose& pose, double a, double b) const
    {
        return squared(turn(pivotA(a), pole(pose), pose.angle), pivotB(b)) - squared(pivotA(a), pivotB(b));
    }
    /// How far each pivot can move along its axis and stay on its face.
    std::pair<double, double> range(const Face& f, int axis, const Point& at) const
    {
        const int a = axis == 0 ? plane.u : plane.w;
        const Cuboid& c = model.cuboids[f.cuboid];
        return {c.at(static_cast<Side>(2 * a)) - at[axis], c.at(static_cast<Side>(2 * a + 1)) - at[axis]};
    }
};

void evaluate(const alglib::real_1d_array& x, alglib::real_1d_array& f, alglib::real_2d_array& jacobian,
              void* data)
{
    const Placement& p = *static_cast<const Placement*>(data);
    f[0] = x[0] * x[0] + x[1] * x[1];  // least change of the offsets (eq. 4.6, second term)
    jacobian[0][0] = 2 * x[0];
    jacobian[0][1] = 2 * x[1];
    const double h = 1e-6;  // the constraints are quadratic: central differences are exact up to rounding
    for (size_t k = 0; k < p.poses.size(); ++k) {
        f[k + 1] = p.position(p.poses[k], x[0], x[1]);
        jacobian[k + 1][0] =
            (p.position(p.poses[k], x[0] + h, x[1]) - p.position(p.poses[k], x[0] - h, x[1])) / (2 * h);
        jacobian[k + 1][1] =
            (p.position(p.poses[k], x[0], x[1] + h) - p.position(p.poses[k], x[0], x[1] - h)) / (2 * h);
    }
}

/// Each solid cuboid of a part in the pivot plane: (low u, low w, high u, high w, low, high along the
/// normal).
std::vector<std::array<double, 6>> rectangles(const Model& model, int part, const PivotPlane& plane)
{
    std::vector<std::array<double, 6>> out;
    for (int c : model.parts[part].cuboids)
        if (!model.cuboids[c].cavity()) {
            const Cuboid& k = model.cuboids[c];
            auto at = [&](int axis, int high) { return k.at(static_cast<Side>(2 * axis + high)); };
            out.push_back({at(plane.u, 0), at(plane.w, 0), at(plane.u, 1), at(plane.w, 1),
                           at(plane.normal, 0), at(plane.normal, 1)});
        }
    return out;
}

/// Whether a turned rectangle (corners) and an axis-aligned one overlap by more than `slack`, by separating
/// axes.
bool overlap(const std::array<Point, 4>& turned, const std::array<double, 6>& box, double slack)
{
    const std::array<Point, 4> corners{Point{box[0], box[1]}, Point{box[2], box[1]}, Point{box[2], box[3]},
                                       Point{box[0], box[3]}};
    std::vector<Point> axes{{1, 0}, {0, 1}};
    for (int e = 0; e < 2; ++e)
        axes.push_back({turned[e + 1][0] - turned[e][0], turned[e + 1][1] - turned[e][1]});
    for (Point axis : axes) {
        const double length = std::hypot(axis[0], axis[1]);
        axis = {axis[0] / length, axis[1] / length};
        auto extent = [&](const std::array<Point, 4>& points) {
            double low = 1e300, high = -1e300;
            for (const Point& q : points) {
                const double t = q[0] * axis[0] + q[1] * axis[1];
                low = std::min(low, t);
                high = std::max(high, t);
            }
            return std::pair{low, high};
        };
        const auto [a0, a1] = extent(turned);
        const auto [b0, b1] = extent(corners);
        if (overlapOf({a0, a1}, {b0, b1}) <= slack)
            return false;  // a separating axis
    }
    return true;
}

/// Whether the part hits its base, or any other part standing still, at one of 32 poses along the four-bar
/// motion to each pose, with the pivots moved by (a, b): solid cuboids, in the pivot plane, where they share
/// depth along the normal (the thesis checked the base only).
/// The base and every part standing still in configuration k, but `part`: their rectangles in the plane.
std::vector<std::array<double, 6>> standingStill(const Model& model, int part, const PivotPlane& plane, int k)
{
    std::vector<std::array<double, 6>> fixed;
    for (size_t q = 0; q < model.parts.size(); ++q)
        if (static_cast<int>(q) != part && jointMovingIn(model, static_cast<int>(q), k) < 0) {
            const auto r = rectangles(model, static_cast<int>(q), plane);
            fixed.insert(fixed.end(), r.begin(), r.end());
        }
    return fixed;
}

/// Whether any of the part's rectangles, each corner moved by `place`, overlaps a fixed one where they share
/// depth along the normal.
template <typename Place>
bool hits(const std::vector<std::array<double, 6>>& moving, const std::vector<std::array<double, 6>>& fixed,
          Place place)
{
    for (const auto& r : moving) {
        std::array<Point, 4> corners{Point{r[0], r[1]}, Point{r[2], r[1]}, Point{r[2], r[3]},
                                     Point{r[0], r[3]}};
        for (Point& q : corners)
            q = place(q);
        for (const auto& box : fixed)
            if (overlapOf(along(r, 2), along(box, 2)) > 1e-6 && overlap(corners, box, 1e-6))
                return true;
    }
    return false;
}

/// The link's turn the shorter way round, for a turn of its part by `degrees` about `pole`.
double shorterTurn(const Point& a, const Point& b, const Point& pole, double degrees)
{
    const Point to = turn(a, pole, degrees);
    return std::remainder(
        (std::atan2(to[1] - b[1], to[0] - b[0]) - std::atan2(a[1] - b[1], a[0] - b[0])) * 180 / kPi, 360.0);
}

/// Whether the link's way round hangs on the last digits of its pivots (as written to the file, or on the
/// doubled link): a turn against its part's within 1e-4° of kHalfTurn, either side, where the half-turn rule
/// sends it the other way (a stage-2 search's least change lies just there).
bool undecided(const Point& a, const Point& b, const Point& pole, double degrees)
{
    const double link = shorterTurn(a, b, pole, degrees);
    return std::abs(std::abs(link) - kHalfTurn) < 1e-4 && std::signbit(link) != std::signbit(degrees);
}

bool collides(const Placement& p, double a, double b)
{
    const Point pivot = p.pivotA(a), base = p.pivotB(b);
    const auto moving = rectangles(p.model, p.joint.part, p.plane);
    for (size_t i = 0; i < p.poses.size(); ++i) {
        const JointPose& pose = p.poses[i];
        const auto fixed = standingStill(p.model, p.joint.part, p.plane, p.configurations[i]);
        if (undecided(pivot, base, p.pole(pose), pose.angle))
            return true;
        const auto [link, part] = fourBarAngles(pivot, base, p.pole(pose), pose.angle);
        for (int step = 1; step <= 32; ++step) {
            const double t = step / 32.0;
            const std::pair<double, double> byPart = cosSin(t * part), byLink = cosSin(t * link);
            // about the part's pivot, then carried round by the link
            if (hits(moving, fixed, [&](const Point& q) {
                    return turn(turn(q, pivot, byPart.first, byPart.second), base, byLink.first,
                                byLink.second);
                }))
                return true;
        }
    }
    return false;
}

/// Where the circles about c1 (radius r1) and c2 (r2) meet: none, or two points (one twice when they touch).
std::vector<Point> meet(const Point& c1, double r1, const Point& c2, double r2)
{
    const double d = std::sqrt(squared(c1, c2));
    if (d < 1e-12 || d > r1 + r2 + 1e-9 || d < std::abs(r1 - r2) - 1e-9)
        return {};
    const double along = (d * d + r1 * r1 - r2 * r2) / (2 * d),
                 across = std::sqrt(std::max(0.0, r1 * r1 - along * along));
    const Point e{(c2[0] - c1[0]) / d, (c2[1] - c1[1]) / d}, m{c1[0] + along * e[0], c1[1] + along * e[1]};
    return {Point{m[0] - across * e[1], m[1] + across * e[0]},
            Point{m[0] + across * e[1], m[1] - across * e[0]}};
}

/// Half a double pivot's link width: half the thinner of the two cuboids its pivots sit on (its round ends,
/// 4.5.2).
double linkRadius(const Model& model, const Joint& joint)
{
    double side = 1e300;
    for (int c : {joint.pivotFace.cuboid, joint.basePivotFace.cuboid})
        for (int a = 0; a < 3; ++a)
            side = std::min(side, model.cuboids[c].at(static_cast<Side>(2 * a + 1)) -
                                      model.cuboids[c].at(static_cast<Side>(2 * a)));
    return side / 2;
}

/// The distance from q to the segment from a to b.
double toSegment(const Point& q, const Point& a, const Point& b)
{
    const Point ab{b[0] - a[0], b[1] - a[1]};
    const double length = ab[0] * ab[0] + ab[1] * ab[1];
    const double t =
        length < 1e-24 ? 0 : std::clamp(((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / length, 0.0, 1.0);
    return std::sqrt(squared(q, {a[0] + t * ab[0], a[1] + t * ab[1]}));
}

/// Whether a four-bar's links, from base pivots b1 and b2 to part pivots a1 and a2, each stay `apart` from
/// the other's pivots. They print one layer over the other (4.5.2), so they may cross, but the pins of each
/// run through the other's layer.
bool linksClear(const Point& a1, const Point& b1, const Point& a2, const Point& b2, double apart)
{
    return toSegment(a2, b1, a1) >= apart && toSegment(b2, b1, a1) >= apart &&
           toSegment(a1, b2, a2) >= apart && toSegment(b1, b2, a2) >= apart;
}

/// Whether `one` and `two`, double pivots of one part and base on opposite faces, are one link doubled: their
/// pivots within the two links' widths of each other in the plane (a bed's head on a link at each side, drawn
/// roughly). Links on opposite faces farther apart are a four-bar.
bool doubled(const Model& model, const Joint& one, const Joint& two)
{
    if (one.type != Joint::Type::DoublePivot || two.type != Joint::Type::DoublePivot ||
        one.part != two.part || one.base != two.base || one.pivotFace.side == two.pivotFace.side ||
        axisOf(one.pivotFace.side) != axisOf(two.pivotFace.side))
        return false;
    const PivotPlane a = pivotPlane(model, one), b = pivotPlane(model, two);
    const double width = linkRadius(model, one) + linkRadius(model, two);
    return squared(a.pivot, b.pivot) < width * width && squared(a.basePivot, b.basePivot) < width * width;
}

/// A four-bar: links `first` and `second` both move their part against one base, along
/// fourBarPath in configuration k. Why it fails, or
/// "" when the part arrives where the configuration puts it, clear of the parts standing still, its links
/// clear of each other's pins (linksClear) all the way.
std::string fourBarMotion(const Model& model, const Joint& first, const Joint& second, int k)
{
    const PivotPlane one = pivotPlane(model, first), two = pivotPlane(model, second);
    const Point a1 = one.pivot, b1 = one.basePivot, a2 = two.pivot, b2 = two.basePivot;
    const auto moving = rectangles(model, first.part, one);
    const auto fixed = standingStill(model, first.part, one, k);
    const std::string where = "the four-bar of '" + first.name + "' and '" + second.name + "' ";
    // Links on opposite faces never meet, but placed one over the other they would be one link doubled.
    const bool oneFace = first.pivotFace.side == second.pivotFace.side;
    const double apart = oneFace ? linkRadius(model, first) + linkRadius(model, second) : 0;
    if (!linksClear(a1, b1, a2, b2, apart))
        return where + "has a link over the other's pin as placed";
    if (!oneFace && doubled(model, first, second))
        return where + "has its links one over the other as placed, one link doubled";
    const int steps = 64;
    const std::vector<FourBarTurns> path = fourBarPath(model, first, second, k, 1.0, steps);
    for (int step = 1; step <= steps; ++step) {
        const std::string when =
            std::to_string(100 * step / steps) + " % of the way to '" + model.configurations[k].name + "'";
        if (step > static_cast<int>(path.size()))
            return where + "locks " + when + ": its links cannot stay joined";
        const FourBarTurns& turns = path[step - 1];
        const Point leader = turn(a1, b1, turns.first), follower = turn(a2, b2, turns.second);
        const std::pair<double, double> by = cosSin(turns.part);
        const auto place = [&](const Point& q) {
            const Point r = turn(q, a1, by.first, by.second);
            return Point{r[0] + leader[0] - a1[0], r[1] + leader[1] - a1[1]};
        };
        if (!linksClear(leader, b1, follower, b2, apart))
            return where + "brings a link onto the other's pin " + when;
        if (hits(moving, fixed, place))
            return where + "takes '" + model.parts[first.part].name + "' into a part standing still " + when;
    }
    const JointPose& pose = *poseOf(model, static_cast<int>(&first - model.joints.data()), k);
    const Point end2 = turn(a2, {pose.pole[one.u], pose.pole[one.w]}, pose.angle);
    if (std::sqrt(squared(turn(a2, b2, path.back().second), end2)) > 1e-3)
        return where + "reaches '" + model.configurations[k].name + "' only on its other assembly branch";
    return "";
}

/// Whether pivots moved by (a, b) keep the link's length in every pose, within 1e-6 mm.
bool keepsLength(const Placement& p, double a, double b)
{
    const Point pa = p.pivotA(a), pb = p.pivotB(b);
    for (const JointPose& pose : p.poses)
        if (std::abs(std::sqrt(squared(turn(pa, p.pole(pose), pose.angle), pb)) -
                     std::sqrt(squared(pa, pb))) > 1e-6)
            return false;
    return true;
}

struct Range {
    double lowA, highA, lowB, highB;
};

/// The least change (a, b) under the position constraints, by ALGLIB's SLP; nullopt when it finds none.
std::optional<std::pair<double, double>> leastChange(Placement& p, const Range& range)
{
    alglib::real_1d_array x0, lower, upper, result;
    x0.setlength(2);
    lower.setlength(2);
    upper.setlength(2);
    x0[0] = x0[1] = 0;
    lower[0] = range.lowA;
    upper[0] = range.highA;
    lower[1] = range.lowB;
    upper[1] = range.highB;
    alglib::minnlcreport report;
    try {
        alglib::minnlcstate state;
        alglib::minnlccreate(2, x0, state);
        alglib::minnlcsetbc(state, lower, upper);
        alglib::minnlcsetnlc(state, static_cast<int>(p.poses.size()), 0);
        alglib::minnlcsetcond(state, 1e-10, 200);
#ifdef FABGUIDE_ALGLIB_SLP
        alglib::minnlcsetalgoslp(state);  // 3x faster than SQP on these two-variable problems
#else
        alglib::minnlcsetalgosqp(state);  // ALGLIB 4 has no SLP
#endif
        alglib::minnlcoptimize(state, evaluate, nullptr, &p);
        alglib::minnlcresults(state, result, report);
    } catch (const alglib::ap_error& e) {  // no third-party exception leaves the core
        throw std::runtime_error("placing a double pivot failed: " + e.msg);
    }
    if (report.terminationtype <= 0 || !keepsLength(p, result[0], result[1]))
        return std::nullopt;
    return std::pair{result[0], result[1]};
}

/// The placement (a, b) with the part's pivot moved by a: b from the first pose's position constraint (linear
/// in b: |x_k^A|² − |x^A|² = 2 (x_k^A − x^A) · x^B), when it lies on its face and the link keeps its length
/// in every pose.
std::optional<std::pair<double, double>> linkAt(const Placement& p, const Range& range, double a)
{
    const Point x0 = p.pivotA(a), xk = turn(x0, p.pole(p.poses[0]), p.poses[0].angle);
    const Point d{xk[0] - x0[0], xk[1] - x0[1]}, base = p.pivotB(0);
    const double along = 2 * d[p.axisB];
    if (std::abs(along) < 1e-12)
        return std::nullopt;
    const double b = (xk[0] * xk[0] + xk[1] * xk[1] - x0[0] * x0[0] - x0[1] * x0[1] -
                      2 * (d[0] * base[0] + d[1] * base[1])) /
                     along;
    if (b < range.lowB || b > range.highB || !keepsLength(p, a, b))
        return std::nullopt;
    return std::pair{a, b};
}

/// The motion constraint (4.3.6.2) by search: along the part's pivot axis, each a fixes b (linkAt); the least
/// change among placements that keep the link's length in every pose and move without interference. The
/// thesis bounds the link's length from below by linear terms for the box corners it may pass; checking the
/// motion itself is exact where those bounds are conservative.
std::optional<std::pair<double, double>> clearPlacement(const Placement& p, const Range& range)
{
    auto placement = [&](double a) -> std::optional<std::pair<double, double>> {
        const auto x = linkAt(p, range, a);
        return x && !collides(p, x->first, x->second) ? x : std::nullopt;
    };
    auto cost = [](const std::pair<double, double>& x) { return x.first * x.first + x.second * x.second; };
    // A coarse sweep, then bisection towards the nearest blocked samples: the least change lies on the edge
    // of a clear stretch (the SQP's optimum, inside one, collided).
    const int steps = 200;  // 5 mm on a 1 m board: clear stretches are often a few cm wide
    auto at = [&](double i) { return range.lowA + (range.highA - range.lowA) * i / steps; };
    std::optional<std::pair<double, double>> best;
    int bestStep = -1;
    for (int i = 0; i <= steps; ++i)
        if (const auto x = placement(at(i)); x && (!best || cost(*x) < cost(*best))) {
            best = x;
            bestStep = i;
        }
    for (int side : {-1, 1}) {
        if (!best || bestStep + side < 0 || bestStep + side > steps || placement(at(bestStep + side)))
            continue;
        double clear = bestStep, blocked = bestStep + side;
        for (int k = 0; k < 30; ++k) {
            const double middle = (clear + blocked) / 2;
            (placement(at(middle)) ? clear : blocked) = middle;
        }
        if (const auto x = placement(at(clear)); x && cost(*x) < cost(*best))
            best = x;
    }
    return best;
}

/// Why a four-bar fails in a configuration that poses it (fourBarMotion), or "".
std::string fourBarFailure(const Model& model, const Joint& first, const Joint& second)
{
    const int j = static_cast<int>(&first - model.joints.data());
    for (int k = 0; k < static_cast<int>(model.configurations.size()); ++k)
        if (poseOf(model, j, k))
            if (std::string why = fourBarMotion(model, first, second, k); !why.empty())
                return why;
    return "";
}

/// A double pivot's stage-2 problem as the joint is placed now, and how far its pivots may move.
std::pair<Placement, Range> placementOf(const Model& model, const Joint& joint)
{
    Placement p{model, joint, pivotPlane(model, joint), 0, 0, {}, {}};
    p.axisA = longest(model.cuboids[joint.pivotFace.cuboid], p.plane);
    p.axisB = longest(model.cuboids[joint.basePivotFace.cuboid], p.plane);
    const int j = static_cast<int>(&joint - model.joints.data());
    for (size_t k = 0; k < model.configurations.size(); ++k)
        for (const JointPose& pose : model.configurations[k].poses)
            if (pose.joint == j) {
                p.poses.push_back(pose);
                p.configurations.push_back(static_cast<int>(k));
            }
    const auto [lowA, highA] = p.range(joint.pivotFace, p.axisA, p.plane.pivot);
    const auto [lowB, highB] = p.range(joint.basePivotFace, p.axisB, p.plane.basePivot);
    return {p, Range{lowA, highA, lowB, highB}};
}

/// A four-bar whose links' least-change places fail, placed anew (the thesis places each link alone): each
/// link's places along its part's face (linkAt, 100 samples), pairs in order of their total change, the first
/// that moves clear in every configuration (fourBarFailure; at most 4000 tried). Whether one was found; the
/// joints are left there, or as they were.
bool placeFourBar(Model& model, Joint& first, Joint& second)
{
    struct Candidate {
        double cost, a, b;
    };
    const auto [p1, range1] = placementOf(model, first);
    const auto [p2, range2] = placementOf(model, second);
    auto sample = [](const Placement& p, const Range& r) {
        std::vector<Candidate> out;
        const int steps = 100;
        for (int i = 0; i <= steps; ++i)
            if (const auto x = linkAt(p, r, r.lowA + (r.highA - r.lowA) * i / steps))
                out.push_back({x->first * x->first + x->second * x->second, x->first, x->second});
        return out;
    };
    const std::vector<Candidate> c1 = sample(p1, range1), c2 = sample(p2, range2);
    std::vector<std::pair<size_t, size_t>> pairs;
    for (size_t i = 0; i < c1.size(); ++i)
        for (size_t k = 0; k < c2.size(); ++k)
            pairs.push_back({i, k});
    std::sort(pairs.begin(), pairs.end(), [&](const auto& x, const auto& y) {
        return c1[x.first].cost + c2[x.second].cost < c1[y.first].cost + c2[y.second].cost;
    });
    const Joint before1 = first, before2 = second;
    auto move = [](Joint& joint, const Joint& before, const Placement& p, const Candidate& c) {
        joint.pivot[p.axisA] = nanometres(before.pivot[p.axisA] + c.a);
        joint.basePivot[p.axisB] = nanometres(before.basePivot[p.axisB] + c.b);
    };
    for (size_t n = 0; n < pairs.size() && n < 4000; ++n) {
        move(first, before1, p1, c1[pairs[n].first]);
        move(second, before2, p2, c2[pairs[n].second]);
        if (fourBarFailure(model, first, second).empty())
            return true;
    }
    first = before1;
    second = before2;
    return false;
}

/// Puts `joint`'s pivots where `placed`, the link it doubles, has them in the plane, so the two move as one
/// link. Whether both still lie on their faces (else `joint` is left as it was).
bool placeLike(const Model& model, Joint& joint, const Joint& placed)
{
    const PivotPlane to = pivotPlane(model, placed), from = pivotPlane(model, joint);
    Joint moved = joint;
    for (int k = 0; k < 2; ++k) {
        moved.pivot[k] = nanometres(joint.pivot[k] + to.pivot[k] - from.pivot[k]);
        moved.basePivot[k] = nanometres(joint.basePivot[k] + to.basePivot[k] - from.basePivot[k]);
    }
    const auto onFace = [&](const Face& face, const std::array<double, 2>& at) {
        const Cuboid& c = model.cuboids[face.cuboid];
        for (int k = 0; k < 2; ++k) {
            const int axis = k == 0 ? from.u : from.w;
            const double extent = c.at(static_cast<Side>(2 * axis + 1)) - c.at(static_cast<Side>(2 * axis));
            if (at[k] < -1e-9 || at[k] > extent + 1e-9)
                return false;
        }
        return true;
    };
    if (!onFace(joint.pivotFace, moved.pivot) || !onFace(joint.basePivotFace, moved.basePivot))
        return false;
    joint = moved;
    return true;
}

}  // namespace

const Joint* fourBarPartner(const Model& model, const Joint& joint)
{
    if (joint.type != Joint::Type::DoublePivot)
        return nullptr;
    for (const Joint& other : model.joints)
        if (&other != &joint && other.type == Joint::Type::DoublePivot && other.part == joint.part &&
            other.base == joint.base &&
            (other.pivotFace.side == joint.pivotFace.side ||
             (axisOf(other.pivotFace.side) == axisOf(joint.pivotFace.side) && !doubled(model, joint, other))))
            return &other;
    return nullptr;
}

std::array<double, 2> fourBarAngles(const Point& a, const Point& b, const Point& pole, double degrees)
{
    double link = shorterTurn(a, b, pole, degrees);
    if (std::abs(link) > kHalfTurn)  // half a turn either way, to a thousandth of a degree: as the part turns
        link = std::copysign(180.0, degrees);
    return {link, degrees - link};
}

PivotPlane pivotPlane(const Model& model, const Joint& joint)
{
    PivotPlane plane;
    plane.normal = axisOf(joint.pivotFace.side);
    plane.u = (plane.normal + 1) % 3;
    plane.w = (plane.normal + 2) % 3;
    const Cuboid& a = model.cuboids[joint.pivotFace.cuboid];
    const Cuboid& b = model.cuboids[joint.basePivotFace.cuboid];
    for (int k = 0; k < 2; ++k) {
        const int axis = k == 0 ? plane.u : plane.w;
        plane.pivot[k] = a.at(static_cast<Side>(2 * axis)) + joint.pivot[k];
        plane.basePivot[k] = b.at(static_cast<Side>(2 * axis)) + joint.basePivot[k];
    }
    return plane;
}

std::array<double, 2> linkAngles(const Model& model, const Joint& joint, const JointPose& pose)
{
    const PivotPlane plane = pivotPlane(model, joint);
    return fourBarAngles(plane.pivot, plane.basePivot, {pose.pole[plane.u], pose.pole[plane.w]}, pose.angle);
}

std::vector<FourBarTurns> fourBarPath(const Model& model, const Joint& first, const Joint& second, int k,
                                      double t, int steps)
{
    const PivotPlane one = pivotPlane(model, first), two = pivotPlane(model, second);
    const JointPose* pose = poseOf(model, static_cast<int>(&first - model.joints.data()), k);
    if (!pose)
        return std::vector<FourBarTurns>(static_cast<size_t>(steps));
    const Point pole{pose->pole[one.u], pose->pole[one.w]};
    const Point a1 = one.pivot, b1 = one.basePivot, a2 = two.pivot, b2 = two.basePivot;
    const double r1 = std::sqrt(squared(a1, b1)), r2 = std::sqrt(squared(a2, b2)),
                 coupler = std::sqrt(squared(a1, a2));
    const Point end1 = turn(a1, pole, pose->angle);
    const double from = std::atan2(a1[1] - b1[1], a1[0] - b1[0]);
    const double sweep = std::remainder(std::atan2(end1[1] - b1[1], end1[0] - b1[0]) - from, 2 * kPi);
    auto degrees = [](double radians) { return std::remainder(radians, 2 * kPi) * 180 / kPi; };
    std::vector<FourBarTurns> path;
    Point follower = a2;
    for (int step = 1; step <= steps; ++step) {
        const double turned = sweep * t * step / steps;
        const Point leader{b1[0] + r1 * std::cos(from + turned), b1[1] + r1 * std::sin(from + turned)};
        const std::vector<Point> places = meet(b2, r2, leader, coupler);
        if (places.empty())
            break;
        follower = squared(places[0], follower) <= squared(places[1], follower) ? places[0] : places[1];
        path.push_back({degrees(turned),
                        degrees(std::atan2(follower[1] - b2[1], follower[0] - b2[0]) -
                                std::atan2(a2[1] - b2[1], a2[0] - b2[0])),
                        degrees(std::atan2(follower[1] - leader[1], follower[0] - leader[0]) -
                                std::atan2(a2[1] - a1[1], a2[0] - a1[0]))});
    }
    return path;
}

std::vector<Unplaced> placePivots(Model& model)
{
    std::vector<Unplaced> failed;
    // A link doubled on the opposite face goes where the first of the two is placed (as modelled, both).
    // Which links are doubled and which make four-bars is decided as modelled, before any of them moves.
    std::vector<int> twin(model.joints.size(), -1);
    std::vector<const Joint*> partner(model.joints.size());
    for (size_t j = 0; j < model.joints.size(); ++j) {
        for (size_t i = 0; i < j && twin[j] < 0; ++i)
            if (doubled(model, model.joints[i], model.joints[j]))
                twin[j] = static_cast<int>(i);
        partner[j] = fourBarPartner(model, model.joints[j]);
    }
    for (Joint& joint : model.joints) {
        if (joint.type != Joint::Type::DoublePivot)
            continue;
        if (const int first = twin[&joint - model.joints.data()]; first >= 0) {
            const auto half = std::find_if(failed.begin(), failed.end(), [&](const Unplaced& u) {
                return u.joint == model.joints[first].name;
            });
            if (half != failed.end()) {
                failed.push_back({joint.name, half->reason});
                continue;
            }
            if (placeLike(model, joint, model.joints[first]))
                continue;
        }
        auto [p, range] = placementOf(model, joint);
        if (p.poses.empty())
            continue;
        const auto reachable = leastChange(p, range);
        auto placed = reachable;
        // A four-bar's links move together: its motion is checked as one linkage below (fourBarFailure).
        if (!partner[&joint - model.joints.data()] && (!placed || collides(p, placed->first, placed->second)))
            placed = clearPlacement(p, range);
        if (!placed) {
            failed.push_back(
                {joint.name, reachable ? "its part would hit '" + model.parts[joint.base].name +
                                             "' or another part standing still on the way, wherever its "
                                             "pivots sit on their faces"
                                       : "no pivot positions on their faces keep the link's length "
                                         "in every configuration"});
            continue;
        }
        joint.pivot[p.axisA] = nanometres(joint.pivot[p.axisA] + placed->first);
        joint.basePivot[p.axisB] = nanometres(joint.basePivot[p.axisB] + placed->second);
    }
    if (!failed.empty())
        return failed;
    for (Joint& joint : model.joints)  // each four-bar once, from its first link
        if (const Joint* other = partner[&joint - model.joints.data()]; other && other > &joint) {
            Joint& second = model.joints[static_cast<size_t>(other - model.joints.data())];
            if (const std::string why = fourBarFailure(model, joint, second);
                !why.empty() && !placeFourBar(model, joint, second))
                failed.push_back(
                    {joint.name, why + ", wherever its pivots sit along their faces: pose the part "
                                       "another way (pole, angle), or put the links on other faces"});
        }
    return failed;
}

}  // namespace fabguide::function
