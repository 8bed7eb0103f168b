// Lower bounds on the sheets a pack problem needs: no layout of it, by any packer, takes fewer. They are what
// "no sheet can be saved" rests on (MinWastage), never a layout attempt.
#pragma once

#include "Layout/Pack.h"

namespace fabguide::material {

/// The sheets no layout of `problem` can do with by area alone: per thickness, the parts' area with their
/// clearance over the largest usable board of that thickness, rounded up (parts of any thickness counted on
/// the largest board).
long sheetsByArea(const PackProblem& problem);

/// The sheets no layout of `problem` can do with, by area and by lines across the sheets (the argument of
/// Martello and Vigo's bound L1 for two-dimensional bin packing, written for poses, grain and kerf): a line
/// across a sheet meets at most one part longer than half the sheet along it, and none of the parts of at
/// least `p` beside a part longer than the sheet less `p`. Plain rectangles of a thickness whose boards are
/// all of one size and grain count; other parts count by area only.
long sheetsBound(const PackProblem& problem);

}  // namespace fabguide::material
