// Design exploration (thesis 5.4): SLIDE, the locking chains, IMPROVEDESIGN and MINWASTAGE on real designs.
#include "Design/Correction.h"
#include "Design/DynamicPacker.h"
#include "Design/MinWastage.h"
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"
#include "IO/PackFormat.h"

#include <gtest/gtest.h>

#include <thread>
#include <tuple>

using namespace fabguide;
using namespace fabguide::material;

namespace {

io::FlatpackDesign example(const std::string& name)
{
    return io::readFlatpack(io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) + "/examples/" + name));
}

/// No two units overlap, every unit inside its board.
void expectValid(const MaterialSpace& material, const GridLayout& layout, const Eigen::VectorXd& sizes)
{
    const RasterProblem units = material.raster(sizes);
    ASSERT_TRUE(layout.unplaced.empty());
    ASSERT_EQ(layout.placed.size(), units.parts.size());
    for (size_t i = 0; i < layout.placed.size(); ++i) {
        const Placed& a = layout.placed[i];
        const Footprint& fa = units.parts[a.part].shapes[a.shape];
        const BoardStock& board = material.stock()[layout.stock[a.sheet]];
        EXPECT_GE(a.x, 0);
        EXPECT_GE(a.y, 0);
        EXPECT_LE(a.x + fa.width(), board.width);
        EXPECT_LE(a.y + fa.height(), board.height);
        for (size_t j = 0; j < i; ++j) {
            const Placed& b = layout.placed[j];
            const Footprint& fb = units.parts[b.part].shapes[b.shape];
            const bool apart = a.sheet != b.sheet || a.x >= b.x + fb.width() || b.x >= a.x + fa.width() ||
                               a.y >= b.y + fb.height() || b.y >= a.y + fa.height();
            EXPECT_TRUE(apart) << "units " << a.part << " and " << b.part << " overlap";
        }
    }
}

/// The coffee table example, its design space and material space.
class MinWastageTest : public ::testing::Test {
protected:
    const io::FlatpackDesign f = example("coffee-table.flatpack.json");
    const ConstrainedDesign design{f.design};
    const MaterialSpace material{f.boards, f.settings, design.parts()};
};

}  // namespace

TEST_F(MinWastageTest, SlideResolvesTheOverlapsAGrownPartMakes)
{
    const DesignLayout start = layOut(design, material, 1);
    expectValid(material, start.layout, start.sizes);
    Eigen::VectorXd sizes = start.sizes;
    sizes[0] += 6;  // the top 6 mm wider: overlaps whatever sat beside or above it
    const GridLayout slid = material.slide(start.layout, sizes);
    expectValid(material, slid, sizes);
    EXPECT_LT(material.wastage(slid, sizes), 1);
    // Shrinking leaves gaps that sliding closes: the layout never grows.
    sizes = start.sizes;
    sizes[1] -= 20;
    const GridLayout shrunk = material.slide(start.layout, sizes);
    expectValid(material, shrunk, sizes);
    EXPECT_LE(shrunk.usedWidth[0] * shrunk.usedHeight[0],
              start.layout.usedWidth[0] * start.layout.usedHeight[0]);
}

TEST(PackedDesignTest, PacksLayoutIsOneOnTheGridAndComesBackFromItsFile)
{
    for (const char* name : {"kitchen-run", "sideboard-18-6mm", "wardrobe", "shoe-rack-12mm"}) {
        SCOPED_TRACE(name);
        const io::FlatpackDesign f = io::readFlatpack(io::readJsonFile(
            std::string(FABGUIDE_SOURCE_DIR) + "/tests/data/flatpack/" + name + ".flatpack.json"));
        const ConstrainedDesign design(f.design);
        const MaterialSpace material(f.boards, f.settings, design.parts());
        const Eigen::VectorXd sizes = design.sizes(design.start());
        const GridLayout packed = material.packed(sizes, 1, 0.3);
        expectValid(material, packed, sizes);
        // As a design file keeps it (a layout JSON's boards and placements), read back: the same cells.
        const PackProblem problem = material.problem(sizes);
        const nlohmann::json file =
            io::layoutToJson(material.inMillimetres(packed, sizes), problem, io::PartNames::Ids);
        const Layout kept = io::readLayout(file, problem, io::PartNames::Ids);
        const GridLayout back = material.onGrid(kept, sizes);
        ASSERT_EQ(back.placed.size(), packed.placed.size());
        for (size_t i = 0; i < back.placed.size(); ++i) {
            const Placed &a = back.placed[i], &b = packed.placed[i];
            EXPECT_EQ(std::tie(a.part, a.sheet, a.x, a.y, a.shape),
                      std::tie(b.part, b.sheet, b.x, b.y, b.shape));
        }
        EXPECT_EQ(material.figures(back, sizes).sheets, material.figures(packed, sizes).sheets);
        // A board grown past its neighbours is slid clear of them, or the layout is given up, never
        // overlapped.
        Eigen::VectorXd grown = sizes;
        grown[0] += 30;
        if (const GridLayout slid = material.onGrid(kept, grown); slid.unplaced.empty())
            expectValid(material, slid, grown);
        // Master boards not the design's (a sheet of another size): not this design's layout.
        Layout elsewhere = kept;
        elsewhere.sheets[0].width -= 100;
        EXPECT_EQ(material.onGrid(elsewhere, sizes).unplaced.size(), packed.placed.size());
    }
}

