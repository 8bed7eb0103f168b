// Helper shared by the works-like tests.
#pragma once

#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include <string>

namespace fabguide::testsupport {

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

}  // namespace fabguide::testsupport
