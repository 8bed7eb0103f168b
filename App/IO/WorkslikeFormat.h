// The works-like model format, *.workslike.json (docs/formats.md).
#pragma once

#include "Function/Solve.h"

#include <nlohmann/json.hpp>

namespace fabguide::io {

constexpr int kWorkslikeFormatVersion = 1;

/// Reads a *.workslike.json document. Throws FormatError naming the offending field.
function::Model readWorkslike(const nlohmann::json& document);

/// Writes a model in the same format; with a solve result, adds "report": {"solved", "conflict",
/// "violation"}.
nlohmann::json workslikeToJson(const function::Model& model, const function::SolveResult* result = nullptr);

}  // namespace fabguide::io
