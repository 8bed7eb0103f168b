// Strip shrinking by overlap minimisation.
#include "Layout/Shrink.h"

#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

using namespace fabguide::material;
using namespace fabguide::material::testing;

namespace {

/// The units stacked one above the other at the strip's left edge: a valid strip, far longer than needed.
GridLayout stacked(const std::vector<RasterPart>& parts)
{
    GridLayout layout;
    layout.stock = {0};
    int y = 0, width = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        layout.placed.push_back({static_cast<int>(i), 0, 0, y, 0});
        y += parts[i].shapes[0].height();
        width = std::max(width, parts[i].shapes[0].width());
    }
    layout.usedWidth = {width};
    layout.usedHeight = {y};
    layout.skylineArea = {0};
    return layout;
}

const Deadline kNoDeadline;  // no time limit

}  // namespace

TEST(Shrink, AStackOfBlobsSpreadsAcrossTheStripWithNoCellTakenTwice)
{
    const std::vector<RasterPart> parts = randomBlobs(24, 10, 5);
    const BoardStock strip{40, 1000};
    const GridLayout start = stacked(parts);
    const GridLayout shrunk = shrinkStrip(parts, strip, start, {20000000, 1, 1}, kNoDeadline);

    // Checked on the cells, not on the search's report: every unit once, inside the strip, no cell twice.
    expectValidLayout(shrunk, parts, {BoardStock{strip.width, shrunk.usedHeight[0]}});
    int top = 0;
    long area = 0;
    for (const Placed& p : shrunk.placed) {
        top = std::max(top, p.y + parts[p.part].shapes[p.shape].height());
        area += parts[p.part].shapes[p.shape].area();
    }
    EXPECT_EQ(shrunk.usedHeight[0], top);
    EXPECT_LT(top, start.usedHeight[0] / 3);
    EXPECT_LT(top, 1.5 * static_cast<double>(area) / strip.width);
}

TEST(Shrink, TheSameSeedGivesTheSameStripAndMoreSearchesNoLongerOne)
{
    const std::vector<RasterPart> parts = randomBlobs(16, 12, 9);
    const BoardStock strip{30, 1000};
    const GridLayout start = stacked(parts);
    const GridLayout once = shrinkStrip(parts, strip, start, {5000000, 7, 1}, kNoDeadline);
    const GridLayout again = shrinkStrip(parts, strip, start, {5000000, 7, 1}, kNoDeadline);
    ASSERT_EQ(once.placed.size(), again.placed.size());
    for (size_t k = 0; k < once.placed.size(); ++k)
        EXPECT_TRUE(once.placed[k].x == again.placed[k].x && once.placed[k].y == again.placed[k].y &&
                    once.placed[k].shape == again.placed[k].shape);
    // The first of two searches is the one above: the lower of the two is never longer.
    const GridLayout two = shrinkStrip(parts, strip, start, {5000000, 7, 2}, kNoDeadline);
    expectValidLayout(two, parts, {BoardStock{strip.width, two.usedHeight[0]}});
    EXPECT_LE(two.usedHeight[0], once.usedHeight[0]);
}

TEST(Shrink, ALayoutThatIsNotOneWholeStripIsKept)
{
    const std::vector<RasterPart> parts = randomBlobs(6, 8, 3);
    GridLayout start = stacked(parts);
    start.placed.pop_back();
    start.unplaced = {5};
    const GridLayout kept = shrinkStrip(parts, BoardStock{30, 1000}, start, {1000000, 1, 1}, kNoDeadline);
    EXPECT_EQ(kept.usedHeight, start.usedHeight);
    EXPECT_EQ(kept.placed.size(), 5u);
}
