// Material space for design exploration (thesis 5.2.2, 5.4.1, 5.4.2.3): a design's parts as rectangles on
// the master-board grid, laid out by Docking or updated by SLIDE (Algorithm 9), and the wastage measure.
#pragma once

#include "Design/DesignSpace.h"
#include "Layout/Pack.h"

#include <Eigen/Core>

#include <array>

namespace fabguide::material {

class MaterialSpace {
public:
    /// Throws std::invalid_argument for bad settings or no master boards.
    MaterialSpace(std::vector<MasterBoard> boards, PackSettings settings, std::vector<PartKind> parts);

    /// The parts at sizes s as a layout problem (rectangles, any orientation unless they follow the grain).
    PackProblem problem(const Eigen::VectorXd& sizes) const;
    RasterProblem raster(const Eigen::VectorXd& sizes) const { return rasterise(problem(sizes)); }
    const std::vector<BoardStock>& stock() const { return stock_; }
    const std::vector<PartKind>& parts() const { return parts_; }
    double resolution() const { return settings_.resolution; }
    double clearance() const { return settings_.kerf + settings_.spacing; }

    /// DOCKING (Algorithm 13) of the parts at sizes s in `order` (unit indices).
    GridLayout dock(const Eigen::VectorXd& sizes, const std::vector<int>& order) const;

    /// The layout command's ordering search on the grid (Docking from best-fit and decreasing-extent starts,
    /// |parts|² swaps each, thesis 5.4.3) for at most `seconds`, or until `cancel` is set: a layout the
    /// exploration's slides and dockings can go on from.
    GridLayout searched(const Eigen::VectorXd& sizes, std::uint64_t seed, double seconds,
                        const std::atomic<bool>* cancel = nullptr) const;

    /// The parts at sizes s laid out by `pack` (Docking's ordering search, MaxRects and the guillotine
    /// search, the better kept) for at most `seconds`, each part and board taken at its size in whole grid
    /// cells so that the layout is one on the grid. Every unit unplaced when the boards run out.
    GridLayout packed(const Eigen::VectorXd& sizes, std::uint64_t seed, double seconds,
                      const std::atomic<bool>* cancel = nullptr) const;

    /// A layout in millimetres of these parts on these master boards (a design file's) as a grid layout at
    /// sizes s: each placement on its nearest cell, then SLIDE to sizes s. Every unit unplaced when it does
    /// not lay out each unit once on these boards, or a unit no longer fits.
    GridLayout onGrid(const Layout& layout, const Eigen::VectorXd& sizes) const;

    /// SLIDE (Algorithm 9): the units of `previous` re-inserted in its docking order at their sizes s, each
    /// on its sheet and in its orientation, moved at most N = 4 times left/right or down/up to close gaps and
    /// resolve overlaps, preferring the move that keeps the layout's bounding box smallest. A layout with
    /// every unit unplaced when a unit no longer fits.
    GridLayout slide(const GridLayout& previous, const Eigen::VectorXd& sizes) const;

    /// W(L): 1 - part area / summed bounding rectangles of the sheets' layouts (5.2.3), 1 when a unit is
    /// unplaced.
    double wastage(const GridLayout& layout, const Eigen::VectorXd& sizes) const;

    /// What a maker reads off a layout: master boards bought (those that cost something: an
    /// offcut already owned does not) and their cost, m² of the boards used not in parts, and the largest
    /// offcut left whole (the strip beside or above a sheet's layout, width × height in mm).
    struct Figures {
        int sheets = 0;
        double cost = 0;    ///< summed cost of the boards used
        double unit = 1;    ///< the cheapest board's cost: cost / unit is the cost in sheets
        double bought = 0;  ///< m² of master boards bought
        double waste = 0;   ///< m²
        std::array<double, 2> offcut{};
    };
    Figures figures(const GridLayout& layout, const Eigen::VectorXd& sizes) const;

    /// The leftovers of a layout's sheets as master boards for the next job: per sheet the strip
    /// above its layout (the sheet's full width) and the strip beside it (up to the layout's top), each kept
    /// when both its sides are at least `least` mm; whole millimetres, the next job trims them itself; cost
    /// 0, so that job uses them before new sheets.
    std::vector<MasterBoard> offcuts(const GridLayout& layout, double least) const;

    /// The layout in millimetres, for files and thumbnails.
    Layout inMillimetres(const GridLayout& layout, const Eigen::VectorXd& sizes) const;

    /// Which size of unit `unit`, turned by `rotation`, runs along material-space axis `axis` (0 x, 1 y):
    /// index 2i (width) or 2i + 1 (height) of s, i its part kind.
    int sizeAlong(int unit, int rotation, int axis) const;
    /// The part kind of each unit.
    const std::vector<int>& kindOf() const { return kindOf_; }
    /// The units in the order of `kinds` (a part kind per unit, as a layout's docking order names them: the
    /// order a design file keeps with it); empty unless `kinds` names each part kind as many times as its
    /// quantity.
    std::vector<int> unitsInOrder(const std::vector<int>& kinds) const;

private:
    /// `layout`, of the parts on `boards` (these master boards, or their sizes on the grid), on the grid.
    GridLayout onGrid(const Layout& layout, const std::vector<MasterBoard>& boards,
                      const Eigen::VectorXd& sizes) const;
    /// Sheet s's strips left whole above its layout (the full width) and beside it (up to the layout's top),
    /// mm.
    std::array<std::array<double, 2>, 2> strips(const GridLayout& layout, size_t s) const;

    std::vector<MasterBoard> boards_;
    PackSettings settings_;
    std::vector<PartKind> parts_;
    std::vector<int> kindOf_;
    std::vector<BoardStock> stock_;
};

}  // namespace fabguide::material
