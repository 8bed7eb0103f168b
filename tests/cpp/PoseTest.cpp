#include "Function/Pose.h"
#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include "WorkslikeTestSupport.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

using namespace fabguide;
using function::Face;
using function::Side;
using nlohmann::json;

namespace {

/// A body and a lid hinged on the edge where two of its faces meet; configuration "turned" poses the hinge.
json hingedLid(const std::string& edgeA, const std::string& edgeB, double angle)
{
    return {
        {"parts",
         {{{"name", "body"}, {"cuboids", {{{"name", "body"}, {"min", {0, 0, 0}}, {"max", {100, 60, 40}}}}}},
          {{"name", "lid"}, {"cuboids", {{{"name", "lid"}, {"min", {5, 10, 40}}, {"max", {95, 60, 47}}}}}}}},
        {"joints", {{{"name", "hinge"}, {"type", "hinge"}, {"part", "lid"}, {"edge", {edgeA, edgeB}}}}},
        {"configurations", {{{"name", "turned"}, {"poses", {{"hinge", angle}}}}}}};
}

/// Turning about joint j's edge (as modelled) by `degrees`.
Eigen::Isometry3d turning(const function::Model& m, const function::Joint& j, double degrees)
{
    const auto& cuboid = m.cuboids[j.edgeA.cuboid];
    const int a = 3 - static_cast<int>(j.edgeA.side) / 2 - static_cast<int>(j.edgeB.side) / 2;
    Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
    pivot[static_cast<int>(j.edgeA.side) / 2] = cuboid.at(j.edgeA.side);
    pivot[static_cast<int>(j.edgeB.side) / 2] = cuboid.at(j.edgeB.side);
    return Eigen::Translation3d(pivot) * Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d::Unit(a)) *
           Eigen::Translation3d(-pivot);
}

/// The bounding box of cuboid c's eight corners moved by `motion`.
std::array<double, 6> movedBox(const function::Model& m, int c, const Eigen::Isometry3d& motion)
{
    const auto& cuboid = m.cuboids[c];
    std::array<double, 6> box{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d p(cuboid.coordinates[corner & 1], cuboid.coordinates[2 + ((corner >> 1) & 1)],
                                cuboid.coordinates[4 + ((corner >> 2) & 1)]);
        const Eigen::Vector3d q = motion * p;
        for (int axis = 0; axis < 3; ++axis) {
            box[2 * axis] = std::min(box[2 * axis], q[axis]);
            box[2 * axis + 1] = std::max(box[2 * axis + 1], q[axis]);
        }
    }
    return box;
}

/// The lid's bounding box in the configuration, by turning its eight corners about the hinge's edge.
std::array<double, 6> bruteForce(const function::Model& m, double degrees)
{
    return movedBox(m, 1, turning(m, m.joints[0], degrees));
}

void expectPosedBox(const function::Model& m, int c, const std::array<double, 6>& expected)
{
    for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(function::evaluate(m, function::posed(m, Face{c, static_cast<Side>(k)}, 0)), expected[k],
                    1e-9)
            << m.cuboids[c].name << " side " << k;
}

}  // namespace

TEST(Pose, HingedBoundingBoxesAreTheTurnedCornersForAnyAngleAndAxis)
{
    const std::pair<const char*, const char*> edges[] = {
        {"lid.far", "lid.bottom"}, {"lid.left", "lid.bottom"}, {"lid.right", "lid.far"}};  // axes x, y, z
    for (const auto& [edgeA, edgeB] : edges)
        for (double angle : {30.0, 90.0, 120.0, -45.0, 200.0, -170.0}) {
            const function::Model m = io::readWorkslike(hingedLid(edgeA, edgeB, angle));
            const std::array<double, 6> expected = bruteForce(m, angle);
            for (int k = 0; k < 6; ++k)
                EXPECT_NEAR(function::evaluate(m, function::posed(m, Face{1, static_cast<Side>(k)}, 0)),
                            expected[k], 1e-9)
                    << edgeA << "/" << edgeB << " at " << angle << " side " << k;
        }
}

