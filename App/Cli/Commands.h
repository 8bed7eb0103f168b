// The fabguide subcommands; each adds itself to the command line.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>

namespace fabguide::cli {

/// A search's --seed: a whole number a double holds exactly (-1 and 2^64 were taken and wrapped).
inline const CLI::Range kSeeds(0LL, 9007199254740991LL);

/// A number from `min` to `max`. CLI::Range alone lets "nan" through: it compares false both ways.
inline CLI::Validator between(double min, double max)
{
    const CLI::Validator aNumber(
        [](std::string& text) {
            double x = 0;
            return CLI::detail::lexical_cast(text, x) && std::isnan(x)
                       ? std::string("must be a number, got ") + text
                       : std::string();
        },
        "");
    return CLI::Range(min, max) & aNumber;
}

void addVersionCommand(CLI::App& app);
void addPackCommand(CLI::App& app);
void addSolveCommand(CLI::App& app);
/// What `fabguide printable` does, in both programs' help.
inline constexpr const char* kPrintableSummary =
    "Turn a works-like model into print-in-place bodies: cavities, joints, gaps; check them; write STL, 3MF "
    "and STEP";

void addPrintableCommand(CLI::App& app);
/// `fabguide printable` hands its command line to fabguide-print, the program beside fabguide that loads
/// OpenCASCADE: loading it took 50 ms of every other command's start-up.
void addPrintableForward(CLI::App& app);
void addOptimiseCommand(CLI::App& app);

}  // namespace fabguide::cli
