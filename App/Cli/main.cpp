// `fabguide`: the command-line face of the core. Every subcommand reads and writes the JSON
// formats of docs/formats.md; errors name the file and the offending field.
#include "Cli/Commands.h"
#include "Core/Version.h"
#include "IO/Output.h"

#include <Standard_Failure.hxx>

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
    fabguide::io::removeTemporariesOnInterrupt();  // SIGINT / SIGTERM: exit 130 / 143, no half-written file
    CLI::App app{"FabGuide: fabrication guided by function and material usage"};
    try {
        app.set_version_flag("--version", fabguide::version());
        app.require_subcommand(1);
        fabguide::cli::addVersionCommand(app);
        fabguide::cli::addPackCommand(app);
        fabguide::cli::addSolveCommand(app);
        fabguide::cli::addPrintableCommand(app);
        fabguide::cli::addOptimiseCommand(app);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "fabguide: error: " << e.what() << "\n";
        return 1;
    } catch (const Standard_Failure& e) {  // OpenCASCADE's exceptions are not std::exceptions
        std::cerr << "fabguide: geometry error: " << e.GetMessageString() << " (" << e.DynamicType()->Name()
                  << ")\n";
        return 1;
    } catch (...) {
        std::cerr
            << "fabguide: internal error (an unknown exception); please report it with the input file\n";
        return 1;
    }
    return 0;
}
