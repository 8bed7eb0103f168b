// Version of the FabGuide core and of the libraries it was built against,
// reported by `fabguide --version`, `fabguide_core.__version__` and the About dialog.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace fabguide {

/// FabGuide's version, "major.minor.patch".
std::string version();

/// (library, version) for each third-party library compiled into the core, in a fixed order.
std::vector<std::pair<std::string, std::string>> dependencyVersions();

}  // namespace fabguide
