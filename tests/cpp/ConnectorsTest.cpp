#include "Layout/Connectors.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace fabguide::material;
using Eigen::Vector3d;
using fabguide::geometry::area;
using fabguide::geometry::Point2;
using fabguide::geometry::Polygon;
using fabguide::geometry::rectangle;

namespace {

Board3 board(const std::string& id, double w, double h, Vector3d origin, Vector3d u, Vector3d v,
             double thickness)
{
    return {id, rectangle(w, h), origin, u, v, thickness};
}

/// A side standing in the y-z plane (x from 0 to t) and a shelf butting against its face at height z.
std::vector<Board3> sideAndShelf(double t, double z = 400)
{
    return {board("side", 300, 800, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, t),
            board("shelf", 564, 300, {t, 0, z}, {1, 0, 0}, {0, 1, 0}, t)};
}

Vector3d world(const Board3& b, Point2 p)
{
    return b.origin + p.x * b.u + p.y * b.v;
}

/// Each tab (on a) and its slot (on b), seen along b's normal, cover the same rectangle in 3-D.
void expectTabsMeetSlots(const std::vector<Board3>& boards, const Connector& c)
{
    ASSERT_EQ(c.tabs.size(), c.slots.size());
    const Board3 &a = boards[c.a], &b = boards[c.b];
    for (size_t k = 0; k < c.tabs.size(); ++k) {
        auto onB = [&](const Polygon& polygon, const Board3& frame, double lift) {
            double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
            for (const Point2& p : polygon)
                for (double z : {0.0, lift}) {
                    const Vector3d q = world(frame, p) + z * frame.n() - b.origin;
                    minX = std::min(minX, q.dot(b.u));
                    maxX = std::max(maxX, q.dot(b.u));
                    minY = std::min(minY, q.dot(b.v));
                    maxY = std::max(maxY, q.dot(b.v));
                }
            return std::array<double, 4>{minX, maxX, minY, maxY};
        };
        const auto tab = onB(c.tabs[k], a, a.thickness);
        const auto slot = onB(c.slots[k], b, 0);
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(tab[i], slot[i], 1e-6) << "tab " << k;
    }
}

ConnectorSettings fingersOnly()
{
    ConnectorSettings s;
    s.style = JointStyle::Fingers;
    return s;
}

}  // namespace

TEST(Connectors, TJointGetsTabsThroughSlotsOfTheSameWidth)
{
    const std::vector<Board3> boards = sideAndShelf(6);
    const JoinedBoards joined = joinBoards(boards, fingersOnly());
    ASSERT_EQ(joined.connectors.size(), 1u);
    const Connector& c = joined.connectors[0];
    EXPECT_EQ(c.kind, Connector::Kind::Fingers);
    EXPECT_EQ(boards[c.a].id, "shelf");
    ASSERT_EQ(c.tabs.size(), 12u);  // 300 mm / 12 mm fingers = 25, every second one a tab
    expectTabsMeetSlots(boards, c);
    for (const Polygon& tab : c.tabs) {
        const auto b = fabguide::geometry::bounds(tab);
        EXPECT_NEAR(std::min(b.width(), b.height()), 6, 1e-9);   // as deep as the side is thick
        EXPECT_NEAR(std::max(b.width(), b.height()), 12, 1e-9);  // finger width 2 x thickness
    }
    EXPECT_NEAR(area(joined.outlines[1]), 564 * 300 + 12 * 12 * 6, 1e-6);
    EXPECT_EQ(joined.outlines[0].holes.size(), 12u);  // through-slots inside the side
    EXPECT_NEAR(area(joined.outlines[0]), 300 * 800 - 12 * 12 * 6, 1e-6);
}

TEST(Connectors, CornerJointNotchesTheMatingEdge)
{
    // A box corner: the front spans x 0..300 in the x-z plane (u = x, v = z, so its normal is -y and the
    // slab spans y 6..0); the side's edge sits on the front's face y = 6 at its very end (x 0..6), so the
    // slots open onto the front's edge.
    const std::vector<Board3> boards{board("front", 300, 200, {0, 6, 0}, {1, 0, 0}, {0, 0, 1}, 6),
                                     board("side", 200, 200, {6, 206, 0}, {0, -1, 0}, {0, 0, 1}, 6)};
    const JoinedBoards joined = joinBoards(boards, fingersOnly());
    ASSERT_EQ(joined.connectors.size(), 1u);
    const Connector& c = joined.connectors[0];
    EXPECT_EQ(boards[c.a].id, "side");
    expectTabsMeetSlots(boards, c);
    EXPECT_TRUE(joined.outlines[0].holes.empty());  // notches, not holes
    EXPECT_NEAR(area(joined.outlines[0]), 300 * 200 - c.tabs.size() * 12 * 6, 1e-6);
    EXPECT_GT(joined.outlines[0].outer.size(), 4u);
}

