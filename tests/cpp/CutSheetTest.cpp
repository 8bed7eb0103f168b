#include "Layout/CutSheet.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace fabguide::material;

namespace {

PackProblem problem()
{
    PackProblem p;
    p.boards.push_back({"birch", "birch plywood", 600, 400, 6, 2});
    p.parts.push_back(rectangularPart("lid", 200, 100, 2, {0, 90, 180, 270}));
    p.parts.push_back(rectangularPart("side", 150, 80, 1, {0, 90, 180, 270}));
    p.settings = {0.5, 0.2, 1, 5};
    return p;
}

OrderingSearchOptions quick()
{
    OrderingSearchOptions o;
    o.iterations = 20;
    return o;
}

}  // namespace

TEST(CutSheet, ToolPathsAreTheOutlinesGrownByHalfTheKerf)
{
    const PackProblem p = problem();
    const Layout layout = pack(p, quick());
    const std::vector<CutSheet> sheets = cutSheets(layout, p);
    ASSERT_EQ(sheets.size(), layout.sheets.size());
    ASSERT_EQ(sheets[0].cuts.size(), 3u);
    double area = 0;
    for (const ToolPath& path : sheets[0].cuts) {
        const Placement& placement = layout.placements[path.placement];
        EXPECT_FALSE(path.hole);
        EXPECT_GE(placement.width * placement.height, area);  // small parts first
        area = placement.width * placement.height;
        const auto& cut = path.points;
        const auto [minX, maxX] =
            std::minmax_element(cut.begin(), cut.end(), [](auto a, auto b) { return a.x < b.x; });
        const auto [minY, maxY] =
            std::minmax_element(cut.begin(), cut.end(), [](auto a, auto b) { return a.y < b.y; });
        EXPECT_NEAR(minX->x, placement.x - 0.1, 1e-6);
        EXPECT_NEAR(maxX->x - minX->x, placement.width + 0.2, 1e-6);
        EXPECT_NEAR(maxY->y - minY->y, placement.height + 0.2, 1e-6);
    }
}

TEST(CutSheet, EveryPartIsLabelledInsideItself)
{
    const PackProblem p = problem();
    const Layout layout = pack(p, quick());
    const CutSheet sheet = cutSheets(layout, p)[0];
    ASSERT_EQ(sheet.labels.size(), layout.placements.size());
    for (size_t i = 0; i < sheet.labels.size(); ++i) {
        const Placement& placement = layout.placements[i];
        const Label& label = sheet.labels[i];
        EXPECT_EQ(label.text, p.parts[placement.part].id);
        EXPECT_GT(label.at.x, placement.x);
        EXPECT_LT(label.at.x, placement.x + placement.width);
        EXPECT_LT(label.height, std::min(placement.width, placement.height));
    }
}

TEST(CutSheet, ALabelSitsInTheMaterialClearOfHolesAndAlongThePart)
{
    // A stool seat with a hand hole in its middle: the label goes beside the hole, not over it; a crescent's
    // label lies in its horns' material, not in the bite; a tall leg's label runs along it.
    PackProblem p = problem();
    p.parts = {rectangularPart("seat", 300, 300), rectangularPart("leg", 40, 400, 1, {0})};
    p.parts[0].outline.holes.push_back({{100, 100}, {100, 200}, {200, 200}, {200, 100}});
    p.parts.push_back(
        {"crescent",
         {{{0, 0}, {200, 0}, {200, 200}, {0, 200}, {0, 160}, {160, 160}, {160, 40}, {0, 40}}, {}},
         1,
         {0},
         {},
         {}});
    p.boards[0].width = p.boards[0].height = 1000;
    const Layout layout = pack(p, quick());
    const CutSheet sheet = cutSheets(layout, p)[0];
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        const Placement& at = layout.placements[i];
        const Label& label = sheet.labels[i];
        const fabguide::geometry::Outline placed = placedOutline(layout, p, i);
        // The label's centre is in the material: inside the outline's box, in none of its holes, and the text
        // box (about 0.6 of its height per character) stays inside the part.
        const double half = 0.3 * label.height * static_cast<double>(label.text.size());
        const auto inside = [&](double x, double y) {
            return !fabguide::geometry::intersect({{x - 0.01, y - 0.01},
                                                   {x + 0.01, y - 0.01},
                                                   {x + 0.01, y + 0.01},
                                                   {x - 0.01, y + 0.01}},
                                                  placed)
                        .empty();
        };
        const bool along = label.angle == 90;
        EXPECT_TRUE(inside(label.at.x, label.at.y)) << label.text;
        EXPECT_TRUE(inside(label.at.x + (along ? 0 : half), label.at.y + (along ? half : 0))) << label.text;
        EXPECT_TRUE(inside(label.at.x - (along ? 0 : half), label.at.y - (along ? half : 0))) << label.text;
        EXPECT_EQ(along, at.height > at.width) << label.text;
    }
}

