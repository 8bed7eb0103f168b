// The use case of printing a works-like model in place (thesis 4.5): the model read and solved, scaled or
// fitted to a build volume, its bodies made, the joint geometry placed where it clears and checked along
// every motion, each body measured, and the print's pass rule. `fabguide-print printable` and the binding
// `printable` run it; the one writes files, the other hands the bodies to FreeCAD.
#pragma once

#include "Printable/Checks.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace fabguide::api {

/// A printer profile: the gap its parts need so they do not fuse.
struct PrinterProfile {
    std::string id;    ///< as `--printer` takes it
    std::string name;  ///< as FreeCAD's Printer property shows it, with the gap
    double gap = 0.4;
};

/// FDM (0.4 mm) and resin (0.2 mm).
const std::vector<PrinterProfile>& printerProfiles();

struct PrintJob {
    nlohmann::json model;  ///< a `*.workslike.json` model, solved or not (docs/formats.md)
    std::string printer = "fdm";
    std::optional<double> gap;  ///< mm; overrides the printer's
    double scale = 1;
    std::optional<printable::Size> fit;  ///< the build volume: the largest scale (at most 1) that fits it
    double partSeconds = printable::Printer{}.partSeconds;
    bool check = true;  ///< joint geometry placed where it clears, then checked along every motion
};

struct PrintReport {
    printable::Fitted fitted;  ///< the model as printed (solved, scaled) and its bodies, placed as checked
    std::optional<printable::Check> check;
    double gap = 0.4;
    printable::Size size{};       ///< on the bed, mm
    std::vector<double> volumes;  ///< each body's, mm³

    /// Parts come nearer than the gap somewhere along a motion (a hundredth of a mm to spare).
    bool tooClose() const;
    /// Why the print does not pass, each in words: an invalid solid, a body in pieces, parts nearer than the
    /// gap (and where); none when it passes or was not checked.
    std::vector<std::string> failures() const;
    /// The print passes: checked, and nothing fails.
    bool ok() const;
};

/// Runs the job. Throws io::FormatError naming a bad field, std::runtime_error (or OpenCASCADE's
/// Standard_Failure) naming what fails.
PrintReport printInPlace(const PrintJob& job);

}  // namespace fabguide::api
