// Docking (thesis 5.4.3.1, Algorithm 13) and Bottom-Left (5.3.1) on the material-space grid.
#pragma once

#include "Layout/Deadline.h"
#include "Layout/Footprint.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fabguide::material {

/// Which way a master board's wood grain runs.
enum class Grain { None, AlongWidth, AlongHeight };

/// A part to lay out: its allowed orientations rasterised, duplicates removed.
struct RasterPart {
    std::string name;
    std::vector<Footprint> shapes;
    std::vector<int> rotations;  ///< degrees counter-clockwise, one per shape
    bool followsGrain = false;   ///< its length (x axis at 0°) must run along the board's grain
    double thickness = 0;        ///< mm: cut only from boards this thick; 0: from any
};

/// A kind of master board, in grid cells; count < 0 means as many as needed.
struct BoardStock {
    int width = 0;
    int height = 0;
    int count = 1;
    Grain grain = Grain::None;
    double thickness = 0;  ///< mm; 0: unknown, any part may be cut from it
    double cost = 1;       ///< of one board: the cheapest is opened first (offcuts, at 0, before new sheets)
};

/// Whether a part `part` mm thick is cut from a board `board` mm thick (0 on either side: any).
inline bool ofThickness(double part, double board)
{
    return part == 0 || board == 0 || std::abs(part - board) <= 1e-6;
}

/// Whether a part turned by `rotation` degrees may lie so on a board of `grain`: any turn unless the part
/// follows the grain of a board that has one (then 0°/180° along the width, 90°/270° along the height).
inline bool grainAllows(bool followsGrain, int rotation, Grain grain)
{
    return !followsGrain || grain == Grain::None || (rotation % 180 != 0) == (grain == Grain::AlongHeight);
}

/// Whether shape `shape` of the part may be cut from the board: one of its thickness, any shape unless the
/// part follows the grain of a board that has one (then 0°/180° along the width, 90°/270° along the height).
bool allowedOn(const RasterPart& part, int shape, const BoardStock& board);

/// Where one part went: sheet index, lower-left cell, and which of its shapes.
struct Placed {
    int part = 0;
    int sheet = 0;
    int x = 0;
    int y = 0;
    int shape = 0;
};

/// A layout on the grid. `stock[s]` is the BoardStock index of sheet s.
struct GridLayout {
    std::vector<int> stock;
    std::vector<int> usedWidth;     ///< per sheet, right edge of the layout's bounding rectangle
    std::vector<int> usedHeight;    ///< per sheet, top edge
    std::vector<long> skylineArea;  ///< per sheet, area under the top height-field A(H^t)
    std::vector<Placed> placed;     ///< in docking order
    std::vector<int> unplaced;      ///< parts left over when the master boards ran out
    bool finished = true;           ///< false: the deadline passed first, and the parts left are unplaced
};

/// How a part's position is chosen among the docking positions.
enum class Criterion {
    Docking,     ///< least wastage of the layout's bounding rectangle, then least enclosed area (5.4.3.2)
    BottomLeft,  ///< lowest, then leftmost (5.3.1)
    /// Bottom-left fill (Burke et al. 2006, past the thesis): at every column the lowest place the part fits,
    /// holes and overhangs included; least wastage of the bounding rectangle, then lowest, then leftmost.
    Fill,
    /// Fill's places, least wastage of the bounding rectangle, then least area left under the part, then
    /// lowest, then leftmost: the part that fits the profile below it.
    SnugFill,
};

/// Whether the criterion places parts at fill positions (a sheet keeps its columns' runs for them).
inline bool fills(Criterion criterion)
{
    return criterion == Criterion::Fill || criterion == Criterion::SnugFill;
}

/// Wastage is measured against the layout's bounding rectangle (thesis 5.4.3.2); in strip mode the
/// rectangle always spans the full sheet width, so the criterion minimises the strip height.
enum class Bounds { Layout, Strip };

/// A part that fits on no master board, or more sheets needed than there are boards.
struct PackingError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// One master board being filled: the right and top height-fields of its layout (Fig. 5.14).
class Sheet {
public:
    /// `holes`: also keep every column's occupied runs, for fill positions.
    Sheet(int width, int height, bool holes = false);

    struct Position {
        int x = 0;
        int y = 0;
    };

    /// Calls visit(position) for each docking position of `part`: dropped from the right at each
    /// row where the right height-field steps, and from the top at each column where the top
    /// height-field steps (ComputeDockingPosition in Algorithm 13). Positions are inside the sheet.
    template <class Visit>
    void forEachDockingPosition(const Footprint& part, Visit&& visit, const Deadline& deadline = {}) const;

    /// E(L, p, pos) of thesis 5.4.3.2: area newly enclosed behind the part, both directions.
    long enclosedArea(const Footprint& part, Position at) const;

    /// Calls visit(position) for the lowest place the part fits at each column, inside the sheet (a sheet
    /// made with `holes`).
    template <class Visit>
    void forEachFillPosition(const Footprint& part, Visit&& visit, const Deadline& deadline = {}) const;

    /// The empty cells between the part's lowest cell in each column and what lies below it (a sheet made
    /// with `holes`).
    long areaBelow(const Footprint& part, Position at) const;

