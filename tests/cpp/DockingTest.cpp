#include "Layout/Docking.h"
#include "PackingTestSupport.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <utility>

using namespace fabguide::material;
using fabguide::material::testing::expectValidLayout;
using fabguide::material::testing::randomBlobs;
using fabguide::material::testing::randomParts;
using fabguide::material::testing::rectanglePart;

namespace {
std::vector<int> inOrder(size_t n)
{
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    return order;
}
}  // namespace

TEST(Docking, FirstPartGoesToTheCorner)
{
    const std::vector<RasterPart> parts{rectanglePart("a", 4, 3)};
    const GridLayout layout = dock(parts, {0}, {{10, 10, 1}}, Criterion::Docking);
    ASSERT_EQ(layout.placed.size(), 1u);
    EXPECT_EQ(layout.placed[0].x, 0);
    EXPECT_EQ(layout.placed[0].y, 0);
}

TEST(Docking, FourSquaresTileTheirBoardExactly)
{
    std::vector<RasterPart> parts;
    for (const char* name : {"a", "b", "c", "d"})
        parts.push_back(rectanglePart(name, 10, 10));
    const std::vector<BoardStock> stock{{20, 20, 1}};
    const GridLayout layout = dock(parts, inOrder(4), stock, Criterion::Docking);
    expectValidLayout(layout, parts, stock);
    EXPECT_EQ(layout.usedWidth[0], 20);
    EXPECT_EQ(layout.usedHeight[0], 20);
}

TEST(Docking, WastageCriterionKeepsTheLayoutCompact)
{
    // A tall part then a wide one: least wastage puts the wide one beside or above, never far away,
    // so the bounding rectangle holds exactly the two parts' area plus the unavoidable gap.
    const std::vector<RasterPart> parts{rectanglePart("tall", 2, 8, false),
                                        rectanglePart("small", 2, 8, false)};
    const GridLayout layout = dock(parts, {0, 1}, {{50, 50, 1}}, Criterion::Docking);
    EXPECT_EQ(layout.usedWidth[0] * layout.usedHeight[0], 32);
}

TEST(Docking, EnclosedAreaCountsTheSpaceShutBehindAPart)
{
    Sheet sheet(10, 10);
    sheet.place(Footprint::rectangle(2, 2), {0, 0});
    // A 2x2 part hovering two rows above the first shuts in the 2x2 gap beneath it.
    EXPECT_EQ(sheet.enclosedArea(Footprint::rectangle(2, 2), {0, 4}), 4);
    // Resting right on top of it encloses nothing.
    EXPECT_EQ(sheet.enclosedArea(Footprint::rectangle(2, 2), {0, 2}), 0);
}

TEST(Docking, RandomPartsNeverOverlapOnBoardsOrStrips)
{
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const std::vector<RasterPart> parts =
            seed % 2 ? randomParts(25, 12, seed) : randomBlobs(25, 12, seed);
        for (Criterion criterion :
             {Criterion::Docking, Criterion::BottomLeft, Criterion::Fill, Criterion::SnugFill}) {
            const std::vector<BoardStock> boards{{30, 20, -1}};
            expectValidLayout(dock(parts, inOrder(parts.size()), boards, criterion), parts, boards);
            const std::vector<BoardStock> strip{{30, 400, 1}};
            expectValidLayout(dock(parts, inOrder(parts.size()), strip, criterion, Bounds::Strip), parts,
                              strip);
        }
    }
}

namespace {
/// A 6 x 4 arch: two legs two cells high under a full top two cells thick.
RasterPart arch()
{
    std::vector<std::uint8_t> cells(24, 1);
    for (int y = 0; y < 2; ++y)
        for (int x = 1; x < 5; ++x)
            cells[y * 6 + x] = 0;
    return {"arch", {Footprint(6, 4, std::move(cells))}, {0}};
}
}  // namespace

