// Parts kept apart, openings kept open, walls kept, results exact.
#include "Function/Separation.h"
#include "Function/Solve.h"
#include "IO/WorkslikeFormat.h"

#include "WorkslikeTestSupport.h"

#include <gtest/gtest.h>

using namespace fabguide;
using function::Side;
using nlohmann::json;
using testsupport::cuboid;
using testsupport::cuboidPart;
using testsupport::typedConflict;
using Kind = function::ConflictKind;

namespace {

double at(const function::Model& m, const std::string& name, Side side)
{
    for (const function::Cuboid& c : m.cuboids)
        if (c.name == name)
            return c.at(side);
    throw std::invalid_argument(name);
}

/// A carcass with an opening at the front and a door drawn 2 mm into it, a bit off the opening.
json doorIntoCarcass()
{
    return {{"parts",
             {{{"name", "carcass"},
               {"cuboids",
                {cuboid("carcass", {0, 0, 0}, {600, 400, 900}),
                 cuboid("opening", {18, 0, 18}, {582, 382, 882}, true)}}},
              cuboidPart("door", {20, -16, 16}, {585, 2, 880})}},
            {"relationships",
             {{{"type", "cover"},
               {"name", "door covers the opening"},
               {"covering", {"door"}},
               {"covered", {"carcass"}},
               {"just", true}}}}};
}

}  // namespace

TEST(Separation, ADoorDrawnIntoItsCarcassEndsOnItsFaceAndTheOpeningStaysOpen)
{
    const function::SolveResult r = function::solve(io::readWorkslike(doorIntoCarcass()));
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    EXPECT_EQ(at(r.model, "door", Side::Far), at(r.model, "carcass", Side::Near));  // to the last bit
    EXPECT_EQ(at(r.model, "opening", Side::Near), at(r.model, "carcass", Side::Near));
    EXPECT_EQ(at(r.model, "door", Side::Left), at(r.model, "opening", Side::Left));  // just covers
    EXPECT_EQ(at(r.model, "door", Side::Top), at(r.model, "opening", Side::Top));
}

