#include "Layout/HoleFill.h"

#include <gtest/gtest.h>

using namespace fabguide;
using namespace fabguide::material;

namespace {

const Deadline kNoDeadline;  // no time limit

/// A 300 x 200 frame with a 200 x 100 window at (50, 50), and 40 x 30 tags.
PackProblem frameAndTags(int tags)
{
    PackProblem problem;
    problem.settings.kerf = 3;
    problem.settings.spacing = 2;
    problem.boards.push_back({"ply", "birch", 1000, 500, 12, -1, Grain::None, 1});
    PartSpec frame = rectangularPart("frame", 300, 200);
    frame.outline.holes.push_back({{50, 50}, {50, 150}, {250, 150}, {250, 50}});
    problem.parts = {frame, rectangularPart("tag", 40, 30, tags)};
    return problem;
}

}  // namespace

TEST(HoleFill, SmallPartsFillTheWindowClearOfItsEdgeAndEachOther)
{
    const PackProblem problem = frameAndTags(20);
    std::vector<int> left{1, 20};
    const auto guests = fillHoles(problem, left, kNoDeadline);
    ASSERT_EQ(guests[0].size(), 1u);
    const std::vector<Guest>& in = guests[0][0];
    // 200 x 100 less 5 mm all round: 190 x 90 holds 4 tags across (45 each with the gap) and 2 up (35 each).
    EXPECT_EQ(in.size(), 8u);
    EXPECT_EQ(left[1], 20 - static_cast<int>(in.size()));
    EXPECT_EQ(left[0], 1);
    for (size_t i = 0; i < in.size(); ++i) {
        const double w = in[i].rotation % 180 ? 30 : 40, h = in[i].rotation % 180 ? 40 : 30;
        EXPECT_GE(in[i].x, 55 - 1e-9);
        EXPECT_GE(in[i].y, 55 - 1e-9);
        EXPECT_LE(in[i].x + w, 245 + 1e-9);
        EXPECT_LE(in[i].y + h, 145 + 1e-9);
        for (size_t j = 0; j < i; ++j) {
            const double v = in[j].rotation % 180 ? 30 : 40, u = in[j].rotation % 180 ? 40 : 30;
            EXPECT_TRUE(in[i].x + w + 5 <= in[j].x + 1e-6 || in[j].x + v + 5 <= in[i].x + 1e-6 ||
                        in[i].y + h + 5 <= in[j].y + 1e-6 || in[j].y + u + 5 <= in[i].y + 1e-6);
        }
    }
}

TEST(HoleFill, APartOfAnotherThicknessOrGrainStaysOut)
{
    PackProblem problem = frameAndTags(3);
    problem.parts[1].thickness = 6;  // the frame is cut from any board, the tags from 6 mm only
    std::vector<int> left{1, 3};
    EXPECT_TRUE(fillHoles(problem, left, kNoDeadline)[0][0].empty());
    problem.parts[1].thickness = 0;
    problem.parts[1].followsGrain = true;  // the frame may turn any way: the tags' grain would not follow
    EXPECT_TRUE(fillHoles(problem, left, kNoDeadline)[0][0].empty());
    EXPECT_EQ(left[1], 3);
}

TEST(HoleFill, GuestsTurnAndMoveWithTheirHost)
{
    const PackProblem problem = frameAndTags(1);
    std::vector<int> left{1, 1};
    const auto guests = fillHoles(problem, left, kNoDeadline);
    ASSERT_EQ(guests[0][0].size(), 1u);
    const Guest g = guests[0][0][0];
    // The frame alone laid out turned a quarter, its bounding box at (10, 20): 200 wide, 300 tall.
    Layout laid;
    laid.sheets = problem.boards;
    laid.placements.push_back({0, 0, 10, 20, 90, 200, 300});
    laid.partArea = 300 * 200 - 200 * 100;
    const Layout all = withGuests(laid, problem, {0}, guests);
    ASSERT_EQ(all.placements.size(), 2u);
    const Placement& tag = all.placements[1];
    EXPECT_EQ(tag.part, 1);
    EXPECT_EQ(tag.rotation, (g.rotation + 90) % 360);
    // The window, turned a quarter counter-clockwise about the frame's corner: x from 200 - 150 to 200 - 50,
    // y from 50 to 250, moved by (10, 20).
    EXPECT_GE(tag.x, 10 + 55 - 1e-9);
    EXPECT_LE(tag.x + tag.width, 10 + 145 + 1e-9);
    EXPECT_GE(tag.y, 20 + 55 - 1e-9);
    EXPECT_LE(tag.y + tag.height, 20 + 245 + 1e-9);
    EXPECT_DOUBLE_EQ(all.partArea, laid.partArea + 40 * 30);
}

TEST(HoleFill, PastItsDeadlineItLeavesTheRestToTheBoards)
{
    const PackProblem problem = frameAndTags(20);
    std::vector<int> left{1, 20};
    const auto guests = fillHoles(problem, left, Deadline(std::chrono::steady_clock::now()));
    EXPECT_TRUE(guests[0][0].empty());
    EXPECT_EQ(left[1], 20);
}
