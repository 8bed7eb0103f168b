// Flat-pack layout in millimetres: master boards, parts, settings -> layout (thesis 5.2.2, 5.3.1, 5.4.3).
#pragma once

#include "Geometry/Polygon.h"
#include "Layout/Drill.h"
#include "Layout/OrderingSearch.h"

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace fabguide::material {

/// A kind of master board (thesis 5.1): a leftover rectangle is just another one.
struct MasterBoard {
    std::string name;
    std::string material;
    double width = 0;      ///< mm, along the layout's x axis
    double height = 0;     ///< mm
    double thickness = 0;  ///< mm
    int count = 1;         ///< boards in stock; -1 means as many as needed
    Grain grain = Grain::None;
    double cost = 1;  ///< what one board costs (any unit; 1: a sheet); 0 for one already owned, an offcut
};

/// The sides of a part's bounding box, in its own frame, that can carry edge banding: L1 and L2 run along its
/// x axis (its length) at y = 0 and at the top, W1 and W2 along y at x = 0 and at the right.
enum class Side { L1, L2, W1, W2 };
constexpr std::array<Side, 4> kSides{Side::L1, Side::L2, Side::W1, Side::W2};

/// A part to cut, `quantity` times: a planar outline (polygon with holes) in millimetres, with the
/// holes to drill and the marks to engrave on it (from its connectors), in the outline's frame.
struct PartSpec {
    std::string id;
    geometry::Outline outline;  ///< its bounding box's lower-left corner at the origin
    int quantity = 1;
    std::vector<int> orientations{0, 90, 180, 270};  ///< allowed rotations, degrees counter-clockwise
    std::vector<Drill> drills;
    std::vector<geometry::Polygon> marks;
    bool followsGrain = false;  ///< its length (x axis) along the grain of boards that have one
    double thickness = 0;       ///< mm: cut only from master boards this thick; 0: from any
    std::array<std::string, 4> edgeBanding{};  ///< the band glued on each Side (its name); empty: none
    double width() const { return geometry::bounds(outline.outer).width(); }
    double height() const { return geometry::bounds(outline.outer).height(); }
    /// The width and height of its bounding box turned by `rotation` degrees (counter-clockwise).
    std::pair<double, double> turnedSize(int rotation) const;
};

/// A plain width × height rectangular part.
PartSpec rectangularPart(std::string id, double width, double height, int quantity = 1,
                         std::vector<int> orientations = {0, 90, 180, 270});

/// How the sheets are cut: `Free`, any outline anywhere (a CNC or laser follows it); `Guillotine`,
/// straight cuts from edge to edge only (a panel, track or table saw), in at most `stages` changes of
/// direction.
enum class Cuts { Free, Guillotine };

/// The direction of a guillotine layout's first cuts: along the sheet's length (its x axis: strips as long as
/// the sheet), across it, or whichever wastes less.
enum class FirstCut { Any, Along, Across };

struct PackSettings {
    double resolution = 0.5;  ///< grid cell size τ in mm (thesis 5.4.1)
    double kerf = 0;          ///< width of the cut in mm
    double spacing = 0;       ///< extra material left between parts, mm
    double trim = 0;          ///< margin cut off every board edge, mm
    double dogbone = 0;       ///< router bit diameter for dogbones at inside corners, mm; 0: none
    double tabWidth = 0;      ///< holding tabs left in the outer cut of small parts, mm wide; 0: none
    double tabBelow = 300;    ///< parts whose longer side is under this (mm) get holding tabs
    int rotationStep = 0;     ///< free rotation: parts without grain that may take every quarter turn take
                              ///< every multiple of this many degrees (a divisor of 90); 0: quarter turns
    Cuts cuts = Cuts::Free;
    int stages = 0;  ///< guillotine cuts: at most this many changes of direction (2, 3, ...); 0: unlimited
    FirstCut firstCut = FirstCut::Any;
    /// Common-line cutting (CommonLine.h): a line two parts a kerf apart share is cut once. The machine's
    /// paths only; as designed, the CAM plans its own.
    bool commonLine = false;
};

struct PackProblem {
    std::vector<MasterBoard> boards;
    std::vector<PartSpec> parts;
    PackSettings settings;
    bool strip = false;  ///< strip packing: one board of boards[0].width, height to minimise
};

/// One unit of a part on a sheet; x, y is the lower-left corner of the part as placed.
struct Placement {
    int part = 0;   ///< index into PackProblem::parts
    int sheet = 0;  ///< index into Layout::sheets
    double x = 0, y = 0;
    int rotation = 0;
    double width = 0, height = 0;  ///< size as placed
};

/// One straight saw cut through a piece of a sheet, from edge to edge (guillotine cuts). The pieces of a
/// sheet are numbered as a tree: cut "2" parts the second first-stage piece from the rest of the sheet, cut
/// "2.1" the first piece of that one from the rest of it, and so on.
struct SawCut {
    std::string number;
    int stage = 1;              ///< 1: through the whole sheet; one more at each change of direction
    bool trim = false;          ///< it parts one part from waste only, one stage past the limit (non-exact)
    geometry::Point2 from, to;  ///< the middle of the kerf, in sheet coordinates
    double length() const { return std::hypot(to.x - from.x, to.y - from.y); }
};

struct Layout {
    std::vector<MasterBoard> sheets;  ///< the boards used, in order
    std::vector<Placement> placements;
    /// Guillotine cuts: per sheet, the saw cuts in the order to make them (every cut of a piece, then each of
    /// its pieces in turn); empty when the cuts are free.
    std::vector<std::vector<SawCut>> sawCuts;
    double stripHeight = 0;   ///< strip mode: height used
    double partArea = 0;      ///< mm²
    double boundingArea = 0;  ///< summed bounding rectangles of each sheet's layout, mm²
    double sheetArea = 0;     ///< summed areas of the boards used, mm²
    double usage() const { return partArea / boundingArea; }  ///< the thesis' measure (5.2.3)
    double sheetUtilisation() const { return partArea / sheetArea; }
    double wasteArea() const { return sheetArea - partArea; }
};

/// Whether layout `a` is better than `b` as the ordering search's LayoutCost has it: what its sheets cost,
/// then how many, then the summed bounding rectangles of their layouts.
bool better(const Layout& a, const Layout& b);

/// What a workshop could use: boards up to 20 m long and 2·10^8 grid cells (a 5 x 10 m sheet at 0.5 mm), and
/// 50,000 parts to lay out (MaxRects' first layout of 100,000 small tiles, the one always made, took 3.8 s of
/// a 2 s limit).
constexpr double kLongest = 20000, kMostCells = 2e8;
constexpr long kMostUnits = 50000;

/// Grid cells rasterised a second (a shop cut list's 1.8·10^8 took 0.25 s on this kind of machine):
/// a job of rectangles is laid out by MaxRects alone when Docking's grid would take longer than the time
/// left.
constexpr double kRasterCellsPerSecond = 5e8;

/// Cells of irregular parts' outlines rasterised a second (a part of 3·10^7 cells in four orientations took
/// 1.1 s): past the time limit, their bounding boxes are laid out instead.
constexpr double kOutlineCellsPerSecond = 1e8;

/// Bytes a grid cell of an irregular part's bitmap takes (a part of 3·10^7 cells in four orientations took
/// 156 MB), a part's profiles per cell of its sides (five arrays of ints along them), and a strip's
/// height-fields per cell of its height, per search thread; checked against the memory limit before anything
/// is rasterised.
constexpr double kBytesPerCell = 1.5, kBytesPerProfileCell = 20, kBytesPerStripCell = 24;

/// Jobs of rectangles with more units than this are laid out by MaxRects alone: Docking's search would spend
/// the time limit rasterising and docking them once.
constexpr long kDockedUnits = 400;
/// Irregular jobs of more units (twice the largest ESICUP instance) have MaxRects on their bounding boxes in
/// hand and Docking's first passes cut at the deadline; smaller ones dock whole, as the benchmarks are
/// measured.
constexpr long kBoxedUnits = 200;

/// Jobs of rectangles with at most this many units are also laid out by the guillotine search (a saw's layout
/// is a free one too), in this share of the time limit (all of it when Docking's grid is out of reach in the
/// rest); the better layout is kept.
constexpr long kSawnUnits = 400;
constexpr double kSawShare = 0.7;

/// A strip of irregular parts is filled (Criterion::Fill) when its first share of the time allows this many
/// passes, at this many column steps a second (measured on ESICUP instances: 1.2-1.6·10^8 on this kind of
/// machine).
constexpr double kFillPasses = 50, kFillStepsPerSecond = 1e8;
/// The share of the time limit in which a strip of irregular parts is laid out first; it is shrunk in the
/// rest.
constexpr double kFirstStripShare = 0.1;

/// Throws std::invalid_argument naming a bad setting, a board beyond kLongest / kMostCells, more than
/// kMostUnits parts, or no boards or parts; PackingError naming a part larger than every master board.
/// Takes no more than a pass over the parts: it runs before anything is rasterised.
void checkSettings(const PackProblem& problem);

/// A part's allowed orientations rasterised at the settings' resolution with kerf + spacing as clearance,
/// identical shapes once (a turned one kept apart when the part follows the grain).
RasterPart rasterPart(const PartSpec& spec, const PackSettings& settings);

/// A problem on the material-space grid: one RasterPart per unit of demand, the part (spec) each unit is
/// of, and the master boards in cells (trim removed, clearance added back at the far edges).
struct RasterProblem {
    std::vector<RasterPart> parts;
    std::vector<int> specOf;
    std::vector<BoardStock> stock;
};
RasterProblem rasterise(const PackProblem& problem);

/// A grid layout of `raster` back in millimetres. Throws PackingError naming the parts left unplaced.
Layout inMillimetres(const GridLayout& grid, const PackProblem& problem, const RasterProblem& raster);

/// The ordering search of `pack`: swaps from several starting orders sharing `options.timeLimit`
/// (best-fit orders and the thesis' decreasing extent); the best layout found, of those whose first docking
/// pass ended by `firstPasses` (none: not `finished`).
GridLayout searchFromStarts(const std::vector<RasterPart>& parts, const std::vector<BoardStock>& stock,
                            OrderingSearchOptions options, Deadline firstPasses = {});

/// Lays the parts out: rasterise at the settings' resolution with kerf + spacing as clearance, order search
/// with Docking (or Bottom-Left; a strip of irregular parts filled, then shrunk and compacted on the
/// outlines), convert back to mm; a job of rectangles is laid out by MaxRects too, which is kept when it is
/// better (and alone beyond kDockedUnits units). Throws std::invalid_argument for bad settings, PackingError
/// for parts that do not fit.
Layout pack(const PackProblem& problem, const OrderingSearchOptions& search);

}  // namespace fabguide::material
