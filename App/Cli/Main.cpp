#include "Cli/Main.h"

#include "Core/Memory.h"
#include "Core/Version.h"
#include "IO/Output.h"

#include <chrono>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>

#include <sys/resource.h>

namespace fabguide::cli {

namespace {

const auto started = std::chrono::steady_clock::now();  // set as the program starts, before main

/// Memory set aside at the start and given back when an allocation first fails: the unwinding that follows
/// allocates too (a JSON value's destructor does), and without room it would end in std::terminate.
constexpr size_t kReserve = 32 << 20;
char* reserve = nullptr;

void outOfMemory()
{
    std::free(reserve);
    reserve = nullptr;
    std::set_new_handler(nullptr);
    throw std::bad_alloc();
}

/// The memory limit, and the process' data limit with it: an allocation past it fails as std::bad_alloc
/// (reported in a sentence) rather than the system stopping the run without a word.
void limitMemory(double bytes)
{
    setMemoryLimit(bytes);
    const rlimit data{static_cast<rlim_t>(bytes), RLIM_INFINITY};
    setrlimit(RLIMIT_DATA, &data);
    if (!reserve) {
        reserve = static_cast<char*>(std::malloc(kReserve));
        std::set_new_handler(outOfMemory);
    }
}

/// `--memory SIZE` on every subcommand (2G, 500M; at least 64 MB).
void addMemoryOption(CLI::App& app)
{
    for (CLI::App* command : app.get_subcommands({}))
        command
            ->add_option_function<double>(
                "--memory", limitMemory,
                "memory the run may use, e.g. 2G or 500M (default: what is free when it begins); what needs "
                "more is refused, naming what makes it large")
            ->transform(CLI::AsSizeValue(true))
            ->check(CLI::Validator(
                [](std::string& bytes) -> std::string {
                    return std::stod(bytes) >= 64e6 ? "" : "at least 64M (a plain number is bytes: 2G, 500M)";
                },
                ""));
}

}  // namespace

double secondsSinceStart()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

int runCommandLine(CLI::App& app, int argc, char** argv)
{
    io::removeTemporariesOnInterrupt();  // SIGINT / SIGTERM: exit 130 / 143, no half-written file
    limitMemory(memoryLimit());
    addMemoryOption(app);
    try {
        app.set_version_flag("--version", version());
        app.require_subcommand(1);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0 || dynamic_cast<const CLI::RuntimeError*>(&e))  // --help; a status said
            return app.exit(e);
        std::cerr << "fabguide: error: " << e.what() << " (--help lists the options)\n";
        return 1;
    } catch (const std::bad_alloc&) {
        std::cerr
            << "fabguide: error: out of memory: the run needed more than the " << inBytes(memoryLimit())
            << " it may use (the memory free when it began, or --memory); a coarser settings.resolution, "
               "fewer or smaller parts need less\n";
        return 1;
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
