// The flat-pack layout formats (docs/formats.md): `*.pack.json` in, layout JSON out, and the
// OR-Datasets strip-packing instances used as benchmarks.
#pragma once

#include "Material/Pack.h"

#include <nlohmann/json.hpp>

namespace fabguide::io {

constexpr int kPackFormatVersion = 1;

/// Reads a `*.pack.json` document. Throws FormatError naming the offending field.
material::PackProblem readPackProblem(const nlohmann::json& document);

/// Reads an OR-Datasets rectangle instance ({"Objects": [{"Length", "Height"}], "Items": [{"Length",
/// "Height", "Demand"}]}) as a strip-packing problem: width Objects[0].Length, grid resolution 1,
/// part ids = 0-based item indices.
material::PackProblem readStripInstance(const nlohmann::json& document);

/// How placements name their part: by the part's id, or (OR-Datasets) by its index in the input.
enum class PartNames { Ids, Indices };

/// The layout JSON contract: {"boards": [{"width", "height", ...}], "strip_height" (strip mode),
/// "placements": [{"part", "board", "x", "y", "rotation", "width", "height"}], metrics}.
nlohmann::json layoutToJson(const material::Layout& layout, const material::PackProblem& problem,
                            PartNames names);

/// Reads a layout JSON written by layoutToJson back, against the problem it was made for, so cut
/// sheets can be written for exactly the layout a user has seen. Throws FormatError naming the field.
material::Layout readLayout(const nlohmann::json& document, const material::PackProblem& problem,
                            PartNames names);

}  // namespace fabguide::io
