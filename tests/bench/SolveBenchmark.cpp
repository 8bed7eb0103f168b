// Google Benchmark: the works-like least-change solve (thesis 4.4) on the example and on synthetic
// mechanisms of N cuboids, cold and during a drag (small edits, each warm-started from the last solution).
// Targets: <= 5 ms per fixture, <= 200 ms at 1000 cuboids.
#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include <benchmark/benchmark.h>

#include <random>

using namespace fabguide;
using function::Face;
using function::Side;

namespace {

/// N cuboids in a row, each meant to sit against the next, to share its height and to stand on the ground,
/// modelled a little off so that every constraint has work to do.
function::Model row(int n)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-2, 2);
    function::Model m;
    for (int i = 0; i < n; ++i) {
        const double x = 30.0 * i;
        m.cuboids.push_back({"c" + std::to_string(i),
                             {x + jitter(random), x + 25 + jitter(random), jitter(random),
                              40 + jitter(random), jitter(random), 20 + jitter(random)}});
        m.parts.push_back({"p" + std::to_string(i), {i}});
    }
    for (int i = 0; i + 1 < n; ++i) {
        const std::string k = std::to_string(i);
        m.flush.push_back({"touch " + k, Face{i, Side::Right}, Face{i + 1, Side::Left}});
        m.geometric.push_back({"same height " + k,
                               function::Geometric::Relation::Equal,
                               {{{1.0, Face{i, Side::Top}}, {-1.0, Face{i, Side::Bottom}}}, 0},
                               {{{1.0, Face{i + 1, Side::Top}}, {-1.0, Face{i + 1, Side::Bottom}}}, 0}});
    }
    for (int i = 0; i < n; ++i)
        m.flush.push_back({"ground " + std::to_string(i), Face{i, Side::Bottom}, Face{0, Side::Bottom}});
    return m;
}

void SolveRow(benchmark::State& state)
{
    const function::Model model = row(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        const function::SolveResult r = function::solve(model);
        if (!r.solved)
            state.SkipWithError("not solved");
    }
}
BENCHMARK(SolveRow)->Arg(50)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond);

void DragRow(benchmark::State& state)
{
    // The user drags the first cuboid's right face: a lock moved 0.5 mm per step, each solve warm-started.
    function::Model model = row(static_cast<int>(state.range(0)));
    model.locks.push_back({Face{0, Side::Right}});
    function::SolveResult last = function::solve(model);
    for (auto _ : state) {
        model = last.model;
        model.cuboids[0].coordinates[1] += 0.5;
        Eigen::VectorXd target(6 * model.cuboids.size());
        for (size_t c = 0; c < model.cuboids.size(); ++c)
            for (int k = 0; k < 6; ++k)
                target[6 * c + k] = model.cuboids[c].coordinates[k];
        const function::LeastChangeResult r =
            function::solveLeastChange(target, function::constraints(model), &target);
        if (!r.solved)
            state.SkipWithError("not solved");
        for (size_t c = 0; c < model.cuboids.size(); ++c)
            for (int k = 0; k < 6; ++k)
                last.model.cuboids[c].coordinates[k] = r.x[6 * c + k];
    }
}
BENCHMARK(DragRow)->Arg(50)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond);

/// A fixture as modelled (rough, so the solve has work to do), from examples/ or tests/data/workslike/.
void SolveFixture(benchmark::State& state, const char* file)
{
    const function::Model model =
        io::readWorkslike(io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) + "/" + file));
    for (auto _ : state)
        if (!function::solve(model).solved)
            state.SkipWithError("not solved");
}
BENCHMARK_CAPTURE(SolveFixture, cabinet, "examples/cabinet.workslike.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, box_with_lid, "examples/box-with-lid.workslike.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, cellphone, "examples/cellphone.workslike.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, crate_bar, "examples/crate-bar.workslike.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, crate_bed, "examples/crate-bed.workslike.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, printer, "examples/printer.workslike.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, sofa_bunk, "examples/sofa-bunk.workslike.json")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, tablet, "examples/tablet.workslike.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(SolveFixture, toolbox, "examples/toolbox.workslike.json")->Unit(benchmark::kMillisecond);
// 24 sloppy cabinets (48 parts) with doors opened in two configurations, one at 85°: the parts kept apart.
BENCHMARK_CAPTURE(SolveFixture, wall_of_cabinets, "tests/data/workslike/wall-of-cabinets.workslike.json")
    ->Unit(benchmark::kMillisecond);

}  // namespace
