// From millimetres to the material-space grid (thesis 5.4.1): parts become bitmaps at resolution τ.
#pragma once

#include "Geometry/Polygon.h"
#include "Layout/Footprint.h"

namespace fabguide::material {

/// Cells a length of `mm` occupies: rounded up, so a rasterised part never overlaps its neighbour.
int cellsCovering(double mm, double resolution);

/// Whole cells inside `mm`: rounded down, so a layout never leaves its board.
int cellsWithin(double mm, double resolution);

/// The cells covered by `outline` (bounding box at the origin) grown by clearance/2 on every side,
/// so that two footprints that do not overlap keep their outlines `clearance` apart. Every cell the
/// grown outline has area in is filled. Footprint cell (0, 0) starts clearance/2 below and left of
/// the outline's bounding box.
Footprint rasterise(const geometry::Outline& outline, double resolution, double clearance);

}  // namespace fabguide::material