TEST(Pose, PartsWithoutAPosedJointStayPut)
{
    const function::Model m = io::readWorkslike(hingedLid("lid.far", "lid.bottom", 90));
    EXPECT_DOUBLE_EQ(function::evaluate(m, function::posed(m, Face{0, Side::Top}, 0)), 40);
    EXPECT_DOUBLE_EQ(function::evaluate(m, function::posed(m, Face{1, Side::Top}, -1)), 47);
}

TEST(Pose, SlidesMoveAlongTheirAxis)
{
    json d = hingedLid("lid.far", "lid.bottom", 0);
    d["joints"] = {{{"name", "drawer"}, {"type", "slide"}, {"part", "lid"}, {"axis", "y"}}};
    d["configurations"] = {{{"name", "open"}, {"poses", {{"drawer", -45}}}}};
    const function::Model m = io::readWorkslike(d);
    EXPECT_DOUBLE_EQ(function::evaluate(m, function::posed(m, Face{1, Side::Near}, 0)), 10 - 45);
    EXPECT_DOUBLE_EQ(function::evaluate(m, function::posed(m, Face{1, Side::Left}, 0)), 5);
}

TEST(Pose, SlidingHingesTurnAboutTheirEdgeAndSlideAlongTheirAxis)
{
    json d = hingedLid("lid.far", "lid.bottom", 0);
    d["joints"][0]["type"] = "sliding_hinge";
    d["joints"][0]["axis"] = "y";
    for (double angle : {-90.0, 35.0})
        for (double offset : {-40.0, 25.0}) {
            d["configurations"][0]["poses"]["hinge"] = {{"angle", angle}, {"offset", offset}};
            const function::Model m = io::readWorkslike(d);
            expectPosedBox(
                m, 1, movedBox(m, 1, Eigen::Translation3d(0, offset, 0) * turning(m, m.joints[0], angle)));
        }
    d["configurations"][0]["poses"]["hinge"] = 30;
    EXPECT_EQ(testsupport::workslikeError(d), "configurations[0].poses.hinge: must be a JSON object");
}

TEST(Pose, AJointCarriesThePartsHangingOnItsPart)
{
    // A flap hinged on the lid's front edge; the lid hinged on the body's back edge carries it.
    json d = hingedLid("lid.far", "lid.bottom", 0);
    d["parts"].push_back(
        {{"name", "flap"}, {"cuboids", {{{"name", "flap"}, {"min", {5, 0, 40}}, {"max", {95, 10, 47}}}}}});
    d["joints"].push_back({{"name", "flap hinge"},
                           {"type", "hinge"},
                           {"part", "flap"},
                           {"base", "lid"},
                           {"edge", {"flap.far", "flap.top"}}});
    d["configurations"][0]["poses"] = {{"hinge", -90}, {"flap hinge", 90}};
    const function::Model m = io::readWorkslike(d);
    expectPosedBox(m, 2, movedBox(m, 2, turning(m, m.joints[0], -90) * turning(m, m.joints[1], 90)));
    expectPosedBox(m, 1, bruteForce(m, -90));

    d["joints"][0]["base"] = "flap";
    EXPECT_EQ(testsupport::workslikeError(d), "joints[0].base: the joints' bases go round in a circle");
    d["joints"][0].erase("base");
    d["joints"][1]["part"] = "lid";
    EXPECT_EQ(testsupport::workslikeError(d), "joints[1].part: 'lid' is already moved by joint 'hinge'");
    d = hingedLid("lid.far", "lid.bottom", 0);
    d["joints"][0]["type"] = "sliding_hinge";
    d["joints"][0]["axis"] = "w";
    EXPECT_EQ(testsupport::workslikeError(d), "joints[0].axis: must be \"x\", \"y\" or \"z\", got \"w\"");
}

TEST(Pose, RelationshipsHoldInTheirConfigurationAfterTheSolve)
{
    // Opened to -90° about its back-bottom edge the lid stands up behind the body, sticking out by its
    // thickness (7 mm); asking that it stick out at most 3 mm makes the solve thin the lid.
    json d = hingedLid("lid.far", "lid.bottom", -90);
    d["relationships"] = {
        {{"type", "geometric"},
         {"name", "open lid close to the back"},
         {"relation", "at_most"},
         {"configuration", "turned"},
         {"left", "lid.far"},
         {"right", "body.far"},
         {"offset", 3}},
        {{"type", "flush"}, {"name", "lid on the body"}, {"faces", {"lid.bottom", "body.top"}}}};
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_TRUE(r.solved);
    const std::array<double, 6> open = bruteForce(r.model, -90);
    EXPECT_LE(open[3], r.model.cuboids[0].at(Side::Far) + 3 + 1e-6);
    EXPECT_NEAR(r.model.cuboids[1].at(Side::Bottom), r.model.cuboids[0].at(Side::Top), 1e-6);
    EXPECT_LT(r.model.cuboids[1].at(Side::Top) - r.model.cuboids[1].at(Side::Bottom), 7);
}

