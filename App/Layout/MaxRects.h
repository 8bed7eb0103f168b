// MaxRects (J. Jylänki, "A Thousand Ways to Pack the Bin", 2010) in millimetres: the layout of jobs made of
// rectangles at shop scale (issue 16), where rasterising thousands of parts for Docking would take minutes.
// pack() compares it with Docking's search on smaller jobs and keeps the better layout.
#pragma once

#include "Layout/Pack.h"

#include <chrono>
#include <optional>
#include <vector>

namespace fabguide::material {

/// A unit of a part as it may lie: its rotation and its size with the clearance added.
struct Pose {
    int rotation = 0;
    double w = 0, h = 0;
};

/// The part's poses allowed on `board`: one per distinct footprint, grain and thickness kept.
std::vector<Pose> posesOn(const PartSpec& part, const MasterBoard& board, double clearance);

/// Whether every part is a plain rectangle without holes, which MaxRects lays out exactly.
bool allRectangles(const PackProblem& problem);

/// The parts laid out by MaxRects (kerf + spacing around every part, trim along the board edges, grain and
/// thickness as Docking has them; a sheet opened as Docking opens one: the cheapest kind left that the part
/// fits on), the best layout (`better`) of the runs done by `deadline`: in four orders (longest side, area,
/// perimeter, shortest side first) by four rules (best short side, long side and area fit, bottom-left), each
/// unit at the best free rectangle of any open sheet; then sheet by sheet, each filled with the best fitting
/// of all the parts left (Jylänki's global variant). The first run always completes. Throws PackingError
/// naming a part the boards run out before in every run.
Layout maxRects(const PackProblem& problem, std::chrono::steady_clock::time_point deadline);

/// Strip packing by MaxRects: the strip's height bisected between the parts' area over its width and every
/// part stacked, each height tried by the runs above until one lays every part out; the lowest layout found
/// by `deadline`, or nothing.
std::optional<Layout> maxRectsStrip(const PackProblem& problem,
                                    std::chrono::steady_clock::time_point deadline);

}  // namespace fabguide::material
