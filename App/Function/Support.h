// Inferring the corresponding-faces graph of a support relationship (thesis 4.3.3).
#pragma once

#include "Function/Model.h"

#include <utility>
#include <vector>

namespace fabguide::function {

/// For each top face of a supporting part's cuboid, the supported part's bottom face nearest above it in the
/// configuration: within `distance` vertically (touching or a little above, never below by more than a
/// hair), nearest first vertically then horizontally; faces need not overlap yet (the solve makes them).
/// Returns (supporting cuboid, supported cuboid) pairs.
std::vector<std::pair<int, int>> inferSupportPairs(const Model& model, const std::vector<int>& supporting,
                                                   const std::vector<int>& supported, int configuration,
                                                   double distance);

}  // namespace fabguide::function
