#include "Layout/Raster.h"

#include <gtest/gtest.h>

using namespace fabguide::material;
using fabguide::geometry::Outline;

TEST(Raster, RoundsPartsUpAndBoardsDown)
{
    EXPECT_EQ(cellsCovering(10.0, 0.5), 20);
    EXPECT_EQ(cellsCovering(10.1, 0.5), 21);
    EXPECT_EQ(cellsWithin(10.4, 0.5), 20);
}

TEST(Raster, RectangleFillsItsGrownBox)
{
    const Footprint f = rasterise(fabguide::geometry::rectangle(10, 4), 1, 2);
    EXPECT_EQ(f.width(), 12);
    EXPECT_EQ(f.height(), 6);
    EXPECT_EQ(f.area(), 72);
}

TEST(Raster, LShapeLeavesItsNotchEmpty)
{
    // 30 x 30 L with a 20 x 20 notch at the top right; 1 mm cells, no clearance.
    const Outline ell{{{0, 0}, {30, 0}, {30, 10}, {10, 10}, {10, 30}, {0, 30}}, {}};
    const Footprint f = rasterise(ell, 1, 0);
    ASSERT_EQ(f.width(), 30);
    ASSERT_EQ(f.height(), 30);
    EXPECT_EQ(f.area(), 30 * 10 + 10 * 20);
    EXPECT_TRUE(f.filled(29, 9));
    EXPECT_FALSE(f.filled(29, 10));
    EXPECT_EQ(f.right()[25], 10);  // the profile docking uses sees the notch
}

TEST(Raster, ClearanceGrowsEveryEdgeByHalf)
{
    const Outline ell{{{0, 0}, {30, 0}, {30, 10}, {10, 10}, {10, 30}, {0, 30}}, {}};
    const Footprint f = rasterise(ell, 1, 2);  // 1 mm on every side
    ASSERT_EQ(f.width(), 32);
    EXPECT_EQ(f.right()[25], 12);   // inner edge x = 10 grown to 11, offset by the 1 mm margin
    EXPECT_TRUE(f.filled(31, 11));  // the arm's top edge y = 10 grown to 11
    EXPECT_FALSE(f.filled(31, 12));
}
