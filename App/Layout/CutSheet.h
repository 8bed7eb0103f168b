// Cutting plans for a layout (thesis 5.1): per master board, the tool paths and the part labels.
#pragma once

#include "Geometry/Polygon.h"
#include "Layout/Pack.h"

#include <string>
#include <vector>

namespace fabguide::material {

/// Text engraved on a part, centred at `at`, `height` mm tall.
struct Label {
    std::string text;
    geometry::Point2 at;  ///< the text's centre
    double height = 0;
    double angle = 0;  ///< degrees counter-clockwise: 90 along a part that stands taller than wide
};

/// One master board's cutting plan, in board coordinates (origin at its lower-left corner).
struct CutSheet {
    MasterBoard board;
    std::vector<geometry::Polygon> cuts;  ///< closed tool paths, holes before outer contours
    /// Open tool paths, cut last: small parts' outer contours broken by holding tabs (settings.tabWidth),
    /// so the part stays in the sheet when cut free.
    std::vector<geometry::Polygon> tabbed;
    std::vector<Label> labels;
    std::vector<Drill> drills;                ///< holes drilled into the face, not through
    std::vector<geometry::Polygon> engraved;  ///< marks engraved on the parts (where to bore an edge)
    std::vector<SawCut> sawCuts;  ///< guillotine cuts: the saw's, in their order (Layout::sawCuts)
};

/// Placement k's outline at its nominal size, turned and moved as placed on its sheet.
geometry::Outline placedOutline(const Layout& layout, const PackProblem& problem, size_t k);

/// The cutting plans of a layout: each part's outline turned and moved as placed, offset by half
/// the kerf so that the cut leaves it at nominal size (outer contours outward, holes inward).
std::vector<CutSheet> cutSheets(const Layout& layout, const PackProblem& problem);

/// One row of a cut list: how many of a part are cut from one board, and their size.
struct CutListRow {
    std::string part;
    int quantity = 0;
    double width = 0, height = 0, thickness = 0;
    std::string material;
    int board = 0;  ///< index into Layout::sheets
};

/// The cut list of a layout, one row per (part, board), in part order then board order.
std::vector<CutListRow> cutList(const Layout& layout, const PackProblem& problem);

}  // namespace fabguide::material
