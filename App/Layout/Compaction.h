// Compaction on the parts' real outlines: the grid keeps each part up to a cell off its
// neighbours; sliding every part toward the strip's start (or a sheet's corner) until its outline meets
// another's gives back what the grid lost between them.
#pragma once

#include "Layout/Pack.h"

namespace fabguide::material {

/// `layout` (a strip of `problem`) with each part, the nearest the strip's start first, slid toward it as far
/// as its outline stays kerf + spacing from every other part's and inside the trim; the strip's height then
/// ends at the part that reaches farthest.
Layout compacted(const Layout& layout, const PackProblem& problem);

/// `layout` (on sheets) with its parts slid together: each, the nearest the sheet's lower edge first, slid
/// down as far as its outline stays kerf + spacing from every other part's on its sheet and inside the trim,
/// then each, the nearest the left edge first, slid left; twice. Parts the grid left up to a cell further
/// apart then lie a kerf apart, so common-line cutting (CommonLine.h) finds the lines they share.
Layout slidTogether(const Layout& layout, const PackProblem& problem);

}  // namespace fabguide::material
