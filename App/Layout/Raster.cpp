#include "Layout/Raster.h"

#include <algorithm>
#include <cmath>

namespace fabguide::material {

namespace {
constexpr double kEpsilon = 1e-9;
}

int cellsCovering(double mm, double resolution)
{
    return static_cast<int>(std::ceil(mm / resolution - kEpsilon));
}

int cellsWithin(double mm, double resolution)
{
    return static_cast<int>(std::floor(mm / resolution + kEpsilon));
}

Footprint rasterise(const geometry::Outline& outline, double resolution, double clearance)
{
    const geometry::Box2 box = geometry::bounds(outline.outer);
    const int width = cellsCovering(box.width() + clearance, resolution);
    const int height = cellsCovering(box.height() + clearance, resolution);
    if (geometry::isRectangle(outline))
        return Footprint::rectangle(width, height);

    // The outline as the grid can tell it: contours within a twentieth of a cell (grown by as much, so the
    // footprint still covers the part), holes that could free no cell left out (they stay material), and each
    // row cut with the holes that reach it. A 100,000-point circle or 10,000 pin holes took 18 s and 24 s
    // here, past any time limit.
    const double tolerance = resolution / 20;
    geometry::Outline coarse{geometry::simplified(outline.outer, tolerance), {}};
    bool moved = coarse.outer.size() != outline.outer.size();  // no vertex left out: nothing to grow by
    for (const geometry::Polygon& hole : outline.holes)
        if (const geometry::Box2 b = geometry::bounds(hole);
            std::min(b.width(), b.height()) >= 2 * resolution + clearance) {
            coarse.holes.push_back(geometry::simplified(hole, tolerance));
            moved = moved || coarse.holes.back().size() != hole.size();
        }
    const geometry::Outline grown = geometry::offset(coarse, clearance / 2 + (moved ? tolerance : 0));
    const double x0 = box.minX - clearance / 2, y0 = box.minY - clearance / 2;
    std::vector<geometry::Box2> holeBoxes;
    for (const geometry::Polygon& hole : grown.holes)
        holeBoxes.push_back(geometry::bounds(hole));
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height, 0);
    for (int row = 0; row < height; ++row) {
        const double low = y0 + row * resolution, high = low + resolution;
        geometry::Outline band{grown.outer, {}};  // with the holes that reach into this row only
        for (size_t h = 0; h < holeBoxes.size(); ++h)
            if (holeBoxes[h].minY < high && holeBoxes[h].maxY > low)
                band.holes.push_back(grown.holes[h]);
        for (const auto& [from, to] : geometry::spansBetween(band, low, high)) {
            const int first = std::max(0, static_cast<int>(std::floor((from - x0) / resolution + kEpsilon)));
            const int last = std::min(width, cellsCovering(to - x0, resolution));
            std::fill(cells.begin() + static_cast<std::ptrdiff_t>(row) * width + first,
                      cells.begin() + static_cast<std::ptrdiff_t>(row) * width + last, 1);
        }
    }
    return Footprint(width, height, std::move(cells));
}

}  // namespace fabguide::material
