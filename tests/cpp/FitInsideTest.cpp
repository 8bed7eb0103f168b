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

json box(const char* name, std::array<double, 3> min, std::array<double, 3> max)
{
    return {{"name", name}, {"cuboids", {{{"name", name}, {"min", min}, {"max", max}}}}};
}

/// A chest and two drawers modelled a little wrong: the lower one too wide, the two overlapping by 10 mm.
json chest()
{
    return {{"parts",
             {box("chest", {0, 0, 0}, {400, 300, 500}), box("low drawer", {10, -5, 10}, {410, 290, 250}),
              box("high drawer", {20, 5, 240}, {380, 290, 490})}},
            {"relationships",
             {{{"type", "fit_inside"},
               {"name", "drawers in the chest"},
               {"inner", {"low drawer", "high drawer"}},
               {"enclosing", "chest"},
               {"just", {"x"}}}}}};
}

double at(const function::Model& m, int c, Side s)
{
    return m.cuboids[c].at(s);
}

}  // namespace

TEST(FitInside, DrawersEndUpInsideApartAndJustFittingAcross)
{
    const function::Model model = io::readWorkslike(chest());
    ASSERT_EQ(model.fitInside[0].apart.size(), 1u);
    EXPECT_EQ(model.fitInside[0].apart[0].axis, 2);  // stacked along z, the low one first
    EXPECT_EQ(model.fitInside[0].apart[0].a, 1);
    const function::SolveResult r = function::solve(model);
    ASSERT_TRUE(r.solved);
    const function::Model& m = r.model;
    for (int drawer : {1, 2})
        for (int k = 0; k < 6; ++k) {
            const Side side = static_cast<Side>(k);
            if (k % 2)
                EXPECT_LE(at(m, drawer, side), at(m, 0, side) + 1e-6) << drawer << " side " << k;
            else
                EXPECT_GE(at(m, drawer, side), at(m, 0, side) - 1e-6) << drawer << " side " << k;
        }
    EXPECT_LE(at(m, 1, Side::Top), at(m, 2, Side::Bottom) + 1e-6);    // apart
    EXPECT_NEAR(at(m, 1, Side::Left), at(m, 0, Side::Left), 1e-6);    // just fits along x: leftmost drawer
    EXPECT_NEAR(at(m, 1, Side::Right), at(m, 0, Side::Right), 1e-6);  // and rightmost drawer touch the sides
}

TEST(FitInside, HoldsInItsConfiguration)
{
    json d = chest();
    d["parts"] = {box("chest", {0, 0, 0}, {400, 300, 500}), box("drawer", {10, -200, 10}, {390, 90, 250})};
    d["joints"] = {{{"name", "runner"}, {"type", "slide"}, {"part", "drawer"}, {"axis", "y"}}};
    d["configurations"] = {{{"name", "closed"}, {"poses", {{"runner", 200}}}}};
    d["relationships"] = {{{"type", "fit_inside"},
                           {"name", "drawer shuts"},
                           {"inner", {"drawer"}},
                           {"enclosing", "chest"},
                           {"configuration", "closed"}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_TRUE(r.solved);
    const double closedFar = function::evaluate(r.model, function::posed(r.model, Face{1, Side::Far}, 0));
    EXPECT_LE(closedFar, at(r.model, 0, Side::Far) + 1e-6);
    EXPECT_GE(function::evaluate(r.model, function::posed(r.model, Face{1, Side::Near}, 0)),
              at(r.model, 0, Side::Near) - 1e-6);
}

TEST(FitInside, ErrorsNameTheFieldAndTheFormatRoundTrips)
{
    json d = chest();
    d["relationships"][0]["enclosing"] = "low drawer";
    EXPECT_EQ(testsupport::workslikeError(d), "relationships[0].enclosing: a part cannot fit inside itself");
    d = chest();
    d["relationships"][0]["just"] = {"w"};
    EXPECT_EQ(
        testsupport::workslikeError(d),
        "relationships[0].just[0]: must be \"x\", \"y\", \"z\", a pair of faces or {\"part\", \"axes\"}, got "
        "\"w\"");
    d = chest();
    d["relationships"][0]["apart"] = json::array({json::array({"low drawer", "q", "high drawer"})});
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].apart[0]: must be [\"cuboid\", \"x|y|z\", \"cuboid\"]");
    const json written = io::workslikeToJson(io::readWorkslike(chest()));
    EXPECT_EQ(io::workslikeToJson(io::readWorkslike(written)), written);
    EXPECT_EQ(written["relationships"][0]["apart"][0], json::array({"low drawer", "z", "high drawer"}));
}

TEST(FitInside, APortionOfAPartFitsACavityAndTheCavityStaysInItsSolid)
{
    // A drawer whose front stays outside: only its box must fit the chest's opening, a cavity.
    json d = chest();
    d["parts"] = {
        {{"name", "chest"},
         {"cuboids",
          {{{"name", "chest"}, {"min", {0, 0, 0}}, {"max", {400, 300, 500}}},
           {{"name", "opening"}, {"min", {20, 0, 20}}, {"max", {380, 280, 250}}, {"cavity", true}}}}},
        {{"name", "drawer"},
         {"cuboids",
          {{{"name", "front"}, {"min", {10, -20, 10}}, {"max", {390, 0, 260}}},
           {{"name", "tray"}, {"min", {10, 0, 30}}, {"max", {390, 290, 240}}}}}}};
    d["relationships"] = {{{"type", "fit_inside"},
                           {"name", "tray in the opening"},
                           {"inner", {"drawer"}},
                           {"enclosing", "chest"},
                           {"cavity", "opening"},
                           {"portion", {"tray"}}}};
    d["locks"] = {"chest.left", "chest.right"};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_TRUE(r.solved);
    const function::Model& m = r.model;  // cuboids: chest 0, opening 1, front 2, tray 3
    for (Side low : {Side::Left, Side::Near, Side::Bottom}) {
        const Side high = static_cast<Side>(static_cast<int>(low) + 1);
        EXPECT_LE(at(m, 1, low), at(m, 3, low) + 1e-6);  // the tray in the opening
        EXPECT_GE(at(m, 1, high), at(m, 3, high) - 1e-6);
        EXPECT_LE(at(m, 0, low), at(m, 1, low) + 1e-6);  // the opening in the chest
        EXPECT_GE(at(m, 0, high), at(m, 1, high) - 1e-6);
    }
    EXPECT_LT(at(m, 2, Side::Near), at(m, 1, Side::Near));  // the front may stay outside
    EXPECT_NEAR(at(m, 3, Side::Far), 285, 1e-6);  // least change: the tray 5 shorter, the opening 5 deeper
}

TEST(FitInside, CavityAndPortionErrorsNameTheField)
{
    json d = chest();
    d["parts"][0]["cuboids"].push_back(
        {{"name", "hole"}, {"min", {500, 0, 0}}, {"max", {600, 10, 10}}, {"cavity", true}});
    EXPECT_EQ(testsupport::workslikeError(d),
              "parts[0].cuboids[1].min: cavity 'hole' lies outside every solid cuboid of part 'chest'");
    d = chest();
    d["parts"][0]["cuboids"][0]["cavity"] = true;
    EXPECT_EQ(testsupport::workslikeError(d),
              "parts[0].cuboids[0].cavity: a part's first cuboid is solid (cavities are cut from solids)");
    d = chest();
    d["relationships"][0]["cavity"] = "low drawer";
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].cavity: 'low drawer' is not a cavity of part 'chest'");
    d = chest();
    d["relationships"][0]["portion"] = {"chest"};
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].portion[0]: 'chest' is not a cuboid of an inner part");
}
