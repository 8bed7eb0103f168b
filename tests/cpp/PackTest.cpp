#include "Layout/Pack.h"

#include "Core/Memory.h"

#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace fabguide::material;

namespace {

PackProblem shelfProblem()
{
    PackProblem problem;
    problem.boards.push_back({"birch", "birch plywood", 1000, 600, 18, 2});
    problem.parts.push_back(rectangularPart("side", 300, 560, 2, {0, 90, 180, 270}));
    problem.parts.push_back(rectangularPart("shelf", 300, 380, 3, {0, 180}));
    problem.settings = {0.5, 6, 2, 10};  // τ, kerf (router bit), spacing, trim
    return problem;
}

OrderingSearchOptions quick()
{
    OrderingSearchOptions options;
    options.iterations = 100;
    options.timeLimit = 10;
    return options;
}

bool apart(const Placement& a, const Placement& b, double gap)
{
    const double eps = 1e-9;
    return a.sheet != b.sheet || a.x + a.width + gap <= b.x + eps || b.x + b.width + gap <= a.x + eps ||
           a.y + a.height + gap <= b.y + eps || b.y + b.height + gap <= a.y + eps;
}

}  // namespace

TEST(Pack, KeepsKerfSpacingAndTrim)
{
    const PackProblem problem = shelfProblem();
    const Layout layout = pack(problem, quick());
    ASSERT_EQ(layout.placements.size(), 5u);
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        const Placement& p = layout.placements[i];
        const MasterBoard& board = layout.sheets[p.sheet];
        EXPECT_GE(p.x, 10 - 1e-9);
        EXPECT_GE(p.y, 10 - 1e-9);
        EXPECT_LE(p.x + p.width, board.width - 10 + 1e-9);
        EXPECT_LE(p.y + p.height, board.height - 10 + 1e-9);
        for (size_t j = i + 1; j < layout.placements.size(); ++j)
            EXPECT_TRUE(apart(p, layout.placements[j], 8))
                << i << " and " << j << " closer than kerf + spacing";
    }
}

TEST(Pack, ACancelledSearchStopsWithAValidLayout)
{
    // Cancelled as it starts, a search with neither a time limit nor an end to its work still returns, with
    // each stage's first layout (the FreeCAD Layout's Stop): on sheets free or sawn, and in a
    // strip.
    const std::atomic<bool> cancelled{true};
    OrderingSearchOptions options;
    options.iterations = std::numeric_limits<long>::max();
    options.timeLimit = 1e9;
    options.cancel = &cancelled;
    for (const Cuts cuts : {Cuts::Free, Cuts::Guillotine})
        for (const bool strip : {false, true}) {
            PackProblem problem = shelfProblem();
            problem.settings.cuts = cuts;
            problem.strip = strip && cuts == Cuts::Free;
            const Layout layout = pack(problem, options);
            ASSERT_EQ(layout.placements.size(), 5u);
            for (size_t i = 0; i < layout.placements.size(); ++i)
                for (size_t j = i + 1; j < layout.placements.size(); ++j)
                    EXPECT_TRUE(apart(layout.placements[i], layout.placements[j], 8)) << i << " and " << j;
        }
}

TEST(Pack, RespectsAllowedOrientationsAndReportsPlacedSizes)
{
    const PackProblem problem = shelfProblem();
    for (const Placement& p : pack(problem, quick()).placements) {
        const PartSpec& spec = problem.parts[p.part];
        if (spec.id == "shelf") {
            EXPECT_EQ(p.rotation % 180, 0);
        }
        const bool turned = p.rotation % 180 != 0;
        EXPECT_DOUBLE_EQ(p.width, turned ? spec.height() : spec.width());
        EXPECT_DOUBLE_EQ(p.height, turned ? spec.width() : spec.height());
    }
}

TEST(Pack, MetricsAddUp)
{
    const Layout layout = pack(shelfProblem(), quick());
    EXPECT_DOUBLE_EQ(layout.partArea, 2 * 300 * 560 + 3 * 300 * 380);
    EXPECT_DOUBLE_EQ(layout.sheetArea, static_cast<double>(layout.sheets.size()) * 1000 * 600);
    EXPECT_DOUBLE_EQ(layout.wasteArea(), layout.sheetArea - layout.partArea);
    EXPECT_GT(layout.usage(), layout.sheetUtilisation() - 1e-12);
    EXPECT_LE(layout.usage(), 1.0);
}

