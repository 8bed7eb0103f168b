#include "Geometry/Polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace fabguide::geometry;

TEST(Polygon, RectangleIsCounterClockwise)
{
    EXPECT_DOUBLE_EQ(signedArea(rectangle(4, 3).outer), 12);
}

TEST(Polygon, PlacedTurnsAndMovesTheBoundingBox)
{
    const Outline o = placed(rectangle(40, 10), 90, 100, 200);
    const Box2 b = bounds(o.outer);
    EXPECT_DOUBLE_EQ(b.minX, 100);
    EXPECT_DOUBLE_EQ(b.minY, 200);
    EXPECT_DOUBLE_EQ(b.maxX, 110);
    EXPECT_DOUBLE_EQ(b.maxY, 240);
}

TEST(Polygon, PlacedTurnsByAnyDegreeKeepingTheArea)
{
    const Outline o = placed(rectangle(40, 10), 30, 5, 7);
    const Box2 b = bounds(o.outer);
    EXPECT_NEAR(b.minX, 5, 1e-9);
    EXPECT_NEAR(b.minY, 7, 1e-9);
    EXPECT_NEAR(b.width(), 40 * std::cos(M_PI / 6) + 10 * std::sin(M_PI / 6), 1e-9);
    EXPECT_NEAR(b.height(), 40 * std::sin(M_PI / 6) + 10 * std::cos(M_PI / 6), 1e-9);
    EXPECT_NEAR(signedArea(o.outer), 400, 1e-9);
}

TEST(Polygon, OffsetGrowsOutlinesAndShrinksHolesKeepingCorners)
{
    Outline frame = rectangle(100, 60);
    frame.holes.push_back({{20, 20}, {20, 40}, {80, 40}, {80, 20}});  // clockwise
    const Outline path = offset(frame, 0.1);
    const Box2 outer = bounds(path.outer);
    EXPECT_NEAR(outer.width(), 100.2, 1e-6);
    EXPECT_NEAR(outer.height(), 60.2, 1e-6);
    EXPECT_EQ(path.outer.size(), 4u);  // mitred: still a rectangle
    ASSERT_EQ(path.holes.size(), 1u);
    const Box2 hole = bounds(path.holes[0]);
    EXPECT_NEAR(hole.width(), 59.8, 1e-6);
    EXPECT_NEAR(hole.height(), 19.8, 1e-6);
}

TEST(Polygon, AreaSubtractsHolesAndRectanglesAreRecognised)
{
    Outline frame = rectangle(10, 10);
    EXPECT_TRUE(isRectangle(frame));
    frame.holes.push_back({{2, 2}, {2, 4}, {4, 4}, {4, 2}});
    EXPECT_DOUBLE_EQ(area(frame), 96);
    EXPECT_FALSE(isRectangle(frame));
    EXPECT_FALSE(isRectangle({{{0, 0}, {10, 0}, {10, 10}, {5, 12}}, {}}));
}

TEST(Polygon, SpansBetweenFollowTheOutline)
{
    const Outline ell{{{0, 0}, {30, 0}, {30, 10}, {10, 10}, {10, 30}, {0, 30}}, {}};
    auto low = spansBetween(ell, 2, 4);
    ASSERT_EQ(low.size(), 1u);
    EXPECT_NEAR(low[0].second, 30, 1e-6);
    auto high = spansBetween(ell, 20, 22);
    ASSERT_EQ(high.size(), 1u);
    EXPECT_NEAR(high[0].second, 10, 1e-6);
    EXPECT_TRUE(spansBetween(ell, 31, 33).empty());
}

TEST(Polygon, SelfCrossingFindsTheEdgesThatMeet)
{
    using fabguide::geometry::selfCrossing;
    EXPECT_EQ(selfCrossing({{0, 0}, {10, 0}, {10, 10}, {0, 10}}), std::make_pair(-1, -1));
    // A bow tie: the edges from points 0 and 2 cross.
    EXPECT_EQ(selfCrossing({{0, 0}, {10, 10}, {10, 0}, {0, 10}}), std::make_pair(0, 2));
    // A figure touching itself at a corner, and an edge folding back onto the one before it.
    EXPECT_NE(selfCrossing({{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}}).first, -1);
    EXPECT_NE(selfCrossing({{0, 0}, {10, 0}, {5, 0}, {5, 5}}).first, -1);
    // A circle of 20,000 points is simple, and told so at once.
    fabguide::geometry::Polygon circle;
    for (int k = 0; k < 20000; ++k)
        circle.push_back({100 * std::cos(k * 2 * M_PI / 20000), 100 * std::sin(k * 2 * M_PI / 20000)});
    EXPECT_EQ(selfCrossing(circle), std::make_pair(-1, -1));
    std::swap(circle[10], circle[15000]);
    EXPECT_NE(selfCrossing(circle).first, -1);
}

TEST(Polygon, TheDeepestPointIsFarthestFromEdgesAndHoles)
{
    using namespace fabguide::geometry;
    const auto [centre, radius] = deepestPoint(rectangle(100, 60));
    EXPECT_NEAR(radius, 30, 0.01);
    EXPECT_NEAR(centre.y, 30, 0.01);
    EXPECT_GT(centre.x, 30 - 0.01);
    EXPECT_LT(centre.x, 70 + 0.01);
    // A seat with a hand hole, 100 mm of material all round it: the pole lies towards a corner, on the
    // diagonal, as far from both edges as from the hole's corner: t = √2 (100 - t).
    Outline seat = rectangle(300, 300);
    seat.holes.push_back({{100, 100}, {100, 200}, {200, 200}, {200, 100}});
    const auto [at, room] = deepestPoint(seat);
    EXPECT_NEAR(room, 100 * std::sqrt(2) / (1 + std::sqrt(2)), 0.02);
    EXPECT_FALSE(at.x > 100 && at.x < 200 && at.y > 100 && at.y < 200);
}

