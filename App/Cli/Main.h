// What every fabguide program does around its subcommands: temporaries removed on interrupt, the command line
// parsed, and every error one line on stderr with exit status 1.
#pragma once

#include <CLI/CLI.hpp>

namespace fabguide::cli {

/// Runs the subcommand named on the command line; its exit status.
int runCommandLine(CLI::App& app, int argc, char** argv);

/// Seconds since the program started: a command's time limit counts from there, start-up and reading
/// included.
double secondsSinceStart();

}  // namespace fabguide::cli
