#include "Layout/OrderingSearch.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <numeric>
#include <random>
#include <tuple>

namespace fabguide::material {

LayoutCost cost(const GridLayout& layout, const std::vector<BoardStock>& stock, Bounds bounds)
{
    LayoutCost total{static_cast<int>(layout.unplaced.size()), 0, static_cast<int>(layout.stock.size()), 0,
                     0};
    for (size_t s = 0; s < layout.stock.size(); ++s) {
        total.sheetCost += stock[layout.stock[s]].cost;
        const long width = bounds == Bounds::Strip ? stock[layout.stock[s]].width : layout.usedWidth[s];
        total.boundingArea += width * layout.usedHeight[s];
        total.skylineArea += layout.skylineArea[s];
    }
    return total;
}

double secondsUntil(std::chrono::steady_clock::time_point deadline)
{
    return Deadline(deadline).secondsLeft();
}

std::chrono::steady_clock::duration seconds(double s)
{
    return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}

OrderingSearchOptions orderingSearch(size_t parts, std::uint64_t seed, double seconds)
{
    OrderingSearchOptions options;
    options.iterations = static_cast<long>(parts * parts);
    options.timeLimit = seconds;
    options.seed = seed;
    return options;
}

std::vector<int> decreasingExtentOrder(const std::vector<RasterPart>& parts)
{
    auto extent = [&](int i) {
        const Footprint& f = parts[i].shapes.front();
        return std::make_pair(std::max(f.width(), f.height()), f.area());
    };
    std::vector<int> order(parts.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return extent(a) > extent(b); });
    return order;
}

std::vector<int> bestFitOrder(const std::vector<RasterPart>& parts, const std::vector<BoardStock>& stock,
                              Criterion criterion, Bounds bounds, Preference preference, Deadline deadline)
{
    // Identical parts are interchangeable: keep one queue of indices per distinct part.
    std::vector<std::vector<int>> kinds;
    std::map<std::tuple<int, int, long>, std::vector<size_t>> byShape;
    for (int i : decreasingExtentOrder(parts)) {
        const Footprint& f = parts[i].shapes.front();
        std::vector<size_t>& same = byShape[{f.width(), f.height(), f.area()}];
        auto kind = std::find_if(same.begin(), same.end(),
                                 [&](size_t k) { return parts[kinds[k].front()].shapes == parts[i].shapes; });
        if (kind == same.end()) {
            same.push_back(kinds.size());
            kinds.push_back({i});
        } else {
            kinds[*kind].push_back(i);
        }
    }
    for (auto& kind : kinds)
        std::reverse(kind.begin(), kind.end());  // pop from the back in input order

    Docker docker(stock, criterion, bounds);
    std::vector<int> order;
    while (order.size() < parts.size()) {
        size_t chosen = kinds.size();
        std::tuple<bool, int, int, long> best{true, 0, 0, 0};  // (needs a new sheet, sheet, y, -size)
        for (size_t k = 0; k < kinds.size() && !deadline.passed(); ++k) {
            if (kinds[k].empty())
                continue;
            const RasterPart& part = parts[kinds[k].back()];
            const Placed at = docker.bestPlace(part);
            const Footprint& shape = part.shapes[std::max(0, at.shape)];
            const long size = preference == Preference::LargestArea ? shape.area()
                              : preference == Preference::LargestExtent
                                  ? std::max(shape.width(), shape.height())
                                  : shape.width();
            const std::tuple<bool, int, int, long> key{at.sheet < 0, at.sheet, at.y, -size};
            if (chosen == kinds.size() || key < best) {
                best = key;
                chosen = k;
            }
        }
        if (chosen == kinds.size()) {  // out of time: the rest in decreasing extent, not docked here
            for (std::vector<int>& kind : kinds)
                order.insert(order.end(), kind.rbegin(), kind.rend());
            break;
        }
        order.push_back(kinds[chosen].back());
        kinds[chosen].pop_back();
        docker.place(parts, order.back());
    }
    return order;
}

GridLayout exploreOrderings(const std::vector<RasterPart>& parts, std::vector<int> order,
                            const std::vector<BoardStock>& stock, const OrderingSearchOptions& options,
                            Deadline firstPass)
{
    using Clock = std::chrono::steady_clock;
    const Deadline deadline(Clock::now() + seconds(options.timeLimit), options.cancel);
    const long n = static_cast<long>(order.size());
    const long iterations = options.iterations >= 0 ? options.iterations : n * n;

    const auto started = Clock::now();
    GridLayout current = dock(parts, order, stock, options.criterion, options.bounds, nullptr, 0, firstPass);
    if (!current.finished)
        return current;
    const auto pass = Clock::now() - started;  // never start a docking pass that cannot end in time
    GridLayout best = current;
    LayoutCost bestCost = cost(best, stock, options.bounds);
    LayoutCost currentCost = bestCost;
    // Late acceptance: a swap is kept when it is no worse than the current ordering or than the
    // one `memory` swaps ago; memory 1 is the thesis' rule (keep swaps that do not increase wastage).
    std::vector<LayoutCost> history(std::max(1, options.memory), bestCost);
    std::mt19937_64 random(options.seed);
    std::uniform_int_distribution<long> pick(0, std::max(0L, n - 1));
    for (long i = 0; i < iterations && n > 1 && deadline.allows(pass); ++i) {
        const long a = pick(random), b = pick(random);
        if (a == b || parts[order[a]].shapes == parts[order[b]].shapes)
            continue;  // swapping identical parts changes nothing
        std::swap(order[a], order[b]);
        // The parts before the first swapped one go where the current layout has them.
        GridLayout candidate = dock(parts, order, stock, options.criterion, options.bounds, &current,
                                    static_cast<size_t>(std::min(a, b)));
        const LayoutCost candidateCost = cost(candidate, stock, options.bounds);
        LayoutCost& past = history[i % history.size()];
        if (currentCost < candidateCost && past < candidateCost) {
            std::swap(order[a], order[b]);
        } else {
            currentCost = candidateCost;
            current = std::move(candidate);
            if (candidateCost < bestCost) {
                best = current;
                bestCost = candidateCost;
            }
        }
        past = std::min(past, currentCost);
    }
    return best;
}

}  // namespace fabguide::material
