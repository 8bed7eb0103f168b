// The flat-pack design format `*.flatpack.json` (docs/formats.md): boards in 3-D with design constraints,
// effectiveness constraints and the master boards to cut them from (thesis 5.1).
#pragma once

#include "Design/Design.h"
#include "Design/MinWastage.h"
#include "IO/Json.h"
#include "Layout/Pack.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace fabguide::io {

constexpr int kFlatpackFormatVersion = 2;

/// Boards to cut (quantities added up) the design exploration finishes in its time limit: 300
/// snapped in a row took 3.3 s of a 2 s limit (one correction of their constraints, or one QP of their
/// sheets, takes seconds), 1,000 took 21 s (each layout docked whole).
constexpr long kMostDesignBoards = 200;

struct FlatpackDesign {
    material::Design design;
    std::vector<material::MasterBoard> boards;
    material::PackSettings settings;
    double maxGrowth =
        1.5;  ///< settings.max_growth: how many times its length now a suggestion may make a side
    /// "layout" (or the older "layout_order", its order alone): the layout the file keeps, as a suggestion is
    /// written, so that it reopens on the sheets it was found on.
    material::KeptLayout kept;
    /// The document read in its normal form (docs/formats.md): this version's, with every default the reader
    /// took written in, what FreeCAD's import builds from.
    nlohmann::json document;
};

/// The design the suggestions are searched in: `f`'s, with no board side longer than maxGrowth times its
/// length now (a 60 mm batten grown into a 373 mm panel, a cleat into a board). Only the search is
/// held to it: the user's own edits and the files read are not.
material::Design forSuggestions(const FlatpackDesign& f);

/// A design that does not satisfy its own constraints (the message names them, and `names` lists every one,
/// constraints and inner volumes by their own names): a FormatError the caller may answer by moving the
/// boards (thesis 5.3.5.2).
struct ConstraintError : FormatError {
    ConstraintError(const std::string& message, std::vector<std::string> broken)
        : FormatError(message), names(std::move(broken))
    {
    }
    std::vector<std::string> names;
};

/// Whether a design read must already satisfy its constraints.
enum class Satisfied { Required, NotRequired };

/// The parts of a parametric design (thesis 5.4.2.2), [{id, quantity (1), grain ("free", "x", "y" or "z")}]:
/// their kinds and each one's grain axis (-1: free). FormatError naming the field (parts[2].grain).
struct ParametricParts {
    std::vector<material::PartKind> kinds;
    std::vector<int> grainAxes;
};
ParametricParts readParametricParts(const nlohmann::json& parts);

/// `board`'s centre and size from its corners as the format writes them (`part`'s "min" and "max").
void placeBoard(material::DesignBoard& board, const Fields& part);

/// `document` in this version's form: the migrations from the version it was written in applied in turn
/// (version 1 wrote a box as "position" and "size"). FormatError naming a field a migration cannot read.
nlohmann::json currentFlatpack(nlohmann::json document);

/// Reads a `*.flatpack.json` document of this version or an older one. Throws FormatError naming the
/// offending field, and, unless told otherwise, when the design does not satisfy its own constraints (naming
/// them).
FlatpackDesign readFlatpack(const nlohmann::json& document, Satisfied satisfied = Satisfied::Required);

/// The boards of `document` drawn equal (Design/DrawnEqual.h) as the "equal" constraints of the format it
/// lacks, for the user to keep: [{"kind": "equal", "name": "drawn equal: size.z of post, post 2", "refs":
/// ["post.size.z", "post 2.size.z"]}]. The design need not satisfy its own constraints yet.
nlohmann::json drawnEqualConstraints(const nlohmann::json& document);

/// The parts at design vector X: [{"id", "min", "max"}].
nlohmann::json partsAt(const material::Design& design, const Eigen::VectorXd& X);

/// `document` with its parts moved and resized to X, its inner volumes moved with their boards; constraints
/// and the outer volume as they were.
nlohmann::json withParts(nlohmann::json document, const material::Design& design, const Eigen::VectorXd& X);

/// What a maker reads off a laid-out design: {"usage" (thesis 5.2.3), "sheets", "waste_m2",
/// "largest_offcut": [w, h] mm}.
nlohmann::json measures(const material::DesignLayout& d);

/// A design's layout as the bindings give it: its measures, "layout" (layoutToJson, parts by id) and
/// "problem" (problemToJson), the pack problem the layout refers to.
nlohmann::json designLayoutJson(const material::MaterialSpace& material, const material::DesignLayout& d);

/// An exploration's figures, as `fabguide optimise`'s summary.json and the binding's result both give them:
/// {"usage_before", "seconds", "stopped", "least_sheets", "least_sheets_by_area", "least_sheets_bound",
/// "no_sheet_saved", "not_reopened"} (docs/formats.md).
nlohmann::json explorationFigures(const material::Exploration& e);

/// A suggestion as a `*.flatpack.json` document: `document` with the suggested parts, plus "usage", "path":
/// [{"usage", "parts"}] from the user's design to the suggestion, at most `steps` of them (evenly picked,
/// first and last kept), and "layout_order": the part ids in the order its layout docked them (`material`'s
/// units).
nlohmann::json suggestionDocument(const nlohmann::json& document, const material::Design& design,
                                  const material::MaterialSpace& material,
                                  const material::Suggestion& suggestion, size_t steps = 40);

}  // namespace fabguide::io
