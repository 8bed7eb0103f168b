// The works-like model format, *.workslike.json (docs/formats.md).
#pragma once

#include "Function/Solve.h"

#include <nlohmann/json.hpp>

namespace fabguide::io {

constexpr int kWorkslikeFormatVersion = 1;

/// A *.workslike.json document read: the model, and the document in its normal form (docs/formats.md): as
/// given, with every default the reader takes written in.
struct WorkslikeDocument {
    function::Model model;
    nlohmann::json document;
};

/// Reads a *.workslike.json document. Throws FormatError naming the offending field.
WorkslikeDocument readWorkslikeDocument(const nlohmann::json& document);
inline function::Model readWorkslike(const nlohmann::json& document)
{
    return readWorkslikeDocument(document).model;
}

/// Writes a model in the same format; with a solve result, adds "report": {"solved", "conflict",
/// "violation"}.
nlohmann::json workslikeToJson(const function::Model& model, const function::SolveResult* result = nullptr);

}  // namespace fabguide::io
