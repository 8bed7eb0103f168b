#include "Layout/CommonLine.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fabguide::material;
using fabguide::geometry::Polygon;

namespace {

ToolPath box(double x0, double y0, double x1, double y1, size_t placement)
{
    ToolPath path;
    path.points = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    path.placement = placement;
    return path;
}

/// The length the tool travels along the path: a closed one back to its start.
double lengthOf(const ToolPath& path)
{
    const Polygon& p = path.points;
    double l = 0;
    for (size_t i = 0; i + 1 < p.size(); ++i)
        l += std::hypot(p[i + 1].x - p[i].x, p[i + 1].y - p[i].y);
    return path.open ? l : l + std::hypot(p.front().x - p.back().x, p.front().y - p.back().y);
}

}  // namespace

TEST(CommonLine, TheSecondOfTwoNeighboursSkipsTheLineTheFirstCut)
{
    // Two 100 x 50 parts side by side, their paths meeting on x = 100 (a kerf apart).
    std::vector<ToolPath> cuts = {box(0, 0, 100, 50, 0), box(100, 0, 200, 50, 1)};
    EXPECT_DOUBLE_EQ(cutCommonLinesOnce(cuts), 50);
    ASSERT_EQ(cuts.size(), 2u);
    EXPECT_FALSE(cuts[0].open);
    EXPECT_TRUE(cuts[1].open);
    EXPECT_EQ(cuts[1].placement, 1u);
    EXPECT_DOUBLE_EQ(lengthOf(cuts[1]),
                     250);  // three sides, one path: (100,0) → (200,0) → (200,50) → (100,50)
    ASSERT_EQ(cuts[1].points.size(), 4u);
    EXPECT_DOUBLE_EQ(cuts[1].points.front().x, 100);
    EXPECT_DOUBLE_EQ(cuts[1].points.back().x, 100);
}

TEST(CommonLine, AShorterNeighbourSharesOnlyItsOwnLength)
{
    // A short part above the left half of a long one: only its 40 mm of the long one's top is shared.
    std::vector<ToolPath> cuts = {box(10, 50, 50, 80, 0), box(0, 0, 200, 50, 1)};
    EXPECT_NEAR(cutCommonLinesOnce(cuts), 40, 1e-9);
    ASSERT_EQ(cuts.size(), 2u);
    EXPECT_NEAR(lengthOf(cuts[1]), 2 * 250 - 40, 1e-9);
    EXPECT_NEAR(cuts[1].points.front().x, 10,
                1e-9);  // the path runs from one end of the gap round to the other
    EXPECT_NEAR(cuts[1].points.back().x, 50, 1e-9);
}

TEST(CommonLine, APartWhoseEveryEdgeWasCutHasNoPathLeft)
{
    // A 3 x 1 row and a part framed above and below by two more: the middle one's edges are all cut.
    std::vector<ToolPath> cuts = {box(0, 0, 10, 10, 0), box(20, 0, 30, 10, 1), box(0, 10, 30, 20, 2),
                                  box(0, -10, 30, 0, 3), box(10, 0, 20, 10, 4)};
    cutCommonLinesOnce(cuts);
    for (const ToolPath& path : cuts)
        EXPECT_NE(path.placement, 4u);
}

TEST(CommonLine, PathsAnyGapApartAndTabbedPathsStayAsTheyAre)
{
    std::vector<ToolPath> cuts = {box(0, 0, 100, 50, 0), box(100.01, 0, 200, 50, 1)};
    EXPECT_EQ(cutCommonLinesOnce(cuts), 0);
    EXPECT_FALSE(cuts[1].open);
    ASSERT_EQ(cuts[1].points.size(), 4u);
    std::vector<ToolPath> tabbed = {box(0, 0, 100, 50, 0), box(100, 0, 200, 50, 1)};
    tabbed[1].tabbed = true;
    EXPECT_EQ(cutCommonLinesOnce(tabbed), 0);
    EXPECT_FALSE(tabbed[1].open);
}

TEST(CommonLine, TheLengthCutIsThePerimetersLessWhatIsShared)
{
    // A 4 x 3 grid of 20 x 10 cells.
    std::vector<ToolPath> cuts;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            cuts.push_back(box(20 * i, 10 * j, 20 * (i + 1), 10 * (j + 1), cuts.size()));
    const double saved = cutCommonLinesOnce(cuts);
    double left = 0;
    for (const ToolPath& path : cuts)
        left += lengthOf(path);
    // Every line of the grid once: 4 horizontal lines of 80, 5 vertical lines of 30.
    EXPECT_NEAR(left, 4 * 80 + 5 * 30, 1e-9);
    EXPECT_NEAR(saved, 12 * 60 - (4 * 80 + 5 * 30), 1e-9);
}
