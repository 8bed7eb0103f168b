#include "Cli/Main.h"

#include "Core/Version.h"
#include "IO/Output.h"

#include <chrono>
#include <exception>
#include <iostream>

namespace fabguide::cli {

namespace {

const auto started = std::chrono::steady_clock::now();  // set as the program starts, before main

}  // namespace

double secondsSinceStart()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

int runCommandLine(CLI::App& app, int argc, char** argv)
{
    io::removeTemporariesOnInterrupt();  // SIGINT / SIGTERM: exit 130 / 143, no half-written file
    try {
        app.set_version_flag("--version", version());
        app.require_subcommand(1);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "fabguide: error: " << e.what() << "\n";
        return 1;
    } catch (...) {
        std::cerr
            << "fabguide: internal error (an unknown exception); please report it with the input file\n";
        return 1;
    }
    return 0;
}

}  // namespace fabguide::cli
