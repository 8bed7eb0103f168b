#include "Layout/Footprint.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

using fabguide::material::Footprint;

TEST(Footprint, RectangleProfilesSpanTheWholePart)
{
    const Footprint f = Footprint::rectangle(3, 2);
    EXPECT_EQ(f.area(), 6);
    EXPECT_EQ(f.left(), (std::vector<int>{0, 0}));
    EXPECT_EQ(f.right(), (std::vector<int>{3, 3}));
    EXPECT_EQ(f.bottom(), (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(f.top(), (std::vector<int>{2, 2, 2}));
}

TEST(Footprint, LShapeProfilesFollowTheOutline)
{
    // Row 0 (bottom): ###   Row 1: #..
    const Footprint f(3, 2, {1, 1, 1, 1, 0, 0});
    EXPECT_EQ(f.area(), 4);
    EXPECT_EQ(f.right(), (std::vector<int>{3, 1}));
    EXPECT_EQ(f.top(), (std::vector<int>{2, 1, 1}));
}

TEST(Footprint, ColumnsListTheirFilledRunsBottomUp)
{
    // Column 0: #.#  (rows 0 and 2), column 1: ### (a run of three), read bottom up.
    const Footprint f(2, 3, {1, 1, 0, 1, 1, 1});
    using Runs = std::vector<std::pair<int, int>>;
    EXPECT_EQ(Runs(f.runs(0).begin(), f.runs(0).end()), (Runs{{0, 1}, {2, 3}}));
    EXPECT_EQ(Runs(f.runs(1).begin(), f.runs(1).end()), (Runs{{0, 3}}));
    const Footprint solid = Footprint::rectangle(2, 5);
    EXPECT_EQ(Runs(solid.runs(1).begin(), solid.runs(1).end()), (Runs{{0, 5}}));
}

TEST(Footprint, RotatingTurnsCounterClockwise)
{
    const Footprint f(3, 2, {1, 1, 1, 1, 0, 0});
    const Footprint r = f.rotated90();
    ASSERT_EQ(r.width(), 2);
    ASSERT_EQ(r.height(), 3);
    // The long bottom row becomes the right column; the lone upper cell goes to the bottom-left.
    EXPECT_TRUE(r.filled(1, 0) && r.filled(1, 1) && r.filled(1, 2));
    EXPECT_TRUE(r.filled(0, 0));
    EXPECT_FALSE(r.filled(0, 1) || r.filled(0, 2));
    EXPECT_EQ(r.rotated90().rotated90().rotated90(), f);
}

TEST(Footprint, RejectsEmptyAndMismatchedBitmaps)
{
    EXPECT_THROW(Footprint(2, 2, {0, 0, 0, 0}), std::invalid_argument);
    EXPECT_THROW(Footprint(2, 2, {1, 1, 1}), std::invalid_argument);
    EXPECT_THROW(Footprint::rectangle(0, 5), std::invalid_argument);
}
