// `fabguide-print`: the program `fabguide printable` runs, the only one that loads OpenCASCADE.
#include "Cli/Commands.h"
#include "Cli/Main.h"

int main(int argc, char** argv)
{
    CLI::App app{"FabGuide: print-in-place bodies of a works-like model", "fabguide"};
    fabguide::cli::addPrintableCommand(app);
    return fabguide::cli::runCommandLine(app, argc, argv);
}
