#include "Layout/LowerBound.h"
#include "Layout/MaxRects.h"
#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <random>

using namespace fabguide::material;
using fabguide::material::testing::cutFromSheets;

namespace {

/// `part` that lies along the width of the board only (0° or 180°).
PartSpec unturned(PartSpec part)
{
    part.orientations = {0, 180};
    return part;
}

}  // namespace

TEST(LowerBound, SheetsByAreaBoundsEachThicknessOnItsOwnBoards)
{
    PackProblem problem;
    problem.boards = {
        {"18", "ply", 100, 60, 18, -1}, {"6", "ply", 100, 60, 6, -1}, {"6 large", "ply", 200, 60, 6, -1}};
    problem.parts = {rectangularPart("a", 60, 40, 3), rectangularPart("b", 50, 60, 2)};
    problem.parts[0].thickness = 18;  // 7200 mm² on 6000 mm² boards: 2
    problem.parts[1].thickness = 6;   // 6000 mm² on a 12000 mm² board: 1
    EXPECT_EQ(sheetsByArea(problem), 3);
    problem.parts.push_back(rectangularPart("any", 100, 60, 3));  // any thickness: 18000 mm² more in all
    EXPECT_EQ(sheetsByArea(problem), 3);  // (7200 + 6000 + 18000) / 12000, rounded up, is 3 too
    problem.parts.back().quantity = 5;
    EXPECT_EQ(sheetsByArea(problem), 4);
    problem.settings.kerf = 10;  // the kerf counts on every part: 70 x 50 each of a on 110 x 70 boards
    problem.parts.pop_back();
    EXPECT_EQ(sheetsByArea(problem), 3);
}

TEST(LowerBound, PartsLongerThanHalfTheSheetLieOneAboveAnother)
{
    PackProblem problem;
    problem.boards = {{"board", "ply", 100, 60, 18, -1}};
    problem.parts = {unturned(rectangularPart("shelf", 60, 20, 4))};  // 4800 mm² of 6000: one sheet by area
    EXPECT_EQ(sheetsByArea(problem), 1);
    EXPECT_EQ(sheetsBound(problem), 2);       // three lie one above another, the fourth on a sheet of its own
    problem.parts[0].orientations = {0, 90};  // turned, four stand side by side on one sheet
    EXPECT_EQ(sheetsBound(problem), 1);
    problem.parts[0].orientations = {0, 90, 180, 270};
    problem.boards[0].grain = Grain::AlongWidth;
    problem.parts[0].followsGrain = true;  // the grain keeps them along the width
    EXPECT_EQ(sheetsBound(problem), 2);
}

TEST(LowerBound, ThePartsBesideALongPartAreThoseShorterThanWhatItLeaves)
{
    PackProblem problem;
    problem.boards = {{"board", "ply", 100, 60, 18, -1}};
    // 80 x 40 leaves a strip 20 wide beside it and 20 deep above it: no 30 x 30 lies in either.
    problem.parts = {unturned(rectangularPart("top", 80, 40)), unturned(rectangularPart("block", 30, 30, 3))};
    EXPECT_EQ(sheetsByArea(problem), 1);  // 5900 mm² of 6000
    EXPECT_EQ(sheetsBound(problem), 2);
    problem.parts[1].outline = rectangularPart("block", 20, 20).outline;  // these fit beside it
    EXPECT_EQ(sheetsBound(problem), 1);
}

TEST(LowerBound, TheKerfBetweenTwoPartsDecidesWhetherTheyLieSideBySide)
{
    PackProblem problem;
    problem.boards = {{"board", "ply", 100, 60, 18, -1}};
    problem.settings.kerf = 4;
    problem.parts = {unturned(rectangularPart("rail", 48, 20, 4))};  // 48 + 4 + 48 = 100: two abreast
    EXPECT_EQ(sheetsBound(problem), 1);
    problem.parts[0].outline = rectangularPart("rail", 49, 20).outline;  // two stacked per sheet: 20 + 4 + 20
    EXPECT_EQ(sheetsBound(problem), 2);
}

TEST(LowerBound, ThicknessesAreBoundedOnTheirOwnBoards)
{
    PackProblem problem;
    problem.boards = {{"18", "ply", 100, 60, 18, -1}, {"6", "ply", 100, 60, 6, -1}};
    problem.parts = {unturned(rectangularPart("shelf", 60, 20, 4)), rectangularPart("back", 30, 30)};
    problem.parts[0].thickness = 18;
    problem.parts[1].thickness = 6;
    EXPECT_EQ(sheetsBound(problem), 3);                        // 2 sheets of 18 mm by lines, 1 of 6 mm
    problem.boards.push_back({"any", "ply", 100, 60, 0, -1});  // a board any part may lie on: by area only
    EXPECT_EQ(sheetsBound(problem), sheetsByArea(problem));
}

/// Parts cut from whole sheets, exactly and less 2 %, turned or kept along the grain: the bound never needs
/// more sheets than they were cut from, and at a whole sheet's area it needs as many.
TEST(LowerBound, NeverAboveTheSheetsThePartsWereCutFrom)
{
    for (unsigned seed = 1; seed <= 60; ++seed)
        for (double slack : {1.0, 0.98}) {
            PackProblem problem = cutFromSheets(seed, 1 + seed % 3, slack);
            if (seed % 2) {
                problem.boards[0].grain = Grain::AlongWidth;
                for (PartSpec& part : problem.parts)
                    part.followsGrain = true;
            }
            EXPECT_LE(sheetsBound(problem), 1 + seed % 3) << "seed " << seed << " slack " << slack;
            if (slack == 1.0) {
                EXPECT_EQ(sheetsBound(problem), 1 + seed % 3) << "seed " << seed;
            }
        }
}

/// Random jobs, their parts long and short, turned or kept along the grain, with kerf and trim: the bound is
/// never above the sheets MaxRects lays them on, and on some it is above the area bound (so the lines count).
TEST(LowerBound, NeverAboveALayoutOfRandomJobs)
{
    std::mt19937 random(7);
    int aboveArea = 0;
    for (int job = 0; job < 1000; ++job) {
        PackProblem problem;
        problem.boards = {{"board", "ply", 1000, 600, 18, -1}};
        problem.boards[0].grain = job % 3 == 0 ? Grain::AlongWidth : Grain::None;
        problem.settings.kerf = std::uniform_real_distribution<double>(0, 6)(random);
        problem.settings.trim = job % 2 ? 5 : 0;
        const int kinds = std::uniform_int_distribution<int>(1, 8)(random);
        for (int k = 0; k < kinds; ++k) {
            std::uniform_real_distribution<double> width(20, 960), height(20, 560);
            problem.parts.push_back(rectangularPart("p" + std::to_string(k), std::round(width(random)),
                                                    std::round(height(random)),
                                                    std::uniform_int_distribution<int>(1, 4)(random)));
            problem.parts.back().followsGrain = k % 2 == 0;
            if (k % 3 == 0)
                problem.parts.back().orientations = {0, 180};
        }
        const Layout layout = maxRects(problem, Deadline());  // every run: no time limit
        const long bound = sheetsBound(problem);
        EXPECT_LE(bound, static_cast<long>(layout.sheets.size())) << "job " << job;
        EXPECT_GE(bound, sheetsByArea(problem));
        aboveArea += bound > sheetsByArea(problem);
    }
    EXPECT_GT(aboveArea, 100);
}
