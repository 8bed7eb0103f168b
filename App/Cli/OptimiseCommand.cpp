// `fabguide optimise`: design variations that waste less material (thesis 5.4, MINWASTAGE).
#include "Api/Explore.h"
#include "Cli/Commands.h"
#include "IO/CutSheetFiles.h"
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"
#include "IO/Output.h"
#include "IO/PackFormat.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace fabguide::cli {

namespace {

struct OptimiseArguments {
    std::string input;
    std::string output;
    material::MinWastageOptions options;
    bool unguided = false;
    bool keepDrawnEqual = false;
};

/// An offcut narrower than this (mm) is sawdust, not a board for the next job.
constexpr double kLeastOffcut = 100;

/// Layout JSON and SVG cut sheets of one design into out/<name>.layout.json and out/<name>/sheet-N.svg, and
/// its offcuts as master boards into out/<name>.offcuts.json.
nlohmann::json writeLayout(const material::MaterialSpace& material, const material::DesignLayout& d,
                           const std::filesystem::path& out, const std::string& name)
{
    const material::PackProblem problem = material.problem(d.sizes);
    const material::Layout layout = material.inMillimetres(d.layout, d.sizes);
    io::writeJsonFile((out / (name + ".layout.json")).string(),
                      io::layoutToJson(layout, problem, io::PartNames::Ids));
    nlohmann::json svgs = nlohmann::json::array();
    for (const std::string& path : io::writeCutSheets(layout, problem, (out / name).string(), "", ""))
        svgs.push_back(std::filesystem::relative(path, out).string());
    nlohmann::json boards = nlohmann::json::array();  // what is left, for the next job
    for (const material::MasterBoard& board : material.offcuts(d.layout, kLeastOffcut))
        boards.push_back(io::boardToJson(board));
    io::writeJsonFile((out / (name + ".offcuts.json")).string(), {{"boards", boards}});
    nlohmann::json entry = io::measures(d);
    entry["layout"] = name + ".layout.json";
    entry["svg"] = svgs;
    entry["offcuts"] = name + ".offcuts.json";
    return entry;
}

/// Why no variation saved a sheet, in the core's one reading of it (Exploration::noSheetSaved).
std::string whyNone(const material::Exploration& e)
{
    switch (e.noSheetSaved()) {
        case material::Exploration::NoSheetSaved::Bound:
            return ": with every side as short as its constraints allow, its parts need as many sheets "
                   "in any layout";
        case material::Exploration::NoSheetSaved::LaidOut:
            return ": shrunk as far as its constraints allow it was laid out on as many sheets, though its "
                   "parts would fit on " +
                   std::to_string(e.leastSheetsBound) +
                   " by their sizes: more time (--time-limit) may save one";
        default:
            return "";
    }
}

void run(const OptimiseArguments& args)
{
    io::checkWritableFolder(args.output);  // before the search, not after
    io::OutputBatch files;
    api::Exploring job{io::readJsonFile(args.input), args.options, args.keepDrawnEqual};
    job.options.guided = !args.unguided;
    job.options.progress = [](double done, double best) {
        std::fprintf(stderr, "\r%3.0f %%  best usage %.4f", 100 * done, best);
    };
    const api::ExplorationReport report = api::explore(job);
    std::fprintf(stderr, "\n");
    for (const nlohmann::json& equal : report.keptEqual)
        std::printf("kept equal    %s\n", equal["name"].get<std::string>().c_str());
    const material::MaterialSpace& material = report.material;
    const material::Exploration& exploration = report.exploration;

    const std::filesystem::path out(args.output);
    std::filesystem::create_directories(out);
    io::replaceSetOf((out / "summary.json").string());  // a suggestion not found again goes with the new set
    nlohmann::json summary = io::explorationFigures(exploration);
    summary["before"] = writeLayout(material, exploration.start, out, "before");
    summary["suggestions"] = nlohmann::json::array();
    const material::MaterialSpace::Figures& before = exploration.start.figures;
    std::printf("usage before  %.4f  (%zu parts)  %d sheets, waste %.3f m2\n", exploration.usageBefore(),
                report.flatpack.design.boards.size(), before.sheets, before.waste);
    // Boards with a cost of their own (or offcuts, at 0): the suggestions' cost is shown beside the sheets.
    const bool priced = std::any_of(report.flatpack.boards.begin(), report.flatpack.boards.end(),
                                    [](const material::MasterBoard& b) { return b.cost != 1; });
    for (size_t k = 0; k < exploration.suggestions.size(); ++k) {
        const material::Suggestion& s = exploration.suggestions[k];
        const std::string name = "suggestion-" + std::to_string(k + 1);
        io::writeJsonFile((out / (name + ".flatpack.json")).string(), report.suggestionDocument(s));
        nlohmann::json entry = writeLayout(material, s.result, out, name);
        entry["usage_after"] = s.usage();
        entry["file"] = name + ".flatpack.json";
        entry["path_length"] = s.path.size();
        summary["suggestions"].push_back(entry);
        const material::MaterialSpace::Figures& after = s.result.figures;
        std::printf("suggestion %zu  %.4f -> %.4f  %d -> %d sheets, waste %.3f -> %.3f m2", k + 1,
                    exploration.usageBefore(), s.usage(), before.sheets, after.sheets, before.waste,
                    after.waste);
        if (priced)
            std::printf(", cost %.2f -> %.2f", before.cost, after.cost);
        std::printf("  %s\n", (out / entry["file"].get<std::string>()).c_str());
    }
    // Why no sheet was saved, or how many more could be: one layout of the least design, and a bound.
    if (exploration.leastSheets > 0)
        std::printf("least design  %d sheets as laid out (every part as small as the constraints allow)\n",
                    exploration.leastSheets);
    if (exploration.leastSheetsBound > 0)
        std::printf(
            "any variation %ld sheets at least, by its parts' sizes with every side as short as the "
            "constraints allow (by their area alone: %ld)\n",
            exploration.leastSheetsBound, exploration.leastSheetsByArea);
    if (exploration.notReopened > 0)
        std::printf("left out     %d design(s) that waste less but laid out afresh need more boards\n",
                    exploration.notReopened);
    if (exploration.suggestions.empty())
        std::printf("no design variation found that wastes less%s\n", whyNone(exploration).c_str());
    std::printf("seconds       %.2f%s\n", exploration.seconds,
                exploration.stopped ? " (stopped at the time limit)" : "");
    io::writeJsonFile((out / "summary.json").string(), summary);
    files.commit();
}

}  // namespace

void addOptimiseCommand(CLI::App& app)
{
    auto args = std::make_shared<OptimiseArguments>();
    auto* cmd = app.add_subcommand("optimise",
                                   "Suggest design variations that waste less material (*.flatpack.json)");
    cmd->alias("optimize");
    cmd->add_option("input", args->input, "*.flatpack.json design")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "folder for the suggestions and summary.json")->required();
    cmd->add_option("--seed", args->options.seed, "same seed, same suggestions")
        ->check(kSeeds)
        ->capture_default_str();
    cmd->add_option("--threads", args->options.threads, "exploration threads")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    cmd->add_option("--time-limit", args->options.timeLimit, "seconds")
        ->check(between(0.0, 86400.0))
        ->capture_default_str();
    cmd->add_option("--rounds", args->options.rounds,
                    "G: rounds of ordering exploration and design improvement")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_flag("--unguided", args->unguided,
                  "shrink random part sizes instead of the layout's locking chains (the thesis' baseline)");
    cmd->add_flag(
        "--keep-drawn-equal", args->keepDrawnEqual,
        "boards drawn the same size (posts, legs, rails) keep the same size: equal constraints added "
        "and said");
    cmd->callback([args] { run(*args); });
}

}  // namespace fabguide::cli
