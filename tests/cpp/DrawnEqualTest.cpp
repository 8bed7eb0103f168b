// Boards drawn equal: alike on every side and lying the same way, in groups, once per in-plane
// axis.
#include "Design/DrawnEqual.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace fabguide::material;

namespace {

DesignBoard board(const std::string& id, Eigen::Vector3d size)
{
    DesignBoard b;
    b.id = id;
    b.size = size;
    b.normal = static_cast<int>(std::min_element(size.data(), size.data() + 3) - size.data());
    return b;
}

}  // namespace

TEST(DrawnEqual, FourLegsAreEqualAlongTheirTwoLongSides)
{
    Design table;
    table.boards = {board("top", {700, 420, 18}), board("leg 1", {18, 60, 700}),
                    board("leg 2", {18, 60, 700}), board("leg 3", {18, 60, 700.00001}),
                    board("leg 4", {18, 60, 700})};
    const std::vector<EqualSizes> equal = drawnEqual(table, 1e-4);
    ASSERT_EQ(equal.size(), 2u);
    EXPECT_EQ(equal[0].axis, 1);
    EXPECT_EQ(equal[1].axis, 2);
    for (const EqualSizes& e : equal)
        EXPECT_EQ(e.boards, (std::vector<int>{1, 2, 3, 4}));
}

TEST(DrawnEqual, BoardsAlikeButForOneSideOrLyingOtherwiseAreNot)
{
    Design shelf;
    shelf.boards = {board("shelf", {564, 300, 18}), board("deeper shelf", {564, 301, 18}),
                    board("side", {18, 300, 564}), board("lone", {300, 564, 18})};
    EXPECT_TRUE(drawnEqual(shelf, 1e-4).empty());
}

TEST(DrawnEqual, EachGroupOnItsOwn)
{
    Design crate;
    crate.boards = {board("side a", {400, 12, 300}), board("end a", {12, 276, 300}),
                    board("side b", {400, 12, 300}), board("end b", {12, 276, 300})};
    const std::vector<EqualSizes> equal = drawnEqual(crate, 1e-4);
    ASSERT_EQ(equal.size(), 4u);
    EXPECT_EQ(equal[0].boards, (std::vector<int>{0, 2}));
    EXPECT_EQ(equal[2].boards, (std::vector<int>{1, 3}));
    EXPECT_EQ(equal[2].axis, 1);
}
