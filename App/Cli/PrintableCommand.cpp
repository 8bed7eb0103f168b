// `fabguide printable`: a works-like model as print-in-place bodies (thesis 4.5), checked, written as STL,
// 3MF and STEP.
#include "Api/PrintInPlace.h"
#include "Cli/Commands.h"
#include "Core/Text.h"
#include "IO/Json.h"
#include "IO/Output.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"

#include <Standard_Failure.hxx>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace fabguide::cli {

namespace {

struct PrintableArguments {
    std::string input, output = "printable", printer = "fdm", fit;
    double gap = -1, scale = 1, partSeconds = printable::Printer{}.partSeconds;
};

/// "250x210x210": a build volume in mm (width x depth x height); empty when the text is not one.
std::optional<printable::Size> buildVolume(const std::string& text)
{
    printable::Size size{};
    char x1 = 0, x2 = 0;
    std::istringstream in(text);
    in >> size[0] >> x1 >> size[1] >> x2 >> size[2];
    if (!in || x1 != 'x' || x2 != 'x' || !(in >> std::ws).eof() ||
        std::any_of(size.begin(), size.end(), [](double v) { return !(v > 0); }))
        return std::nullopt;
    return size;
}

/// report.json: what the run made and measured, for tools and tests (docs/formats.md).
nlohmann::json reportJson(const api::PrintReport& made, double seconds, const std::vector<std::string>& files)
{
    nlohmann::json bodies = nlohmann::json::array();
    for (size_t b = 0; b < made.volumes.size(); ++b)
        bodies.push_back({{"name", made.fitted.printable.bodies[b].name}, {"volume_mm3", made.volumes[b]}});
    std::vector<std::string> names;  // in the output folder
    for (const std::string& path : files)
        names.push_back(std::filesystem::path(path).filename().string());
    const printable::Check& check = *made.check;
    return {{"format", "fabguide.printable-report"},
            {"version", 1},
            {"ok", made.ok()},
            {"scale", made.fitted.scale},
            {"turned", made.fitted.turned},
            {"size_mm", made.size},
            {"gap_mm", made.gap},
            {"clearance", {{"least_mm", check.clearance}, {"where", check.where}}},
            {"invalid", check.invalid},
            {"loose", check.loose},
            {"bodies", bodies},
            {"notes", made.fitted.printable.notes},
            {"seconds", seconds},
            {"files", names}};
}

int run(const PrintableArguments& args)
{
    const auto started = std::chrono::steady_clock::now();
    io::checkWritableFolder(args.output);  // before minutes of geometry, not after
    io::OutputBatch files;
    api::PrintJob job;
    job.model = io::readJsonFile(args.input);
    job.printer = args.printer;
    job.gap = args.gap >= 0 ? std::optional<double>(args.gap) : std::nullopt;
    job.scale = args.scale;
    job.fit = args.fit.empty() ? std::nullopt : buildVolume(args.fit);
    job.partSeconds = args.partSeconds;
    const api::PrintReport made = api::printInPlace(job);
    if (job.fit)
        std::printf("scale %.4g: fits %s mm%s\n", made.fitted.scale, args.fit.c_str(),
                    made.fitted.turned ? ", turned a quarter about z" : "");
    std::printf("size %.1f x %.1f x %.1f mm\n", made.size[0], made.size[1], made.size[2]);
    for (size_t b = 0; b < made.volumes.size(); ++b)
        std::printf("body %-28s %10.1f mm3\n", made.fitted.printable.bodies[b].name.c_str(), made.volumes[b]);
    const printable::Check& check = *made.check;
    for (const std::string& note : made.fitted.printable.notes)
        std::printf("note: %s\n", note.c_str());
    for (const std::string& name : check.invalid)
        std::printf("INVALID solid: %s\n", name.c_str());
    for (const std::string& body : check.loose)
        std::printf(
            "IN PIECES: %s (a cut went through it: a joint turning the wrong way round, or a "
            "part in the way)\n",
            body.c_str());
    std::printf("minimum clearance %.3f mm (gap %.2f mm): %s\n", check.clearance, made.gap,
                check.where.c_str());
    io::replaceSetOf((std::filesystem::path(args.output) / "report.json").string());  // bodies since renamed
    std::vector<std::string> written =
        io::writePrintFiles(printable::onTheBed(made.fitted.printable, made.fitted.turned), args.output);
    const std::string solvedPath = (std::filesystem::path(args.output) / "solved.workslike.json").string();
    io::writeJsonFile(solvedPath, io::workslikeToJson(made.fitted.solved));
    written.push_back(solvedPath);
    for (const std::string& path : written)
        std::printf("wrote %s\n", path.c_str());
    const std::string reportPath = (std::filesystem::path(args.output) / "report.json").string();
    written.push_back(reportPath);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    io::writeJsonFile(reportPath, reportJson(made, seconds, written));
    std::printf("wrote %s\n", reportPath.c_str());
    files.commit();
    if (made.ok())
        return 0;
    std::fprintf(stderr,
                 "fabguide printable: not printable as it is: %s (the files are written to look at)\n",
                 joined(made.failures(), asIs, "; ").c_str());
    return 1;
}

}  // namespace

void addPrintableCommand(CLI::App& app)
{
    auto args = std::make_shared<PrintableArguments>();
    auto* cmd = app.add_subcommand("printable", kPrintableSummary);
    cmd->add_option("input", args->input, "*.workslike.json (solved or not: it is solved first)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "folder for assembly.* and one file per body")
        ->capture_default_str();
    std::vector<std::string> printers;
    for (const api::PrinterProfile& p : api::printerProfiles())
        printers.push_back(p.id);
    cmd->add_option("--printer", args->printer, "printer profile: fdm (0.4 mm gap) or resin (0.2 mm)")
        ->check(CLI::IsMember(printers))
        ->capture_default_str();
    cmd->add_option("--gap", args->gap, "clearance between parts in mm (overrides the printer's)")
        ->check(between(0.01, 10.0));
    cmd->add_option(
           "--part-seconds", args->partSeconds,
           "what OpenCASCADE may take on one part or joint at each step before the run stops with an "
           "error naming it")
        ->check(between(0.001, 86400.0))
        ->capture_default_str();
    auto* scale =
        cmd->add_option("--scale", args->scale, "print at this scale, e.g. 0.2 for 1:5 (the gap stays in mm)")
            ->check(between(0.001, 100.0))
            ->capture_default_str();
    cmd->add_option("--fit", args->fit,
                    "print at the largest scale (at most 1) that fits this build volume, WxDxH in mm, e.g. "
                    "250x210x210 (upright; turned a quarter about z if that prints larger)")
        ->check(CLI::Validator(
            [](const std::string& text) {
                return buildVolume(text) ? std::string()
                                         : "expected width x depth x height in mm, e.g. 250x210x210";
            },
            "WxDxH"))
        ->excludes(scale);
    cmd->callback([args] {
        int code = 0;
        try {
            code = run(*args);
        } catch (const Standard_Failure& e) {  // OpenCASCADE's exceptions are not std::exceptions
            throw std::runtime_error(std::string("geometry error: ") + e.GetMessageString() + " (" +
                                     e.DynamicType()->Name() + ")");
        }
        if (code)
            throw CLI::RuntimeError(code);
    });
}

}  // namespace fabguide::cli
