#include "Core/Version.h"

#include "Core/BuildInfo.h"

#include <Eigen/Core>
#include <Standard_Version.hxx>
#include <nlohmann/json.hpp>
#include <polyclipping/clipper.hpp>

namespace fabguide {

std::string version()
{
    return FABGUIDE_VERSION;
}

std::vector<std::pair<std::string, std::string>> dependencyVersions()
{
    auto dotted = [](int a, int b, int c) {
        return std::to_string(a) + "." + std::to_string(b) + "." + std::to_string(c);
    };
    return {
        {"Eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
        {"OpenCASCADE", OCC_VERSION_COMPLETE},
        {"Clipper", CLIPPER_VERSION},
        {"nlohmann-json",
         dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
    };
}

}  // namespace fabguide