TEST(Pack, StripModeReportsTheHeightUsed)
{
    PackProblem problem;
    problem.strip = true;
    problem.settings.resolution = 1;
    problem.boards.push_back({"strip", "", 10, 0, 0, 1});
    problem.parts.push_back(rectangularPart("0", 10, 3, 2, {0, 90, 180, 270}));
    problem.parts.push_back(rectangularPart("1", 5, 4, 2, {0, 90, 180, 270}));
    const Layout layout = pack(problem, quick());
    EXPECT_DOUBLE_EQ(layout.stripHeight, 10);
    EXPECT_DOUBLE_EQ(layout.usage(), 1.0);
}

TEST(Pack, RunningOutOfBoardsNamesAPart)
{
    PackProblem problem = shelfProblem();
    problem.boards[0].count = 1;
    try {
        pack(problem, quick());
        FAIL() << "expected PackingError";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("not enough master boards: part '"), std::string::npos)
            << e.what();
        EXPECT_EQ(std::string(e.what()).find(" 0 more"), std::string::npos) << e.what();
    }
}

TEST(Pack, RejectsBadSettings)
{
    PackProblem problem = shelfProblem();
    problem.settings.resolution = 0;
    EXPECT_THROW(pack(problem, quick()), std::invalid_argument);
    problem = shelfProblem();
    problem.parts.clear();
    EXPECT_THROW(pack(problem, quick()), std::invalid_argument);
}

TEST(Pack, OversizedPartIsNamed)
{
    PackProblem problem = shelfProblem();
    problem.parts.push_back(rectangularPart("table top", 1200, 700, 1, {0, 90}));
    try {
        pack(problem, quick());
        FAIL() << "expected PackingError";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("'table top'"), std::string::npos) << e.what();
    }
}

namespace {

/// Area shared by two outlines (Clipper, 0.001 mm² resolution).
double sharedArea(const fabguide::geometry::Outline& a, const fabguide::geometry::Outline& b)
{
    auto path = [](const fabguide::geometry::Polygon& polygon) {
        ClipperLib::Path p;
        for (const auto& q : polygon)
            p.emplace_back(std::llround(q.x * 1000), std::llround(q.y * 1000));
        return p;
    };
    ClipperLib::Clipper clipper;
    clipper.AddPath(path(a.outer), ClipperLib::ptSubject, true);
    clipper.AddPath(path(b.outer), ClipperLib::ptClip, true);
    ClipperLib::Paths shared;
    clipper.Execute(ClipperLib::ctIntersection, shared);
    double area = 0;
    for (const auto& p : shared)
        area += std::abs(ClipperLib::Area(p)) / 1e6;
    return area;
}

/// Every placed outline grown by `grow` mm (negative: shrunk) shares no area with any other.
void expectOutlinesApart(const PackProblem& problem, const Layout& layout, double grow)
{
    std::vector<fabguide::geometry::Outline> grown;
    for (const Placement& p : layout.placements)
        grown.push_back(fabguide::geometry::offset(
            fabguide::geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y), grow));
    for (size_t i = 0; i < grown.size(); ++i)
        for (size_t j = i + 1; j < grown.size(); ++j)
            EXPECT_EQ(sharedArea(grown[i], grown[j]), 0) << i << " and " << j;
}

/// `ells` L-shapes (200 mm arms, 60 wide) and `triangles` right triangles (120 mm legs), every quarter turn
/// allowed.
void addEllsAndTriangles(PackProblem& problem, int ells, int triangles)
{
    const fabguide::geometry::Outline ell{{{0, 0}, {200, 0}, {200, 60}, {60, 60}, {60, 200}, {0, 200}}, {}};
    const fabguide::geometry::Outline triangle{{{0, 0}, {120, 0}, {0, 120}}, {}};
    problem.parts.push_back({"ell", ell, ells, {0, 90, 180, 270}, {}, {}});
    problem.parts.push_back({"tri", triangle, triangles, {0, 90, 180, 270}, {}, {}});
}

