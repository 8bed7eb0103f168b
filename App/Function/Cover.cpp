#include "Function/Cover.h"

#include "Function/Pose.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace fabguide::function {

namespace {

int axisOf(Side side)
{
    return static_cast<int>(side) / 2;
}

double at(const Model& model, int cuboid, int side, int configuration)
{
    return evaluate(model, posed(model, Face{cuboid, static_cast<Side>(side)}, configuration));
}

/// How far two faces' extents along an axis overlap (negative: the gap between them).
double overlap(const Model& model, const Face& a, const Face& b, int axis, int configuration)
{
    return std::min(at(model, a.cuboid, 2 * axis + 1, configuration),
                    at(model, b.cuboid, 2 * axis + 1, configuration)) -
           std::max(at(model, a.cuboid, 2 * axis, configuration),
                    at(model, b.cuboid, 2 * axis, configuration));
}

double extent(const Model& model, const Face& f, int axis, int configuration)
{
    return at(model, f.cuboid, 2 * axis + 1, configuration) - at(model, f.cuboid, 2 * axis, configuration);
}

double centre(const Model& model, const Face& f, int axis, int configuration)
{
    return (at(model, f.cuboid, 2 * axis + 1, configuration) + at(model, f.cuboid, 2 * axis, configuration)) /
           2;
}

/// Whether a cavity's side lies on its solid's same side: an opening, which can be covered.
bool opening(const Model& model, int cavity, int side)
{
    const Cuboid& c = model.cuboids[cavity];
    return std::abs(c.coordinates[side] - model.cuboids[c.within].coordinates[side]) < 1e-6;
}

}  // namespace

std::vector<std::pair<Face, Face>> inferCoverPairs(const Model& model, const std::vector<int>& covering,
                                                   const std::vector<int>& covered, int configuration,
                                                   double distance)
{
    std::vector<std::pair<Face, Face>> pairs;
    for (int p : covering)
        for (int a : model.parts[p].cuboids)
            for (int sa = 0; sa < 6 && !model.cuboids[a].cavity(); ++sa)
                for (bool cavities : {true, false})  // an opening first: then not the wall around it
                    for (int q : covered)
                        for (int b : model.parts[q].cuboids) {
                            if (model.cuboids[b].cavity() != cavities ||
                                (cavities && !opening(model, b, sa ^ 1)) ||
                                (!cavities && !pairs.empty() &&
                                 pairs.back().first == Face{a, static_cast<Side>(sa)}))
                                continue;
                            const Face fa{a, static_cast<Side>(sa)},
                                fb{b, static_cast<Side>(sa ^ 1)};  // facing
                            const int n = sa / 2, u = (n + 1) % 3, v = (n + 2) % 3;

                            const double gap = std::abs(at(model, a, sa, configuration) -
                                                        at(model, b, sa ^ 1, configuration));
                            const double ou = overlap(model, fa, fb, u, configuration),
                                         ov = overlap(model, fa, fb, v, configuration);
                            const double smaller = std::min(
                                extent(model, fa, u, configuration) * extent(model, fa, v, configuration),
                                extent(model, fb, u, configuration) * extent(model, fb, v, configuration));
                            if (gap <= distance && ou > 0 && ov > 0 && ou * ov > smaller / 2)
                                pairs.push_back({fa, fb});
                        }
    return pairs;
}

std::vector<CoverComponent> components(const std::vector<std::pair<Face, Face>>& pairs)
{
    std::map<Face, Face> parent;  // union-find over the faces of M
    auto root = [&](Face f) {
        while (parent.count(f) && !(parent.at(f) == f))
            f = parent.at(f);
        return f;
    };
    for (const auto& [a, b] : pairs) {
        parent.emplace(a, a);
        parent.emplace(b, b);
        parent[root(b)] = root(a);
    }
    std::vector<CoverComponent> result;
    std::map<Face, size_t> index;
    auto add = [&](const Face& f, bool covering) {
        const Face r = root(f);
        if (!index.count(r)) {
            index[r] = result.size();
            result.emplace_back();
        }
        auto& list = covering ? result[index[r]].covering : result[index[r]].covered;
        if (std::find(list.begin(), list.end(), f) == list.end())
            list.push_back(f);
    };
    for (const auto& [a, b] : pairs) {
        add(a, true);
        add(b, false);
    }
    return result;
}

Packing packing(const Model& model, const std::vector<Face>& faces, int configuration)
{
    Packing result;
    const int n = axisOf(faces.front().side);
    const double threshold = model.minimumSize;  // overlaps below it do not order two faces
    for (int k : {(n + 1) % 3, (n + 2) % 3}) {
        const int other = 3 - n - k;
        // b's predecessors along k: faces that overlap it across k, more than along k, and lie before it.
        std::vector<bool> first(faces.size(), true), last(faces.size(), true);
        for (size_t b = 0; b < faces.size(); ++b) {
            int nearest = -1;
            for (size_t a = 0; a < faces.size(); ++a) {
                const double across = overlap(model, faces[a], faces[b], other, configuration);
                if (a == b || across <= threshold ||
                    overlap(model, faces[a], faces[b], k, configuration) >= across ||
                    centre(model, faces[a], k, configuration) >= centre(model, faces[b], k, configuration))
                    continue;
                if (nearest < 0 || centre(model, faces[a], k, configuration) >
                                       centre(model, faces[nearest], k, configuration))
                    nearest = static_cast<int>(a);
            }
            if (nearest >= 0) {
                result.neighbours.push_back({faces[nearest], faces[b], k});
                first[b] = false;
                last[nearest] = false;
            }
        }
        for (size_t f = 0; f < faces.size(); ++f) {
            if (first[f])
                result.ends[2 * k].push_back(faces[f]);
            if (last[f])
                result.ends[2 * k + 1].push_back(faces[f]);
        }
    }
    return result;
}

}  // namespace fabguide::function
