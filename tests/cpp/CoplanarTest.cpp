#include "Layout/Coplanar.h"

#include <gtest/gtest.h>

using namespace fabguide::material;
using fabguide::geometry::area;
using fabguide::geometry::rectangle;

namespace {

Board3 flat(const std::string& id, double w, double h, Eigen::Vector3d origin, double thickness = 6)
{
    return {id, rectangle(w, h), origin, {1, 0, 0}, {0, 1, 0}, thickness};
}

std::vector<Piece> pieces(const std::vector<Board3>& boards)
{
    ConnectorSettings none;
    none.style = JointStyle::None;
    return coplanarPieces(boards, joinBoards(boards, none), 0.01);
}

}  // namespace

TEST(Coplanar, TouchingBoardsInOnePlaneAreOnePiece)
{
    // A T: a 300 x 50 bar with a 50 x 200 stem standing on its middle, both in the plane z = 0..6.
    const std::vector<Board3> boards{flat("bar", 300, 50, {0, 0, 0}), flat("stem", 50, 200, {125, 50, 0})};
    const std::vector<Piece> result = pieces(boards);
    ASSERT_EQ(result.size(), 1u);
    EXPECT_EQ(result[0].boards, (std::vector<int>{0, 1}));
    EXPECT_NEAR(area(result[0].outline), 300 * 50 + 50 * 200, 1e-6);
    EXPECT_EQ(result[0].outline.outer.size(), 8u);  // one T-shaped contour
}

TEST(Coplanar, AMirroredFrameOfTheSamePlaneStillJoins)
{
    // The stem's frame is turned over: v = -y, so u x v = -z and its slab hangs from z = 6 down to 0.
    const std::vector<Board3> boards{flat("bar", 300, 50, {0, 0, 0}),
                                     {"stem", rectangle(50, 200), {125, 250, 6}, {1, 0, 0}, {0, -1, 0}, 6}};
    const std::vector<Piece> result = pieces(boards);
    ASSERT_EQ(result.size(), 1u);
    EXPECT_NEAR(area(result[0].outline), 300 * 50 + 50 * 200, 1e-6);
}

TEST(Coplanar, BoardsApartOrInOtherPlanesStayPiecesOfTheirOwn)
{
    const std::vector<Board3> boards{flat("bar", 300, 50, {0, 0, 0}), flat("apart", 50, 50, {0, 60, 0}),
                                     flat("above", 300, 50, {0, 0, 6}),
                                     flat("thicker", 50, 50, {300, 0, 0}, 12)};
    const std::vector<Piece> result = pieces(boards);
    ASSERT_EQ(result.size(), 4u);
    for (size_t i = 0; i < result.size(); ++i)
        EXPECT_EQ(result[i].boards, (std::vector<int>{static_cast<int>(i)}));
}

TEST(Coplanar, BoardsDrawnOnTopOfEachOtherAreBoardsOfTheirOwn)
{
    // Panels each modelled at the origin (a PartDesign habit) are two sides and a top, not one piece of the
    // three; an L-shaped desk top drawn as two rectangles overlapping at a corner is one piece.
    const std::vector<Board3> stacked{flat("side L", 400, 600, {0, 0, 0}),
                                      flat("side R", 400, 600, {0, 0, 0}), flat("top", 450, 400, {0, 0, 0})};
    EXPECT_EQ(pieces(stacked).size(), 3u);
    const std::vector<Board3> desk{flat("long", 1600, 600, {0, 0, 0}),
                                   flat("return", 600, 1200, {1000, 0, 0})};
    const std::vector<Piece> l = pieces(desk);
    ASSERT_EQ(l.size(), 1u);
    EXPECT_NEAR(area(l[0].outline), 1600 * 600 + 600 * 600, 1e-6);
}
