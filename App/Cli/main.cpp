// `fabguide`: the command-line face of the core. Every subcommand reads and writes the JSON
// formats of docs/formats.md; errors name the file and the offending field.
#include "Cli/Main.h"
#include "Cli/Commands.h"

int main(int argc, char** argv)
{
    CLI::App app{"FabGuide: fabrication guided by function and material usage"};
    fabguide::cli::addVersionCommand(app);
    fabguide::cli::addPackCommand(app);
    fabguide::cli::addSolveCommand(app);
    fabguide::cli::addPrintableForward(app);
    fabguide::cli::addOptimiseCommand(app);
    return fabguide::cli::runCommandLine(app, argc, argv);
}
