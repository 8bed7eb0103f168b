#include "Function/Cover.h"

#include "Function/Pose.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace fabguide::function {

namespace {

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

/// A covering face and a covered face that face each other, overlapping by half the smaller face, `gap`
/// apart.
struct Candidate {
    Face covering, covered;
    double gap = 0;
    bool opening = false;
};

/// Whether a face is at least half as large as its cuboid's largest: a door's front or back, a lid's top or
/// bottom, not the edge of a board, which covers nothing.
bool broad(const Model& model, const Face& f, int configuration)
{
    double area[3];
    for (int n = 0; n < 3; ++n)
        area[n] = extent(model, f, (n + 1) % 3, configuration) * extent(model, f, (n + 2) % 3, configuration);
    return 2 * area[axisOf(f.side)] >= std::max({area[0], area[1], area[2]});
}

std::vector<Candidate> candidates(const Model& model, const std::vector<int>& covering,
                                  const std::vector<int>& covered, int configuration)
{
    std::vector<Candidate> found;
    for (int p : covering)
        for (int a : model.parts[p].cuboids)
            for (int sa = 0; sa < 6 && !model.cuboids[a].cavity(); ++sa)
                if (broad(model, Face{a, static_cast<Side>(sa)}, configuration))
                    for (int q : covered)
                        for (int b : model.parts[q].cuboids) {
                            const bool cavity = model.cuboids[b].cavity();
                            if (cavity && !isOpening(model, b, sa ^ 1))
                                continue;
                            const Face fa{a, static_cast<Side>(sa)},
                                fb{b, static_cast<Side>(sa ^ 1)};  // facing
                            const int n = sa / 2, u = (n + 1) % 3, v = (n + 2) % 3;
                            const double ou = overlap(model, fa, fb, u, configuration),
                                         ov = overlap(model, fa, fb, v, configuration);
                            const double smaller = std::min(
                                extent(model, fa, u, configuration) * extent(model, fa, v, configuration),
                                extent(model, fb, u, configuration) * extent(model, fb, v, configuration));
                            if (ou > 0 && ov > 0 && ou * ov > smaller / 2)
                                found.push_back({fa, fb,
                                                 std::abs(at(model, a, sa, configuration) -
                                                          at(model, b, sa ^ 1, configuration)),
                                                 cavity});
                        }
    return found;
}

/// The links of one covering face within `distance`: to openings if it has any, else to solids.
void link(const std::vector<Candidate>& all, const Face& face, double distance,
          std::vector<std::pair<Face, Face>>& pairs)
{
    for (bool openings : {true, false}) {
        for (const Candidate& c : all)
            if (c.covering == face && c.opening == openings && c.gap <= distance)
                pairs.push_back({c.covering, c.covered});
        if (!pairs.empty() && pairs.back().first == face)
            return;
    }
}

}  // namespace

InferredCover inferCover(const Model& model, const std::vector<int>& covering,
                         const std::vector<int>& covered, int configuration, double distance)
{
    const std::vector<Candidate> all = candidates(model, covering, covered, configuration);
    InferredCover result;
    std::vector<Face> faces;
    for (const Candidate& c : all)
        if (std::find(faces.begin(), faces.end(), c.covering) == faces.end())
            faces.push_back(c.covering);
    for (const Face& f : faces)
        link(all, f, distance, result.pairs);
    // Every part named takes part: one left out is linked by its nearest candidate, and noted.
    auto linked = [&](int part, bool isCovering) {
        return std::any_of(result.pairs.begin(), result.pairs.end(), [&](const auto& pair) {
            return partOf(model, (isCovering ? pair.first : pair.second).cuboid) == part;
        });
    };
    for (bool isCovering : {true, false})
        for (int part : isCovering ? covering : covered) {
            if (linked(part, isCovering))
                continue;
            const Candidate* nearest = nullptr;
            for (const Candidate& c : all)
                if (partOf(model, (isCovering ? c.covering : c.covered).cuboid) == part &&
                    (!nearest || c.gap < nearest->gap || (c.gap == nearest->gap && c.opening)))
                    nearest = &c;
            if (!nearest) {
                result.unlinked.push_back(part);
                continue;
            }
            result.pairs.push_back({nearest->covering, nearest->covered});
            result.notes.push_back(model.parts[part].name + ": " + millimetres(nearest->gap) + " mm from " +
                                   faceName(model, isCovering ? nearest->covered : nearest->covering) +
                                   ", beyond the " + millimetres(distance) +
                                   " mm face distance; linked to it");
        }
    return result;
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

Packing packing(const Model& model, const std::vector<Face>& faces, int configuration, double align)
{
    Packing result;
    const int n = axisOf(faces.front().side);
    const size_t count = faces.size();
    for (int k : {(n + 1) % 3, (n + 2) % 3}) {
        const int other = 3 - n - k;
        // a before b along k: side by side (overlapping across k by half the narrower, not a few millimetres
        // of a rough drawing), overlapping less along k, a's centre first.
        auto before = [&](size_t a, size_t b) {
            const double across = overlap(model, faces[a], faces[b], other, configuration);
            const double narrower = std::min(extent(model, faces[a], other, configuration),
                                             extent(model, faces[b], other, configuration));
            return a != b && across > std::max(model.minimumSize, narrower / 2) &&
                   overlap(model, faces[a], faces[b], k, configuration) < across &&
                   centre(model, faces[a], k, configuration) < centre(model, faces[b], k, configuration);
        };
        // Every two faces with none between them meet (a wide drawer front over two doors meets both), and
        // their sides across that lie within `align` of each other line up (seams drawn a few mm apart are
        // one seam, which leaves no hole at a four-way corner); a face with none before (after) it is at that
        // end.
        std::vector<std::vector<bool>> order(count, std::vector<bool>(count));
        for (size_t a = 0; a < count; ++a)
            for (size_t b = 0; b < count; ++b)
                order[a][b] = before(a, b);
        for (size_t f = 0; f < count; ++f) {
            bool hasPrevious = false, hasNext = false;
            for (size_t g = 0; g < count; ++g) {
                hasPrevious = hasPrevious || order[g][f];
                hasNext = hasNext || order[f][g];
                bool between = false;
                for (size_t c = 0; c < count && order[f][g] && !between; ++c)
                    between = order[f][c] && order[c][g];
                if (!order[f][g] || between)
                    continue;
                result.neighbours.push_back({faces[f], faces[g], k});
                for (int side : {2 * other, 2 * other + 1})
                    if (std::abs(at(model, faces[f].cuboid, side, configuration) -
                                 at(model, faces[g].cuboid, side, configuration)) <= align)
                        result.aligned.push_back({Face{faces[f].cuboid, static_cast<Side>(side)},
                                                  Face{faces[g].cuboid, static_cast<Side>(side)}});
            }
            if (!hasPrevious)
                result.ends[2 * k].push_back(faces[f]);
            if (!hasNext)
                result.ends[2 * k + 1].push_back(faces[f]);
        }
    }
    return result;
}

}  // namespace fabguide::function
