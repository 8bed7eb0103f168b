// MaxRects (J. Jylänki, "A Thousand Ways to Pack the Bin", 2010) in millimetres: the layout of jobs made of
// rectangles at shop scale, where rasterising thousands of parts for Docking would take minutes.
// pack() compares it with Docking's search on smaller jobs and keeps the better layout.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Pack.h"

#include <chrono>
#include <optional>
#include <utility>
#include <vector>

namespace fabguide::material {

/// mm: what the millimetre packers count as touching (two edges, or a size and its room, this close are
/// equal).
constexpr double kHair = 1e-9;

/// A unit of a part as it may lie: its rotation and its size with the clearance added.
struct Pose {
    int rotation = 0;
    double w = 0, h = 0;
};

/// The part's poses allowed on `board`: one per distinct footprint, grain and thickness kept.
std::vector<Pose> posesOn(const PartSpec& part, const MasterBoard& board, double clearance);

/// The width and height of `board` that parts may take, with their clearance: the board less its trim, with
/// one clearance added back at the far edges (every pose carries its clearance on those sides).
std::pair<double, double> usableSize(const MasterBoard& board, const PackSettings& settings);

/// The kind of sheet to open for `part`: the first listed of the least cost of those `left` (boards of each
/// kind in stock, -1: unlimited) that it fits on; -1: none.
int sheetKindFor(const PackProblem& problem, const PartSpec& part, const std::vector<int>& left);

/// A sheet of `kind` opened in `layout` (one of `left` taken, unless unlimited).
void openSheet(const PackProblem& problem, int kind, std::vector<int>& left, Layout& layout);

/// A unit of `part` turned by `rotation` on `sheet` of `layout`, at (x, y) of the board less its trim.
void addPlacement(const PackProblem& problem, int part, int sheet, double x, double y, int rotation,
                  Layout& layout);

/// PackingError: the boards ran out before `part` and `more` others.
PackingError ranOut(const PartSpec& part, size_t more);

/// The orders parts are taken in, largest first by: longest side, area, perimeter, shortest side.
enum class Order { LongestSide, Area, Perimeter, ShortestSide };

/// What a part is sorted by in `order` (ties by the second), largest first.
std::pair<double, double> orderKey(Order order, const PartSpec& p);

/// Whether the part is a rectangle without holes.
bool rectangular(const PartSpec& part);

/// Whether every part is a plain rectangle without holes, which MaxRects lays out exactly.
bool allRectangles(const PackProblem& problem);

/// The parts laid out by MaxRects (kerf + spacing around every part, trim along the board edges, grain and
/// thickness as Docking has them; a sheet opened as Docking opens one: the cheapest kind left that the part
/// fits on), the best layout (`better`) of the runs done by `deadline`: in four orders (longest side, area,
/// perimeter, shortest side first) by four rules (best short side, long side and area fit, bottom-left), each
/// unit at the best free rectangle of any open sheet; then sheet by sheet, each filled with the best fitting
/// of all the parts left (Jylänki's global variant). The first run always completes. Throws PackingError
/// naming a part the boards run out before in every run.
Layout maxRects(const PackProblem& problem, Deadline deadline);

/// Strip packing by MaxRects: the strip's height bisected between the parts' area over its width and every
/// part stacked, each height tried by the runs above until one lays every part out; the lowest layout found
/// by `deadline`, or nothing.
std::optional<Layout> maxRectsStrip(const PackProblem& problem, Deadline deadline);

}  // namespace fabguide::material
