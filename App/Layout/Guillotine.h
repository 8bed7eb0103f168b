// Guillotine layouts for a saw: every sheet comes apart by straight cuts from edge to edge, in at
// most settings.stages changes of direction, and the cuts come in the order a person makes them.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Pack.h"

#include <chrono>
#include <cstdint>

namespace fabguide::material {

/// The runs pack() makes for a saw when the search's iterations are not given (the time limit may stop it
/// sooner).
constexpr long kGuillotineRuns = 2000;

/// The parts laid out for a saw, sheet by sheet (a sheet opened as MaxRects opens one). A piece is filled in
/// slabs, one after the other along one direction, each as thick as the part that leads it; a slab is filled
/// the same way across, one stage deeper; a slab of the last stage holds its one part, parted from the waste
/// beside it by one trim cut more (non-exact stages: Lodi, Martello & Vigo, 2002). Kerf + spacing lies
/// between every two pieces, the cut in its middle; trim along the board edges, taken off by cuts 0.1-0.4.
/// Parts lie as their bounding rectangles, turned by square turns as their orientations, grain and thickness
/// allow. Each sheet is filled every way settings allow (first direction when FirstCut::Any; 2, 3, 4 and 6
/// stages when unlimited; lead parts tall or flat), the way that lays the most part area kept. Runs differ in
/// the order of the parts (largest first by four measures, then swaps of the best order from `seed`) and,
/// when unlimited, in the stage counts tried (all, then each alone, as a limit's runs); the best layout
/// (`better`) of the runs made by three quarters of the time to `deadline`, at most `runs`, the first
/// completing whatever the deadline. Then, in the time left, a beam search (GuillotineBeam.h, at most `runs`
/// wide) lays each board kind's parts in 3 stages (2 when the limit is 2), each first direction allowed; its
/// layout is kept when it needs fewer sheets or leaves the last emptier. With 2 `threads` or more, the beam
/// search runs on a thread of its own beside the rules' runs, both to `deadline`. Fills Layout::sawCuts.
/// Throws PackingError naming a part the boards run out before in every run, or one that would leave a strip
/// too narrow to saw off at a board's edge.
Layout guillotine(const PackProblem& problem, long runs, std::uint64_t seed, Deadline deadline,
                  int threads = 1);

}  // namespace fabguide::material
