// Compaction on the parts' real outlines: a strip, parts on sheets slid together (issue
// 31).
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

TEST(Compaction, PartsOnASheetSlideTogetherAKerfApart)
{
    // Three rectangles a grid's slack apart (kerf 3.2 kept as 3.5) on a sheet with a 10 mm trim: slid down
    // and left, each ends a kerf (and the slide's hair) from its neighbour and the trim; the one on the
    // second sheet ignores the first sheet's parts.
    PackProblem problem;
    problem.boards.push_back({"sheet", "", 1000, 500, 18, 2});
    problem.settings.kerf = 3.2;
    problem.settings.trim = 10;
    for (const char* id : {"a", "b", "c"})
        problem.parts.push_back(part(id, fabguide::geometry::rectangle(100, 50)));
    Layout layout = strip(problem, {{10.5, 10.5}, {114, 10.5}, {10.5, 64}});
    layout.placements[2].sheet = 1;
    layout.sheets.push_back(problem.boards.front());
    const Layout slid = slidTogether(layout, problem);
    EXPECT_NEAR(slid.placements[0].x, 10, 1e-6);
    EXPECT_NEAR(slid.placements[0].y, 10, 1e-6);
    EXPECT_NEAR(slid.placements[1].x, 10 + 100 + 3.2, 2e-3);
    EXPECT_GE(slid.placements[1].x, 10 + 100 + 3.2 - 1e-9);
    EXPECT_NEAR(slid.placements[1].y, 10, 1e-6);
    EXPECT_NEAR(slid.placements[2].x, 10, 1e-6);  // alone on its sheet: into the corner
    EXPECT_NEAR(slid.placements[2].y, 10, 1e-6);
}
