#include "Printable/Gaps.h"

#include "Function/Pose.h"
#include "Geometry/Interval.h"
#include "Printable/Motion.h"

#include <Bnd_Box.hxx>
#include <gp_Dir.hxx>

#include <algorithm>
#include <cmath>
#include <functional>

namespace fabguide::printable {

namespace {

/// The modelled side of cuboid c that configuration k turns onto side `side` of its posed box, or -1 (a turn
/// by other than a multiple of 90° leaves no face there).
int modelledSide(const Model& m, int part, int c, int k, int side)
{
    const gp_Trsf motion = partMotion(m, part, k, 1);
    const auto& x = m.cuboids[c].coordinates;
    const double at = function::evaluate(m, function::posed(m, {c, static_cast<Side>(side)}, k));
    for (int s = 0; s < 6; ++s) {
        gp_Pnt centre((x[0] + x[1]) / 2, (x[2] + x[3]) / 2, (x[4] + x[5]) / 2);
        setCoord(centre, s / 2, x[s]);
        centre.Transform(motion);
        if (std::abs(coord(centre, side / 2) - at) < 1e-6) {
            gp_Vec normal(0, 0, 0);
            setCoord(normal, s / 2, s % 2 ? 1 : -1);
            normal.Transform(motion);
            if (std::abs(coord(normal, side / 2) - (side % 2 ? 1 : -1)) < 1e-9)
                return s;
        }
    }
    return -1;
}

/// Whether a rigid motion turns (a translation or none does not).
bool turns(const gp_Trsf& t)
{
    for (int r = 1; r <= 3; ++r)
        for (int c = 1; c <= 3; ++c)
            if (std::abs(t.Value(r, c) - (r == c ? 1 : 0)) > 1e-12)
                return true;
    return false;
}

/// A box's corner i (bit 0: high x, bit 1: high y, bit 2: high z).
gp_Pnt corner(const Coordinates& x, int i)
{
    return gp_Pnt(x[i & 1], x[2 + (i >> 1 & 1)], x[4 + (i >> 2)]);
}

/// A box's faces as the corner numbers round each, and its half-spaces (normal · p <= offset).
constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                              {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
using HalfSpace = std::pair<gp_Dir, double>;

/// Box x moved by t: its corners and its half-spaces.
std::pair<std::array<gp_Pnt, 8>, std::array<HalfSpace, 6>> placedBox(const Coordinates& x, const gp_Trsf& t)
{
    std::array<gp_Pnt, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[i] = corner(x, i).Transformed(t);
    std::array<HalfSpace, 6> sides;
    for (int side = 0; side < 6; ++side) {
        gp_Vec normal(0, 0, 0);
        setCoord(normal, side / 2, side % 2 ? 1 : -1);
        const gp_Dir n = gp_Dir(normal).Transformed(t);
        sides[side] = {n, gp_Vec(n).Dot(gp_Vec(corners[kFaces[side][0]].XYZ()))};
    }
    return {corners, sides};
}

/// The bounds of the part of box a inside box b, each placed: every face of each clipped by the other's
/// half-spaces (Sutherland-Hodgman); the common's corners are among what is left. Void when they only touch.
Bnd_Box common(const Coordinates& a, const gp_Trsf& ta, const Coordinates& b, const gp_Trsf& tb)
{
    const auto boxA = placedBox(a, ta), boxB = placedBox(b, tb);
    Bnd_Box bounds;
    for (const auto& [from, by] : {std::pair{&boxA, &boxB}, std::pair{&boxB, &boxA}})
        for (const auto& face : kFaces) {
            std::vector<gp_Pnt> polygon;
            for (int i : face)
                polygon.push_back(from->first[i]);
            for (const auto& [n, offset] : by->second) {
                std::vector<gp_Pnt> kept;
                for (size_t i = 0; i < polygon.size(); ++i) {
                    const gp_Pnt &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
                    const double dp = gp_Vec(n).Dot(gp_Vec(p.XYZ())) - offset,
                                 dq = gp_Vec(n).Dot(gp_Vec(q.XYZ())) - offset;
                    if (dp <= 0)
                        kept.push_back(p);
                    if ((dp < 0) != (dq < 0) && dp != 0 && dq != 0)
                        kept.push_back(p.XYZ() + (q.XYZ() - p.XYZ()) * (dp / (dp - dq)));
                }
                polygon = kept;
            }
            for (const gp_Pnt& p : polygon)
                bounds.Add(p);
        }
    if (bounds.IsVoid())
        return bounds;
    double lo[3], hi[3];
    bounds.Get(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    for (int axis = 0; axis < 3; ++axis)
        if (hi[axis] - lo[axis] < 1e-6)  // a face, an edge or a corner in common: they touch
            return Bnd_Box();
    return bounds;
}

/// The least step back of one side of box `a` (side, mm) that leaves box `b`, moved by `t` into a's frame,
/// the gap away from it; {-1, 0} when it is that far already. The part of b inside a grown by the gap is
/// found exactly; a side steps back to the gap from its nearest point.
std::pair<int, double> leastStep(const Coordinates& a, const Coordinates& b, const gp_Trsf& t, double gap)
{
    Coordinates grown = a;
    for (int i = 0; i < 6; ++i)
        grown[i] += i % 2 ? gap : -gap;
    const Bnd_Box r = common(grown, gp_Trsf(), b, t);
    if (r.IsVoid())
        return {-1, 0};
    double lo[3], hi[3];
    r.Get(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    std::pair<int, double> least{-1, 0};
    for (int side = 0; side < 6; ++side) {
        const int axis = side / 2;
        const double step = side % 2 ? a[side] - (lo[axis] - gap) : hi[axis] + gap - a[side];
        if (least.first < 0 || step < least.second)
            least = {side, step};
    }
    return least;
}

/// Near misses along the motions (4.5.3 between the poses): where a cuboid turning relative to another's
/// passes within the gap of it (an ironing board's leg frame folding on its links grazes the board), the side
/// of the one that steps (`steps`) that clears it with the least step backs off, if by at most a third of the
/// cuboid; a hinge and its base are left to the hinge (clearHingeBases).
void stepAlongMotions(const Model& m, double gap, const std::vector<int>& partOf,
                      const std::function<bool(int, int)>& steps, std::vector<std::array<double, 6>>& out)
{
    auto hingedOn = [&](int p, int base) {
        const int j = jointMoving(m, function::carrierOf(m, p));
        return j >= 0 && m.joints[j].turns() && m.joints[j].base == base;
    };
    constexpr int kSamples = 64;  // twice the clearance check's
    for (int k = 0; k < static_cast<int>(m.configurations.size()); ++k)
        for (int s = 1; s <= kSamples; ++s) {
            std::vector<gp_Trsf> motions;
            for (size_t p = 0; p < m.parts.size(); ++p)
                motions.push_back(partMotion(m, static_cast<int>(p), k, static_cast<double>(s) / kSamples));
            for (size_t a = 0; a < m.cuboids.size(); ++a)
                for (size_t b = 0; b < m.cuboids.size(); ++b) {
                    const int pa = partOf[a], pb = partOf[b];
                    if (!steps(static_cast<int>(a), static_cast<int>(b)) || m.cuboids[b].cavity() ||
                        hingedOn(pa, pb) || hingedOn(pb, pa))
                        continue;
                    const gp_Trsf relative = motions[pa].Inverted() * motions[pb];
                    if (!turns(relative))
                        continue;
                    const auto& x = m.cuboids[a].coordinates;
                    const auto [side, step] = leastStep(x, m.cuboids[b].coordinates, relative, gap);
                    if (side >= 0 && step <= (x[2 * (side / 2) + 1] - x[2 * (side / 2)]) / 3)
                        out[a][side] = std::max(out[a][side], step);
                }
        }
}

}  // namespace

std::vector<Coordinates> gapped(const Model& m, double gap)
{
    std::vector<int> partOf(m.cuboids.size());
    for (size_t p = 0; p < m.parts.size(); ++p)
        for (int c : m.parts[p].cuboids)
            partOf[c] = static_cast<int>(p);
    std::vector<int> bodyOf(m.parts.size());
    const std::vector<std::vector<int>> bodies = rigidBodies(m);
    for (size_t b = 0; b < bodies.size(); ++b)
        for (int p : bodies[b])
            bodyOf[p] = static_cast<int>(b);
    std::vector<std::array<double, 6>> steps(m.cuboids.size(), std::array<double, 6>{});
    const double hair = 1e-6;
    // Of two cuboids of different bodies, a steps back from b: from a cavity, or when it moves and b stands
    // still, or else the later one.
    auto aSteps = [&](int a, int b) {
        if (a == b || partOf[a] == partOf[b] || m.cuboids[a].cavity() ||
            bodyOf[partOf[a]] == bodyOf[partOf[b]])
            return false;  // parts that print as one body (rigidBodies) keep no gap between them
        return m.cuboids[b].cavity() ||
               (standsStill(m, partOf[a]) != standsStill(m, partOf[b]) ? !standsStill(m, partOf[a]) : a > b);
    };
    for (int k = -1; k < static_cast<int>(m.configurations.size()); ++k) {
        std::vector<Coordinates> posed(m.cuboids.size());
        for (size_t c = 0; c < m.cuboids.size(); ++c)
            posed[c] = function::posedBounds(m, static_cast<int>(c), k);
        for (size_t a = 0; a < m.cuboids.size(); ++a)
            for (size_t b = 0; b < m.cuboids.size(); ++b) {
                if (!aSteps(static_cast<int>(a), static_cast<int>(b)))
                    continue;
                const Coordinates &ca = posed[a], &cb = posed[b];
                for (int axis = 0; axis < 3; ++axis) {
                    bool overlaps = true;  // across the other two axes
                    for (int o = 0; o < 3; ++o)
                        if (o != axis)
                            overlaps = overlaps && overlapOf(along(ca, o), along(cb, o)) > hair;
                    if (!overlaps)
                        continue;
                    for (int high : {0, 1}) {
                        const int side = 2 * axis + high;
                        // Against another solid: a's side on b's opposite side; against a cavity: on its same
                        // side.
                        const int facing = m.cuboids[b].cavity() ? side : side ^ 1;
                        const bool opening =
                            m.cuboids[b].cavity() &&  // no wall there: the cavity opens
                            std::abs(m.cuboids[b].coordinates[side] -
                                     m.cuboids[m.cuboids[b].within].coordinates[side]) < hair;
                        const double apart = high ? cb[facing] - ca[side] : ca[side] - cb[facing];
                        if (apart > -hair && apart < gap - hair && !opening)
                            if (const int s = modelledSide(m, partOf[a], static_cast<int>(a), k, side);
                                s >= 0)
                                steps[a][s] = std::max(steps[a][s], gap - std::max(apart, 0.0));
                    }
                }
            }
    }
    stepAlongMotions(m, gap, partOf, aSteps, steps);
    std::vector<Coordinates> out;
    for (size_t c = 0; c < m.cuboids.size(); ++c) {
        Coordinates x = m.cuboids[c].coordinates;
        for (int s = 0; s < 6; ++s)
            x[s] += s % 2 ? -steps[c][s] : steps[c][s];
        out.push_back(x);
    }
    // Cuboids of one body stay joined: where one face stepped back further than the face glued to it, that
    // face follows (a drawer front stepping back from a door that swings past it, and its knob; a knob
    // stepping back from the shell its lever slides in, and the lever's end, which steps from nothing).
    const auto glued = [&](size_t a, size_t b, int side) {
        const Coordinates &x = m.cuboids[a].coordinates, &y = m.cuboids[b].coordinates;
        if (a == b || bodyOf[partOf[a]] != bodyOf[partOf[b]] || m.cuboids[a].cavity() ||
            m.cuboids[b].cavity() || std::abs(x[side] - y[side ^ 1]) >= hair ||
            steps[a][side] <= steps[b][side ^ 1])
            return false;
        for (int o = 0; o < 3; ++o)
            if (o != side / 2 && overlapOf(along(x, o), along(y, o)) <= hair)
                return false;
        return true;
    };
    for (size_t a = 0; a < m.cuboids.size(); ++a)
        for (size_t b = 0; b < m.cuboids.size(); ++b)
            for (int side = 0; side < 6; ++side)
                if (glued(a, b, side))
                    out[b][side ^ 1] = out[a][side];
    return out;
}

}  // namespace fabguide::printable
