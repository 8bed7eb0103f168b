// Inferring the corresponding-faces graph of a support relationship (thesis 4.3.3).
#pragma once

#include "Function/Model.h"

#include <utility>
#include <vector>

namespace fabguide::function {

/// The corresponding-faces graph of a support (4.3.3) and what it took to link every part named.
struct InferredSupport {
    std::vector<std::pair<int, int>> pairs;  ///< (supporting cuboid, supported cuboid)
    InferenceNotes notes;                    ///< parts linked beyond the distance
    std::vector<int> unlinked;               ///< parts with nothing to link at all
};

/// For each top face of a supporting part's cuboid, the supported part's bottom face nearest to it in the
/// configuration: within `distance` vertically, below it or sunk into the lower half of the supported cuboid
/// (a leg drawn 3 mm into the top), nearest first vertically then horizontally; faces need not overlap yet
/// (the solve makes them). A part named but left with no pair (a leg 110 mm short at 100 mm) is linked by its
/// nearest pair and noted: every part the user named takes part.
InferredSupport inferSupport(const Model& model, const std::vector<int>& supporting,
                             const std::vector<int>& supported, int configuration, double distance);

}  // namespace fabguide::function