TEST_F(MinWastageTest, LockingChainsGiveSizesTheDesignCanShrink)
{
    Explorer explorer{
        design, material, {}, std::mt19937_64(3), nullptr, std::chrono::steady_clock::time_point::max(), {}};
    const DesignLayout start = layOut(design, material, 1);
    const std::vector<int> sizes = selectPartSizesToShrink(explorer, start);
    ASSERT_FALSE(sizes.empty());
    for (int s : sizes) {
        Eigen::VectorXd change = Eigen::VectorXd::Zero(start.sizes.size());
        change[s] = -material.resolution();
        EXPECT_TRUE(design.changePartSizes(start.X, change)) << "size " << s;
    }
}

TEST_F(MinWastageTest, SuggestionsWasteLessOnNoMoreSheetsAndKeepEveryConstraint)
{
    MinWastageOptions options;
    options.timeLimit = 600;  // a backstop: the search ends by its work (rounds, tasks, iterations)
    const Exploration e = minWastage(design, material, options);
    ASSERT_FALSE(e.suggestions.empty());
    EXPECT_LE(e.suggestions.size(), 3u);
    for (const Suggestion& s : e.suggestions) {
        // The maker's measure: never more sheets, better on it, and a change of the design, not of its
        // layout.
        EXPECT_LE(s.result.figures.sheets, e.start.figures.sheets);
        EXPECT_TRUE(s.result.figures.sheets < e.start.figures.sheets ||
                    s.result.figures.waste < e.start.figures.waste);
        EXPECT_GT((s.result.sizes - e.start.sizes).norm(), 1.0);
        EXPECT_TRUE(unsatisfied(f.design, s.result.X, 1e-6).empty());
        EXPECT_TRUE(ineffective(f.design, s.result.X).empty());
        expectValid(material, s.result.layout, s.result.sizes);
        // The path runs from the user's design to the suggestion, each step valid.
        ASSERT_GE(s.path.size(), 2u);
        EXPECT_EQ(s.path.front().X, design.start());
        EXPECT_EQ(s.path.back().X, s.result.X);
        for (const DesignLayout& step : s.path)
            EXPECT_TRUE(unsatisfied(f.design, step.X, 1e-6).empty());
    }
    // Suggestions differ from each other in their part sizes.
    for (size_t i = 1; i < e.suggestions.size(); ++i)
        EXPECT_GT((e.suggestions[i].result.sizes - e.suggestions[0].result.sizes).norm(), 1.0);
}

TEST_F(MinWastageTest, TheSameSeedGivesTheSameSuggestionsOnOneThreadOrTwo)
{
    MinWastageOptions options;
    options.timeLimit = 600;  // a backstop: the search ends by its work (rounds, tasks, iterations)
    options.seed = 7;
    options.threads = 1;
    const Exploration one = minWastage(design, material, options);
    options.threads = 2;
    const Exploration two = minWastage(design, material, options);
    ASSERT_EQ(one.suggestions.size(), two.suggestions.size());
    for (size_t i = 0; i < one.suggestions.size(); ++i)
        EXPECT_EQ(one.suggestions[i].result.X, two.suggestions[i].result.X);
}

TEST_F(MinWastageTest, CancellingStopsTheSearchAndReportsProgressOnTheCallersThread)
{
    std::atomic<bool> cancel{false};
    const std::thread::id caller = std::this_thread::get_id();
    int calls = 0;
    MinWastageOptions options;
    options.cancel = &cancel;
    options.progress = [&](double done, double best) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        EXPECT_GT(done, 0);
        EXPECT_LE(done, 1);
        EXPECT_GT(best, 0);
        ++calls;
        cancel = true;
    };
    const Exploration e = minWastage(design, material, options);
    EXPECT_TRUE(e.stopped);
    EXPECT_GE(calls, 1);
    EXPECT_LT(e.designsImproved, options.rounds * options.tasksPerRound);
}

