// The use case of exploring a flat-pack design's variations that waste less (thesis 5.4, MINWASTAGE): the
// design read, held to its growth limit, laid out and improved. `fabguide optimise` and the binding
// `optimise` run it; each then writes what it found its own way (files, or a dict).
#pragma once

#include "Design/MinWastage.h"
#include "IO/FlatpackFormat.h"

#include <nlohmann/json.hpp>

namespace fabguide::api {

struct Exploring {
    nlohmann::json document;              ///< a `*.flatpack.json` design (docs/formats.md)
    material::MinWastageOptions options;  ///< its `kept` is the document's layout
    /// Boards drawn the same size (posts, legs, rails) kept the same size: their equal constraints added.
    bool keepDrawnEqual = false;
};

struct ExplorationReport {
    nlohmann::json document;   ///< as explored: with the equal constraints kept
    nlohmann::json keptEqual;  ///< those constraints, [{kind, name, refs}]
    io::FlatpackDesign flatpack;
    material::MaterialSpace material;
    material::Exploration exploration;

    /// The suggestion as a design file: the document with its boards, their layout and the path to it.
    nlohmann::json suggestionDocument(const material::Suggestion& s) const;
};

/// Runs the exploration. Throws io::FormatError naming a bad field, io::ConstraintError naming constraints
/// the design breaks, material::PackingError naming a part that does not fit.
ExplorationReport explore(const Exploring& job);

}  // namespace fabguide::api
