// `fabguide printable`: a works-like model as print-in-place bodies (thesis 4.5), checked, written as STL,
// 3MF and STEP.
#include "Cli/Commands.h"
#include "IO/Json.h"
#include "IO/PrintFiles.h"
#include "IO/WorkslikeFormat.h"
#include "Printable/Checks.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <cstdio>
#include <map>
#include <memory>

namespace fabguide::cli {

namespace {

struct PrintableArguments {
    std::string input, output = "printable", printer = "fdm";
    double gap = -1, scale = 1;
};

/// Printer profiles: the gap a printer needs so parts do not fuse (FDM 0.4 mm, resin 0.2 mm).
const std::map<std::string, double> kPrinters{{"fdm", 0.4}, {"resin", 0.2}};

int run(const PrintableArguments& args)
{
    const function::Model model =
        printable::solvedToPrint(io::readWorkslike(io::readJsonFile(args.input)), args.scale);
    const double gap = args.gap >= 0 ? args.gap : kPrinters.at(args.printer);
    const printable::Printable made = printable::makePrintable(model, {gap});
    for (const printable::Body& b : made.bodies) {
        GProp_GProps volume;
        BRepGProp::VolumeProperties(b.shape, volume);
        std::printf("body %-28s %10.1f mm3\n", b.name.c_str(), volume.Mass());
    }
    for (const std::string& note : made.notes)
        std::printf("note: %s\n", note.c_str());
    const printable::Check check = printable::check(model, made, gap);
    for (const std::string& name : check.invalid)
        std::printf("INVALID solid: %s\n", name.c_str());
    std::printf("minimum clearance %.3f mm (gap %.2f mm): %s\n", check.clearance, gap, check.where.c_str());
    for (const std::string& path : io::writePrintFiles(made, args.output))
        std::printf("wrote %s\n", path.c_str());
    return check.invalid.empty() && check.clearance >= gap - 0.01 ? 0 : 1;
}

}  // namespace

void addPrintableCommand(CLI::App& app)
{
    auto args = std::make_shared<PrintableArguments>();
    auto* cmd =
        app.add_subcommand("printable",
                           "Turn a works-like model into print-in-place bodies: cavities, joints, gaps; "
                           "check them; write STL, 3MF and STEP");
    cmd->add_option("input", args->input, "*.workslike.json (solved or not: it is solved first)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", args->output, "folder for assembly.* and one file per body")
        ->capture_default_str();
    cmd->add_option("--printer", args->printer, "printer profile: fdm (0.4 mm gap) or resin (0.2 mm)")
        ->check(CLI::IsMember({"fdm", "resin"}))
        ->capture_default_str();
    cmd->add_option("--gap", args->gap, "clearance between parts in mm (overrides the printer's)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--scale", args->scale, "print at this scale, e.g. 0.2 for 1:5 (the gap stays in mm)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->callback([args] {
        if (const int code = run(*args))
            throw CLI::RuntimeError(code);
    });
}

}  // namespace fabguide::cli
