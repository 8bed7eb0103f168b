// `fabguide pack`: lay parts out on master boards (thesis 5.3.1, 5.4.3), or pack a strip.
#include "Api/Pack.h"
#include "Cli/Commands.h"
#include "Cli/Main.h"
#include "Core/Parallel.h"
#include "IO/Json.h"
#include "IO/LayoutFiles.h"
#include "IO/Output.h"
#include "IO/PackFormat.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>

namespace fabguide::cli {

namespace {

struct PackArguments {
    std::string input;
    std::string output;
    io::LayoutFiles files;
    bool bottomLeft = false;
    api::PackJob job;  // its document read from `input`
};

void run(const PackArguments& args)
{
    io::checkWritableFile(args.output);
    const io::LayoutFiles& out = args.files;
    for (const std::string* folder : {&out.svgFolder, &out.dxfFolder})
        if (!folder->empty())
            io::checkWritableFolder(*folder);
    for (const std::string* file : {&out.csvFile, &out.reportFile, &out.labelsFile, &out.optiCutterFile})
        if (!file->empty())
            io::checkWritableFile(*file);
    io::OutputBatch files;
    api::PackJob job = args.job;
    job.document = io::readJsonFile(args.input);
    job.search.timeLimit =
        std::max(0.0, job.search.timeLimit - secondsSinceStart());  // start-up and reading count
    job.search.criterion = args.bottomLeft ? material::Criterion::BottomLeft : material::Criterion::Docking;
    const auto [problem, layout] = api::pack(job);
    const nlohmann::json written =
        io::layoutToJson(layout, problem, job.strip ? io::PartNames::Indices : io::PartNames::Ids);
    io::writeJsonFile(args.output, written);

    std::printf("%zu parts on %zu board(s)\n", layout.placements.size(), layout.sheets.size());
    if (problem.strip)
        std::printf("strip height  %.6g (width %.6g)\n", layout.stripHeight, layout.sheets[0].width);
    std::printf("usage         %.4f  (part area / layout bounding rectangle)\n", layout.usage());
    std::printf("utilisation   %.4f  (part area / boards used)\n", layout.sheetUtilisation());
    std::printf("waste area    %.6g mm^2\n", layout.wasteArea());
    if (!layout.sawCuts.empty()) {
        size_t count = 0;
        double length = 0;
        for (const std::vector<material::SawCut>& sheet : layout.sawCuts)
            for (const material::SawCut& c : sheet)
                ++count, length += c.length();
        std::printf("saw cuts      %zu, %.1f m\n", count, length / 1000);
    }
    if (written.contains("common_line") && !out.options.asDesigned && layout.sawCuts.empty())
        std::printf("common line   %.1f m cut once for two parts\n",
                    written["common_line"].get<double>() / 1000);
    std::printf("layout        %s\n", args.output.c_str());
    io::LayoutFiles named = out;
    named.title = std::filesystem::path(args.input).stem().stem().string();  // job.pack.json: job
    for (const io::WrittenFile& file : io::writeLayoutFiles(layout, problem, named))
        std::printf("%-13s %s\n", file.what.c_str(), file.path.c_str());
    files.commit();
}

}  // namespace

void addPackCommand(CLI::App& app)
{
    auto args = std::make_shared<PackArguments>();
    auto* cmd = app.add_subcommand("pack", "Lay parts out on master boards (*.pack.json) or pack a strip");
    cmd->add_option("input", args->input, "*.pack.json, or an OR-Datasets instance with --strip")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "layout JSON to write")->required();
    cmd->add_option("--svg", args->files.svgFolder,
                    "folder for one SVG cut sheet per board (an Inkscape layer per operation)");
    cmd->add_option("--dxf", args->files.dxfFolder,
                    "folder for one DXF R2000 cut sheet per board (a layer per operation)");
    cmd->add_option("--csv", args->files.csvFile, "CSV cut list to write");
    cmd->add_option(
        "--report", args->files.reportFile,
        "PDF report to write: each sheet with its parts numbered and sized, grain, edge banding and "
        "saw cuts, then the cut list and the totals");
    cmd->add_option(
        "--opticutter", args->files.optiCutterFile,
        "the job as optiCutter's CSV import (parts, sheets, kerf), to compare or optimise there; one "
        "file per thickness");
    cmd->add_option("--labels", args->files.labelsFile,
                    "PDF of labels for a label printer, one page per part cut");
    cmd->add_option("--label-size", args->files.labelSize, "label width and height in mm")
        ->delimiter('x')
        ->check(between(1.0, 1000.0))
        ->capture_default_str();
    cmd->add_flag(
        "--text-labels", args->files.options.textLabels,
        "labels as text in a font (default: as single strokes to engrave, which laser software, CAM "
        "and FreeCAD's DXF import take as they are)");
    cmd->add_flag("--as-designed", args->files.options.asDesigned,
                  "cut sheets for CAM software that offsets by its tool itself: the parts' nominal outlines, "
                  "closed, no dogbones, the holding tabs on a layer of their own (default: tool paths as the "
                  "machine cuts them, offset by half the kerf)");
    cmd->add_flag(
           "--common-line", args->job.commonLine,
           "common-line cutting: a line two parts a kerf apart share is cut once, by the part cut first "
           "(default: the file's settings.common_line)")
        ->excludes("--as-designed");
    cmd->add_flag("--strip", args->job.strip,
                  "input is an OR-Datasets strip-packing instance: fixed width, minimise height");
    cmd->add_flag("--bottom-left", args->bottomLeft, "place by Bottom-Left instead of the docking criterion");
    cmd->add_option(
           "--rotation-step", args->job.rotationStep,
           "free rotation: parts without grain that may take every quarter turn may take every multiple "
           "of this many degrees (a divisor of 90, e.g. 15); 0: quarter turns (default: the file's "
           "settings.rotation_step)")
        ->check(CLI::Range(0, 90));
    cmd->add_option(
           "--cuts", args->job.cuts,
           "free: any outline (CNC, laser); guillotine: straight cuts from edge to edge (panel saw), "
           "with the cut sequence in the layout (default: the file's settings.cuts)")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, material::Cuts>(io::cutsNames().begin(), io::cutsNames().end())));
    cmd->add_option("--stages", args->job.stages,
                    "guillotine cuts: at most this many changes of direction (2, 3, ...; 0: unlimited; "
                    "default: the file's settings.stages)")
        ->check(CLI::Range(0, 100));
    cmd->add_option("--first-cut", args->job.firstCut,
                    "guillotine cuts: the first cuts along the sheet's length, across it, or any "
                    "(default: the file's settings.first_cut)")
        ->transform(CLI::CheckedTransformer(std::map<std::string, material::FirstCut>(
            io::firstCutNames().begin(), io::firstCutNames().end())));
    cmd->add_option("--seed", args->job.search.seed, "seed of the ordering search")
        ->check(kSeeds)
        ->capture_default_str();
    cmd->add_option(
           "--time-limit", args->job.search.timeLimit,
           "seconds for the run, from start-up to the files written (most of it the ordering search)")
        ->check(between(0.0, 86400.0))
        ->capture_default_str();
    args->job.search.iterations = std::numeric_limits<long>::max();
    cmd->add_option(
           "--iterations", args->job.search.iterations,
           "ordering swaps to try, and as many runs of the saw's search (default: as many as --time-limit "
           "allows; -1: parts squared, and 2000 runs)")
        ->check(CLI::Range(-1LL, 1000000000000000000LL));
    args->job.search.threads = cores();
    cmd->add_option(
           "--threads", args->job.search.threads,
           "threads of the search: its starts, a strip's skyline searches, a saw's beam search beside its "
           "rules, run at once")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    cmd->add_option("--history", args->job.search.memory, "late-acceptance history of the ordering search")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->callback([args] { run(*args); });
}

}  // namespace fabguide::cli
