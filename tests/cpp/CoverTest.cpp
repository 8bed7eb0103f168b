#include "Function/Cover.h"
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

using testsupport::cuboidPart;

namespace {

/// A clamshell: the lid modelled open behind the body, hinged on its near-top edge; "closed" turns it 180°
/// onto the body, where it lands 3 mm low, a little small and off-centre.
json clamshell(bool just)
{
    return {{"parts",
             {cuboidPart("body", {0, 0, 0}, {60, 120, 10}), cuboidPart("lid", {3, 122, 0}, {57, 230, 7})}},
            {"joints",
             {{{"name", "hinge"}, {"type", "hinge"}, {"part", "lid"}, {"edge", {"lid.near", "lid.top"}}}}},
            {"configurations", {{{"name", "closed"}, {"poses", {{"hinge", 180}}}}}},
            {"relationships",
             {{{"type", "cover"},
               {"name", "lid covers the body"},
               {"covering", {"lid"}},
               {"covered", {"body"}},
               {"just", just},
               {"configuration", "closed"}}}}};
}

double closed(const function::Model& m, const std::string& face)
{
    const auto dot = face.find('.');
    int c = 0;
    while (m.cuboids[c].name != face.substr(0, dot))
        ++c;
    for (int k = 0; k < 6; ++k)
        if (face.substr(dot + 1) == function::sideName(static_cast<Side>(k)))
            return function::evaluate(m, function::posed(m, Face{c, static_cast<Side>(k)}, 0));
    throw std::invalid_argument(face);
}

}  // namespace

TEST(Cover, InfersTheFacingFacesInTheCoveredConfiguration)
{
    const function::Model m = io::readWorkslike(clamshell(false));
    ASSERT_EQ(m.cover[0].pairs.size(), 1u);
    EXPECT_EQ(function::faceName(m, m.cover[0].pairs[0].first), "lid.bottom");  // the lid's box when closed
    EXPECT_EQ(function::faceName(m, m.cover[0].pairs[0].second), "body.top");
}

TEST(Cover, TheClosedLidLiesOnTheBodyAndCoversIt)
{
    const function::SolveResult r = function::solve(io::readWorkslike(clamshell(false)));
    ASSERT_TRUE(r.solved);
    const function::Model& m = r.model;
    EXPECT_NEAR(closed(m, "lid.bottom"), closed(m, "body.top"), 1e-6);
    EXPECT_LE(closed(m, "lid.left"), closed(m, "body.left") + 1e-6);
    EXPECT_GE(closed(m, "lid.right"), closed(m, "body.right") - 1e-6);
    EXPECT_LE(closed(m, "lid.near"), closed(m, "body.near") + 1e-6);
    EXPECT_GE(closed(m, "lid.far"), closed(m, "body.far") - 1e-6);
}

TEST(Cover, JustCoverMakesTheBoxesEqual)
{
    const function::SolveResult r = function::solve(io::readWorkslike(clamshell(true)));
    ASSERT_TRUE(r.solved);
    for (const char* side : {"left", "right", "near", "far"})
        EXPECT_NEAR(closed(r.model, std::string("lid.") + side), closed(r.model, std::string("body.") + side),
                    1e-6)
            << side;
    const function::SolveResult again = function::solve(r.model);  // idempotent
    ASSERT_TRUE(again.solved);
    for (size_t c = 0; c < r.model.cuboids.size(); ++c)
        for (int k = 0; k < 6; ++k)
            EXPECT_NEAR(again.model.cuboids[c].coordinates[k], r.model.cuboids[c].coordinates[k], 1e-6);
}

