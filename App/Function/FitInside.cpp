#include "Function/FitInside.h"

#include "Function/Pose.h"

#include <algorithm>
#include <limits>

namespace fabguide::function {

namespace {

double at(const Model& model, const Face& face, int configuration)
{
    return evaluate(model, posed(model, face, configuration));
}

bool isHigh(Side side)
{
    return static_cast<int>(side) % 2 == 1;
}

}  // namespace

Face extremeFace(const Model& model, int part, Side side, int configuration, const std::vector<int>& portion)
{
    const auto& cuboids = model.parts[part].cuboids;
    const bool partial = std::any_of(cuboids.begin(), cuboids.end(), [&](int c) {
        return std::find(portion.begin(), portion.end(), c) != portion.end();
    });
    Face best{cuboids.front(), side};  // the reader puts a solid cuboid first
    bool found = false;
    for (int c : cuboids) {
        if (model.cuboids[c].cavity() ||
            (partial && std::find(portion.begin(), portion.end(), c) == portion.end()))
            continue;
        const Face face{c, side};
        const double value = at(model, face, configuration), current = at(model, best, configuration);
        if (!found || (isHigh(side) ? value > current : value < current))
            best = face;
        found = true;
    }
    return best;
}

std::vector<FitInside::Apart> inferApart(const Model& model, const std::vector<int>& inner, int configuration)
{
    std::vector<FitInside::Apart> apart;
    for (size_t i = 0; i < inner.size(); ++i)
        for (size_t j = i + 1; j < inner.size(); ++j)
            for (int a : model.parts[inner[i]].cuboids)
                for (int b : model.parts[inner[j]].cuboids) {
                    if (model.cuboids[a].cavity() || model.cuboids[b].cavity())
                        continue;
                    FitInside::Apart best;
                    double widest = -std::numeric_limits<double>::max();
                    for (int axis = 0; axis < 3; ++axis) {
                        const Side low = static_cast<Side>(2 * axis), high = static_cast<Side>(2 * axis + 1);
                        const double aBelow =
                            at(model, {b, low}, configuration) - at(model, {a, high}, configuration);
                        const double bBelow =
                            at(model, {a, low}, configuration) - at(model, {b, high}, configuration);
                        if (aBelow > widest) {
                            widest = aBelow;
                            best = {a, b, axis};
                        }
                        if (bBelow > widest) {
                            widest = bBelow;
                            best = {b, a, axis};
                        }
                    }
                    apart.push_back(best);
                }
    return apart;
}

Face wall(const Model& model, int enclosing, int cavity, Side side, int configuration)
{
    return cavity >= 0 ? Face{cavity, side} : extremeFace(model, enclosing, side, configuration);
}

std::vector<std::pair<Face, Face>> inferJust(const Model& model, const FitInside& f,
                                             const std::vector<int>& inner, const std::vector<int>& axes)
{
    std::vector<std::pair<Face, Face>> just;
    const int k = f.configuration;
    for (int axis : axes)
        for (Side side : {static_cast<Side>(2 * axis), static_cast<Side>(2 * axis + 1)}) {
            Face extreme = extremeFace(model, inner.front(), side, k, f.portion);
            for (int part : inner) {
                const Face face = extremeFace(model, part, side, k, f.portion);
                const double value = at(model, face, k), current = at(model, extreme, k);
                if (isHigh(side) ? value > current : value < current)
                    extreme = face;
            }
            just.push_back({extreme, wall(model, f.enclosing, f.cavity, side, k)});
        }
    return just;
}

}  // namespace fabguide::function
