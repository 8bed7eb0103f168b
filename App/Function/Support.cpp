#include "Function/Support.h"

#include "Function/Pose.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>

namespace fabguide::function {

namespace {

double at(const Model& model, int cuboid, Side side, int configuration)
{
    return evaluate(model, posed(model, Face{cuboid, side}, configuration));
}

/// Horizontal gap between two cuboids' footprints (0 when they overlap).
double gap(const Model& model, int a, int b, int configuration)
{
    double squared = 0;
    for (const auto& [low, high] : {std::pair{Side::Left, Side::Right}, std::pair{Side::Near, Side::Far}}) {
        const double d = std::max(at(model, a, low, configuration) - at(model, b, high, configuration),
                                  at(model, b, low, configuration) - at(model, a, high, configuration));
        if (d > 0)
            squared += d * d;
    }
    return std::sqrt(squared);
}

struct Candidate {
    int a = 0, b = 0;
    double rise = 0, gap = 0;  ///< b's bottom above a's top; footprints apart
    bool operator<(const Candidate& other) const
    {
        return std::tuple{std::abs(rise), gap} < std::tuple{std::abs(other.rise), other.gap};
    }
};

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
                    const double bottom = at(model, b, Side::Bottom, configuration);
                    const double rise = bottom - at(model, a, Side::Top, configuration);
                    if (rise >= -(at(model, b, Side::Top, configuration) - bottom) / 2)
                        found.push_back({a, b, rise, gap(model, a, b, configuration)});
                }
    return found;
}

std::string show(double mm)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", mm);
    return text;
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
            result.notes.push_back(model.parts[part].name + ": " + show(std::abs(best->rise)) + " mm " +
                                   (best->rise > 0 ? "below " : "into ") +
                                   faceName(model, {best->b, Side::Bottom}) + ", beyond the " +
                                   show(distance) + " mm support distance; linked to it");
        }
    return result;
}

}  // namespace fabguide::function