TEST(Connectors, ThickBoardsAreDoweledUnderAuto)
{
    const std::vector<Board3> boards = sideAndShelf(18);
    const JoinedBoards joined = joinBoards(boards, ConnectorSettings{});
    ASSERT_EQ(joined.connectors.size(), 1u);
    EXPECT_EQ(joined.connectors[0].kind, Connector::Kind::Dowels);
    ASSERT_EQ(joined.drills[0].size(), 3u);  // 300 mm joint: 32 mm in from each end, 128 mm apart at most
    for (const Drill& d : joined.drills[0]) {
        EXPECT_NEAR(d.at.y, 400 + 9, 1e-9);  // in the middle of the shelf's thickness, on the side's face
        EXPECT_DOUBLE_EQ(d.diameter, 8);
        EXPECT_DOUBLE_EQ(d.depth, 9);
    }
    EXPECT_EQ(joined.marks[1].size(), 3u);                   // where to bore the shelf's edge
    EXPECT_NEAR(area(joined.outlines[1]), 564 * 300, 1e-6);  // outlines unchanged
}

TEST(Connectors, CrossingBoardsAreSlottedHalfWayFromOppositeEdges)
{
    const std::vector<Board3> boards{board("long", 200, 100, {0, 50, 0}, {1, 0, 0}, {0, 0, 1}, 6),
                                     board("short", 100, 100, {97, 100, 0}, {0, -1, 0}, {0, 0, 1}, 6)};
    const JoinedBoards joined = joinBoards(boards, fingersOnly());
    ASSERT_EQ(joined.connectors.size(), 1u);
    EXPECT_EQ(joined.connectors[0].kind, Connector::Kind::CrossSlots);
    for (int i = 0; i < 2; ++i) {
        EXPECT_TRUE(joined.outlines[i].holes.empty()) << i;  // open slots, not holes
        const double full = i == 0 ? 200 * 100 : 100 * 100;
        EXPECT_NEAR(area(joined.outlines[i]), full - 6 * 50, 1e-6)
            << i;  // 6 wide, half of the 100 mm overlap
    }
    // One slot opens at the bottom edge, the other at the top.
    auto lowest = [](const Polygon& p) {
        double low = 1e300;
        for (const Point2& q : p)
            low = std::min(low, q.y);
        return low;
    };
    EXPECT_NE(lowest(joined.connectors[0].tabs[0]) < 0, lowest(joined.connectors[0].slots[0]) < 0);
}

TEST(Connectors, ShortContactsAreLeftButtJointedWithANote)
{
    std::vector<Board3> boards = sideAndShelf(6);
    boards[1].outline = rectangle(564, 30);  // a 30 mm rail: 2 fingers of 12 mm, too few
    const JoinedBoards joined = joinBoards(boards, fingersOnly());
    EXPECT_TRUE(joined.connectors.empty());
    ASSERT_EQ(joined.notes.size(), 1u);
    EXPECT_NE(joined.notes[0].find("'shelf' meets 'side'"), std::string::npos) << joined.notes[0];
}

TEST(Connectors, NoneCutsTheBoardsAsModelled)
{
    ConnectorSettings none;
    none.style = JointStyle::None;
    const JoinedBoards joined = joinBoards(sideAndShelf(6), none);
    EXPECT_TRUE(joined.connectors.empty());
    EXPECT_NEAR(area(joined.outlines[1]), 564 * 300, 1e-9);
}

TEST(Connectors, BoardsApartAreNotJoined)
{
    std::vector<Board3> boards = sideAndShelf(6);
    boards[1].origin.x() += 1;  // a 1 mm gap
    EXPECT_TRUE(joinBoards(boards, fingersOnly()).connectors.empty());
}
