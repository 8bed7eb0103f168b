// `fabguide printable`: a works-like model as print-in-place bodies (thesis 4.5), checked, written as STL,
// 3MF and STEP.
#include "Cli/Commands.h"
#include "IO/Json.h"
#include "IO/Output.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"
#include "Printable/Checks.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
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

/// Printer profiles: the gap a printer needs so parts do not fuse (FDM 0.4 mm, resin 0.2 mm).
const std::map<std::string, double> kPrinters{{"fdm", 0.4}, {"resin", 0.2}};

/// report.json: what the run made and measured, for tools and tests (docs/formats.md).
nlohmann::json report(const printable::Fitted& fitted, const std::vector<double>& volumes,
                      const printable::Size& size, const printable::Check& check, double gap, bool ok,
                      double seconds, const std::vector<std::string>& files)
{
    nlohmann::json bodies = nlohmann::json::array();
    for (size_t b = 0; b < volumes.size(); ++b)
        bodies.push_back({{"name", fitted.printable.bodies[b].name}, {"volume_mm3", volumes[b]}});
    std::vector<std::string> names;  // in the output folder
    for (const std::string& path : files)
        names.push_back(std::filesystem::path(path).filename().string());
    return {{"format", "fabguide.printable-report"},
            {"version", 1},
            {"ok", ok},
            {"scale", fitted.scale},
            {"turned", fitted.turned},
            {"size_mm", size},
            {"gap_mm", gap},
            {"clearance", {{"least_mm", check.clearance}, {"where", check.where}}},
            {"invalid", check.invalid},
            {"loose", check.loose},
            {"bodies", bodies},
            {"notes", fitted.printable.notes},
            {"seconds", seconds},
            {"files", names}};
}

int run(const PrintableArguments& args)
{
    const auto started = std::chrono::steady_clock::now();
    io::checkWritableFolder(args.output);  // before minutes of geometry, not after
    io::OutputBatch files;
    const double gap = args.gap >= 0 ? args.gap : kPrinters.at(args.printer);
    const std::optional<printable::Size> fit = args.fit.empty() ? std::nullopt : buildVolume(args.fit);
    const printable::Printer printer{gap, args.partSeconds};
    printable::Fitted fitted =
        printable::printed(io::readWorkslike(io::readJsonFile(args.input)), printer, args.scale, fit);
    if (fit)
        std::printf("scale %.4g: fits %s mm%s\n", fitted.scale, args.fit.c_str(),
                    fitted.turned ? ", turned a quarter about z" : "");
    const function::Model& model = fitted.model;
    // Joint geometry placed where it clears, then checked as written.
    const printable::Checked placed = printable::placedByCheck(model, fitted.printable, printer);
    fitted.printable = placed.printable;
    const printable::Printable& made = fitted.printable;
    const printable::Check& check = placed.check;
    const printable::Printable onTheBed = printable::onTheBed(made, fitted.turned);
    const printable::Size size = printable::sizeOf(onTheBed);
    std::printf("size %.1f x %.1f x %.1f mm\n", size[0], size[1], size[2]);
    std::vector<double> volumes;
    for (const printable::Body& b : made.bodies) {
        GProp_GProps volume;
        BRepGProp::VolumeProperties(b.shape, volume);
        volumes.push_back(volume.Mass());
        std::printf("body %-28s %10.1f mm3\n", b.name.c_str(), volumes.back());
    }
    for (const std::string& note : made.notes)
        std::printf("note: %s\n", note.c_str());
    for (const std::string& name : check.invalid)
        std::printf("INVALID solid: %s\n", name.c_str());
    for (const std::string& body : check.loose)
        std::printf(
            "IN PIECES: %s (a cut went through it: a joint turning the wrong way round, or a "
            "part in the way)\n",
            body.c_str());
    std::printf("minimum clearance %.3f mm (gap %.2f mm): %s\n", check.clearance, gap, check.where.c_str());
    io::replaceSetOf((std::filesystem::path(args.output) / "report.json").string());  // bodies since renamed
    std::vector<std::string> written = io::writePrintFiles(onTheBed, args.output);
    for (const std::string& path : written)
        std::printf("wrote %s\n", path.c_str());
    const std::string reportPath = (std::filesystem::path(args.output) / "report.json").string();
    written.push_back(reportPath);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const bool ok = check.invalid.empty() && check.loose.empty() && check.clearance >= gap - 0.01;
    io::writeJsonFile(reportPath, report(fitted, volumes, size, check, gap, ok, seconds, written));
    std::printf("wrote %s\n", reportPath.c_str());
    files.commit();
    return ok ? 0 : 1;
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
    cmd->add_option("--printer", args->printer, "printer profile: fdm (0.4 mm gap) or resin (0.2 mm)")
        ->check(CLI::IsMember({"fdm", "resin"}))
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