TEST(Docking, FillReachesTheHoleUnderAnOverhang)
{
    const std::vector<RasterPart> parts{arch(), rectanglePart("block", 2, 2, false)};
    const std::vector<BoardStock> strip{{6, 100, 1}};
    const GridLayout filled = dock(parts, {0, 1}, strip, Criterion::Fill, Bounds::Strip);
    expectValidLayout(filled, parts, strip);
    EXPECT_EQ(filled.placed[1].y, 0);  // under the arch, between its legs
    EXPECT_EQ(filled.usedHeight[0], 4);
    // Docking's height-fields see the arch's top only: the block goes on it.
    EXPECT_EQ(dock(parts, {0, 1}, strip, Criterion::Docking, Bounds::Strip).usedHeight[0], 6);
}

TEST(Docking, SnugFillPrefersThePlaceThatLeavesLeastBelowThePart)
{
    // A floor 8 cells wide: a pit in columns 0-1, a ledge 2 high over columns 2-5, a post 4 high at 6-7. A
    // 3 x 1 bar lies on the ledge either way; Fill takes the leftmost place, over the pit, SnugFill the
    // place that leaves nothing below it.
    std::vector<std::uint8_t> cells(32, 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 2; x < 8; ++x)
            cells[y * 8 + x] = x >= 6 || y < 2;
    const std::vector<RasterPart> parts{{"floor", {Footprint(8, 4, std::move(cells))}, {0}},
                                        rectanglePart("bar", 3, 1, false)};
    const std::vector<BoardStock> strip{{8, 20, 1}};
    const GridLayout fill = dock(parts, {0, 1}, strip, Criterion::Fill, Bounds::Strip);
    const GridLayout snug = dock(parts, {0, 1}, strip, Criterion::SnugFill, Bounds::Strip);
    EXPECT_TRUE(fill.placed[1].x == 0 && fill.placed[1].y == 2);
    EXPECT_TRUE(snug.placed[1].x == 2 && snug.placed[1].y == 2);
}

TEST(Docking, AreaBelowCountsTheEmptyCellsUnderEachColumnOfThePart)
{
    Sheet sheet(10, 10, true);
    sheet.place(arch().shapes[0], {0, 0});
    EXPECT_EQ(sheet.areaBelow(Footprint::rectangle(2, 2), {6, 0}), 0);
    EXPECT_EQ(sheet.areaBelow(Footprint::rectangle(2, 2), {6, 3}), 6);
    EXPECT_EQ(sheet.areaBelow(Footprint::rectangle(4, 1), {1, 1}), 4);  // hovering one row over the floor
    EXPECT_EQ(sheet.areaBelow(Footprint::rectangle(2, 1), {0, 4}), 0);  // on the arch's top
}

TEST(Docking, AnOrderThatBeginsAlikeIsDockedAsIfFromScratch)
{
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const std::vector<RasterPart> parts = randomBlobs(20, 9, seed);
        const std::vector<BoardStock> boards{{20, 15, 2}, {25, 25, -1}};
        for (Criterion criterion : {Criterion::Docking, Criterion::SnugFill}) {
            std::vector<int> order = inOrder(parts.size());
            const GridLayout before = dock(parts, order, boards, criterion);
            std::swap(order[7], order[15]);
            const GridLayout replayed = dock(parts, order, boards, criterion, Bounds::Layout, &before, 7);
            const GridLayout fresh = dock(parts, order, boards, criterion);
            ASSERT_EQ(replayed.placed.size(), fresh.placed.size());
            for (size_t k = 0; k < fresh.placed.size(); ++k) {
                const Placed &r = replayed.placed[k], &f = fresh.placed[k];
                EXPECT_TRUE(r.part == f.part && r.sheet == f.sheet && r.x == f.x && r.y == f.y &&
                            r.shape == f.shape)
                    << "seed " << seed << ", part " << k;
            }
            EXPECT_EQ(replayed.stock, fresh.stock);
            EXPECT_EQ(replayed.usedHeight, fresh.usedHeight);
        }
    }
}

