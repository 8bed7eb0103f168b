#include "Layout/Guillotine.h"
#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <random>
#include <stdexcept>

using namespace fabguide::material;
using fabguide::material::testing::expectValid;

namespace {

const Deadline kNoDeadline;  // no time limit

/// Cabinet-shop parts: sides, shelves and rails, 60-900 x 60-600 mm, some of them repeated.
PackProblem shopJob(unsigned seed, int stages)
{
    PackProblem problem;
    problem.boards.push_back({"chipboard", "melamine", 2800, 2070, 18, -1});
    problem.settings.kerf = 3.2;
    problem.settings.trim = 10;
    problem.settings.cuts = Cuts::Guillotine;
    problem.settings.stages = stages;
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> along(60, 900), across(60, 600);
    std::uniform_int_distribution<int> many(1, 6);
    for (int k = 0; k < 25; ++k)
        problem.parts.push_back(rectangularPart("p" + std::to_string(k), std::round(along(random)),
                                                std::round(across(random)), many(random)));
    return problem;
}

/// Every cut's kerf clear of every part on its sheet, every cut on its board and straight, its stage within
/// the settings' limit (a trim one past it).
void expectSawCuts(const PackProblem& problem, const Layout& layout)
{
    const PackSettings& s = problem.settings;
    ASSERT_EQ(layout.sawCuts.size(), layout.sheets.size());
    for (size_t sheet = 0; sheet < layout.sheets.size(); ++sheet)
        for (const SawCut& c : layout.sawCuts[sheet]) {
            const bool upright = std::abs(c.from.x - c.to.x) < 1e-9;
            ASSERT_TRUE(upright || std::abs(c.from.y - c.to.y) < 1e-9) << c.number;
            EXPECT_GE(std::min({c.from.x, c.from.y, c.to.x, c.to.y}), -1e-9) << c.number;
            EXPECT_LE(std::max(c.from.x, c.to.x), layout.sheets[sheet].width + 1e-9) << c.number;
            EXPECT_LE(std::max(c.from.y, c.to.y), layout.sheets[sheet].height + 1e-9) << c.number;
            if (s.stages > 0) {
                EXPECT_LE(c.stage, s.stages + (c.trim ? 1 : 0)) << c.number;
            }
            for (const Placement& p : layout.placements) {
                if (p.sheet != static_cast<int>(sheet))
                    continue;
                const double at = upright ? c.from.x : c.from.y, lo = upright ? p.x : p.y,
                             hi = lo + (upright ? p.width : p.height);
                const double from = std::min(upright ? c.from.y : c.from.x, upright ? c.to.y : c.to.x),
                             to = std::max(upright ? c.from.y : c.from.x, upright ? c.to.y : c.to.x),
                             plo = upright ? p.y : p.x, phi = plo + (upright ? p.height : p.width);
                const bool alongside = from < phi - 1e-6 && plo < to - 1e-6;
                EXPECT_FALSE(alongside && at + s.kerf / 2 > lo + 1e-6 && at - s.kerf / 2 < hi - 1e-6)
                    << "cut " << c.number << " on sheet " << sheet + 1 << " cuts into "
                    << problem.parts[p.part].id;
            }
        }
}

}  // namespace

TEST(Guillotine, APerfectTilingInStripsTakesOneSheetAndTheCutsBetweenItsPartsOnly)
{
    // Three strips of 1000 x 200: one part, two halves, four quarters. Any tiling in strips needs the two
    // cuts between them and one cut between neighbours in a strip: 6 cuts, 2 x 1000 + 4 x 200 mm long.
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 1000, 600, 18, -1});
    problem.parts = {rectangularPart("whole", 1000, 200), rectangularPart("half", 500, 200, 2),
                     rectangularPart("quarter", 250, 200, 4)};
    problem.settings.cuts = Cuts::Guillotine;
    problem.settings.stages = 2;
    problem.settings.firstCut = FirstCut::Along;
    const Layout layout = pack(problem, {Criterion::Docking, Bounds::Layout, 20});
    expectValid(problem, layout);
    expectSawCuts(problem, layout);
    ASSERT_EQ(layout.sheets.size(), 1u);
    ASSERT_EQ(layout.sawCuts[0].size(), 6u);
    double length = 0;
    for (const SawCut& c : layout.sawCuts[0]) {
        length += c.length();
        EXPECT_FALSE(c.trim) << c.number;
        EXPECT_EQ(c.stage, c.number.size() == 1 ? 1 : 2) << c.number;
    }
    EXPECT_NEAR(length, 2800, 1e-9);
}

