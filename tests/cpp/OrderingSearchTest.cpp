#include "Layout/OrderingSearch.h"
#include "Layout/Pack.h"
#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>

using namespace fabguide::material;
using fabguide::material::testing::expectValidLayout;
using fabguide::material::testing::randomParts;
using fabguide::material::testing::rectanglePart;

TEST(OrderingSearch, NeverWorseThanItsStartingOrder)
{
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const std::vector<RasterPart> parts = randomParts(15, 10, seed);
        const std::vector<BoardStock> stock{{25, 300, 1}};
        const std::vector<int> start = decreasingExtentOrder(parts);
        OrderingSearchOptions options;
        options.bounds = Bounds::Strip;
        const GridLayout searched = exploreOrderings(parts, start, stock, options);
        expectValidLayout(searched, parts, stock);
        const LayoutCost initial =
            cost(dock(parts, start, stock, Criterion::Docking, Bounds::Strip), stock, Bounds::Strip);
        EXPECT_FALSE(initial < cost(searched, stock, Bounds::Strip)) << "seed " << seed;
    }
}

TEST(OrderingSearch, SameSeedSameLayout)
{
    const std::vector<RasterPart> parts = randomParts(12, 9, 7);
    const std::vector<BoardStock> stock{{20, 200, 1}};
    OrderingSearchOptions options;
    options.iterations = 200;
    options.timeLimit = 60;
    const GridLayout a = exploreOrderings(parts, decreasingExtentOrder(parts), stock, options);
    const GridLayout b = exploreOrderings(parts, decreasingExtentOrder(parts), stock, options);
    ASSERT_EQ(a.placed.size(), b.placed.size());
    for (size_t i = 0; i < a.placed.size(); ++i)
        EXPECT_TRUE(a.placed[i].part == b.placed[i].part && a.placed[i].x == b.placed[i].x &&
                    a.placed[i].y == b.placed[i].y);
}

TEST(OrderingSearch, FindsThePerfectPackingOfASmallPuzzle)
{
    // 10 wide: two 10x3 strips and two 5x4 blocks stack to exactly 10 high.
    const std::vector<RasterPart> parts{rectanglePart("a", 5, 4), rectanglePart("b", 10, 3),
                                        rectanglePart("c", 5, 4), rectanglePart("d", 10, 3)};
    const std::vector<BoardStock> stock{{10, 100, 1}};
    OrderingSearchOptions options;
    options.bounds = Bounds::Strip;
    const GridLayout layout = exploreOrderings(parts, {0, 1, 2, 3}, stock, options);
    EXPECT_EQ(layout.usedHeight[0], 10);
}

TEST(OrderingSearch, BestFitOrderHoldsEveryPartOnceAndStartsLow)
{
    const std::vector<RasterPart> parts = randomParts(30, 8, 3);
    const std::vector<BoardStock> stock{{24, 400, 1}};
    const auto far = std::chrono::steady_clock::now() + std::chrono::hours(1);
    const std::vector<int> order =
        bestFitOrder(parts, stock, Criterion::Docking, Bounds::Strip, Preference::LargestArea, Deadline(far));
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (size_t i = 0; i < sorted.size(); ++i)
        ASSERT_EQ(sorted[i], static_cast<int>(i));
    // Lowest position first: the first two parts both sit on the bottom edge.
    Docker docker(stock, Criterion::Docking, Bounds::Strip);
    docker.place(parts, order[0]);
    docker.place(parts, order[1]);
    EXPECT_EQ(docker.layout().placed[1].y, 0);
    const GridLayout layout = dock(parts, order, stock, Criterion::Docking, Bounds::Strip);
    expectValidLayout(layout, parts, stock);
}

TEST(OrderingSearch, StartsSearchedOnTwoThreadsFindWhatOneThreadFinds)
{
    const std::vector<RasterPart> parts = fabguide::material::testing::randomBlobs(16, 6, 5);
    const std::vector<BoardStock> stock{{14, 400, 1}};
    OrderingSearchOptions options;
    options.criterion = Criterion::Fill;
    options.bounds = Bounds::Strip;
    options.iterations = 150;  // the iterations end each start, not the time: the same on any thread
    options.timeLimit = 600;
    const GridLayout one = searchFromStarts(parts, stock, options);
    options.threads = 2;
    const GridLayout two = searchFromStarts(parts, stock, options);
    expectValidLayout(two, parts, stock);
    ASSERT_EQ(one.placed.size(), two.placed.size());
    for (size_t i = 0; i < one.placed.size(); ++i)
        EXPECT_TRUE(one.placed[i].part == two.placed[i].part && one.placed[i].x == two.placed[i].x &&
                    one.placed[i].y == two.placed[i].y && one.placed[i].shape == two.placed[i].shape);
}
