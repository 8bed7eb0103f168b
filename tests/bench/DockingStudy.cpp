// Thesis Fig. 5.20a: usage of Docking vs Bottom-Left over 500 random part orders of a design.
// Usage: fabguide_docking_study DESIGN.pack.json... ; prints a Markdown table.
#include "IO/Json.h"
#include "IO/PackFormat.h"
#include "Layout/OrderingSearch.h"
#include "Layout/Raster.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>

using namespace fabguide;
using namespace fabguide::material;

namespace {

constexpr int kOrders = 500;

struct Summary {
    double mean, median, best;
};

Summary summarise(std::vector<double> usage)
{
    std::sort(usage.begin(), usage.end());
    return {std::accumulate(usage.begin(), usage.end(), 0.0) / usage.size(), usage[usage.size() / 2],
            usage.back()};
}

/// The thesis' usage of a grid layout: part cells / bounding rectangle cells, over all sheets.
double usage(const GridLayout& layout, const std::vector<RasterPart>& parts)
{
    double area = 0, bounding = 0;
    for (const Placed& p : layout.placed)
        area += parts[p.part].shapes[p.shape].area();
    for (size_t s = 0; s < layout.stock.size(); ++s)
        bounding += static_cast<double>(layout.usedWidth[s]) * layout.usedHeight[s];
    return area / bounding;
}

void study(const std::string& path)
{
    const PackProblem problem = io::readPackProblem(io::readJsonFile(path));
    // The layout grid of pack(), without kerf and spacing: the study compares placement rules only.
    std::vector<RasterPart> parts;
    const double tau = problem.settings.resolution;
    for (const PartSpec& spec : problem.parts)
        for (int q = 0; q < spec.quantity; ++q) {
            parts.push_back({spec.id,
                             {rasterise(spec.outline, tau, 0),
                              rasterise(geometry::placed(spec.outline, 90, 0, 0), tau, 0)},
                             {0, 90}});
        }
    const MasterBoard& board = problem.boards.front();
    const std::vector<BoardStock> stock{
        {static_cast<int>(board.width / tau), static_cast<int>(board.height / tau), -1}};

    std::vector<int> order(parts.size());
    std::iota(order.begin(), order.end(), 0);
    std::mt19937 random(2016);
    std::vector<double> docking, bottomLeft;
    for (int i = 0; i < kOrders; ++i) {
        std::shuffle(order.begin(), order.end(), random);
        docking.push_back(usage(dock(parts, order, stock, Criterion::Docking), parts));
        bottomLeft.push_back(usage(dock(parts, order, stock, Criterion::BottomLeft), parts));
    }
    const Summary d = summarise(docking), b = summarise(bottomLeft);
    const size_t slash = path.find_last_of('/');
    std::printf("| %s | %zu | %.3f / %.3f / %.3f | %.3f / %.3f / %.3f | %+.1f %% |\n",
                path.substr(slash == std::string::npos ? 0 : slash + 1).c_str(), parts.size(), d.mean,
                d.median, d.best, b.mean, b.median, b.best, 100 * (d.mean - b.mean) / b.mean);
}

}  // namespace

int main(int argc, char** argv)
{
    std::printf(
        "| design | parts | Docking usage mean / median / best | Bottom-Left mean / median / best | mean "
        "gain |\n");
    std::printf("|---|---|---|---|---|\n");
    for (int i = 1; i < argc; ++i)
        study(argv[i]);
    return 0;
}
