// The fabguide subcommands; each adds itself to the command line.
#pragma once

#include <CLI/CLI.hpp>

namespace fabguide::cli {

void addVersionCommand(CLI::App& app);
void addPackCommand(CLI::App& app);
void addSolveCommand(CLI::App& app);
void addPrintableCommand(CLI::App& app);
void addOptimiseCommand(CLI::App& app);

}  // namespace fabguide::cli
