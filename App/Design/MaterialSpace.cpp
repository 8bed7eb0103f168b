#include "Design/MaterialSpace.h"

#include "Layout/Raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

namespace fabguide::material {

MaterialSpace::MaterialSpace(std::vector<MasterBoard> boards, PackSettings settings,
                             std::vector<PartKind> parts)
    : boards_(std::move(boards)), settings_(settings), parts_(std::move(parts))
{
    const PackProblem sized = problem(Eigen::VectorXd::Ones(2 * static_cast<Eigen::Index>(parts_.size())));
    checkSettings(sized);  // before the quantities are expanded
    for (size_t k = 0; k < parts_.size(); ++k)
        kindOf_.insert(kindOf_.end(), std::max(0, parts_[k].quantity), static_cast<int>(k));
    stock_ = rasterise(sized).stock;
}

PackProblem MaterialSpace::problem(const Eigen::VectorXd& sizes) const
{
    PackProblem problem{boards_, {}, settings_, false};
    for (size_t k = 0; k < parts_.size(); ++k) {
        problem.parts.push_back(
            rectangularPart(parts_[k].id, sizes[2 * k], sizes[2 * k + 1], parts_[k].quantity));
        problem.parts.back().followsGrain = parts_[k].followsGrain;
        problem.parts.back().thickness = parts_[k].thickness;
    }
    return problem;
}

GridLayout MaterialSpace::dock(const Eigen::VectorXd& sizes, const std::vector<int>& order) const
{
    try {
        return material::dock(raster(sizes).parts, order, stock_, Criterion::Docking);
    } catch (const PackingError&) {  // a part larger than every board: no layout
        GridLayout none;
        none.unplaced = order;
        return none;
    }
}

std::vector<int> MaterialSpace::unitsInOrder(const std::vector<int>& kinds) const
{
    std::vector<std::vector<int>> units(parts_.size());  // per kind, its units not yet taken, last first
    for (int u = static_cast<int>(kindOf_.size()) - 1; u >= 0; --u)
        units[kindOf_[u]].push_back(u);
    std::vector<int> order;
    for (int kind : kinds) {
        if (kind < 0 || kind >= static_cast<int>(units.size()) || units[kind].empty())
            return {};
        order.push_back(units[kind].back());
        units[kind].pop_back();
    }
    return order.size() == kindOf_.size() ? order : std::vector<int>{};
}

namespace {

/// Every one of `units` unplaced: no layout.
GridLayout nothingPlaced(size_t units)
{
    GridLayout none;
    none.unplaced.resize(units);
    std::iota(none.unplaced.begin(), none.unplaced.end(), 0);
    return none;
}

/// A unit's cells on its sheet: lower corner `at`, extent `length`, per material-space axis.
struct Rect {
    int at[2];
    int length[2];
};

bool overlaps(const Rect& a, const Rect& b)
{
    for (int k = 0; k < 2; ++k)
        if (a.at[k] >= b.at[k] + b.length[k] || b.at[k] >= a.at[k] + a.length[k])
            return false;
    return true;
}

bool collides(const std::vector<Rect>& placed, const Rect& r)
{
    return std::any_of(placed.begin(), placed.end(), [&](const Rect& o) { return overlaps(o, r); });
}

/// smallestLeftFreeInterval / smallestBottomFreeInterval: the free cells before `r` along `axis`.
int freeBefore(const std::vector<Rect>& placed, const Rect& r, int axis)
{
    const int other = 1 - axis;
    int gap = r.at[axis];
    for (const Rect& o : placed)
        if (o.at[other] < r.at[other] + r.length[other] && r.at[other] < o.at[other] + o.length[other] &&
            o.at[axis] + o.length[axis] <= r.at[axis])
            gap = std::min(gap, r.at[axis] - (o.at[axis] + o.length[axis]));
    return gap;
}

/// smallestRightDecollision / smallestTopDecollision: the least move along `axis` that clears every
/// overlap, nullopt when that leaves the sheet.
std::optional<int> decollision(const std::vector<Rect>& placed, const Rect& r, int axis, int limit)
{
    Rect moved = r;
    for (int to = r.at[axis];; moved.at[axis] = to) {
        for (const Rect& o : placed)
            if (overlaps(o, moved))
                to = std::max(to, o.at[axis] + o.length[axis]);
        if (to == moved.at[axis])
            break;
    }
    if (moved.at[axis] + moved.length[axis] > limit)
        return std::nullopt;
    return moved.at[axis] - r.at[axis];
}

/// `grid`'s units each where it says, with its sheets' extents; nullopt when one leaves its sheet or overlaps
/// another.
std::optional<GridLayout> asPlaced(GridLayout grid, const RasterProblem& units,
                                   const std::vector<BoardStock>& stock)
{
    grid.usedWidth.assign(grid.stock.size(), 0);
    grid.usedHeight.assign(grid.stock.size(), 0);
    grid.skylineArea.assign(grid.stock.size(), 0);
    std::vector<std::vector<Rect>> placed(grid.stock.size());
    for (const Placed& p : grid.placed) {
        const Footprint& shape = units.parts[p.part].shapes[p.shape];
        const Rect r{{p.x, p.y}, {shape.width(), shape.height()}};
        const BoardStock& board = stock[grid.stock[p.sheet]];
        if (p.x < 0 || p.y < 0 || p.x + shape.width() > board.width || p.y + shape.height() > board.height ||
            collides(placed[p.sheet], r))
            return std::nullopt;
        placed[p.sheet].push_back(r);
        grid.usedWidth[p.sheet] = std::max(grid.usedWidth[p.sheet], p.x + shape.width());
        grid.usedHeight[p.sheet] = std::max(grid.usedHeight[p.sheet], p.y + shape.height());
    }
    return grid;
}

}  // namespace

GridLayout MaterialSpace::searched(const Eigen::VectorXd& sizes, std::uint64_t seed, double seconds,
                                   const std::atomic<bool>* cancel) const
{
    OrderingSearchOptions search = orderingSearch(kindOf_.size(), seed, seconds);
    search.cancel = cancel;
    return searchFromStarts(raster(sizes).parts, stock_, search);
}

GridLayout MaterialSpace::packed(const Eigen::VectorXd& sizes, std::uint64_t seed, double seconds,
                                 const std::atomic<bool>* cancel) const
{
    checkSettings(problem(sizes));  // a part larger than every master board named, at its size in mm
    // Every side in whole cells: a part as long as its footprint less the clearance, a board's usable side as
    // its cells less the clearance (which its far edges add back), so that pack's placements fall on cells.
    const double tau = settings_.resolution, clearance = settings_.kerf + settings_.spacing;
    Eigen::VectorXd cells = sizes;
    for (double& side : cells)
        side = cellsCovering(side + clearance, tau) * tau - clearance;
    PackProblem onCells = problem(cells);
    onCells.settings.commonLine = false;  // parts a kerf apart, as on the grid
    for (size_t k = 0; k < boards_.size(); ++k) {
        MasterBoard& board = onCells.boards[k];
        board.width = stock_[k].width * tau - clearance + 2 * settings_.trim;
        board.height = stock_[k].height * tau - clearance + 2 * settings_.trim;
    }
    OrderingSearchOptions search = orderingSearch(kindOf_.size(), seed, seconds);
    search.cancel = cancel;
    try {
        return onGrid(pack(onCells, search), onCells.boards, sizes);
    } catch (const PackingError&) {  // the boards or the time ran out
        return nothingPlaced(kindOf_.size());
    }
}

GridLayout MaterialSpace::onGrid(const Layout& layout, const Eigen::VectorXd& sizes) const
{
    return onGrid(layout, boards_, sizes);
}

GridLayout MaterialSpace::onGrid(const Layout& layout, const std::vector<MasterBoard>& boards,
                                 const Eigen::VectorXd& sizes) const
{
    const RasterProblem units = raster(sizes);
    GridLayout grid;
    std::vector<int> opened(boards.size(), 0);
    for (const MasterBoard& sheet : layout.sheets) {
        const auto kind = std::find_if(boards.begin(), boards.end(), [&](const MasterBoard& b) {
            return b.name == sheet.name && b.material == sheet.material && b.width == sheet.width &&
                   b.height == sheet.height && b.thickness == sheet.thickness && b.grain == sheet.grain &&
                   b.cost == sheet.cost;
        });
        const auto k = static_cast<size_t>(kind - boards.begin());
        if (kind == boards.end() || (stock_[k].count >= 0 && ++opened[k] > stock_[k].count))
            return nothingPlaced(kindOf_.size());
        grid.stock.push_back(static_cast<int>(k));
    }
    std::vector<int> kinds;
    for (const Placement& p : layout.placements)
        kinds.push_back(p.part);
    const std::vector<int> order = unitsInOrder(kinds);
    if (order.empty())
        return nothingPlaced(kindOf_.size());
    const double tau = settings_.resolution, trim = settings_.trim;
    for (size_t i = 0; i < order.size(); ++i) {
        const Placement& p = layout.placements[i];
        const RasterPart& unit = units.parts[order[i]];
        const auto turn = std::find_if(unit.rotations.begin(), unit.rotations.end(),
                                       [&](int r) { return r % 180 == p.rotation % 180; });
        const int shape = turn == unit.rotations.end() ? 0 : static_cast<int>(turn - unit.rotations.begin());
        if (p.sheet < 0 || p.sheet >= static_cast<int>(grid.stock.size()) ||
            !allowedOn(unit, shape, stock_[grid.stock[p.sheet]]))
            return nothingPlaced(kindOf_.size());
        grid.placed.push_back({order[i], p.sheet, static_cast<int>(std::lround((p.x - trim) / tau)),
                               static_cast<int>(std::lround((p.y - trim) / tau)), shape});
    }
    // Where it was laid when the parts still fit there (any order: a packer's is not Docking's), else slid.
    if (std::optional<GridLayout> same = asPlaced(grid, units, stock_))
        return *same;
    return slide(grid, sizes);
}

GridLayout MaterialSpace::slide(const GridLayout& previous, const Eigen::VectorXd& sizes) const
{
    constexpr int kMoves = 4;  // N in thesis 5.4.2.3
    const RasterProblem units = raster(sizes);
    GridLayout out;
    out.stock = previous.stock;
    out.usedWidth.assign(previous.stock.size(), 0);
    out.usedHeight.assign(previous.stock.size(), 0);
    out.skylineArea.assign(previous.stock.size(), 0);
    std::vector<std::vector<Rect>> placed(previous.stock.size());
    const auto fail = [&] { return nothingPlaced(units.parts.size()); };
    if (!previous.unplaced.empty())
        return fail();

    for (const Placed& p : previous.placed) {
        // Rectangles have their 0° shape first and their 90° one second, unless square (one shape).
        const RasterPart& unit = units.parts[p.part];
        const int shape = std::min<int>(p.shape, static_cast<int>(unit.shapes.size()) - 1);
        const BoardStock& board = stock_[previous.stock[p.sheet]];
        const int limit[2] = {board.width, board.height};
        Rect r{{p.x, p.y}, {unit.shapes[shape].width(), unit.shapes[shape].height()}};
        for (int k = 0; k < 2; ++k) {
            if (r.length[k] > limit[k])
                return fail();
            r.at[k] = std::min(r.at[k], limit[k] - r.length[k]);
        }
        std::vector<Rect>& sheet = placed[p.sheet];
        const auto boxArea = [&](const Rect& m) {
            return static_cast<long>(std::max(out.usedWidth[p.sheet], m.at[0] + m.length[0])) *
                   std::max(out.usedHeight[p.sheet], m.at[1] + m.length[1]);
        };
        for (int move = 0; move < kMoves; ++move) {
            std::optional<int> delta[2];
            for (int k = 0; k < 2; ++k)
                delta[k] = collides(sheet, r) ? decollision(sheet, r, k, limit[k])
                                              : std::optional<int>(-freeBefore(sheet, r, k));
            if (!delta[0] && !delta[1])
                return fail();
            if (delta[0] == 0 && delta[1] == 0)
                break;
            Rect along[2] = {r, r};
            for (int k = 0; k < 2; ++k)
                along[k].at[k] += delta[k].value_or(0);
            int pick;
            if (!delta[0] || !delta[1])
                pick = delta[0] ? 0 : 1;
            else if (boxArea(along[0]) != boxArea(along[1]))
                pick = boxArea(along[0]) < boxArea(along[1]) ? 0 : 1;
            else
                pick = *delta[0] < *delta[1] && *delta[0] != 0 ? 0 : 1;
            r = along[pick];
        }
        if (collides(sheet, r))
            return fail();
        sheet.push_back(r);
        out.usedWidth[p.sheet] = std::max(out.usedWidth[p.sheet], r.at[0] + r.length[0]);
        out.usedHeight[p.sheet] = std::max(out.usedHeight[p.sheet], r.at[1] + r.length[1]);
        out.placed.push_back({p.part, p.sheet, r.at[0], r.at[1], shape});
    }
    return out;
}

double MaterialSpace::wastage(const GridLayout& layout, const Eigen::VectorXd& sizes) const
{
    if (!layout.unplaced.empty() || layout.placed.empty())
        return 1.0;
    const double tau = settings_.resolution, clearance = settings_.kerf + settings_.spacing;
    double bounding = 0, parts = 0;
    for (size_t s = 0; s < layout.stock.size(); ++s)
        bounding += (layout.usedWidth[s] * tau - clearance) * (layout.usedHeight[s] * tau - clearance);
    for (int kind : kindOf_)
        parts += sizes[2 * kind] * sizes[2 * kind + 1];
    return 1.0 - parts / bounding;
}

std::array<std::array<double, 2>, 2> MaterialSpace::strips(const GridLayout& layout, size_t s) const
{
    const MasterBoard& sheet = boards_[layout.stock[s]];
    // The layout starts inside the trim: what lies beyond its right (top) edge is left whole.
    const double tau = settings_.resolution, trim = settings_.trim;
    const double right = trim + layout.usedWidth[s] * tau, top = trim + layout.usedHeight[s] * tau;
    return {{{sheet.width, sheet.height - top}, {sheet.width - right, top}}};
}

MaterialSpace::Figures MaterialSpace::figures(const GridLayout& layout, const Eigen::VectorXd& sizes) const
{
    Figures f;
    double used = 0, bought = 0, parts = 0;
    double cheapest = std::numeric_limits<double>::infinity();
    for (const MasterBoard& board : boards_)
        if (board.cost > 0)
            cheapest = std::min(cheapest, board.cost);
    f.unit = std::isfinite(cheapest) ? cheapest : 1;
    for (size_t s = 0; s < layout.stock.size(); ++s) {
        const MasterBoard& sheet = boards_[layout.stock[s]];
        used += sheet.width * sheet.height;  // the whole sheet, trim and all
        f.cost += sheet.cost;
        if (sheet.cost > 0) {
            ++f.sheets;
            bought += sheet.width * sheet.height;
        }
        for (const auto& strip : strips(layout, s))
            if (strip[0] * strip[1] > f.offcut[0] * f.offcut[1])
                f.offcut = strip;
    }
    for (int kind : kindOf_)
        parts += sizes[2 * kind] * sizes[2 * kind + 1];
    f.bought = bought / 1e6;
    f.waste = (used - parts) / 1e6;
    return f;
}

std::vector<MasterBoard> MaterialSpace::offcuts(const GridLayout& layout, double least) const
{
    std::vector<MasterBoard> out;
    for (size_t s = 0; s < layout.stock.size(); ++s) {
        const MasterBoard& sheet = boards_[layout.stock[s]];
        const auto both = strips(layout, s);
        const char* where[] = {"above", "beside"};
        for (int k = 0; k < 2; ++k)
            if (both[k][0] >= least && both[k][1] >= least)
                out.push_back({sheet.name + " offcut " + std::to_string(s + 1) + " " + where[k],
                               sheet.material, std::floor(both[k][0]), std::floor(both[k][1]),
                               sheet.thickness, 1, sheet.grain, 0});
    }
    return out;
}

Layout MaterialSpace::inMillimetres(const GridLayout& layout, const Eigen::VectorXd& sizes) const
{
    const PackProblem sized = problem(sizes);
    return material::inMillimetres(layout, sized, rasterise(sized));
}

int MaterialSpace::sizeAlong(int unit, int rotation, int axis) const
{
    const bool turned = rotation % 180 != 0;
    return 2 * kindOf_[unit] + ((axis == 0) != turned ? 0 : 1);
}

}  // namespace fabguide::material
