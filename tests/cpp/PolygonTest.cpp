#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace fabguide::geometry;

namespace {
struct Box {
    double minX, minY, maxX, maxY;
};
Box bounds(const Polygon& p)
{
    Box b{1e300, 1e300, -1e300, -1e300};
    for (const Point2& q : p)
        b = {std::min(b.minX, q.x), std::min(b.minY, q.y), std::max(b.maxX, q.x), std::max(b.maxY, q.y)};
    return b;
}
}  // namespace

TEST(Polygon, RectangleIsCounterClockwise)
{
    EXPECT_DOUBLE_EQ(signedArea(rectangle(4, 3).outer), 12);
}

TEST(Polygon, PlacedTurnsAndMovesTheBoundingBox)
{
    const Outline o = placed(rectangle(40, 10), 90, 100, 200);
    const Box b = bounds(o.outer);
    EXPECT_DOUBLE_EQ(b.minX, 100);
    EXPECT_DOUBLE_EQ(b.minY, 200);
    EXPECT_DOUBLE_EQ(b.maxX, 110);
    EXPECT_DOUBLE_EQ(b.maxY, 240);
}

TEST(Polygon, OffsetGrowsOutlinesAndShrinksHolesKeepingCorners)
{
    Outline frame = rectangle(100, 60);
    frame.holes.push_back({{20, 20}, {20, 40}, {80, 40}, {80, 20}});  // clockwise
    const Outline path = offset(frame, 0.1);
    const Box outer = bounds(path.outer);
    EXPECT_NEAR(outer.maxX - outer.minX, 100.2, 1e-6);
    EXPECT_NEAR(outer.maxY - outer.minY, 60.2, 1e-6);
    EXPECT_EQ(path.outer.size(), 4u);  // mitred: still a rectangle
    ASSERT_EQ(path.holes.size(), 1u);
    const Box hole = bounds(path.holes[0]);
    EXPECT_NEAR(hole.maxX - hole.minX, 59.8, 1e-6);
    EXPECT_NEAR(hole.maxY - hole.minY, 19.8, 1e-6);
}
