#include "Printable/Gaps.h"

#include "Function/Pose.h"
#include "Printable/Motion.h"

#include <algorithm>
#include <cmath>

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
        centre.SetCoord(s / 2 + 1, x[s]);
        centre.Transform(motion);
        if (std::abs(centre.Coord(side / 2 + 1) - at) < 1e-6) {
            gp_Vec normal(0, 0, 0);
            normal.SetCoord(s / 2 + 1, s % 2 ? 1 : -1);
            normal.Transform(motion);
            if (std::abs(normal.Coord(side / 2 + 1) - (side % 2 ? 1 : -1)) < 1e-9)
                return s;
        }
    }
    return -1;
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
    for (int k = -1; k < static_cast<int>(m.configurations.size()); ++k) {
        std::vector<Coordinates> posed(m.cuboids.size());
        for (size_t c = 0; c < m.cuboids.size(); ++c)
            for (int s = 0; s < 6; ++s)
                posed[c][s] =
                    function::evaluate(m, function::posed(m, {static_cast<int>(c), static_cast<Side>(s)}, k));
        for (size_t a = 0; a < m.cuboids.size(); ++a)
            for (size_t b = 0; b < m.cuboids.size(); ++b) {
                if (a == b || partOf[a] == partOf[b] || m.cuboids[a].cavity() ||
                    bodyOf[partOf[a]] == bodyOf[partOf[b]])
                    continue;  // parts that print as one body (rigidBodies) keep no gap between them
                const Coordinates &ca = posed[a], &cb = posed[b];
                const bool aSteps =
                    m.cuboids[b].cavity() ||
                    (standsStill(m, partOf[a]) != standsStill(m, partOf[b]) ? !standsStill(m, partOf[a])
                                                                            : a > b);
                if (!aSteps)
                    continue;
                for (int axis = 0; axis < 3; ++axis) {
                    bool overlaps = true;  // across the other two axes
                    for (int o = 0; o < 3; ++o)
                        if (o != axis)
                            overlaps = overlaps && std::min(ca[2 * o + 1], cb[2 * o + 1]) -
                                                           std::max(ca[2 * o], cb[2 * o]) >
                                                       hair;
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
    std::vector<Coordinates> out;
    for (size_t c = 0; c < m.cuboids.size(); ++c) {
        Coordinates x = m.cuboids[c].coordinates;
        for (int s = 0; s < 6; ++s)
            x[s] += s % 2 ? -steps[c][s] : steps[c][s];
        out.push_back(x);
    }
    // Cuboids of one part stay joined: where one face stepped back, the cuboid glued to it follows.
    for (size_t a = 0; a < m.cuboids.size(); ++a)
        for (size_t b = 0; b < m.cuboids.size(); ++b)
            for (int side = 0; side < 6 && a != b && partOf[a] == partOf[b] && !m.cuboids[a].cavity() &&
                               !m.cuboids[b].cavity();
                 ++side)
                if (std::abs(m.cuboids[a].coordinates[side] - m.cuboids[b].coordinates[side ^ 1]) < hair)
                    out[b][side ^ 1] = out[a][side];
    return out;
}

}  // namespace fabguide::printable