TEST(CutSheet, SmallPartsAreHeldByTabsAndCutLast)
{
    PackProblem p = problem();
    p.settings.tabWidth = 4;
    p.settings.tabBelow = 180;  // the 150 x 80 side, not the 200 x 100 lids
    const Layout layout = pack(p, quick());
    const CutSheet sheet = cutSheets(layout, p)[0];
    const long small = std::count_if(
        layout.placements.begin(), layout.placements.end(),
        [&](const Placement& at) { return at.sheet == 0 && std::max(at.width, at.height) < 180; });
    ASSERT_GT(small, 0);
    const auto open = [](const ToolPath& cut) { return cut.open; };
    EXPECT_EQ(std::count_if(sheet.cuts.begin(), sheet.cuts.end(), open), 2 * small);  // two open pieces each
    EXPECT_EQ(sheet.cuts.size(), layout.placements.size() + small);  // the others closed as before
    EXPECT_TRUE(std::is_partitioned(sheet.cuts.begin(), sheet.cuts.end(), std::not_fn(open))) << "open last";
    EXPECT_TRUE(sheet.tabs.empty());
    // As designed: every contour closed at its nominal size, the tabs listed where the gaps were.
    const CutSheet designed = cutSheets(layout, p, {true})[0];
    EXPECT_EQ(designed.cuts.size(), layout.placements.size());
    EXPECT_EQ(std::count_if(designed.cuts.begin(), designed.cuts.end(), open), 0);
    EXPECT_EQ(designed.tabs.size(), static_cast<size_t>(2 * small));
    for (const auto& [from, to] : designed.tabs)
        EXPECT_NEAR(std::hypot(to.x - from.x, to.y - from.y), 4, 1e-6);  // along an edge, not at a corner
}

TEST(CutSheet, AsDesignedTheOutlinesAreNominalAndTheHolesInnerCuts)
{
    PackProblem p = problem();
    p.settings.dogbone = 6;
    p.parts[0].outline.holes.push_back({{50, 40}, {50, 60}, {150, 60}, {150, 40}});
    const Layout layout = pack(p, quick());
    const CutSheet sheet = cutSheets(layout, p, {true})[0];
    for (const ToolPath& cut : sheet.cuts) {
        EXPECT_FALSE(cut.open);
        EXPECT_EQ(cut.points.size(), 4u) << "no dogbones, no offset corners: a rectangle stays four points";
    }
    const auto inner =
        std::find_if(sheet.cuts.begin(), sheet.cuts.end(), [](const ToolPath& c) { return c.inner; });
    ASSERT_NE(inner, sheet.cuts.end());
    EXPECT_NEAR(std::abs(fabguide::geometry::signedArea(inner->points)), 100 * 20, 1e-6);
    EXPECT_TRUE(inner->hole);
    EXPECT_EQ(layout.placements[inner->placement].part, 0);  // the part whose hole it is
    EXPECT_EQ(std::count_if(sheet.cuts.begin(), sheet.cuts.end(), [](const ToolPath& c) { return c.inner; }),
              std::count_if(layout.placements.begin(), layout.placements.end(),
                            [](const Placement& at) { return at.sheet == 0 && at.part == 0; }));
}