/// Two ells and three triangles on a plywood board at 0.5 mm.
PackProblem ellsAndTrianglesOnPly()
{
    PackProblem problem;
    problem.boards.push_back({"ply", "", 600, 400, 6, 1});
    problem.settings = {0.5, 0.2, 2, 5};
    addEllsAndTriangles(problem, 2, 3);
    return problem;
}

}  // namespace

TEST(Pack, IrregularOutlinesNestWithoutOverlapKeepingTheClearance)
{
    const PackProblem problem = ellsAndTrianglesOnPly();
    const Layout layout = pack(problem, quick());
    ASSERT_EQ(layout.placements.size(), 5u);
    EXPECT_NEAR(layout.partArea, 2 * fabguide::geometry::area(problem.parts[0].outline) + 3 * 7200, 1e-6);

    // Every outline grown by just under half the clearance stays clear of every other one.
    expectOutlinesApart(problem, layout, 1.1 - 1e-3);
    // The L-shapes interlock: the layout is far smaller than their bounding boxes side by side.
    EXPECT_LT(layout.boundingArea, 2 * 200 * 200 + 3 * 120 * 120);
}

TEST(Pack, AStripOfArchesTakesItsBlocksUnderTheArches)
{
    // Arches as wide as the strip, open below: a block fits between each one's legs, which only a
    // bottom-left fill reaches (docking would stack the blocks on top: a strip 150 mm long, not 120).
    PackProblem problem;
    problem.strip = true;
    problem.boards.push_back({"strip", "", 60, 0, 0, 1});
    problem.settings = {1, 0, 0, 0};
    const fabguide::geometry::Outline arch{
        {{0, 0}, {10, 0}, {10, 40}, {50, 40}, {50, 0}, {60, 0}, {60, 60}, {0, 60}}, {}};
    problem.parts.push_back({"arch", arch, 2, {0}, {}, {}});
    problem.parts.push_back(rectangularPart("block", 30, 30, 2, {0}));
    OrderingSearchOptions options = quick();
    options.timeLimit = 2;  // the shrinking tries to the end: no strip is shorter, but the area allows one
    const Layout layout = pack(problem, options);
    EXPECT_NEAR(layout.stripHeight, 120, 1e-6);
    expectOutlinesApart(problem, layout, -1e-3);
}

TEST(Pack, AStripOfIrregularPartsIsShrunkKeepingTheClearance)
{
    using fabguide::geometry::Outline;
    PackProblem problem;
    problem.strip = true;
    problem.boards.push_back({"roll", "", 300, 0, 0, 1});
    problem.settings = {0.5, 2, 0, 0};
    addEllsAndTriangles(problem, 3, 4);
    OrderingSearchOptions options = quick();
    options.timeLimit = 3;
    const Layout layout = pack(problem, options);
    ASSERT_EQ(layout.placements.size(), 7u);
    // Measured on the outlines: no two overlap or come closer than the kerf (to a micrometre, as
    // outline_check measures), every part on the strip.
    std::vector<Outline> placed;
    for (const Placement& p : layout.placements) {
        placed.push_back(fabguide::geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y));
        EXPECT_TRUE(p.x >= -1e-9 && p.y >= -1e-9 && p.x + p.width <= 300 + 1e-9 &&
                    p.y + p.height <= layout.stripHeight + 1e-6);
    }
    for (size_t i = 0; i < placed.size(); ++i)
        for (size_t j = i + 1; j < placed.size(); ++j) {
            EXPECT_EQ(sharedArea(placed[i], placed[j]), 0) << i << " and " << j;
            EXPECT_GE(fabguide::material::testing::distance(placed[i].outer, placed[j].outer), 2 - 1e-3)
                << i << " and " << j;
        }
    // 90,000 mm² of parts on a strip 300 mm wide: no strip is shorter than 300 mm; this one uses 71 % or
    // more.
    EXPECT_LT(layout.stripHeight, 1.4 * 300);
}