    void place(const Footprint& part, Position at);

    int width() const { return width_; }
    int height() const { return height_; }
    int usedWidth() const { return usedWidth_; }
    int usedHeight() const { return usedHeight_; }
    long skylineArea() const { return skylineArea_; }

private:
    int dropFromRight(const Footprint& part, int y) const;
    int dropFromTop(const Footprint& part, int x) const;
    int lowestFit(const Footprint& part, int x) const;

    using Run = std::pair<int, int>;
    /// The first of `column`'s occupied runs that ends above `y`.
    std::vector<Run>::const_iterator runAbove(int column, int y) const;

    int width_, height_;
    std::vector<std::vector<Run>> columns_;  ///< with `holes`: per column, the occupied runs bottom up
    std::vector<int> right_;                 ///< per row: one past the rightmost occupied cell
    std::vector<int> top_;                   ///< per column: one past the topmost occupied cell
    int usedWidth_ = 0, usedHeight_ = 0;
    long skylineArea_ = 0;
};

/// Algorithm 13 one part at a time: the sheets being filled and the stock left.
class Docker {
public:
    /// Past `deadline` a part is looked at no further and left unplaced, the layout not `finished`.
    Docker(const std::vector<BoardStock>& stock, Criterion criterion, Bounds bounds, Deadline deadline = {});

    /// Where `part` would go: the best docking position on the first open sheet that has one
    /// (sheet = -1 when it needs a new sheet, or shape = -1 when it has a position nowhere).
    Placed bestPlace(const RasterPart& part) const;

    /// Places part `index` at its best position, opening a new sheet from the cheapest stock (the first
    /// listed among equals) with boards left that it fits on; when the boards have run out the part is
    /// listed as unplaced.
    /// Throws PackingError naming the part when it is larger than every master board.
    void place(const std::vector<RasterPart>& parts, int index);

    /// Places a part where an earlier docking of the same parts before it put it, opening its sheet (of
    /// `stock`) when it was the first there.
    void replay(const std::vector<RasterPart>& parts, const Placed& placed, int stock);

    const GridLayout& layout() const { return layout_; }

private:
    Placed bestOn(int sheet, const RasterPart& part) const;
    int openSheet(const RasterPart& part);  ///< -1 when no board it fits on is left
    void open(int stock);
    void commit(const RasterPart& part, const Placed& choice);

    const std::vector<BoardStock>& stock_;
    Criterion criterion_;
    Bounds bounds_;
    Deadline deadline_;
    std::vector<int> left_;  ///< boards left per stock
    std::vector<Sheet> sheets_;
    GridLayout layout_;
};

/// Lays the parts out in the given order (Algorithm 13): each part goes to the first open sheet
/// where it has a docking position, at the best position by `criterion`. The first `same` parts of `order`
/// that `before` (a docking of an order that begins alike) placed in the same order are put where it put
/// them. Throws PackingError naming a part larger than every master board. Past `deadline` the parts left
/// are unplaced and the layout not `finished`.
GridLayout dock(const std::vector<RasterPart>& parts, const std::vector<int>& order,
                const std::vector<BoardStock>& stock, Criterion criterion, Bounds bounds = Bounds::Layout,
                const GridLayout* before = nullptr, size_t same = 0, Deadline deadline = {});

// ---------------------------------------------------------------------------------------------

/// Whether a loop at step `i` must end: every 1024 steps, the deadline asked (a step scans a part's rows).
inline bool late(int i, const Deadline& deadline)
{
    return (i & 1023) == 1023 && deadline.passed();
}

template <class Visit>
void Sheet::forEachDockingPosition(const Footprint& part, Visit&& visit, const Deadline& deadline) const
{
    // Past the used height every row is empty, so only its first row and the board-top-aligned
    // row give distinct positions (likewise for columns past the used width).
    const int w = part.width(), h = part.height();
    const int lastY = height_ - h, lastX = width_ - w;
    for (int y = 0; y <= lastY && !late(y, deadline);
         y = y < usedHeight_ ? y + 1 : (y < lastY ? lastY : lastY + 1)) {
        const bool step = y == 0 || y == lastY || right_[y] != right_[y - 1] ||  // bottom on a step
                          right_[y + h] != right_[y + h - 1];                    // top on a step
        if (!step)
            continue;
        const int x = dropFromRight(part, y);
        if (x <= lastX)
            visit(Position{x, y});
    }
    for (int x = 0; x <= lastX && !late(x, deadline);
         x = x < usedWidth_ ? x + 1 : (x < lastX ? lastX : lastX + 1)) {
        const bool step = x == 0 || x == lastX || top_[x] != top_[x - 1] || top_[x + w] != top_[x + w - 1];
        if (!step)
            continue;
        const int y = dropFromTop(part, x);
        if (y <= lastY)
            visit(Position{x, y});
    }
}

template <class Visit>
void Sheet::forEachFillPosition(const Footprint& part, Visit&& visit, const Deadline& deadline) const
{
    for (int x = 0; x + part.width() <= width_ && !late(x, deadline); ++x) {
        const int y = lowestFit(part, x);
        if (y + part.height() <= height_)
            visit(Position{x, y});
    }
}

}  // namespace fabguide::material
