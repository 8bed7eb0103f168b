#include "Layout/Lettering.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

using namespace fabguide::material;

namespace {

/// The strokes' bounding box: min x, min y, max x, max y.
std::array<double, 4> box(const std::vector<fabguide::geometry::Polygon>& lines)
{
    std::array<double, 4> b{1e9, 1e9, -1e9, -1e9};
    for (const auto& line : lines)
        for (const auto& p : line)
            b = {std::min(b[0], p.x), std::min(b[1], p.y), std::max(b[2], p.x), std::max(b[3], p.y)};
    return b;
}

}  // namespace

TEST(Lettering, CapitalsAreTwoThirdsOfTheEmCentredOnTheLabelsPoint)
{
    // "HI" in Simplex Roman: H's stems and I's stem, 21 of 32 units of the em tall, centred on the point.
    const std::vector<fabguide::geometry::Polygon> lines = strokes({"HI", {100, 50}, 16, 0});
    EXPECT_EQ(lines.size(), 4u);  // H: two stems and a bar; I: one stem
    const auto [x0, y0, x1, y1] = box(lines);
    EXPECT_NEAR(y1 - y0, 21.0 / 32 * 16, 1e-9);
    EXPECT_NEAR((y0 + y1) / 2, 50, 1e-9);
    EXPECT_NEAR((x0 + x1) / 2, 100, 1.0);
}

TEST(Lettering, ALabelAlongATallPartTurnsAQuarterAndOddCharactersShowAsQuestionMarks)
{
    const auto [x0, y0, x1, y1] = box(strokes({"HI", {0, 0}, 16, 90}));
    EXPECT_NEAR(x1 - x0, 21.0 / 32 * 16, 1e-9) << "the capitals' height now runs across";
    EXPECT_GT(y1 - y0, x1 - x0);
    EXPECT_EQ(strokes({"\xc3\xa9", {0, 0}, 10, 0}).size(), strokes({"??", {0, 0}, 10, 0}).size());
}
