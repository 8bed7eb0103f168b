// The use case of a flat-pack design's recompute (thesis 5.3.5, 5.3.2): the user's edit of the boards kept as
// far as the constraints allow, boards moved until a constraint just added holds, the design laid out, and an
// edit that overflows the master boards absorbed by the dynamic packer or undone. One call, one layout.
#pragma once

#include "IO/FlatpackFormat.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fabguide::api {

struct DesignEdit {
    nlohmann::json design;  ///< the design as drawn now (`*.flatpack.json`, docs/formats.md)
    /// The boards' last valid state (the format's parts): an edit of the same boards is kept valid from it
    /// and absorbed from it. None, or other boards: the design is taken as drawn.
    std::optional<nlohmann::json> valid;
    bool keepEdits = true;  ///< false: the boards are taken as drawn, only moved when constraints break
    double seconds = 2;     ///< the layout's search (material::layOut)
    std::uint64_t seed = 1;
};

struct DesignEditReport {
    /// The design as it ends, its inner volumes moved with their boards: the boards corrected, satisfied or
    /// absorbed; the valid ones when the edit was undone.
    nlohmann::json design;
    double kept = 1;                   ///< the share of the edit the constraints kept (alpha, 5.3.5)
    std::vector<std::string> limits;   ///< the constraints that held it short
    bool satisfied = false;            ///< boards moved so that every constraint holds (one just added)
    bool absorbed = false;             ///< the edit overflowed the boards and the dynamic packer made it fit
    std::vector<std::string> snapped;  ///< the snapping lines that absorbed it
    std::string undone;                ///< why the edit was undone; empty when the design was laid out
    std::string warning;     ///< why the valid state could not be read (the design is then taken as drawn)
    nlohmann::json laidOut;  ///< {measures, layout, problem} (io::designLayoutJson); null when undone
};

/// The design `f` laid out as it is: the layout's search of `seconds`, or the layout `kept` when that is
/// better (material::layOut); {measures, layout, problem} (io::designLayoutJson). Throws
/// material::PackingError naming a part left over.
nlohmann::json layOutDesign(const io::FlatpackDesign& f, std::uint64_t seed, double seconds,
                            const material::KeptLayout& kept);

/// Runs the edit. Throws io::FormatError naming a bad field, io::ConstraintError when no move of the boards
/// makes every constraint hold, material::PackingError when the design does not fit and there is no edit to
/// absorb or undo.
DesignEditReport editDesign(const DesignEdit& edit);

}  // namespace fabguide::api
