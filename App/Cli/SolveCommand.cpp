// `fabguide solve`: the works-like model nearest to the given one that satisfies its relationships
// (thesis 4.4).
#include "Cli/Commands.h"
#include "Core/Text.h"
#include "Function/Pose.h"
#include "IO/Json.h"
#include "IO/Output.h"
#include "IO/WorkslikeFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace fabguide::cli {

namespace {

struct SolveArguments {
    std::string input;
    std::string output;
    bool poses = false;
};

/// Where each solid cuboid's box is in each configuration (thesis 4.1.2), after the solve.
void printPoses(const function::Model& model)
{
    for (size_t k = 0; k < model.configurations.size(); ++k) {
        std::printf("in configuration '%s':\n", model.configurations[k].name.c_str());
        for (size_t c = 0; c < model.cuboids.size(); ++c) {
            if (model.cuboids[c].cavity())
                continue;
            const std::array<double, 6> at =
                function::posedBounds(model, static_cast<int>(c), static_cast<int>(k));
            std::printf("  %-20s x %.6g .. %.6g  y %.6g .. %.6g  z %.6g .. %.6g\n",
                        model.cuboids[c].name.c_str(), at[0], at[1], at[2], at[3], at[4], at[5]);
        }
    }
}

void printChanges(const function::Model& before, const function::Model& after)
{
    for (const function::Part& part : before.parts) {
        std::string changes;
        for (int c : part.cuboids)
            for (int k = 0; k < 6; ++k) {
                const double from = before.cuboids[c].coordinates[k], to = after.cuboids[c].coordinates[k];
                if (std::abs(to - from) > 1e-4) {  // smaller is solver noise
                    char text[160];
                    std::snprintf(text, sizeof text, "  %s %.6g -> %.6g",
                                  function::faceName(before, {c, static_cast<function::Side>(k)}).c_str(),
                                  from, to);
                    changes += text;
                }
            }
        std::printf("part %-20s %s\n", part.name.c_str(), changes.empty() ? "unchanged" : changes.c_str());
    }
}

int run(const SolveArguments& args)
{
    if (!args.output.empty())
        io::checkWritableFile(args.output);
    const function::Model model = io::readWorkslike(io::readJsonFile(args.input));
    const function::SolveResult result = function::solve(model);
    auto status = [&](const std::string& name) {
        if (result.solved)
            return "satisfied";
        return std::find(result.conflict.begin(), result.conflict.end(), name) != result.conflict.end()
                   ? "CONFLICT"
                   : "-";
    };
    auto report = [&](const char* kind, const auto& relationships) {
        for (const auto& r : relationships)
            std::printf("%-10s %-30s %s\n", kind, r.name.c_str(), status(r.name));
    };
    report("cover", model.cover);
    report("fit inside", model.fitInside);
    report("support", model.support);
    report("flush", model.flush);
    report("geometric", model.geometric);
    if (!result.solved) {
        std::fprintf(stderr, "fabguide solve: these cannot hold together: %s\n",
                     joined(result.conflict, quoted).c_str());
        for (const std::string& note : result.notes)
            std::fprintf(stderr, "  %s\n", note.c_str());
        return 1;
    }
    for (const std::string& note : result.notes)
        std::printf("note: %s\n", note.c_str());
    printChanges(model, result.model);
    if (args.poses)
        printPoses(result.model);
    std::printf("largest violation %.2g mm\n", result.violation);
    if (!args.output.empty()) {
        io::writeJsonFile(args.output, io::workslikeToJson(result.model, &result));
        std::printf("solved model  %s\n", args.output.c_str());
    }
    return 0;
}

}  // namespace

void addSolveCommand(CLI::App& app)
{
    auto args = std::make_shared<SolveArguments>();
    auto* cmd = app.add_subcommand(
        "solve", "Size the parts of a works-like model so its relationships hold (*.workslike.json)");
    cmd->add_option("input", args->input, "*.workslike.json")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "solved model to write");
    cmd->add_flag("--poses", args->poses, "print where each cuboid is in each configuration");
    cmd->callback([args] {
        if (const int code = run(*args))
            throw CLI::RuntimeError(code);
    });
}

}  // namespace fabguide::cli
