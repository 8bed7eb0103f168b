#include "Function/Separation.h"

#include "Function/Pose.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

namespace fabguide::function {

namespace {

using Box = std::array<double, 6>;  ///< by Side

Box boxOf(const Model& model, int cuboid, int configuration)
{
    Box box{};
    for (int k = 0; k < 6; ++k)
        box[k] = evaluate(model, posed(model, Face{cuboid, static_cast<Side>(k)}, configuration));
    return box;
}

/// The pairs of parts that a fit inside lets overlap: its inner parts and the enclosing part.
std::set<std::pair<int, int>> fitting(const Model& model)
{
    std::set<std::pair<int, int>> pairs;
    for (const FitInside& f : model.fitInside)
        for (int p : f.inner)
            pairs.insert(std::minmax(p, f.enclosing));
    return pairs;
}

/// How far `inner` reaches out of cavity c on the sides that are not openings.
double outside(const Model& model, const Box& inner, int cavity, int configuration)
{
    const Box c = boxOf(model, cavity, configuration);
    double total = 0;
    for (int k = 0; k < 6; ++k)
        if (!isOpening(model, cavity, k))
            total += std::max(0.0, k % 2 ? inner[k] - c[k] : c[k] - inner[k]);
    return total;
}

bool overlaps(const Box& a, const Box& b)
{
    for (int axis = 0; axis < 3; ++axis)
        if (std::min(a[2 * axis + 1], b[2 * axis + 1]) <= std::max(a[2 * axis], b[2 * axis]))
            return false;
    return true;
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
    const std::set<std::pair<int, int>> exempt = fitting(model);
    std::vector<std::pair<int, int>> pairs;
    for (size_t i = 0; i < solids.size(); ++i)
        for (size_t k = i + 1; k < solids.size() && boxes[solids[k]][0] < boxes[solids[i]][1] + margin; ++k) {
            const int a = solids[i], b = solids[k];
            const int pa = partOf(model, a), pb = partOf(model, b);
            bool near = pa != pb && !exempt.count(std::minmax(pa, pb));
            for (int axis = 1; axis < 3 && near; ++axis)
                near = std::min(boxes[a][2 * axis + 1], boxes[b][2 * axis + 1]) -
                           std::max(boxes[a][2 * axis], boxes[b][2 * axis]) >
                       -margin;
            if (near)
                pairs.push_back(std::minmax(a, b));
        }
    return pairs;
}

bool inferSeparation(const Model& drawn, int a, int b, int configuration, Separation& separation)
{
    const Box boxA = boxOf(drawn, a, configuration), boxB = boxOf(drawn, b, configuration);
    // Apart along an axis: the order that overlaps least (4.3.2's farthest apart).
    double least = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis)
        for (bool aFirst : {true, false}) {
            const Box& low = aFirst ? boxA : boxB;
            const Box& high = aFirst ? boxB : boxA;
            if (const double overlap = low[2 * axis + 1] - high[2 * axis]; overlap < least) {
                least = overlap;
                separation = {aFirst ? a : b, aFirst ? b : a, axis, -1, configuration};
            }
        }
    const bool exact = exactlyPosed(drawn, partOf(drawn, a), configuration) &&
                       exactlyPosed(drawn, partOf(drawn, b), configuration);
    if (!exact)
        return least <= 0;
    // Or inside a cavity of the other's cuboid, if that changes less (a drawer in its compartment).
    double cost = std::max(0.0, least);
    for (const auto& [held, holder] : {std::pair{a, b}, std::pair{b, a}}) {
        const Box box = held == a ? boxA : boxB;
        for (int c = 0; c < static_cast<int>(drawn.cuboids.size()); ++c)
            if (drawn.cuboids[c].within == holder && overlaps(box, boxOf(drawn, c, configuration)))
                if (const double change = outside(drawn, box, c, configuration); change < cost) {
                    cost = change;
                    separation = {held, holder, 0, c, configuration};
                }
    }
    return true;
}

std::string separationName(const Model& model, const Separation& separation)
{
    const int a = partOf(model, separation.a), b = partOf(model, separation.b);
    return "no overlap: " + model.parts[std::min(a, b)].name + ", " + model.parts[std::max(a, b)].name;
}

}  // namespace fabguide::function
