#include "Function/Support.h"

#include "Function/Pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

namespace fabguide::function {

namespace {

double at(const Model& model, int cuboid, Side side, int configuration)
{
    return evaluate(model, posed(model, Face{cuboid, side}, configuration));
}

struct Candidate {
    int a = 0, b = 0;
    double rise = 0;     ///< b's bottom above a's top
    double gap = 0;      ///< between the footprints (0 when they overlap)
    bool above = false;  ///< the footprints overlap by more than half the smaller one
    /// Nearer: right above first, then nearest vertically, then horizontally.
    bool operator<(const Candidate& other) const
    {
        return std::tuple{!above, std::abs(rise), gap} <
               std::tuple{!other.above, std::abs(other.rise), other.gap};
    }
};

Candidate candidate(const Model& model, int a, int b, int configuration)
{
    Candidate c{a, b, at(model, b, Side::Bottom, configuration) - at(model, a, Side::Top, configuration)};
    double squared = 0, shared = 1, areaA = 1, areaB = 1;
    for (const auto& [low, high] : {std::pair{Side::Left, Side::Right}, std::pair{Side::Near, Side::Far}}) {
        const double aLow = at(model, a, low, configuration), aHigh = at(model, a, high, configuration),
                     bLow = at(model, b, low, configuration), bHigh = at(model, b, high, configuration);
        const double d = std::max(aLow - bHigh, bLow - aHigh);
        squared += d > 0 ? d * d : 0;
        shared *= std::max(0.0, -d);
        areaA *= aHigh - aLow;
        areaB *= bHigh - bLow;
    }
    c.gap = std::sqrt(squared);
    c.above = shared > std::min(areaA, areaB) / 2;
    return c;
}

std::vector<Candidate> candidates(const Model& model, const std::vector<int>& supporting,
                                  const std::vector<int>& supported, int configuration)
{
    std::vector<Candidate> found;
    for (int p : supporting)
        for (int a : model.parts[p].cuboids)
            for (int q : supported)
                for (int b : model.parts[q].cuboids) {
                    if (model.cuboids[a].cavity() || model.cuboids[b].cavity())
                        continue;
                    const Candidate c = candidate(model, a, b, configuration);
                    const double height =
                        at(model, b, Side::Top, configuration) - at(model, b, Side::Bottom, configuration);
                    if (c.rise >= -height / 2)
                        found.push_back(c);
                }
    return found;
}

}  // namespace

InferredSupport inferSupport(const Model& model, const std::vector<int>& supporting,
                             const std::vector<int>& supported, int configuration, double distance)
{
    const std::vector<Candidate> all = candidates(model, supporting, supported, configuration);
    InferredSupport result;
    for (int p : supporting)
        for (int a : model.parts[p].cuboids) {
            const Candidate* best = nullptr;
            for (const Candidate& c : all)
                if (c.a == a && std::abs(c.rise) <= distance && (!best || c < *best))
                    best = &c;
            if (best)
                result.pairs.push_back({best->a, best->b});
        }
    // Every part named takes part: one left out is linked by its nearest pair, and noted.
    for (bool isSupporting : {true, false})
        for (int part : isSupporting ? supporting : supported) {
            auto mine = [&](int a, int b) { return partOf(model, isSupporting ? a : b) == part; };
            if (std::any_of(result.pairs.begin(), result.pairs.end(),
                            [&](const auto& pair) { return mine(pair.first, pair.second); }))
                continue;
            const Candidate* best = nullptr;
            for (const Candidate& c : all)
                if (mine(c.a, c.b) && (!best || c < *best))
                    best = &c;
            if (!best) {
                result.unlinked.push_back(part);
                continue;
            }
            result.pairs.push_back({best->a, best->b});
            const bool beyond = std::abs(best->rise) > distance;
            result.notes.push_back(model.parts[part].name + ": " + millimetres(std::abs(best->rise)) +
                                   " mm " +
                                   (isSupporting ? (best->rise > 0 ? "below " : "into ")
                                                 : (best->rise > 0 ? "above " : "sunk by ")) +
                                   (isSupporting ? faceName(model, {best->b, Side::Bottom})
                                                 : faceName(model, {best->a, Side::Top})) +
                                   (beyond ? ", beyond the " + millimetres(distance) + " mm support distance"
                                           : ", its faces nearer to others") +
                                   "; linked to it");
        }
    return result;
}

}  // namespace fabguide::function