TEST(Polygon, DogbonesLetTheBitReachEveryInsideCorner)
{
    using namespace fabguide::geometry;
    // A 100 x 50 board with a 20 x 20 notch from the top: its two inside corners, (40, 30) and (60, 30).
    const Outline notched{{{0, 0}, {100, 0}, {100, 50}, {60, 50}, {60, 30}, {40, 30}, {40, 50}, {0, 50}}, {}};
    const double bit = 6, r = bit / 2;
    const auto nearest = [](const Outline& path, Point2 c) {
        double d = 1e300;
        for (const Point2& p : path.outer)
            d = std::min(d, std::hypot(p.x - c.x, p.y - c.y));
        return d;
    };
    // The bit's centre must reach r out from each corner along its bisector into the notch.
    const Point2 right{60 - r / std::sqrt(2), 30 + r / std::sqrt(2)},
        left{40 + r / std::sqrt(2), 30 + r / std::sqrt(2)};
    const Outline plain = offset(notched, r), relieved = offset(dogboned(notched, bit), r);
    EXPECT_GT(nearest(plain, right), 1.0);  // a plain path stops short: a 3 mm fillet is left in the corner
    EXPECT_LT(nearest(relieved, right), 0.1);
    EXPECT_LT(nearest(relieved, left), 0.1);
    // Only the two corners lose material, each less than half a disc; outer corners stay square.
    const double lost = area(notched) - area(dogboned(notched, bit));
    EXPECT_GT(lost, 0);
    EXPECT_LT(lost, 2 * 3.14159 * r * r / 2);
    EXPECT_LT(nearest(dogboned(notched, bit), {100, 50}), 1e-6);
    // A hole's corners are inside corners too.
    Outline framed = rectangle(100, 100);
    framed.holes.push_back({{30, 30}, {30, 70}, {70, 70}, {70, 30}});
    EXPECT_EQ(dogboned(framed, bit).holes.size(), 1u);
    EXPECT_GT(area(framed) - area(dogboned(framed, bit)), 4 * 0.5);
}

TEST(Polygon, HoldingTabsLeaveGapsEvenlyAlongTheContour)
{
    using namespace fabguide::geometry;
    const Polygon contour = rectangle(100, 50).outer;
    const auto length = [](const Polygon& piece) {
        double l = 0;
        for (size_t k = 1; k < piece.size(); ++k)
            l += std::hypot(piece[k].x - piece[k - 1].x, piece[k].y - piece[k - 1].y);
        return l;
    };
    const std::vector<Polygon> pieces = withTabs(contour, 2, 5);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(length(pieces[0]) + length(pieces[1]), 300 - 2 * 5, 1e-9);
    EXPECT_NEAR(length(pieces[0]), length(pieces[1]), 1e-9);
    // Each piece ends 5 mm (along the contour) before the next begins.
    for (int k = 0; k < 2; ++k) {
        const Point2 end = pieces[k].back(), next = pieces[(k + 1) % 2].front();
        EXPECT_NEAR(std::hypot(end.x - next.x, end.y - next.y), 5, 1e-9);
    }
    // Too short for the tabs: the contour whole.
    EXPECT_EQ(withTabs(rectangle(4, 4).outer, 2, 5).size(), 1u);
}

TEST(Polygon, OutlinesOverlapWhereTheirMaterialDoesNotWhereTheyOnlyTouch)
{
    const Outline frame{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{{20, 20}, {20, 80}, {80, 80}, {80, 20}}}};
    const auto square = [](double x, double y, double side) {
        return Outline{{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}, {}};
    };
    EXPECT_TRUE(inMaterial(frame, {10, 50}));
    EXPECT_FALSE(inMaterial(frame, {50, 50}));           // in the hole
    EXPECT_FALSE(overlap(frame, square(40, 40, 10)));    // in the hole, clear of its edge
    EXPECT_FALSE(overlap(frame, square(100, 0, 10)));    // touching the side
    EXPECT_TRUE(overlap(frame, square(75, 40, 10)));     // across the hole's edge
    EXPECT_TRUE(overlap(frame, square(5, 40, 10)));      // wholly in the material
    EXPECT_TRUE(overlap(square(-10, -10, 200), frame));  // holding the frame
}

TEST(Polygon, SimplifiedKeepsEveryVertexWithinTheToleranceAndCornersAsTheyAre)
{
    Polygon circle;
    const int n = 100000;
    for (int k = 0; k < n; ++k)
        circle.push_back({250 * std::cos(2 * M_PI * k / n), 250 * std::sin(2 * M_PI * k / n)});
    const Polygon fewer = simplified(circle, 0.025);
    EXPECT_LT(fewer.size(), 1000u);
    for (size_t k = 0; k < circle.size(); k += 97) {  // every vertex dropped lies near the new contour
        double nearest = 1e9;
        for (size_t j = 0; j < fewer.size(); ++j) {
            const Point2 a = fewer[j], b = fewer[(j + 1) % fewer.size()], p = circle[k];
            const double dx = b.x - a.x, dy = b.y - a.y;
            const double t =
                std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
            nearest = std::min(nearest, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
        }
        EXPECT_LE(nearest, 0.025 + 1e-9) << k;
    }
    const Polygon ell{{0, 0}, {30, 0}, {30, 10}, {10, 10}, {10, 30}, {0, 30}};
    EXPECT_EQ(simplified(ell, 0.05).size(), ell.size());
}
