// Intervals of the real line, and boxes as FabGuide keeps them: by side (thesis 4.1.1's six coordinates).
#pragma once

#include <algorithm>
#include <array>
#include <limits>

namespace fabguide {

/// A closed interval, its ends possibly infinite.
struct Interval {
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
};

/// How far two intervals overlap: negative, the gap between them; 0, they touch. Every rule of "overlapping"
/// in FabGuide is this beyond some hair.
inline double overlapOf(const Interval& a, const Interval& b)
{
    return std::min(a.upper, b.upper) - std::max(a.lower, b.lower);
}

/// A box by side: x lower, x upper, y lower, y upper, z lower, z upper.
using BoxSides = std::array<double, 6>;

/// A box's extent along axis 0 (x), 1 (y) or 2 (z).
inline Interval along(const BoxSides& box, int axis)
{
    return {box[2 * axis], box[2 * axis + 1]};
}

}  // namespace fabguide
