// A hole drilled into a board's face, e.g. for a dowel (thesis 5.1 connectors).
#pragma once

#include "Geometry/Polygon.h"

namespace fabguide::material {

struct Drill {
    geometry::Point2 at;  ///< centre, in the board's outline frame
    double diameter = 0;  ///< mm
    double depth = 0;     ///< mm into the face
};

}  // namespace fabguide::material
