#include "IO/ApiJson.h"

namespace fabguide::io {

nlohmann::json toJson(const api::DesignEditReport& report)
{
    return {{"design", report.design},       {"kept", report.kept},         {"limits", report.limits},
            {"satisfied", report.satisfied}, {"absorbed", report.absorbed}, {"snapped", report.snapped},
            {"undone", report.undone},       {"warning", report.warning},   {"laid_out", report.laidOut}};
}

}  // namespace fabguide::io
