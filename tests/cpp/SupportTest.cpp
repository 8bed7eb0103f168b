#include "Function/Pose.h"
#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include "WorkslikeTestSupport.h"

#include <gtest/gtest.h>

using namespace fabguide;
using function::Face;
using function::Side;
using nlohmann::json;

namespace {

/// A table top on three legs modelled a little off: one leg sags 3 mm, one pokes out from under the top,
/// one stands 5 mm lower than the others.
json table()
{
    auto box = [](const char* name, std::array<double, 3> min, std::array<double, 3> max) {
        return json{{"name", name}, {"cuboids", {{{"name", name}, {"min", min}, {"max", max}}}}};
    };
    return {{"parts",
             {box("top", {0, 0, 700}, {1000, 600, 720}), box("leg1", {20, 20, 0}, {80, 80, 697}),
              box("leg2", {960, 20, 0}, {1040, 80, 700}), box("leg3", {20, 520, -5}, {80, 580, 700})}},
            {"relationships",
             {{{"type", "support"},
               {"name", "legs hold the top"},
               {"supporting", {"leg1", "leg2", "leg3"}},
               {"supported", {"top"}}}}}};
}

double at(const function::Model& m, int cuboid, Side side)
{
    return m.cuboids[cuboid].at(side);
}

}  // namespace

TEST(Support, EveryLegEndsUnderTheTopOnOneGround)
{
    const function::Model model = io::readWorkslike(table());
    ASSERT_EQ(model.support[0].pairs.size(), 3u);  // inferred: each leg's top under the table top
    const function::SolveResult r = function::solve(model);
    ASSERT_TRUE(r.solved);
    const function::Model& m = r.model;
    for (int leg = 1; leg <= 3; ++leg) {
        EXPECT_NEAR(at(m, leg, Side::Top), at(m, 0, Side::Bottom), 1e-6) << leg;     // same height
        EXPECT_LE(at(m, leg, Side::Left), at(m, 0, Side::Right) - 1 + 1e-6) << leg;  // overlap >= 1 mm
        EXPECT_LE(at(m, 0, Side::Left), at(m, leg, Side::Right) - 1 + 1e-6) << leg;
        EXPECT_NEAR(at(m, leg, Side::Bottom), at(m, 1, Side::Bottom), 1e-6) << leg;  // one ground
    }
    EXPECT_GT(at(m, 2, Side::Left), 950);  // leg2 still mostly where it was: the least change
}

TEST(Support, PairsCanBeGivenAndAreWrittenBack)
{
    json d = table();
    d["relationships"][0]["pairs"] = json::array({json::array({"leg1.top", "top.bottom"})});
    const function::Model model = io::readWorkslike(d);
    EXPECT_EQ(model.support[0].pairs, (std::vector<std::pair<int, int>>{{1, 0}}));
    const json written = io::workslikeToJson(io::readWorkslike(table()));
    EXPECT_EQ(written["relationships"][0]["pairs"].size(), 3u);
    EXPECT_EQ(io::workslikeToJson(io::readWorkslike(written)), written);
}

TEST(Support, LegsShortOrSunkAreLinkedAndNoted)
{
    json d = table();
    d["relationships"][0]["distance"] = 40;
    d["parts"][1]["cuboids"][0]["max"][2] = 590;  // leg1 110 mm short of the top
    d["parts"][2]["cuboids"][0]["max"][2] = 703;  // leg2 sunk 3 mm into it
    const function::Model m = io::readWorkslike(d);
    EXPECT_EQ(m.support[0].pairs, (std::vector<std::pair<int, int>>{{2, 0}, {3, 0}, {1, 0}}));
    EXPECT_EQ(m.support[0].notes,
              (function::InferenceNotes{
                  "leg1: 110 mm below top.bottom, beyond the 40 mm support distance; linked to it"}));
    const function::SolveResult r = function::solve(m);
    ASSERT_TRUE(r.solved);
    for (int leg = 1; leg <= 3; ++leg)  // every leg ends under the top, none inside it
        EXPECT_EQ(at(r.model, leg, Side::Top), at(r.model, 0, Side::Bottom));
}

TEST(Support, ErrorsNameTheField)
{
    json d = table();
    d["relationships"][0]["supported"] = {"tabletop"};
    EXPECT_EQ(testsupport::workslikeError(d), "relationships[0].supported[0]: no part named 'tabletop'");
    d = table();
    d["parts"][0]["cuboids"][0]["min"][2] = -100;  // the top under its legs
    d["parts"][0]["cuboids"][0]["max"][2] = -80;
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].supporting[0] ('leg1'): no bottom face of a "
              "supported part lies above a top face of a supporting one");
    d = table();
    d["relationships"][0]["pairs"] = json::array({json::array({"top.bottom", "leg1.top"})});
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].pairs[0]: a supporting top face rests under a supported bottom face");
    d["relationships"][0]["pairs"] = {{"leg1.top", "top.bottom"}};  // an object, not a list of pairs
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].pairs: must be an array, got {\"leg1.top\":\"top.bottom\"}");
}
