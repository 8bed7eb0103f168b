#include "Layout/MaxRects.h"
#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <random>

using namespace fabguide::material;
using fabguide::material::testing::expectValid;

namespace {

const Deadline kNoDeadline;  // no time limit

}  // namespace

TEST(MaxRects, AGuillotinePerfectPackingFillsOneBoardExactly)
{
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 100, 60, 18, 1});
    problem.parts = {rectangularPart("a", 60, 40), rectangularPart("b", 40, 60),
                     rectangularPart("c", 30, 20, 2)};
    const Layout layout = maxRects(problem, kNoDeadline);
    expectValid(problem, layout);
    EXPECT_EQ(layout.sheets.size(), 1u);
    EXPECT_DOUBLE_EQ(layout.partArea, 100.0 * 60);
}

TEST(MaxRects, KerfSpacingAndTrimKeepEveryPartApartAndOffTheEdges)
{
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 1220, 610, 12, -1});
    std::mt19937 random(7);
    std::uniform_real_distribution<double> side(30, 400);
    for (int k = 0; k < 60; ++k)
        problem.parts.push_back(rectangularPart("p" + std::to_string(k), side(random), side(random)));
    problem.settings = {0.5, 3, 1, 10};
    const Layout layout = maxRects(problem, kNoDeadline);
    expectValid(problem, layout);
    EXPECT_NEAR(layout.sheetArea, 1220.0 * 610 * static_cast<double>(layout.sheets.size()), 1e-6);
}

TEST(MaxRects, GrainAndThicknessChooseTheBoardsAndTurns)
{
    const PackProblem problem = fabguide::material::testing::grainAndThicknessJob();
    const Layout layout = maxRects(problem, kNoDeadline);
    expectValid(problem, layout);
    fabguide::material::testing::expectGrainAndThicknessKept(problem, layout);
}

TEST(MaxRects, BoardsRunningOutNameThePartAndHowManyMore)
{
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 100, 100, 18, 1});
    problem.parts = {rectangularPart("tile", 60, 60, 3)};
    try {
        maxRects(problem, kNoDeadline);
        FAIL() << "three 60 mm tiles do not fit one 100 mm board";
    } catch (const PackingError& e) {
        EXPECT_STREQ(e.what(),
                     "not enough master boards: part 'tile' and 1 more do not fit on the boards available");
    }
}

TEST(MaxRects, PackKeepsTheBetterOfMaxRectsAndDockingAndLaysOutAShopJobWhole)
{
    PackProblem problem;
    problem.boards.push_back({"sheet", "ply", 2440, 1220, 18, -1});
    std::mt19937 random(3);
    std::uniform_real_distribution<double> side(40, 900);
    for (int k = 0; k < 500; ++k)  // beyond kDockedUnits: MaxRects alone
        problem.parts.push_back(rectangularPart("p" + std::to_string(k), side(random), side(random) / 2));
    problem.settings = {0.5, 3, 0, 10};
    OrderingSearchOptions options;
    options.timeLimit = 30;
    const Layout layout = pack(problem, options);
    expectValid(problem, layout);
    EXPECT_EQ(layout.sheets.size(), maxRects(problem, kNoDeadline).sheets.size());
}

TEST(MaxRects, AStripOfAPerfectPackingIsAsLowAsItsArea)
{
    PackProblem problem;
    problem.strip = true;
    problem.boards.push_back({"strip", "", 100, 0, 0, 1});
    problem.parts = {rectangularPart("a", 60, 40), rectangularPart("b", 40, 60),
                     rectangularPart("c", 30, 20, 2)};
    const auto layout =
        maxRectsStrip(problem, Deadline(std::chrono::steady_clock::now() + std::chrono::seconds(5)));
    ASSERT_TRUE(layout);
    EXPECT_NEAR(layout->stripHeight, 60, 60e-3);  // the bisection stops within 0.1 % of the height
    PackProblem board = problem;
    board.boards[0].height = layout->stripHeight;
    expectValid(board, *layout);
}
