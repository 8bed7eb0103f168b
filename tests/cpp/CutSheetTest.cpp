#include "Material/CutSheet.h"

#include <gtest/gtest.h>

#include <algorithm>

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
    for (size_t i = 0; i < layout.placements.size(); ++i) {
        const Placement& placement = layout.placements[i];
        const auto& cut = sheets[0].cuts[i];
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