TEST(Separation, OverlappingPartsMoveApartByTheLeastChange)
{
    const json d = {
        {"parts", {cuboidPart("a", {0, 0, 0}, {100, 50, 50}), cuboidPart("b", {97, 10, 0}, {200, 40, 50})}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_TRUE(r.solved);
    EXPECT_EQ(at(r.model, "a", Side::Right), 98.5);  // 1.5 mm each along x, the least overlap
    EXPECT_EQ(at(r.model, "b", Side::Left), 98.5);
    EXPECT_EQ(at(r.model, "b", Side::Near), 10);  // nothing else moves
}

TEST(Separation, ThePartMoreInsideTheOtherIsTheOneDrawnInside)
{
    // A tray filling most of its carcass: the carcass is more than half within the tray's box too (68 %), and
    // was named as drawn inside the tray, with a cavity to make in the tray.
    json d = {{"parts",
               {cuboidPart("carcass", {0, 0, 0}, {400, 350, 200}),
                cuboidPart("drawer tray", {20, 10, 20}, {380, 340, 180})}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    EXPECT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, std::vector<std::string>{"drawn inside: drawer tray in carcass"});
    EXPECT_EQ(typedConflict(r), (decltype(typedConflict(r)){{Kind::DrawnInside, "drawer tray in carcass"}}));
}

TEST(Separation, APartDrawnInsideAnotherBeforeItsCavityIsNamedAndNothingChanges)
{
    // A tray drawn inside a carcass, its cavity not made yet. Keeping them apart shrank the carcass
    // (800 -> 665 mm) and the top standing on it: edits no relationship asked for.
    json d = {
        {"parts",
         {cuboidPart("carcass", {0, 0, 0}, {600, 400, 800}), cuboidPart("top", {0, 0, 800}, {600, 400, 830}),
          cuboidPart("tray", {30, 0, 610}, {570, 380, 770})}}};
    const function::Model drawn = io::readWorkslike(d);
    function::SolveResult r = function::solve(drawn);
    EXPECT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, std::vector<std::string>{"drawn inside: tray in carcass"});
    EXPECT_EQ(typedConflict(r), (decltype(typedConflict(r)){{Kind::DrawnInside, "tray in carcass"}}));
    EXPECT_EQ(r.parts, (std::vector<std::string>{"tray", "carcass"}));
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_NE(r.notes[0].find("make a cavity in 'carcass' where 'tray' goes"), std::string::npos)
        << r.notes[0];
    EXPECT_EQ(at(r.model, "carcass", Side::Top), 800);
    // With its cavity made it solves, and nothing moves: the tray is in the void.
    d["parts"][0]["cuboids"].push_back(cuboid("drawer space", {20, 0, 600}, {580, 390, 780}, true));
    r = function::solve(io::readWorkslike(d));
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    EXPECT_EQ(at(r.model, "carcass", Side::Top), 800);
    EXPECT_EQ(at(r.model, "top", Side::Bottom), 800);
    EXPECT_EQ(at(r.model, "tray", Side::Bottom), 610);
}

TEST(Separation, PartsTheSolveBringsTogetherAreKeptApartToo)
{
    json d = {
        {"parts", {cuboidPart("a", {0, 0, 0}, {10, 10, 10}), cuboidPart("b", {20, 0, 0}, {30, 10, 10})}},
        {"relationships",
         {{{"type", "geometric"},
           {"name", "a 25 wide"},
           {"left", "a.width"},
           {"right", json::array()},
           {"offset", 25}}}},
        {"locks", {"a.left"}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_TRUE(r.solved);
    EXPECT_EQ(at(r.model, "a", Side::Right), 25);
    EXPECT_EQ(at(r.model, "b", Side::Left), 25);  // its side pushed back, not passed through
    EXPECT_EQ(at(r.model, "b", Side::Right), 30);
}

TEST(Separation, LockedPartsThatOverlapAreAConflictNamingThem)
{
    json d = {{"parts", {cuboidPart("a", {0, 0, 0}, {10, 10, 10}), cuboidPart("b", {8, 0, 0}, {20, 10, 10})}},
              {"locks", {"a.right", "b.left"}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{"lock: a.right", "lock: b.left", "no overlap: a, b"}));
    EXPECT_EQ(typedConflict(r),
              (decltype(typedConflict(r)){
                  {Kind::Lock, "a.right"}, {Kind::Lock, "b.left"}, {Kind::NoOverlap, "a, b"}}));
}

TEST(Separation, ADrawerInACompartmentStaysInsideItButThroughTheMouth)
{
    // Drawn 3 mm through the back wall and pulled out 100 mm in "open".
    json d = {{"parts",
               {{{"name", "chest"},
                 {"cuboids",
                  {cuboid("chest", {0, 0, 0}, {400, 300, 200}),
                   cuboid("bay", {10, 0, 10}, {390, 290, 190}, true)}}},
                cuboidPart("drawer", {12, 0, 12}, {388, 293, 150})}},
              {"joints", {{{"name", "runner"}, {"type", "slide"}, {"part", "drawer"}, {"axis", "y"}}}},
              {"configurations", {{{"name", "open"}, {"poses", {{"runner", -100}}}}}}};
    const function::Model m = io::readWorkslike(d);
    const function::Separation s = function::inferSeparation(m, 0, 2, -1);  // the chest and the drawer
    EXPECT_EQ(s.a, 2);  // the drawer in the bay: less to change than pulling it out of the chest
    for (const function::Face& wall : s.walls)  // the bay's five walls; its mouth is an opening
        EXPECT_EQ(wall.cuboid, 1);
    EXPECT_EQ(s.walls.size(), 5u);
    const function::SolveResult r = function::solve(m);
    ASSERT_TRUE(r.solved);
    EXPECT_LE(at(r.model, "drawer", Side::Far), at(r.model, "bay", Side::Far));
    EXPECT_EQ(at(r.model, "bay", Side::Near), 0);  // its mouth stays on the face
    EXPECT_GE(at(r.model, "chest", Side::Far) - at(r.model, "bay", Side::Far), 1);  // a wall behind it
}

TEST(Separation, APartReachesThroughAPassageIntoTheNextCavity)
{
    // A toaster's lever in a T-slot: the slider runs in a channel, the stem through a narrower slot beside it
    // that opens on the body's face, the knob outside. The stem crosses from the channel into the slot.
    json d = {
        {"parts",
         {{{"name", "body"},
           {"cuboids",
            {cuboid("body", {0, 0, 0}, {280, 160, 190}),
             cuboid("channel", {262, 60, 50}, {276, 100, 160}, true),
             cuboid("slot", {276, 72, 50}, {280, 88, 160}, true)}}},
          {{"name", "lever"},
           {"cuboids",
            {cuboid("slider", {264, 62, 140}, {274, 98, 150}), cuboid("stem", {274, 74, 140}, {282, 86, 150}),
             cuboid("knob", {282, 60, 135}, {310, 100, 155})}}}}},
        {"joints", {{{"name", "lever slide"}, {"type", "slide"}, {"part", "lever"}, {"axis", "z"}}}},
        {"configurations", {{{"name", "down"}, {"poses", {{"lever slide", -80}}}}}}};
    const function::Model m = io::readWorkslike(d);
    const function::Separation s = function::inferSeparation(m, 0, 4, -1);  // the body and the stem
    EXPECT_EQ(s.a, 4);
    for (const function::Face& wall : s.walls)  // no wall between the channel and the slot
        EXPECT_FALSE((wall.cuboid == 1 && wall.side == Side::Right) ||
                     (wall.cuboid == 2 && wall.side == Side::Left));
    EXPECT_EQ(s.walls.size(), 9u);  // the channel's five others, the slot's four (its right is the mouth)
    const function::SolveResult r = function::solve(m);
    ASSERT_TRUE(r.solved);
    for (const char* name : {"stem", "slot", "channel"})  // nothing to change: the lever stays whole
        for (int k = 0; k < 6; ++k)
            EXPECT_EQ(at(r.model, name, static_cast<Side>(k)), at(m, name, static_cast<Side>(k))) << name;
}

TEST(Separation, AWallCannotBeEatenBelowTheMinimum)
{
    json d = {{"parts",
               {{{"name", "box"},
                 {"cuboids",
                  {cuboid("box", {0, 0, 0}, {100, 60, 40}), cuboid("well", {5, 5, 5}, {95, 55, 40}, true)}}},
                cuboidPart("tray", {0.5, 8, 10}, {99.5, 52, 30})}},  // 0.5 mm walls at most
              {"relationships",
               {{{"type", "fit_inside"},
                 {"name", "tray in the well"},
                 {"inner", {"tray"}},
                 {"enclosing", "box"},
                 {"cavity", "well"}}}},
              {"locks", {"box.left", "box.right", "tray.left", "tray.right"}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{"wall: well", "tray in the well", "lock: box.right",
                                                    "lock: tray.right"}));  // the right side is enough
    EXPECT_EQ(typedConflict(r), (decltype(typedConflict(r)){{Kind::Wall, "well"},
                                                            {Kind::FitInside, "tray in the well"},
                                                            {Kind::Lock, "box.right"},
                                                            {Kind::Lock, "tray.right"}}));
}

TEST(Separation, AnInnerPartOfAFitInsideMayLieInTheEnclosingSolid)
{
    // Print-in-place sweeps its room out (thesis 4.5.1): the tray inside a solid box is no overlap.
    json d = {
        {"parts",
         {cuboidPart("box", {0, 0, 0}, {100, 60, 40}), cuboidPart("tray", {10, 10, 10}, {90, 50, 30})}},
        {"relationships",
         {{{"type", "fit_inside"}, {"name", "tray in the box"}, {"inner", {"tray"}}, {"enclosing", "box"}}}}};
    const function::Model m = io::readWorkslike(d);
    EXPECT_TRUE(function::nearPairs(m, -1, 1).empty());
    const function::SolveResult r = function::solve(m);
    ASSERT_TRUE(r.solved);
    EXPECT_EQ(r.model.cuboids[1].coordinates, m.cuboids[1].coordinates);
}

TEST(Separation, PosesTurnedByOtherThanQuartersAreNotExact)
{
    json d = {
        {"parts",
         {cuboidPart("body", {0, 0, 0}, {100, 60, 40}), cuboidPart("lid", {0, 0, 40}, {100, 60, 45})}},
        {"joints",
         {{{"name", "hinge"}, {"type", "hinge"}, {"part", "lid"}, {"edge", {"lid.far", "lid.bottom"}}}}},
        {"configurations",
         {{{"name", "up"}, {"poses", {{"hinge", -90}}}}, {{"name", "ajar"}, {"poses", {{"hinge", -30}}}}}}};
    const function::Model m = io::readWorkslike(d);
    EXPECT_TRUE(function::exactlyPosed(m, 1, -1));
    EXPECT_TRUE(function::exactlyPosed(m, 1, 0));
    EXPECT_FALSE(function::exactlyPosed(m, 1, 1));
    EXPECT_TRUE(function::exactlyPosed(m, 0, 1));
}

TEST(Separation, APairKeptApartNoWayIsAConflictNamingWhatEachWayConflictsWith)
{
    // Two blocks drawn overlapping at a corner, kept apart across x or across y; one relationship holds them
    // together across x, another across y. Before, the conflict named the first way's only: the x one and the
    // overlap, which hold together once the y one is gone.
    json blocks = {
        {"parts", {cuboidPart("a", {0, 0, 0}, {100, 100, 10}), cuboidPart("b", {98, 97, 0}, {150, 150, 10})}},
        {"relationships",
         {{{"type", "geometric"},
           {"name", "b over a across x"},
           {"relation", "at_most"},
           {"left", "b.left"},
           {"right", "a.right"},
           {"offset", -2}},
          {{"type", "geometric"},
           {"name", "b over a across y"},
           {"relation", "at_most"},
           {"left", "b.near"},
           {"right", "a.far"},
           {"offset", -3}}}}};
    const function::SolveResult r = function::solve(io::readWorkslike(blocks));
    ASSERT_FALSE(r.solved);
    const auto typed = typedConflict(r);
    EXPECT_EQ(typed.size(), 3u) << testing::PrintToString(r.conflict);
    for (const auto& conflict : {std::pair{Kind::Geometric, std::string("b over a across x")},
                                 std::pair{Kind::Geometric, std::string("b over a across y")},
                                 std::pair{Kind::NoOverlap, std::string("a, b")}})
        EXPECT_NE(std::find(typed.begin(), typed.end(), conflict), typed.end())
            << conflict.second << " not in " << testing::PrintToString(r.conflict);
    for (int drop : {0, 1}) {  // either way alone holds
        json one = blocks;
        one["relationships"].erase(drop);
        EXPECT_TRUE(function::solve(io::readWorkslike(one)).solved) << drop;
    }
}

TEST(Separation, AFitInsideWhoseEnclosingPartHasNoCavitySaysToMakeOne)
{
    // A drawer fitting inside a solid carcass lies in it, but cannot slide out through it (a new user's
    // model): the conflict says what to make, not only what conflicts.
    const json drawer = {
        {"parts",
         {cuboidPart("carcass", {0, 0, 0}, {400, 350, 200}),
          cuboidPart("drawer", {20, 0, 20}, {380, 330, 180})}},
        {"joints", {{{"name", "runner"}, {"type", "slide"}, {"part", "drawer"}, {"axis", "y"}}}},
        {"configurations", {{{"name", "out"}, {"poses", {{"runner", -250}}}}}},
        {"relationships",
         {{{"type", "fit_inside"},
           {"name", "drawer in carcass"},
           {"inner", {"drawer"}},
           {"enclosing", "carcass"}}}}};
    const function::SolveResult r = function::solve(io::readWorkslike(drawer));
    ASSERT_FALSE(r.solved);
    const std::string note =
        "drawer in carcass: 'carcass' has no cavity for 'drawer' to move in; make a cavity in 'carcass' "
        "where it goes";
    EXPECT_NE(std::find(r.notes.begin(), r.notes.end(), note), r.notes.end())
        << testing::PrintToString(r.notes);
}

TEST(Separation, AWayNearAsDrawnIsTried)
{
    // A jewellery box's lid turned back 100° on its far edge (a new user's model), drawn behind the casket,
    // no more than 15 mm behind it; the relationships alone arrange it over the casket, where it meets the
    // cover. Before, only the way over the casket was tried, and the solve was refused naming the cover and
    // the overlap, which hold together. Behind the casket, it holds: the lid and the tray it covers get
    // shallower (the least change that keeps the limit).
    json box = {
        {"parts",
         {{{"name", "casket"},
           {"cuboids",
            {cuboid("casket", {0, 0, 0}, {150, 100, 60}), cuboid("tray", {8, 8, 8}, {142, 92, 60}, true)}}},
          cuboidPart("lid", {1, 1, 61}, {149, 99, 73})}},
        {"joints",
         {{{"name", "lid hinge"}, {"type", "hinge"}, {"part", "lid"}, {"edge", {"lid.far", "lid.bottom"}}}}},
        {"configurations", {{{"name", "open"}, {"poses", {{"lid hinge", -100}}}}}},
        {"relationships",
         {{{"type", "cover"},
           {"name", "lid closes the casket"},
           {"covering", {"lid"}},
           {"covered", {"casket"}}},
          {{"type", "geometric"},
           {"name", "open lid at most 15 behind"},
           {"relation", "at_most"},
           {"configuration", "open"},
           {"left", "lid.far"},
           {"right", "casket.far"},
           {"offset", 15}}}}};
    const function::SolveResult r = function::solve(io::readWorkslike(box));
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    EXPECT_LT(r.violation, 1e-6);
    EXPECT_LT(at(r.model, "lid", Side::Far) - at(r.model, "lid", Side::Near), 98 - 1);
    EXPECT_EQ(at(r.model, "lid", Side::Bottom), at(r.model, "casket", Side::Top));
}
