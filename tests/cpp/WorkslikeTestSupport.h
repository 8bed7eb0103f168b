// Helper shared by the works-like tests.
#pragma once

#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fabguide::testsupport {

/// A *.workslike.json cuboid, a cavity if `cavity`.
inline nlohmann::json cuboid(const std::string& name, std::array<double, 3> min, std::array<double, 3> max,
                             bool cavity = false)
{
    nlohmann::json c = {{"name", name}, {"min", min}, {"max", max}};
    if (cavity)
        c["cavity"] = true;
    return c;
}

/// A part of one cuboid of its name.
inline nlohmann::json cuboidPart(const std::string& name, std::array<double, 3> min,
                                 std::array<double, 3> max)
{
    return {{"name", name}, {"cuboids", {cuboid(name, min, max)}}};
}

/// The FormatError message reading `document` as a *.workslike.json gives, or "" if it reads.
inline std::string workslikeError(const nlohmann::json& document)
{
    try {
        io::readWorkslike(document);
    } catch (const io::FormatError& e) {
        return e.what();
    }
    return "";
}

/// A solve's conflict as its kinds and subjects read (SolveResult::conflicts), in its order.
inline std::vector<std::pair<function::ConflictKind, std::string>> typedConflict(
    const function::SolveResult& r)
{
    std::vector<std::pair<function::ConflictKind, std::string>> typed;
    for (const function::Conflict& c : r.conflicts)
        typed.emplace_back(c.kind, c.subject);
    return typed;
}

}  // namespace fabguide::testsupport
