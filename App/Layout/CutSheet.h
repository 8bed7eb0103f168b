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
    double angle = 0;      ///< degrees counter-clockwise: 90 along a part that stands taller than wide
    size_t placement = 0;  ///< the placement (Layout::placements) it labels
};

/// One tool path of a cut sheet.
struct ToolPath {
    geometry::Polygon points;
    /// An inner cut: a hole with no part in it, cut before the outline round it. Outer cuts are the parts'
    /// outlines and the holes that hold parts (cut after the parts inside them).
    bool inner = false;
    /// Not a closed contour: a stretch between two holding tabs (settings.tabWidth), so a small part stays in
    /// the sheet when cut free (such paths come last); or what is left of an outline whose other stretches an
    /// earlier path cut (common-line cutting).
    bool open = false;
    /// Holding tabs go on it: as the machine cuts, it is split into open stretches; as designed, it stays
    /// closed and the tabs are listed in CutSheet::tabs.
    bool tabbed = false;
    bool hole = false;     ///< a hole of its part; else the part's outline
    size_t placement = 0;  ///< the placement (Layout::placements) whose outline or hole it is
};

/// Edge banding to glue on a placed part's edge (PartSpec::edgeBanding), drawn just inside that edge.
struct Banding {
    geometry::Point2 from, to;
    std::string band;
};

/// How a cut sheet is drawn. For the machine as it cuts (a laser or a CNC's own path): tool paths offset by
/// half the kerf, dogbones in inside corners, holding tabs as gaps. As designed (CAM software that offsets by
/// its tool itself): the parts' nominal outlines, closed, no dogbones, the tabs listed as data.
struct CutSheetOptions {
    bool asDesigned = false;
    /// Labels as text in a font rather than as engravable strokes (Lettering.h), which laser software,
    /// CAM and FreeCAD's DXF import all take as they are.
    bool textLabels = false;
};

/// One master board's cutting plan, in board coordinates (origin at its lower-left corner).
struct CutSheet {
    MasterBoard board;
    /// In the order to cut them: deepest parts first, holes before outlines, small parts before large.
    std::vector<ToolPath> cuts;
    /// As designed: where holding tabs go, each the stretch of a closed contour it spans.
    std::vector<std::pair<geometry::Point2, geometry::Point2>> tabs;
    std::vector<Label> labels;
    std::vector<std::vector<geometry::Polygon>> lettering;  ///< per label, its strokes (none: text labels)
    std::vector<Drill> drills;                              ///< holes drilled into the face, not through
    std::vector<geometry::Polygon> engraved;  ///< marks engraved on the parts (where to bore an edge)
    std::vector<SawCut> sawCuts;  ///< guillotine cuts: the saw's, in their order (Layout::sawCuts)
    std::vector<Banding> banding;
    double commonLine = 0;  ///< mm of path cut once where two parts share it (PackSettings::commonLine)
};

/// The stretch of part k's bounding box along `side`, turned and moved as placed, as its banded edge.
std::pair<geometry::Point2, geometry::Point2> placedSide(const Layout& layout, const PackProblem& problem,
                                                         size_t k, Side side);

/// Placement k's outline at its nominal size, turned and moved as placed on its sheet.
geometry::Outline placedOutline(const Layout& layout, const PackProblem& problem, size_t k);

/// The cutting plans of a layout: each part's outline turned and moved as placed; for the machine as it cuts,
/// offset by half the kerf so that the cut leaves it at nominal size (outer contours outward, holes inward).
std::vector<CutSheet> cutSheets(const Layout& layout, const PackProblem& problem,
                                CutSheetOptions options = {});

/// One row of a cut list: how many of a part are cut from one board, and their size.
struct CutListRow {
    std::string part;
    int quantity = 0;
    double width = 0, height = 0, thickness = 0;
    std::string material;
    int board = 0;                             ///< index into Layout::sheets
    bool grain = false;                        ///< its length (width) runs along the board's grain
    std::array<std::string, 4> edgeBanding{};  ///< PartSpec::edgeBanding
    int index = 0;                             ///< the part's place in PackProblem::parts
};

/// What a layout takes and gives, for the shop's report.
struct Totals {
    int sheets = 0, parts = 0;
    double sheetArea = 0, partArea = 0;  ///< mm²
    double cost = 0;                     ///< of the sheets used (MasterBoard::cost)
    /// mm: the saw's cuts for guillotine layouts, else every part's outline and holes, a line two parts share
    /// counted once with common-line cutting.
    double cutLength = 0;
    double commonLine = 0;  ///< mm of that cut once for two parts (common-line cutting)
    std::vector<std::pair<std::string, double>> banding;  ///< mm of each band, by name
};

Totals totals(const Layout& layout, const PackProblem& problem);

/// The length of a part's Side.
double sideLength(const PartSpec& part, Side side);

/// The cut list of a layout, one row per (part, board), in part order then board order.
std::vector<CutListRow> cutList(const Layout& layout, const PackProblem& problem);

}  // namespace fabguide::material
