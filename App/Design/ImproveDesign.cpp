#include "Design/ImproveDesign.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>

namespace fabguide::material {

namespace {

/// X with its part sizes laid out by `layOut(sizes)`, and the wastage of that layout.
template <typename LayOut>
DesignLayout laidOut(const Explorer& explorer, const Eigen::VectorXd& X, LayOut&& layOut)
{
    Eigen::VectorXd sizes = explorer.design.sizes(X);
    GridLayout layout = layOut(sizes);
    return designLayout(explorer.material, X, std::move(sizes), std::move(layout));
}

}  // namespace

DesignLayout designLayout(const MaterialSpace& material, const Eigen::VectorXd& X, Eigen::VectorXd sizes,
                          GridLayout layout)
{
    const double wastage = material.wastage(layout, sizes);
    const MaterialSpace::Figures figures = material.figures(layout, sizes);
    return {X, std::move(sizes), std::move(layout), wastage, figures};
}

DesignLayout Explorer::docked(const Eigen::VectorXd& X) const
{
    return laidOut(*this, X, [&](const Eigen::VectorXd& sizes) { return material.dock(sizes, order); });
}

DesignLayout Explorer::slid(const DesignLayout& from, const Eigen::VectorXd& X) const
{
    return laidOut(*this, X,
                   [&](const Eigen::VectorXd& sizes) { return material.slide(from.layout, sizes); });
}

namespace {

/// One cell more (or less) of part size `size`, through CHANGEPARTSIZE.
std::optional<Eigen::VectorXd> changePartSize(const Explorer& explorer, const Eigen::VectorXd& X, int size,
                                              double cells)
{
    Eigen::VectorXd change =
        Eigen::VectorXd::Zero(2 * static_cast<Eigen::Index>(explorer.design.parts().size()));
    change[size] = cells * explorer.material.resolution();
    return explorer.design.changePartSizes(X, change, explorer.until());
}

}  // namespace

constexpr size_t kSubset = 24;  // part sizes grown per pass: every size of a 12-part design

void growParts(Explorer& explorer, DesignLayout& best, DesignLayout& current)
{
    std::vector<int> all(2 * explorer.design.parts().size());
    std::iota(all.begin(), all.end(), 0);
    for (bool improvement = true; improvement && !explorer.stopped();) {
        improvement = false;
        std::shuffle(all.begin(), all.end(), explorer.random);
        // A large design is explored a subset of its sizes at a time (thesis 5.5.4's proposal): each pass
        // grows a random 24, so a 60-board design changes within a time limit of seconds.
        const std::vector<int> sizes(all.begin(), all.begin() + std::min<size_t>(all.size(), kSubset));
        for (int size : sizes) {
            if (explorer.stopped())
                return;
            // Grow once, then on while the score drops (lines 5-15); keep the least-score growth.
            std::optional<DesignLayout> grown;
            for (DesignLayout at = current; !explorer.stopped();) {
                const auto X = changePartSize(explorer, at.X, size, +1);
                if (!X)
                    break;
                DesignLayout next = explorer.slid(at, *X);
                if (grown ? next.score() > grown->score() : std::isinf(next.score()))
                    next = explorer.docked(*X);  // sliding lost (or failed): dock again (line 11)
                if (grown && next.score() >= grown->score())
                    break;
                grown = next;
                at = std::move(next);
            }
            if (grown && grown->score() < current.score()) {
                current = std::move(*grown);
                improvement = true;
                if (current.score() < best.score()) {
                    best = current;
                    explorer.improved(best);
                }
            }
        }
    }
}

namespace {

/// A unit's cells on its sheet.
struct Box {
    int sheet;
    int at[2];
    int length[2];
    int rotation;
};

std::vector<Box> boxesOf(const Explorer& explorer, const DesignLayout& d)
{
    const RasterProblem units = explorer.material.raster(d.sizes);
    std::vector<Box> boxes(units.parts.size());
    for (const Placed& p : d.layout.placed) {
        const RasterPart& unit = units.parts[p.part];
        boxes[p.part] = {p.sheet,
                         {p.x, p.y},
                         {unit.shapes[p.shape].width(), unit.shapes[p.shape].height()},
                         unit.rotations[p.shape]};
    }
    return boxes;
}

/// FORMCONTACTCHAINS along `axis`: from units touching the far border of their sheet's layout, through units
/// touching each other, to the near border; each chain as the part sizes along `axis`.
void lockingChains(const Explorer& explorer, const DesignLayout& d, int axis,
                   std::vector<std::vector<int>>& chains)
{
    constexpr size_t kMostChains = 512;
    const std::vector<Box> boxes = boxesOf(explorer, d);
    const int other = 1 - axis;
    const auto touchesBefore = [&](const Box& u, const Box& v) {  // v ends where u starts, side by side
        return u.sheet == v.sheet && v.at[axis] + v.length[axis] == u.at[axis] &&
               v.at[other] < u.at[other] + u.length[other] && u.at[other] < v.at[other] + v.length[other];
    };
    std::vector<int> chain;
    const auto extend = [&](auto&& self, int unit) -> void {
        if (chains.size() >= kMostChains)
            return;
        chain.push_back(explorer.material.sizeAlong(unit, boxes[unit].rotation, axis));
        if (boxes[unit].at[axis] == 0)
            chains.push_back(chain);
        for (int v = 0; v < static_cast<int>(boxes.size()); ++v)
            if (touchesBefore(boxes[unit], boxes[v]))
                self(self, v);
        chain.pop_back();
    };
    for (int u = 0; u < static_cast<int>(boxes.size()); ++u) {
        const Box& b = boxes[u];
        const int used = axis == 0 ? d.layout.usedWidth[b.sheet] : d.layout.usedHeight[b.sheet];
        if (b.at[axis] + b.length[axis] == used)
            extend(extend, u);
    }
}

}  // namespace

namespace {

/// DRAWPARTSIZEWITHPROBABILITY: a number of occurrences o with P(o) ∝ Σ occ of the sizes occurring o times,
/// then among those sizes one with P(s | o) ∝ 1 - dep(s) / Σ dep.
int drawPartSize(const std::map<int, int>& occurrences, const std::map<int, int>& dependence,
                 std::mt19937_64& random)
{
    std::map<int, double> weightOf;
    for (const auto& [size, occ] : occurrences)
        weightOf[occ] += occ;
    std::vector<int> counts;
    std::vector<double> weights;
    for (const auto& [occ, weight] : weightOf) {
        counts.push_back(occ);
        weights.push_back(weight);
    }
    const int o = counts[std::discrete_distribution<int>(weights.begin(), weights.end())(random)];
    std::vector<int> candidates;
    double depSum = 0;
    for (const auto& [size, occ] : occurrences)
        if (occ == o) {
            candidates.push_back(size);
            depSum += dependence.at(size);
        }
    std::vector<double> p;
    for (int size : candidates)
        p.push_back(candidates.size() == 1 || depSum == 0 ? 1.0 : 1.0 - dependence.at(size) / depSum);
    return candidates[std::discrete_distribution<int>(p.begin(), p.end())(random)];
}

}  // namespace

std::vector<int> selectPartSizesToShrink(Explorer& explorer, const DesignLayout& best)
{
    if (!best.layout.unplaced.empty())
        return {};
    std::vector<std::vector<int>> chains;
    for (int axis : {0, 1})
        lockingChains(explorer, best, axis, chains);

    // dep(s): how many part sizes shrinking s changes; sizes that cannot shrink are never drawn.
    std::map<int, int> dependence;
    std::set<int> unshrinkable;
    for (const auto& chain : chains)
        for (int size : chain) {
            if (explorer.stopped())
                return {};  // each test is a correction (a QR): a large design has hundreds
            if (dependence.count(size) || unshrinkable.count(size))
                continue;
            if (const auto X = changePartSize(explorer, best.X, size, -1)) {
                const Eigen::VectorXd change = explorer.design.sizes(*X) - best.sizes;
                dependence[size] = static_cast<int>((change.array().abs() > 1e-9).count());
            } else {
                unshrinkable.insert(size);
            }
        }

    std::vector<int> chosen;
    while (!chains.empty()) {
        std::map<int, int> occurrences;
        for (const auto& chain : chains)
            for (int size : std::set<int>(chain.begin(), chain.end()))
                if (dependence.count(size))
                    ++occurrences[size];
        if (occurrences.empty())
            break;  // what is left cannot be broken
        const int size = drawPartSize(occurrences, dependence, explorer.random);
        chosen.push_back(size);
        // KILLEDCHAINS: every chain the size is in.
        chains.erase(std::remove_if(chains.begin(), chains.end(),
                                    [&](const std::vector<int>& c) {
                                        return std::find(c.begin(), c.end(), size) != c.end();
                                    }),
                     chains.end());
    }
    return chosen;
}

namespace {

/// The baseline of thesis Fig. 5.20: one to three part sizes drawn at random.
std::vector<int> randomSizes(Explorer& explorer, const DesignLayout& best)
{
    std::vector<int> sizes(best.sizes.size());
    std::iota(sizes.begin(), sizes.end(), 0);
    std::shuffle(sizes.begin(), sizes.end(), explorer.random);
    sizes.resize(
        std::min<size_t>(sizes.size(), std::uniform_int_distribution<size_t>(1, 3)(explorer.random)));
    return sizes;
}

}  // namespace

DesignLayout improveDesign(Explorer& explorer, const DesignLayout& start, int iterations)
{
    DesignLayout best = start, current = start;
    for (int i = 0; i < iterations && !explorer.stopped(); ++i) {
        growParts(explorer, best, current);
        // SHRINKPARTS (Algorithm 11): one cell off each chosen size at once.
        const std::vector<int> shrink =
            explorer.guided ? selectPartSizesToShrink(explorer, best) : randomSizes(explorer, best);
        if (shrink.empty())
            break;
        Eigen::VectorXd change = Eigen::VectorXd::Zero(best.sizes.size());
        for (int size : shrink)
            change[size] = -explorer.material.resolution();
        const auto X = explorer.design.changePartSizes(best.X, change, explorer.until());
        if (!X)
            break;
        current = explorer.slid(best, *X);
        if (std::isinf(current.score()))
            current = explorer.docked(*X);
        if (current.score() < best.score()) {
            best = current;
            explorer.improved(best);
        }
    }
    return best;
}

}  // namespace fabguide::material
