// Strip packing of rectangles by a tree search on the skyline at a target height: the lowest,
// leftmost gap of the skyline is filled by a part put at its left end, or left as waste while the waste
// the target height allows lasts. In a packing without waste that gap is always some part's lower-left
// corner, so the search is complete at the area's lower bound; limited by nodes, it is restarted with the
// candidates shuffled. Most restarts keep the bottom of the lowest strip found and search its top again
// (a large neighbourhood search), each just below that strip.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Pack.h"

#include <chrono>
#include <cstdint>
#include <optional>

namespace fabguide::material {

/// Work `pack` gives the skyline search of a strip per second of its time limit. Work counts what a node
/// costs (64 a node, one per kind and skyline segment scanned, 11 per candidate ranked, one per two words of
/// subset sums), so a second's work takes about as long on every instance: 0.6-0.7 of the second on each of
/// this machine's cores, and the same seed gives the same strip unless the machine is loaded.
constexpr long kSkylineWorkPerSecond = 110000000;

struct SkylineBudget {
    long work = 0;  ///< over every target height: the search's size
    std::uint64_t seed = 1;
};

/// The most units the skyline search lays: it goes a level deeper per unit, each level with a copy of the
/// skyline (199,999 units overflowed the stack); the largest benchmark instance has 3,152.
constexpr long kSkylineUnits = 5000;

/// The lowest strip of `problem` (rectangles; kerf + spacing around every part, trim along the strip's
/// edges, grain kept) the search finds by `deadline` within `budget`; nothing when the time runs out before
/// a first greedy strip, or for more than kSkylineUnits units.
std::optional<Layout> skylineStrip(const PackProblem& problem, const SkylineBudget& budget,
                                   Deadline deadline);

/// The least height any strip of `problem` needs: the parts' area over the strip's width, and the tallest
/// part as it lies lowest, with clearance and trim.
double leastStripHeight(const PackProblem& problem);

}  // namespace fabguide::material
