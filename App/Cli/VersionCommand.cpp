// `fabguide version`: the versions a bug report needs.
#include "Cli/Commands.h"
#include "Core/Version.h"

#include <iostream>

namespace fabguide::cli {

void addVersionCommand(CLI::App& app)
{
    auto* cmd =
        app.add_subcommand("version", "Print the FabGuide version and the libraries it was built with");
    cmd->callback([] {
        std::cout << "fabguide " << fabguide::version() << "\n";
        for (const auto& [library, version] : fabguide::dependencyVersions())
            std::cout << "  " << library << " " << version << "\n";
    });
}

}  // namespace fabguide::cli
