#include "Layout/Raster.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(Raster, ADenseCircleAndAPlateOfPinHolesRasteriseCoveringTheirMaterial)
{
    // A 100,000-point circle and 10,000 holes once took 18 s and 24 s to rasterise.
    const int n = 100000;
    Outline disc;
    for (int k = 0; k < n; ++k)
        disc.outer.push_back(
            {250 + 250 * std::cos(2 * M_PI * k / n), 250 + 250 * std::sin(2 * M_PI * k / n)});
    const Footprint f = rasterise(disc, 0.5, 0);
    for (int y = 0; y < f.height(); y += 7)
        for (int x = 0; x < f.width(); x += 7)
            if (std::hypot(x * 0.5 + 0.25 - 250, y * 0.5 + 0.25 - 250) < 250) {  // a cell centre in the disc
                EXPECT_TRUE(f.filled(x, y)) << x << " " << y;
            }
    EXPECT_LE(f.area(), M_PI * 251 * 251 / 0.25);  // and not much more
    Outline plate{{{0, 0}, {500, 0}, {500, 500}, {0, 500}}, {}};
    for (int k = 0; k < 10000; ++k) {
        const double x = 2 + 5 * (k % 100), y = 2 + 5 * (k / 100);
        plate.holes.push_back({{x, y}, {x, y + 2}, {x + 2, y + 2}, {x + 2, y}});  // clockwise, as read
    }
    const Footprint g = rasterise(plate, 0.5, 0);
    EXPECT_EQ(g.width(), 1000);
    EXPECT_TRUE(g.filled(0, 0) && g.filled(999, 999));
    EXPECT_FALSE(g.filled(5, 5)) << "inside the first hole (2..4 mm): free";
    // Every hole frees at least the 3 x 3 cells wholly inside it and at most its 4 x 4: kept, conservatively.
    EXPECT_LE(g.area(), 1000 * 1000 - 10000 * 3 * 3);
    EXPECT_GE(g.area(), 1000 * 1000 - 10000 * 4 * 4);
}