TEST(Pose, JointAndConfigurationErrorsNameTheField)
{
    EXPECT_EQ(testsupport::workslikeError(hingedLid("lid.top", "lid.bottom", 0)),
              "joints[0].edge: the two faces are parallel, they meet at no edge");
    EXPECT_EQ(testsupport::workslikeError(hingedLid("body.far", "body.top", 0)),
              "joints[0].edge: both faces must belong to one cuboid of part 'lid'");
    json d = hingedLid("lid.far", "lid.bottom", 0);
    d["configurations"][0]["poses"] = {{"latch", 10}};
    EXPECT_EQ(testsupport::workslikeError(d), "configurations[0].poses.latch: no joint named 'latch'");
    d = hingedLid("lid.far", "lid.bottom", 0);
    d["relationships"] = {
        {{"type", "flush"}, {"name", "f"}, {"faces", {"lid.top", "body.top"}}, {"configuration", "shut"}}};
    EXPECT_EQ(testsupport::workslikeError(d),
              "relationships[0].configuration: no configuration named 'shut'");
    d = hingedLid("lid.far", "lid.bottom", 0);
    EXPECT_EQ(io::workslikeToJson(io::readWorkslike(io::workslikeToJson(io::readWorkslike(d)))),
              io::workslikeToJson(io::readWorkslike(d)));
}

TEST(Pose, ModelsSolveCannotFinishAreRefusedByName)
{
    // A 3,000-joint chain took 104 s. A chain of 64 reads; 65, more than 10,000 cuboids, or more
    // than 100,000 cuboids times configurations are refused, each naming where.
    const auto chain = [](int joints) {
        json d = {{"format", "fabguide.workslike"},
                  {"version", 1},
                  {"parts", json::array()},
                  {"joints", json::array()}};
        for (int i = 0; i <= joints; ++i) {
            const std::string name = "p" + std::to_string(i);
            d["parts"].push_back(testsupport::cuboidPart(name, {0, 0, 30.0 * i}, {20, 20, 30.0 * i + 20}));
            if (i > 0)
                d["joints"].push_back({{"name", "j" + std::to_string(i)},
                                       {"type", "slide"},
                                       {"part", name},
                                       {"base", "p" + std::to_string(i - 1)},
                                       {"axis", "x"}});
        }
        return d;
    };
    EXPECT_EQ(testsupport::workslikeError(chain(64)), "");
    EXPECT_EQ(
        testsupport::workslikeError(chain(65)),
        "joints[64].base: more than 64 joints in a chain to the ground; FabGuide solves chains up to that");
    json many = chain(0);
    for (int i = 1; i <= 10000; ++i)
        many["parts"].push_back(
            testsupport::cuboidPart("q" + std::to_string(i), {30.0 * i, 0, 0}, {30.0 * i + 20, 20, 20}));
    EXPECT_EQ(testsupport::workslikeError(many),
              "parts[10000].cuboids: more than 10000 cuboids in the model; FabGuide solves up to that");
    json posed = chain(1);
    for (int i = 2; i < 2000; ++i)
        posed["parts"].push_back(
            testsupport::cuboidPart("q" + std::to_string(i), {30.0 * i, 0, 0}, {30.0 * i + 20, 20, 20}));
    posed["configurations"] = json::array();
    for (int k = 0; k < 51; ++k)
        posed["configurations"].push_back({{"name", "k" + std::to_string(k)}, {"poses", {{"j1", k}}}});
    EXPECT_EQ(testsupport::workslikeError(posed),
              "configurations: 51 configurations of 2000 cuboids; FabGuide solves up "
              "to 100000 cuboids times configurations");
}