TEST(Cover, TwoDoorsArePackedSideBySideOverTheCarcassFront)
{
    // Two doors modelled with a gap between them and uneven heights just cover the carcass' front.
    json d = {
        {"parts",
         {cuboidPart("carcass", {0, 0, 0}, {80, 40, 100}), cuboidPart("left door", {1, -2, 2}, {38, 0, 98}),
          cuboidPart("right door", {42, -2, 1}, {79, 0, 97})}},
        {"relationships",
         {{{"type", "cover"},
           {"name", "doors cover the front"},
           {"covering", {"left door", "right door"}},
           {"covered", {"carcass"}},
           {"just", true}}}}};
    const function::Model model = io::readWorkslike(d);
    ASSERT_EQ(model.cover[0].pairs.size(), 2u);  // both doors' backs on the carcass' front
    const function::Packing p =
        function::packing(model, {model.cover[0].pairs[0].first, model.cover[0].pairs[1].first}, -1, 5);
    ASSERT_EQ(p.neighbours.size(), 1u);
    EXPECT_EQ(p.neighbours[0].axis, 0);
    EXPECT_EQ(model.cuboids[p.neighbours[0].a.cuboid].name, "left door");

    const function::SolveResult r = function::solve(model);
    ASSERT_TRUE(r.solved);
    const auto& carcass = r.model.cuboids[0];
    const auto& left = r.model.cuboids[1];
    const auto& right = r.model.cuboids[2];
    EXPECT_NEAR(left.at(Side::Right), right.at(Side::Left), 1e-6);  // no gap, no overlap
    EXPECT_NEAR(left.at(Side::Left), carcass.at(Side::Left), 1e-6);
    EXPECT_NEAR(right.at(Side::Right), carcass.at(Side::Right), 1e-6);
    for (const auto* door : {&left, &right}) {
        EXPECT_NEAR(door->at(Side::Bottom), carcass.at(Side::Bottom), 1e-6);
        EXPECT_NEAR(door->at(Side::Top), carcass.at(Side::Top), 1e-6);
        EXPECT_NEAR(door->at(Side::Far), carcass.at(Side::Near), 1e-6);
    }
}

TEST(Cover, ALidTooSmallToCoverIsAConflictNamingWhatHoldsItSmall)
{
    json d = clamshell(false);
    d["relationships"].push_back({{"type", "geometric"},
                                  {"name", "lid 50 wide"},
                                  {"left", "lid.width"},
                                  {"right", json::array()},
                                  {"offset", 50}});
    d["locks"] = {"body.left", "body.right"};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{"lid 50 wide", "lid covers the body", "lock: body.left",
                                                    "lock: body.right"}));
}

TEST(Cover, APartBeyondTheFaceDistanceIsLinkedAndNoted)
{
    json d = clamshell(false);
    d["relationships"][0]["distance"] = 1;  // closed, the lid lands 3 mm into the body
    const function::Model m = io::readWorkslike(d);
    ASSERT_EQ(m.cover[0].pairs.size(), 1u);
    EXPECT_EQ(function::faceName(m, m.cover[0].pairs[0].first), "lid.bottom");
    EXPECT_EQ(
        m.cover[0].notes,
        (function::InferenceNotes{"lid: 3 mm from body.top, beyond the 1 mm face distance; linked to it"}));
    const function::SolveResult r = function::solve(m);
    ASSERT_TRUE(r.solved);
    EXPECT_EQ(r.notes, (std::vector<std::string>{"lid covers the body: " + m.cover[0].notes[0]}));
}

TEST(Cover, TheEdgeOfABoardCoversNothing)
{
    json d = clamshell(false);
    d["relationships"][0].erase("configuration");  // open, only the lid's 7 mm edge faces the body
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].covering[0] ('lid'): no face of it faces a face "
              "of the other side, overlapping it by half");
}

TEST(Cover, ErrorsNameTheField)
{
    json d = clamshell(false);
    d["relationships"][0].erase("configuration");  // open, the lid's near face is 2 mm behind the body
    d["parts"][1]["cuboids"][0]["min"][0] = 100;   // … and beside it: no face of the lid faces the body's
    d["parts"][1]["cuboids"][0]["max"][0] = 150;
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].covering[0] ('lid'): no face of it faces a face "
              "of the other side, overlapping it by half");
    d = clamshell(false);
    d["relationships"][0]["pairs"] = json::array({json::array({"lid.bottom", "body.near"})});
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].pairs: body.near and lid.bottom are linked but not parallel");
    d = clamshell(false);
    d["relationships"][0]["just"] = "yes";
    EXPECT_EQ(testsupport::workslikeError(d), "relationships[0].just: must be true or false, got \"yes\"");
    d = clamshell(true);
    EXPECT_EQ(io::workslikeToJson(io::readWorkslike(io::workslikeToJson(io::readWorkslike(d)))),
              io::workslikeToJson(io::readWorkslike(d)));
}
