#include "Function/Support.h"

#include "Function/Pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

}  // namespace

std::vector<std::pair<int, int>> inferSupportPairs(const Model& model, const std::vector<int>& supporting,
                                                   const std::vector<int>& supported, int configuration,
                                                   double distance)
{
    const double hair = 1e-6;
    std::vector<std::pair<int, int>> pairs;
    for (int p : supporting)
        for (int a : model.parts[p].cuboids) {
            if (model.cuboids[a].cavity())
                continue;
            const double top = at(model, a, Side::Top, configuration);
            std::tuple<double, double> best{std::numeric_limits<double>::max(), 0};
            int chosen = -1;
            for (int q : supported)
                for (int b : model.parts[q].cuboids) {
                    if (model.cuboids[b].cavity())
                        continue;
                    const double rise = at(model, b, Side::Bottom, configuration) - top;
                    if (rise < -hair || rise > distance)
                        continue;
                    const std::tuple<double, double> key{rise, gap(model, a, b, configuration)};
                    if (key < best) {
                        best = key;
                        chosen = b;
                    }
                }
            if (chosen >= 0)
                pairs.push_back({a, chosen});
        }
    return pairs;
}

}  // namespace fabguide::function
