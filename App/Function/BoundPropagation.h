// Bound propagation over linear constraints: a box every point satisfying them lies in, without solving.
#pragma once

#include "Function/LeastChange.h"
#include "Geometry/Interval.h"

#include <vector>

namespace fabguide::function {

/// For each of the n variables, an interval that holds every x satisfying `rows`: from the whole line, each
/// row's bounds are carried to each of its variables through the other variables' intervals, sweep after
/// sweep, until no end moves by more than 1e-9 (relative) or after `sweeps` sweeps. Every interval is
/// valid after any sweep; an empty one (lower > upper) means the rows cannot hold together.
std::vector<Interval> propagatedBounds(const std::vector<LinearConstraint>& rows, int n, int sweeps = 100);

/// The values Σ a·x of a row's terms takes over the box `x` (one interval per variable).
Interval rangeOf(const LinearConstraint& row, const std::vector<Interval>& x);

}  // namespace fabguide::function
