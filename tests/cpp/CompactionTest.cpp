// Compaction of a strip on the parts' real outlines (issue 16, item 3).
#include "Layout/Compaction.h"

#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace fabguide::material;
using fabguide::geometry::Outline;
using fabguide::geometry::Point2;
using fabguide::geometry::Polygon;
using fabguide::material::testing::distance;

namespace {

PartSpec part(const std::string& id, Outline outline)
{
    return {id, std::move(outline), 1, {0}, {}, {}};
}

/// A strip `width` wide of the problem's parts, one unit each, at (x, y), turned by 0°.
Layout strip(const PackProblem& problem, const std::vector<Point2>& at)
{
    Layout layout;
    double top = 0;
    for (size_t i = 0; i < at.size(); ++i) {
        const PartSpec& spec = problem.parts[i];
        layout.placements.push_back(
            {static_cast<int>(i), 0, at[i].x, at[i].y, 0, spec.width(), spec.height()});
        top = std::max(top, at[i].y + spec.height());
    }
    layout.sheets = {problem.boards.front()};
    layout.sheets.front().height = layout.stripHeight = top;
    layout.sheetArea = layout.boundingArea = problem.boards.front().width * top;
    return layout;
}

Polygon placedOuter(const PackProblem& problem, const Placement& p)
{
    return fabguide::geometry::placed(problem.parts[p.part].outline, p.rotation, p.x, p.y).outer;
}

}  // namespace

TEST(Compaction, AWedgeSlidesDownOntoTheSlopeBelowIt)
{
    // Two halves of a 100 x 50 rectangle cut along its diagonal, the upper one left 3 mm above the lower.
    PackProblem problem;
    problem.strip = true;
    problem.boards.push_back({"strip", "", 100, 0, 0, 1});
    problem.parts.push_back(part("lower", {{{0, 0}, {100, 0}, {0, 50}}, {}}));
    problem.parts.push_back(part("upper", {{{0, 50}, {100, 0}, {100, 50}}, {}}));
    const Layout layout = compacted(strip(problem, {{0, 0}, {0, 3}}), problem);
    EXPECT_NEAR(layout.placements[1].y, 0, 1e-6);
    EXPECT_NEAR(layout.stripHeight, 50, 1e-6);
    EXPECT_NEAR(layout.sheets.front().height, 50, 1e-6);
    EXPECT_NEAR(layout.sheetArea, 100 * 50, 1e-4);
}

TEST(Compaction, AWedgeKeepsTheKerfFromTheSlopeBelowIt)
{
    PackProblem problem;
    problem.strip = true;
    problem.boards.push_back({"strip", "", 110, 0, 0, 1});
    problem.settings.kerf = 2;
    problem.parts.push_back(part("lower", {{{0, 0}, {100, 0}, {0, 50}}, {}}));
    problem.parts.push_back(part("upper", {{{0, 50}, {100, 0}, {100, 50}}, {}}));
    const Layout layout = compacted(strip(problem, {{0, 0}, {0, 8}}), problem);
    // Measured here, not by the compaction: the outlines at least the kerf apart, and the wedge moved down.
    EXPECT_GE(
        distance(placedOuter(problem, layout.placements[0]), placedOuter(problem, layout.placements[1])),
        2 - 1e-6);
    EXPECT_LT(layout.placements[1].y, 8);
    EXPECT_GE(layout.placements[1].y, 2 * std::sqrt(1.25) - 1e-6);  // 2 mm square to the slope
}

TEST(Compaction, APartInAFramesHoleSettlesOnTheHolesEdge)
{
    PackProblem problem;
    problem.strip = true;
    problem.boards.push_back({"strip", "", 100, 0, 0, 1});
    problem.parts.push_back(part(
        "frame", {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {{{20, 20}, {20, 80}, {80, 80}, {80, 20}}}}));
    problem.parts.push_back(part("tile", fabguide::geometry::rectangle(10, 10)));
    const Layout layout = compacted(strip(problem, {{0, 0}, {40, 50}}), problem);
    EXPECT_NEAR(layout.placements[1].y, 20, 1e-6);
    EXPECT_NEAR(layout.placements[0].y, 0, 1e-12);
    EXPECT_NEAR(layout.stripHeight, 100, 1e-12);
}
