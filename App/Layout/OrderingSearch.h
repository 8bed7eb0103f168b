// Exploring orderings by pairwise swaps (thesis 5.4.3, EXPLOREORDERINGS in Algorithm 7).
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Docking.h"

#include <chrono>
#include <cstdint>
#include <tuple>
#include <vector>

namespace fabguide::material {

/// What a layout costs: parts left unplaced (boards ran out) first, then what its sheets cost (offcuts
/// nothing), then sheets used, then the summed
/// bounding-rectangle areas of their layouts (thesis 5.4.3.2: wastage against the bounding rectangle), then
/// the area under the top height-fields, which tells apart layouts of equal wastage by how low their parts
/// sit. Lower is better.
struct LayoutCost {
    int unplaced = 0;
    double sheetCost = 0;
    int sheets = 0;
    long boundingArea = 0;
    long skylineArea = 0;
    bool operator<(const LayoutCost& o) const
    {
        return std::tie(unplaced, sheetCost, sheets, boundingArea, skylineArea) <
               std::tie(o.unplaced, o.sheetCost, o.sheets, o.boundingArea, o.skylineArea);
    }
};

LayoutCost cost(const GridLayout& layout, const std::vector<BoardStock>& stock, Bounds bounds);

struct OrderingSearchOptions {
    Criterion criterion = Criterion::Docking;
    Bounds bounds = Bounds::Layout;
    long iterations = -1;    ///< swaps to try; -1 means |parts|² as in the thesis
    double timeLimit = 1.0;  ///< seconds; the search stops early when it runs out
    std::uint64_t seed = 1;  ///< same seed, same result
    int memory = 1;          ///< late-acceptance history length; 1 = the thesis' acceptance rule
    int threads =
        1;  ///< pack: starts searched at once, a strip's skyline searches, a saw's beam beside its rules
    const std::atomic<bool>* cancel = nullptr;  ///< set by another thread: stop now with the best so far
};

/// Seconds left until `deadline` (0 when past it): what a time-limited search may still take.
double secondsUntil(std::chrono::steady_clock::time_point deadline);

/// `s` seconds as the steady clock counts them: a deadline is a time point plus these.
std::chrono::steady_clock::duration seconds(double s);

/// The thesis' ordering search for `parts` units: |parts|² swaps (5.4.3), for at most `seconds`.
OrderingSearchOptions orderingSearch(size_t parts, std::uint64_t seed, double seconds);

/// The order in which the thesis' Bottom-Left inserts parts: decreasing largest extent (5.3.1).
std::vector<int> decreasingExtentOrder(const std::vector<RasterPart>& parts);

/// Which part a best-fit order docks next among those whose best position is equally low.
enum class Preference { LargestArea, LargestExtent, Widest };

/// A starting order built greedily: at each step, of the part types left, the one whose best docking
/// position is lowest (ties by `preference`) is docked next. Docking this order gives the same layout.
/// Past `deadline` the remaining parts follow in decreasing-extent order.
std::vector<int> bestFitOrder(const std::vector<RasterPart>& parts, const std::vector<BoardStock>& stock,
                              Criterion criterion, Bounds bounds, Preference preference, Deadline deadline);

/// Starting from `order`, repeatedly swaps two random parts, re-docks, and keeps the swap when the
/// layout costs no more (thesis 5.4.3). Stops after the iterations, or before a docking pass that would
/// end past the time limit, or when cancelled. Returns the best layout found; the first docking pass is cut
/// at `firstPass` (the layout then not `finished`).
GridLayout exploreOrderings(const std::vector<RasterPart>& parts, std::vector<int> order,
                            const std::vector<BoardStock>& stock, const OrderingSearchOptions& options,
                            Deadline firstPass = {});

}  // namespace fabguide::material