TEST(ParametricDesignTest, IsImprovedThroughItsGradients)
{
    // A box of side s and height h from 12 mm boards: two sides s x h, two ends (s - 24) x h, a bottom
    // (s - 24) x (s - 24); parameters s in [200, 400], h in [100, 300].
    const ParametricDesign design(
        {{"side", 2}, {"end", 2}, {"bottom", 1}},
        [](const Eigen::VectorXd& x) {
            Eigen::VectorXd s(6);
            s << x[0], x[1], x[0] - 24, x[1], x[0] - 24, x[0] - 24;
            return s;
        },
        Eigen::Vector2d(300, 170), Eigen::Vector2d(200, 100), Eigen::Vector2d(400, 300));
    const MaterialSpace material({{"mdf", "mdf", 900, 600, 12, 1}}, {1.0, 0, 0, 0}, design.parts());
    MinWastageOptions options;
    options.timeLimit = 600;  // a backstop: the search ends by its work (rounds, tasks, iterations)
    options.rounds = 2;
    const Exploration e = minWastage(design, material, options);
    ASSERT_FALSE(e.suggestions.empty());
    const Eigen::VectorXd x = e.suggestions[0].result.X;
    EXPECT_GT(e.suggestions[0].usage(), e.usageBefore());
    EXPECT_GE(x[0], 200);
    EXPECT_LE(x[0], 400);
    EXPECT_GE(x[1], 100);
    EXPECT_LE(x[1], 300);
    expectValid(material, e.suggestions[0].result.layout, e.suggestions[0].result.sizes);
}

TEST(DynamicPackerTest, AnEditThatOverflowsTheBoardIsAbsorbedBySnappingTheOtherParts)
{
    // The coffee table without its ranges: a top 1000 mm wide fits the board in no layout; the packer keeps
    // its width and makes the top, and the legs flush with it, shallower so the line across the board fits.
    nlohmann::json doc =
        io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) + "/examples/coffee-table.flatpack.json");
    auto& constraints = doc["constraints"];
    constraints.erase(std::remove_if(constraints.begin(), constraints.end(),
                                     [](const nlohmann::json& c) { return c["kind"] == "range"; }),
                      constraints.end());
    const io::FlatpackDesign f = io::readFlatpack(doc);
    const ConstrainedDesign design(f.design);
    const MaterialSpace material(f.boards, f.settings, design.parts());
    const DesignLayout start = layOut(design, material, 1);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(start.X.size());
    u[sizeVariable(0, 0)] = 1000 - start.X[sizeVariable(0, 0)];
    const Eigen::VectorXd edited = correctChange(f.design, start.X, u).X;
    ASSERT_FALSE(material.slide(start.layout, design.sizes(edited)).unplaced.empty());
    const Absorbed a = dynamicPacker(design, material, start.X, start.layout, u);
    ASSERT_TRUE(a.fitted);
    EXPECT_FALSE(a.snapped.empty());
    EXPECT_NEAR(a.X[sizeVariable(0, 0)], 1000, 1e-9);  // the edit is kept
    EXPECT_LT(a.X[sizeVariable(0, 1)], 450);           // the top gave way in depth
    EXPECT_TRUE(unsatisfied(f.design, a.X, 1e-6).empty());
    EXPECT_TRUE(ineffective(f.design, a.X).empty());
    expectValid(material, a.layout, design.sizes(a.X));
}

TEST(DynamicPackerTest, AnEditNoBoardCanHoldIsNotAbsorbed)
{
    const io::FlatpackDesign f = example("coffee-table.flatpack.json");
    const ConstrainedDesign design(f.design);
    const MaterialSpace material(f.boards, f.settings, design.parts());
    const DesignLayout start = layOut(design, material, 1);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(start.X.size());
    u[sizeVariable(3, 1)] = 1300 - start.X[sizeVariable(3, 1)];  // the shelf deeper than any board
    EXPECT_FALSE(dynamicPacker(design, material, start.X, start.layout, u).fitted);
}

TEST(ExplorationTest, NoSheetSavedIsSaidOnlyFromABoundOrALayoutOfTheLeastDesign)
{
    Exploration e;
    e.start.figures.sheets = 3;
    using Why = Exploration::NoSheetSaved;
    EXPECT_EQ(e.noSheetSaved(), Why::Unknown);  // the least design was not laid out
    e.leastSheets = 2;
    e.leastSheetsBound = 2;
    EXPECT_EQ(e.noSheetSaved(), Why::Unknown);  // it saves a sheet
    EXPECT_EQ(io::explorationFigures(e)["no_sheet_saved"], "");
    e.leastSheets = 3;
    EXPECT_EQ(e.noSheetSaved(), Why::LaidOut);  // one layout took 3, the bound is 2: not proved
    EXPECT_EQ(io::explorationFigures(e)["no_sheet_saved"], "laid_out");
    e.leastSheetsBound = 3;
    EXPECT_EQ(e.noSheetSaved(), Why::Bound);
    EXPECT_EQ(io::explorationFigures(e)["no_sheet_saved"], "bound");
}
