#include "Design/DynamicPacker.h"

#include "Design/Correction.h"

#include <algorithm>
#include <set>

namespace fabguide::material {

std::vector<std::vector<int>> overflowingLines(const MaterialSpace& material, const GridLayout& layout,
                                               const Eigen::VectorXd& sizes, int axis)
{
    const RasterProblem units = material.raster(sizes);
    const int across = 1 - axis;
    struct Span {
        int unit, sheet, from, to, length;  // from/to across the line; length along it
    };
    std::vector<Span> spans;
    for (const Placed& p : layout.placed) {
        const Footprint& f =
            units.parts[p.part].shapes[std::min<size_t>(p.shape, units.parts[p.part].shapes.size() - 1)];
        const int at[2] = {p.x, p.y}, extent[2] = {f.width(), f.height()};
        spans.push_back({p.part, p.sheet, at[across], at[across] + extent[across], extent[axis]});
    }
    std::set<std::vector<int>> lines;
    for (const Span& line : spans) {  // a line through the start of every span is enough (SWEEP's events)
        std::vector<int> crossing;
        long length = 0;
        for (const Span& s : spans)
            if (s.sheet == line.sheet && s.from <= line.from && line.from < s.to) {
                crossing.push_back(s.unit);
                length += s.length;
            }
        const BoardStock& board = material.stock()[layout.stock[line.sheet]];
        if (length > (axis == 0 ? board.width : board.height)) {
            std::sort(crossing.begin(), crossing.end());
            lines.insert(crossing);
        }
    }
    return {lines.begin(), lines.end()};
}

namespace {

/// ADDSNAPPINGCONSTRAINTS: the line's part lengths along `axis` sum to what its sheet holds (one cell of
/// rounding and the kerf and spacing per part left over).
DesignConstraint snappingConstraint(const ConstrainedDesign& design, const MaterialSpace& material,
                                    const GridLayout& layout, const std::vector<int>& line, int axis)
{
    DesignConstraint snap{"fit", {}};
    int sheet = 0;
    for (int unit : line) {
        const auto placed = std::find_if(layout.placed.begin(), layout.placed.end(),
                                         [&](const Placed& p) { return p.part == unit; });
        sheet = placed->sheet;
        // A rectangle's shapes are its 0° and 90° turns: the part keeps the turn it had in the layout.
        const int size = material.sizeAlong(unit, 90 * placed->shape, axis);
        snap.expression.terms.emplace_back(design.variableOfSize(size), 1.0);
        snap.name += (snap.name == "fit" ? " " : " + ") + material.parts()[material.kindOf()[unit]].id;
    }
    const BoardStock& board = material.stock()[layout.stock[sheet]];
    const double tau = material.resolution(), n = static_cast<double>(line.size());
    snap.expression.constant =
        -(((axis == 0 ? board.width : board.height) - n) * tau - n * material.clearance());
    snap.name += std::string(" across the board along ") + (axis == 0 ? "x" : "y");
    return snap;
}

}  // namespace

Absorbed dynamicPacker(const ConstrainedDesign& design, const MaterialSpace& material,
                       const Eigen::VectorXd& X, const GridLayout& previous, const Eigen::VectorXd& u,
                       int iterations)
{
    Absorbed result;
    result.X = correctChange(design.design(), X, u).X;
    std::vector<int> order;
    for (const Placed& p : previous.placed)
        order.push_back(p.part);
    // BINPACKER (line 1): the layout as it was, slid, else docked again in its order.
    const auto layOut = [&] {
        const Eigen::VectorXd sizes = design.sizes(result.X);
        result.layout = material.slide(previous, sizes);
        if (!result.layout.unplaced.empty())
            result.layout = material.dock(sizes, order);
        return result.fitted = result.layout.unplaced.empty();
    };
    if (layOut())
        return result;
    Design snapped = design.design();
    for (int k = 0, axis = 0; k < iterations; ++k, axis = 1 - axis) {
        // A line whose snapping contradicts the edit (or those kept so far) is left to the other axis.
        for (const std::vector<int>& line :
             overflowingLines(material, previous, design.sizes(result.X), axis)) {
            Design candidate = snapped;
            candidate.equalities.push_back(snappingConstraint(design, material, previous, line, axis));
            const CorrectedChange solved = correctChange(candidate, X, u);
            if (solved.alpha < 1)
                continue;
            result.snapped.push_back(candidate.equalities.back().name);
            snapped = std::move(candidate);
            result.X = solved.X;
        }
        if (layOut())
            return result;
    }
    return result;
}

}  // namespace fabguide::material
