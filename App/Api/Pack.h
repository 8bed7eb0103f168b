// The use case of laying parts out on master boards (thesis 5.3.1, 5.4.3), or packing a strip: the job read,
// the settings its caller overrides applied, the layout searched. `fabguide pack` and the binding `pack` run
// it.
#pragma once

#include "Layout/Pack.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace fabguide::api {

struct PackJob {
    nlohmann::json document;  ///< a `*.pack.json` problem, or an OR-Datasets strip instance when `strip`
    bool strip = false;
    /// What overrides the document's settings (unset: as the document says).
    std::optional<int> rotationStep;
    std::optional<material::Cuts> cuts;
    std::optional<int> stages;
    std::optional<material::FirstCut> firstCut;
    bool commonLine = false;  ///< on even when the document has it off
    material::OrderingSearchOptions search;
};

struct PackReport {
    material::PackProblem problem;  ///< as read, with the overrides
    material::Layout layout;
};

/// Throws io::FormatError naming a bad field, material::PackingError naming a part that fits no board.
PackReport pack(const PackJob& job);

}  // namespace fabguide::api
