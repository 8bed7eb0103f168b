// `fabguide`: the command-line face of the core. Each domain adds its subcommands here
// (solve, pack, optimise, printable); every one reads and writes the documented JSON formats.
#include "Core/Version.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

namespace {

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

}  // namespace

int main(int argc, char** argv)
{
    CLI::App app{"FabGuide: fabrication guided by function and material usage"};
    app.set_version_flag("--version", fabguide::version());
    app.require_subcommand(1);
    addVersionCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "fabguide: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
