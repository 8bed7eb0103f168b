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

    const geometry::Outline grown = geometry::offset(outline, clearance / 2);
    const double x0 = box.minX - clearance / 2, y0 = box.minY - clearance / 2;
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(width) * height, 0);
    for (int row = 0; row < height; ++row)
        for (const auto& [from, to] :
             geometry::spansBetween(grown, y0 + row * resolution, y0 + (row + 1) * resolution)) {
            const int first = std::max(0, static_cast<int>(std::floor((from - x0) / resolution + kEpsilon)));
            const int last = std::min(width, cellsCovering(to - x0, resolution));
            std::fill(cells.begin() + static_cast<std::ptrdiff_t>(row) * width + first,
                      cells.begin() + static_cast<std::ptrdiff_t>(row) * width + last, 1);
        }
    return Footprint(width, height, std::move(cells));
}

}  // namespace fabguide::material