TEST(Guillotine, KerfTrimAndTheStageLimitHoldInEveryCut)
{
    for (int stages : {1, 2, 3, 0})
        for (unsigned seed : {1u, 2u, 3u}) {
            const PackProblem problem = shopJob(seed, stages);
            const Layout layout = guillotine(problem, 30, 1, kNoDeadline);
            expectValid(problem, layout);
            expectSawCuts(problem, layout);
            ASSERT_EQ(layout.sawCuts[0].front().number, "0.1") << "the edges are trimmed first";
        }
}

TEST(Guillotine, GrainAndThicknessChooseTheBoardsAndTurns)
{
    PackProblem problem = fabguide::material::testing::grainAndThicknessJob();
    problem.settings.cuts = Cuts::Guillotine;
    const Layout layout = guillotine(problem, 10, 1, kNoDeadline);
    expectValid(problem, layout);
    expectSawCuts(problem, layout);
    fabguide::material::testing::expectGrainAndThicknessKept(problem, layout);
}

TEST(Guillotine, TheSameRunsGiveTheSameLayout)
{
    const PackProblem problem = shopJob(7, 3);
    const Layout a = guillotine(problem, 40, 5, kNoDeadline), b = guillotine(problem, 40, 5, kNoDeadline);
    ASSERT_EQ(a.placements.size(), b.placements.size());
    for (size_t k = 0; k < a.placements.size(); ++k) {
        EXPECT_EQ(a.placements[k].x, b.placements[k].x);
        EXPECT_EQ(a.placements[k].y, b.placements[k].y);
        EXPECT_EQ(a.placements[k].sheet, b.placements[k].sheet);
    }
}

TEST(Guillotine, BoardsRunningOutNameThePartLeft)
{
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 1000, 600, 18, 1});
    problem.parts = {rectangularPart("door", 900, 500, 2)};
    problem.settings.cuts = Cuts::Guillotine;
    try {
        guillotine(problem, 10, 1, kNoDeadline);
        FAIL() << "two doors do not fit on one sheet";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("'door'"), std::string::npos) << e.what();
    }
}

TEST(Guillotine, RunsWithoutEndStopAtTheDeadlineWhenEveryOrderRunsOutOfBoards)
{
    // Unbounded runs (the CLI's default) ran on for ever when no order fitted: the deadline was only checked
    // once a layout was in hand. A search cancelled before it starts now names the part left after one run.
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 1000, 600, 18, 1});
    problem.parts = {rectangularPart("door", 900, 500, 2)};
    problem.settings.cuts = Cuts::Guillotine;
    const std::atomic<bool> cancelled{true};
    try {
        guillotine(problem, std::numeric_limits<long>::max(), 1,
                   Deadline(Deadline::Clock::time_point::max(), &cancelled));
        FAIL() << "two doors do not fit on one sheet";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("'door'"), std::string::npos) << e.what();
    }
}

TEST(Guillotine, APartLeavingLessThanHalfAKerfAtTheBoardsEdgeIsRefusedByName)
{
    // 999 mm on a 1000 mm board with a 3.2 mm blade and no trim: the cut that parts 1 mm off would run off
    // the board. 990 mm leaves room for it; 1000 mm needs no cut.
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 1000, 600, 18, -1});
    problem.settings.cuts = Cuts::Guillotine;
    problem.settings.kerf = 3.2;
    for (double length : {990.0, 1000.0}) {
        problem.parts = {rectangularPart("rail", length, 100, 1, {0})};
        const Layout layout = guillotine(problem, 4, 1, kNoDeadline);
        expectValid(problem, layout);
        expectSawCuts(problem, layout);
    }
    problem.parts = {rectangularPart("rail", 999, 100, 1, {0})};
    try {
        guillotine(problem, 4, 1, kNoDeadline);
        FAIL() << "999 mm cannot be sawn from 1000 mm with a 3.2 mm kerf";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("'rail'"), std::string::npos) << e.what();
    }
}

TEST(Guillotine, AStripCannotBeSawnAndStagesMustNotBeNegative)
{
    PackProblem problem = shopJob(1, 3);
    problem.strip = true;
    EXPECT_THROW(checkSettings(problem), std::invalid_argument);
    problem.strip = false;
    problem.settings.stages = -1;
    EXPECT_THROW(checkSettings(problem), std::invalid_argument);
}