TEST(Pack, PartsAreCutOnlyFromBoardsOfTheirThickness)
{
    PackProblem problem = shelfProblem();
    problem.boards.push_back({"hardboard", "hardboard", 1000, 600, 6, 1});
    problem.parts.push_back(rectangularPart("back", 560, 380, 1));
    problem.parts.back().thickness = 6;
    for (PartSpec& part : problem.parts)
        if (part.thickness == 0)
            part.thickness = 18;
    const Layout layout = pack(problem, quick());
    for (const Placement& p : layout.placements)
        EXPECT_EQ(layout.sheets[p.sheet].thickness, problem.parts[p.part].thickness)
            << problem.parts[p.part].id;
    problem.parts.back().thickness = 12;
    try {
        pack(problem, quick());
        FAIL() << "a 12 mm part was laid out with no 12 mm board";
    } catch (const PackingError& e) {
        EXPECT_STREQ(e.what(), "part 'back' is 12 mm thick: no master board is (add one that thick)");
    }
}

TEST(Pack, OffcutsAreUsedBeforeNewSheetsAndCostNothing)
{
    // The shelf problem's parts need two 1000 x 600 sheets; an offcut (cost 0, listed last) large enough for
    // a side and a shelf takes them, and the layout costs one sheet less than without it.
    PackProblem problem = shelfProblem();
    problem.boards.front().count = 3;
    const Layout without = pack(problem, quick());
    problem.boards.push_back({"offcut", "birch plywood", 720, 600, 18, 1, Grain::None, 0});
    const Layout with = pack(problem, quick());
    const auto cost = [](const Layout& l) {
        double total = 0;
        for (const MasterBoard& sheet : l.sheets)
            total += sheet.cost;
        return total;
    };
    EXPECT_TRUE(std::any_of(with.sheets.begin(), with.sheets.end(),
                            [](const MasterBoard& b) { return b.name == "offcut"; }));
    EXPECT_LT(cost(with), cost(without));
}

TEST(Pack, FreeRotationTurnsAStickThatFitsTheBoardOnlyAcrossIt)
{
    // A 130 mm stick on a 100 mm square board: no quarter turn fits it, 45 degrees does.
    PackProblem problem;
    problem.boards.push_back({"square", "ply", 100, 100, 6, 1});
    problem.parts.push_back(rectangularPart("stick", 130, 8));
    problem.settings.resolution = 0.5;
    try {
        pack(problem, quick());
        FAIL() << "the stick fits no quarter turn";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("'stick'"), std::string::npos) << e.what();
    }
    problem.settings.rotationStep = 15;
    const Layout layout = pack(problem, quick());
    ASSERT_EQ(layout.placements.size(), 1u);
    const Placement& p = layout.placements[0];
    EXPECT_EQ(p.rotation % 90, 45);
    const fabguide::geometry::Box2 at = fabguide::geometry::bounds(
        fabguide::geometry::placed(problem.parts[0].outline, p.rotation, p.x, p.y).outer);
    EXPECT_GE(at.minX, -1e-9);
    EXPECT_GE(at.minY, -1e-9);
    EXPECT_LE(at.maxX, 100 + 1e-9);
    EXPECT_LE(at.maxY, 100 + 1e-9);
    EXPECT_NEAR(p.width, at.width(), 1e-9);
    problem.parts[0].followsGrain = true;  // a part along the grain keeps its quarter turns
    problem.boards[0].grain = Grain::AlongWidth;
    EXPECT_THROW(pack(problem, quick()), PackingError);
    problem.settings.rotationStep = 7;
    EXPECT_THROW(pack(problem, quick()), std::invalid_argument);
}

namespace {

/// The memory limit set for one test, the old one back after it.
class MemoryLimit {
public:
    explicit MemoryLimit(double bytes) : before_(fabguide::memoryLimit()) { fabguide::setMemoryLimit(bytes); }
    ~MemoryLimit() { fabguide::setMemoryLimit(before_); }
    MemoryLimit(const MemoryLimit&) = delete;
    MemoryLimit& operator=(const MemoryLimit&) = delete;

private:
    double before_;
};

}  // namespace

TEST(Pack, IrregularGridsPastTheMemoryLimitAreRefusedNamingTheResolution)
{
    const PackProblem problem = ellsAndTrianglesOnPly();
    const MemoryLimit tight(1e6);  // the ell's four bitmaps of 400 x 400 cells need ~1 MB
    try {
        pack(problem, quick());
        FAIL() << "expected MemoryError";
    } catch (const fabguide::MemoryError& e) {
        EXPECT_NE(std::string(e.what()).find("settings.resolution 0.5 mm"), std::string::npos) << e.what();
    }
}
