// The use cases' results (App/Api) as JSON, the one form the bindings return them in (docs/formats.md).
#pragma once

#include "Api/DesignEdit.h"

#include <nlohmann/json.hpp>

namespace fabguide::io {

/// {"design", "kept", "limits", "satisfied", "absorbed", "snapped", "undone", "warning", "laid_out"}: the
/// report's fields by those names ("laid_out" null when the edit was undone).
nlohmann::json toJson(const api::DesignEditReport& report);

}  // namespace fabguide::io
