// Strip shrinking by overlap minimisation (past the thesis, after Egeblad et al. 2007 and
// Gardeyn & Wauters' sparrow 2025): a feasible strip of irregular parts is cut shorter, the parts squeezed
// together, and the overlaps that leaves are separated again by moving one part at a time to where it
// overlaps the others least, the pairs that keep overlapping weighing more each round (guided local search).
// On the material-space grid, so a strip with no cell taken twice is a valid layout.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Docking.h"

#include <chrono>
#include <cstdint>
#include <vector>

namespace fabguide::material {

/// Work (grid columns summed, or sixteen cells updated) `pack` gives the strip shrinking per second of its
/// time limit: about what a core does then on the ESICUP instances, so a seed mostly gives the same strip.
constexpr long kShrinkWorkPerSecond = 170000000;

/// The largest strip shrunk, in grid cells (each search keeps a count per cell): 80 MB a search.
constexpr double kShrinkCells = 2e7;

struct ShrinkBudget {
    long work = 0;  ///< on each thread, as kShrinkWorkPerSecond counts it: the search's size
    std::uint64_t seed = 1;
    int threads = 1;  ///< searches at once, their seeds 2^32 apart; the lowest strip is kept
};

/// The lowest strip the shrinking finds from `start` (a layout of `parts` on the one sheet of `strip`, its
/// width across and its height the length to shorten) by `deadline` within `budget`: never higher than
/// `start`, which is returned as it is when it is not a single strip with every part placed, or larger than
/// kShrinkCells.
GridLayout shrinkStrip(const std::vector<RasterPart>& parts, const BoardStock& strip, const GridLayout& start,
                       const ShrinkBudget& budget, Deadline deadline);

}  // namespace fabguide::material
