#include "Cli/Commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace fabguide::cli {

void addPrintableForward(CLI::App& app)
{
    auto* cmd = app.add_subcommand("printable", kPrintableSummary);
    cmd->prefix_command();  // every word after `printable` is fabguide-print's, --help included
    cmd->set_help_flag();
    cmd->callback([cmd] {
        const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
        const std::string program = (self.parent_path() / "fabguide-print").string();
        std::vector<std::string> words{program, "printable"};
        for (const std::string& word : cmd->remaining())
            words.push_back(word);
        std::vector<char*> argv;
        for (std::string& word : words)
            argv.push_back(word.data());
        argv.push_back(nullptr);
        std::fflush(nullptr);
        execv(program.c_str(), argv.data());
        throw std::runtime_error(program + " could not be run (" + std::strerror(errno) +
                                 "); it is built beside fabguide");
    });
}

}  // namespace fabguide::cli
