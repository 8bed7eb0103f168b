// Google Benchmark: one docking pass (Algorithm 13), the inner loop of the ordering search and
// of the design exploration, which call it thousands of times. Target: ≤ 1 ms for 20 parts.
#include "IO/Json.h"
#include "IO/PackFormat.h"
#include "Layout/OrderingSearch.h"

#include <benchmark/benchmark.h>

#include <random>

using namespace fabguide::material;

namespace {

/// A 20-part furniture design on a 2440 x 1220 mm board at τ = 0.5 mm: sides, shelves, rails, a top.
std::vector<RasterPart> furnitureParts()
{
    const double sizes[][2] = {{1800, 300}, {1800, 300}, {764, 300}, {764, 300}, {764, 300},
                               {764, 300},  {764, 300},  {764, 80},  {764, 60},  {700, 420},
                               {400, 380},  {400, 380},  {640, 150}, {450, 450}, {450, 450},
                               {300, 300},  {300, 200},  {250, 120}, {250, 120}, {600, 100}};
    std::vector<RasterPart> parts;
    for (const auto& s : sizes) {
        const Footprint f = Footprint::rectangle(static_cast<int>(s[0] * 2), static_cast<int>(s[1] * 2));
        parts.push_back({"part", {f, f.rotated90()}, {0, 90}});
    }
    return parts;
}

void DockingPass20Parts(benchmark::State& state, Criterion criterion)
{
    const std::vector<RasterPart> parts = furnitureParts();
    const std::vector<BoardStock> stock{{4880, 2440, -1}};
    std::vector<int> order = decreasingExtentOrder(parts);
    std::mt19937 random(1);
    for (auto _ : state) {
        std::shuffle(order.begin(), order.end(), random);
        benchmark::DoNotOptimize(dock(parts, order, stock, criterion));
    }
}
BENCHMARK_CAPTURE(DockingPass20Parts, docking, Criterion::Docking)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(DockingPass20Parts, bottom_left, Criterion::BottomLeft)->Unit(benchmark::kMicrosecond);

void DockingPassStrip(benchmark::State& state)
{
    // A C7-sized strip instance: 196 random parts of up to 40 cells on a 160-wide strip.
    std::mt19937 random(2);
    std::uniform_int_distribution<int> side(1, 40);
    std::vector<RasterPart> parts;
    for (int i = 0; i < 196; ++i) {
        const Footprint f = Footprint::rectangle(side(random), side(random));
        parts.push_back({"part", {f, f.rotated90()}, {0, 90}});
    }
    const std::vector<BoardStock> stock{{160, 8000, 1}};
    std::vector<int> order = decreasingExtentOrder(parts);
    for (auto _ : state) {
        std::shuffle(order.begin(), order.end(), random);
        benchmark::DoNotOptimize(dock(parts, order, stock, Criterion::Docking, Bounds::Strip));
    }
}
BENCHMARK(DockingPassStrip)->Unit(benchmark::kMicrosecond);

}  // namespace