TEST(Docking, BottomLeftPlacesLowestThenLeftmost)
{
    const std::vector<RasterPart> parts{rectanglePart("a", 5, 5, false), rectanglePart("b", 5, 5, false)};
    const GridLayout layout = dock(parts, {0, 1}, {{20, 20, 1}}, Criterion::BottomLeft);
    EXPECT_EQ(layout.placed[1].x, 5);
    EXPECT_EQ(layout.placed[1].y, 0);
}

TEST(Docking, OverflowOpensFurtherBoards)
{
    std::vector<RasterPart> parts{rectanglePart("a", 6, 6), rectanglePart("b", 6, 6),
                                  rectanglePart("c", 6, 6)};
    const std::vector<BoardStock> stock{{10, 10, 3}};
    const GridLayout layout = dock(parts, inOrder(3), stock, Criterion::Docking);
    EXPECT_EQ(layout.stock.size(), 3u);
    expectValidLayout(layout, parts, stock);
}

TEST(Docking, UsesTheNextStockWhenTheFirstRunsOut)
{
    std::vector<RasterPart> parts{rectanglePart("a", 6, 6), rectanglePart("b", 6, 6)};
    const std::vector<BoardStock> stock{{10, 10, 1}, {8, 8, 1}};
    const GridLayout layout = dock(parts, inOrder(2), stock, Criterion::Docking);
    EXPECT_EQ(layout.stock, (std::vector<int>{0, 1}));
}

TEST(Docking, PartsLeftWhenTheBoardsRunOutAreListed)
{
    std::vector<RasterPart> parts{rectanglePart("left side", 6, 6), rectanglePart("right side", 6, 6)};
    const GridLayout layout = dock(parts, inOrder(2), {{10, 10, 1}}, Criterion::Docking);
    EXPECT_EQ(layout.placed.size(), 1u);
    EXPECT_EQ(layout.unplaced, (std::vector<int>{1}));
}

TEST(Docking, PartLargerThanEveryBoardIsNamed)
{
    std::vector<RasterPart> parts{rectanglePart("table top", 30, 12)};
    try {
        dock(parts, {0}, {{20, 20, 5}, {25, 10, 5}}, Criterion::Docking);
        FAIL() << "expected PackingError";
    } catch (const PackingError& e) {
        EXPECT_NE(std::string(e.what()).find("'table top' is larger than every master board"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Docking, PartsFollowingTheGrainTurnWithEachBoardsGrain)
{
    RasterPart slat = rectanglePart("slat", 8, 2);
    slat.followsGrain = true;
    const std::vector<RasterPart> parts{slat, slat};
    const std::vector<BoardStock> stock{{10, 10, 1, Grain::AlongWidth}, {10, 10, 1, Grain::AlongHeight}};
    // The first board takes one slat lying along its width; the second slat would fit beside it only
    // turned, which that board's grain forbids, so it goes to the second board, standing up.
    std::vector<RasterPart> big{rectanglePart("filler", 10, 7, false), slat, slat};
    big[1].followsGrain = big[2].followsGrain = true;
    const GridLayout layout = dock(big, {0, 1, 2}, stock, Criterion::Docking);
    ASSERT_EQ(layout.placed.size(), 3u);
    for (const Placed& p : layout.placed) {
        if (p.part == 0)
            continue;
        const bool turned = big[p.part].rotations[p.shape] % 180 != 0;
        EXPECT_EQ(turned, layout.stock[p.sheet] == 1) << "part " << p.part;
    }
    EXPECT_EQ(layout.stock, (std::vector<int>{0, 1}));
    EXPECT_FALSE(allowedOn(slat, 1, stock[0]));
    EXPECT_TRUE(allowedOn(slat, 1, stock[1]));
    EXPECT_TRUE(allowedOn(rectanglePart("free", 8, 2), 1, stock[0]));
}
