// Labels as strokes: lines a laser, router or CAM engraves as they are, where SVG or DXF text
// would be dropped or set in another font. Hershey's Simplex Roman (Debian's hershey-fonts-data, read by
// libhersheyfont).
#pragma once

#include "Geometry/Polygon.h"
#include "Layout/CutSheet.h"

#include <vector>

namespace fabguide::material {

/// The label's text as open polylines, `height` its em (capitals about two thirds of it), centred at its
/// point and turned by its angle as SVG text would be; a character outside printable ASCII is drawn as '?'.
/// Throws std::runtime_error when the font is not installed.
std::vector<geometry::Polygon> strokes(const Label& label);

}  // namespace fabguide::material
