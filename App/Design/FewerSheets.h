// Saving a sheet (past the thesis): GROWPARTS and SHRINKPARTS change a design one grid cell at a
// time inside its layout, so they never free a whole master board. This shrinks the design as far as its
// constraints allow, lays it out afresh (MaterialSpace::packed: the layout command's packers), and when that
// needs fewer sheets looks for the least shrink that still does.
#pragma once

#include "Design/ImproveDesign.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace fabguide::material {

/// What FEWERSHEETS found: the least design with its fresh layout (none when it could not be found), and the
/// designs that save sheets.
struct SavedSheets {
    std::optional<DesignLayout> least;
    std::vector<DesignLayout> designs;
};

/// FEWERSHEETS: the least design from `start` (DesignSpace::least: every design and effectiveness
/// constraint holds) laid out afresh, in half the time; if that needs fewer sheets, then for each sheet count
/// from one fewer down to that one, the design nearest to `start` on the way (bisection on the fraction of
/// the shrink) whose fresh layout fits on that many. No designs when the design cannot shrink onto fewer
/// sheets or the deadline (or `cancel`) came first.
SavedSheets fewerSheets(const DesignSpace& design, const MaterialSpace& material, const DesignLayout& start,
                        std::uint64_t seed, std::chrono::steady_clock::time_point deadline,
                        const std::atomic<bool>* cancel = nullptr);

}  // namespace fabguide::material