TEST(CutSheet, APartInAHoleIsCutBeforeTheHoleWhichKeepsTabsWithTheirs)
{
    // A 300 x 200 frame with a 200 x 100 window at (50, 50), laid at (10, 10), and a 40 x 30 tag in the
    // window.
    PackProblem p = problem();
    p.parts[0] = rectangularPart("frame", 300, 200);
    p.parts[0].outline.holes.push_back({{50, 50}, {50, 150}, {250, 150}, {250, 50}});
    p.parts[1] = rectangularPart("tag", 40, 30);
    Layout layout;
    layout.sheets = {p.boards[0]};
    layout.placements = {{0, 0, 10, 10, 0, 300, 200}, {1, 0, 100, 100, 0, 40, 30}};
    const auto left = [](const fabguide::geometry::Polygon& cut) {  // its leftmost x
        return std::min_element(cut.begin(), cut.end(),
                                [](const auto& a, const auto& b) { return a.x < b.x; })
            ->x;
    };
    // Without tabs: the tag, then the window round it, then the frame.
    CutSheet sheet = cutSheets(layout, p)[0];
    ASSERT_EQ(sheet.cuts.size(), 3u);
    EXPECT_NEAR(left(sheet.cuts[0].points), 100 - 0.1, 1e-6);  // the tag, grown by half the kerf
    EXPECT_NEAR(left(sheet.cuts[1].points), 60 + 0.1, 1e-6);   // the window, shrunk by it
    EXPECT_NEAR(left(sheet.cuts[2].points), 10 - 0.1, 1e-6);   // the frame
    EXPECT_FALSE(sheet.cuts[1].inner) << "the window holds the tag: an outer cut, after it";
    EXPECT_TRUE(sheet.cuts[1].hole);
    EXPECT_EQ(sheet.cuts[1].placement, 0u);
    // With tabs for the tag, the window keeps tabs too, and both are cut after the frame's closed outline.
    p.settings.tabWidth = 4;
    p.settings.tabBelow = 100;
    sheet = cutSheets(layout, p)[0];
    ASSERT_EQ(sheet.cuts.size(), 5u);
    EXPECT_FALSE(sheet.cuts[0].open);
    EXPECT_NEAR(left(sheet.cuts[0].points), 10 - 0.1, 1e-6);
    std::vector<fabguide::geometry::Polygon> tabbed;  // the tag's two pieces, then the window's
    for (size_t k = 1; k < 5; ++k) {
        EXPECT_TRUE(sheet.cuts[k].open);
        tabbed.push_back(sheet.cuts[k].points);
    }
    EXPECT_GE(left(tabbed[0]), 100 - 0.1 - 1e-6);
    EXPECT_GE(left(tabbed[1]), 100 - 0.1 - 1e-6);
    EXPECT_LE(std::min(left(tabbed[2]), left(tabbed[3])), 60 + 0.1 + 1e-6);
    EXPECT_GE(std::min(left(tabbed[2]), left(tabbed[3])), 60 + 0.1 - 1e-6);
}

TEST(CutSheet, CutListCountsPartsPerBoard)
{
    const PackProblem p = problem();
    const std::vector<CutListRow> rows = cutList(pack(p, quick()), p);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].part, "lid");
    EXPECT_EQ(rows[0].quantity, 2);
    EXPECT_DOUBLE_EQ(rows[0].thickness, 6);
    EXPECT_EQ(rows[0].material, "birch plywood");
    EXPECT_EQ(rows[1].part, "side");
}

TEST(CutSheet, EdgeBandingFollowsItsPartAsPlacedAndIntoTheCutList)
{
    PackProblem p;
    p.boards = {{"sheet", "oak", 1000, 1000, 18, -1}};
    p.parts = {rectangularPart("shelf", 300, 100, 1, {90})};
    p.parts[0].edgeBanding[static_cast<int>(Side::L1)] = "oak 1 mm";  // its long edge at y = 0
    Layout layout;
    layout.sheets = p.boards;
    layout.placements = {{0, 0, 50, 20, 90, 100, 300}};  // turned a quarter: the long edge stands upright
    const CutSheet sheet = cutSheets(layout, p)[0];
    ASSERT_EQ(sheet.banding.size(), 1u);
    const Banding& band = sheet.banding[0];
    EXPECT_EQ(band.band, "oak 1 mm");
    EXPECT_NEAR(band.from.x, band.to.x, 1e-9);  // upright
    EXPECT_NEAR(std::abs(band.to.y - band.from.y), 300, 1e-9);
    EXPECT_TRUE(std::abs(band.from.x - 50) < 1e-9 ||
                std::abs(band.from.x - 150) < 1e-9);  // on the part's edge
    const std::vector<CutListRow> rows = cutList(layout, p);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].edgeBanding[0], "oak 1 mm");
    EXPECT_DOUBLE_EQ(sideLength(p.parts[0], Side::L1), 300);
    EXPECT_DOUBLE_EQ(sideLength(p.parts[0], Side::W2), 100);
}
