// Double pivots (thesis 4.3.6): stage 2 places the pivots so the rigid link keeps its length between the
// modelled pose and each configuration, the four-bar motion ends exactly in the configuration's pose, and
// the parts do not collide on the way; when no placement exists, the joints are named.
#include "Function/DoublePivot.h"
#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include "WorkslikeTestSupport.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

using namespace fabguide;
using nlohmann::json;

namespace {

json crateBed()
{
    return io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) + "/examples/crate-bed.workslike.json");
}

Eigen::Vector2d turned(const Eigen::Vector2d& p, const Eigen::Vector2d& centre, double degrees)
{
    return centre + Eigen::Rotation2Dd(degrees * M_PI / 180) * (p - centre);
}

/// A pivot of the solved file, in the joint's pivot plane (y, z for faces normal to x).
Eigen::Vector2d planar(const json& pivot)
{
    return {pivot[1][1].get<double>(), pivot[1][2].get<double>()};
}

/// How the model's only configuration poses joint j.
const function::JointPose& poseOf(const function::Model& m, int j)
{
    const auto& poses = m.configurations[0].poses;
    return *std::find_if(poses.begin(), poses.end(), [&](const auto& p) { return p.joint == j; });
}

}  // namespace

TEST(DoublePivot, TheLinkKeepsItsLengthAndTheMotionEndsInThePose)
{
    const function::SolveResult r = function::solve(io::readWorkslike(crateBed()));
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    const json solved = io::workslikeToJson(r.model);
    for (size_t j = 0; j < r.model.joints.size(); ++j) {
        const json& joint = solved["joints"][j];
        const json& pose = solved["configurations"][0]["poses"][joint["name"].get<std::string>()];
        const Eigen::Vector2d a = planar(joint["pivot"]), b = planar(joint["base_pivot"]);
        const Eigen::Vector2d pole{pose["pole"][1].get<double>(), pose["pole"][2].get<double>()};
        const double angle = pose["angle"].get<double>();
        EXPECT_NEAR((turned(a, pole, angle) - b).norm(), (a - b).norm(), 1e-6) << joint["name"];
        // The four-bar: turn about the part's pivot, then the link about the base pivot, ends in the pose.
        const auto [link, part] =
            function::linkAngles(r.model, r.model.joints[j], poseOf(r.model, static_cast<int>(j)));
        for (const Eigen::Vector2d& corner : {Eigen::Vector2d{2000, 0}, Eigen::Vector2d{-29, 995}})
            EXPECT_LT((turned(turned(corner, a, part), b, link) - turned(corner, pole, angle)).norm(), 1e-6);
    }
}

TEST(DoublePivot, TheHeadboardClearsTheBedAllTheWay)
{
    const function::SolveResult r = function::solve(io::readWorkslike(crateBed()));
    ASSERT_TRUE(r.solved);
    const function::Joint& joint = r.model.joints[0];  // head pivot left
    const function::PivotPlane plane = function::pivotPlane(r.model, joint);
    const auto [link, part] = function::linkAngles(r.model, joint, poseOf(r.model, 0));
    const auto& head = r.model.cuboids[2].coordinates;  // bed 0, mattress well 1, headboard 2
    const Eigen::Vector2d a{plane.pivot[0], plane.pivot[1]}, b{plane.basePivot[0], plane.basePivot[1]};
    double nearest =
        1e300;  // how far into the bed (y < 2000 and z < 300) any headboard corner goes, at 1000 poses
    for (int step = 0; step <= 1000; ++step)
        for (int corner = 0; corner < 4; ++corner) {
            const Eigen::Vector2d q{head[2 + (corner & 1)], head[4 + (corner >> 1)]};
            const Eigen::Vector2d p = turned(turned(q, a, step / 1000.0 * part), b, step / 1000.0 * link);
            nearest = std::min(nearest, std::max(p.x() - 2000, p.y() - 300));
        }
    EXPECT_GE(nearest, -1e-6) << "a headboard corner entered the bed";
}

TEST(DoublePivot, APlacedLinksWayRoundDoesNotHangOnTheLastDigitOfItsPivots)
{
    // A generated crate (tests/gen seed 1755) whose least-change placement lay where the link turns a
    // thousandth of a degree short of half a turn against its board: as written to the file, its pivots sent
    // it the other way round, through the base. Placed now, both links turn half a turn with the board, and
    // stay so with their pivots a nanometre (the file's last digit) off.
    json model = io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) +
                                  "/tests/gen/regressions/link-half-turn-seed-1755.workslike.json");
    model.erase("generated");
    const function::SolveResult r = function::solve(io::readWorkslike(model));
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    for (size_t j = 0; j < r.model.joints.size(); ++j) {
        const function::JointPose& pose = poseOf(r.model, static_cast<int>(j));
        function::Joint joint = r.model.joints[j];
        EXPECT_EQ(function::linkAngles(r.model, joint, pose)[0], 180) << joint.name;
        for (double off : {-1e-6, 1e-6}) {
            joint.basePivot[1] = r.model.joints[j].basePivot[1] + off;
            EXPECT_GT(function::linkAngles(r.model, joint, pose)[0], 0) << joint.name;
        }
    }
}

TEST(DoublePivot, APoseTheLinkCannotReachNamesTheJoints)
{
    // Base pivots on the line through the pole: the link must turn with the board, which sweeps the bed.
    json d = crateBed();
    for (json& joint : d["joints"])
        joint["base_pivot"][1][2] = 150;
    const function::SolveResult r = function::solve(io::readWorkslike(d));
    ASSERT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{"head pivot left", "head pivot right", "foot pivot left",
                                                    "foot pivot right"}));
    for (const function::Conflict& c : r.conflicts)
        EXPECT_EQ(c.kind, function::ConflictKind::Joint) << c.name;
    EXPECT_EQ(r.conflicts.size(), r.conflict.size());
}

TEST(DoublePivot, ErrorsNameTheField)
{
    json d = crateBed();
    d["joints"][0].erase("base");
    EXPECT_EQ(testsupport::workslikeError(d), "joints[0].base: a double pivot links its part to a base part");
    d = crateBed();
    d["joints"][0]["pivot"][1] = {0, 2015, 5000};
    EXPECT_EQ(testsupport::workslikeError(d), "joints[0].pivot[1]: the point lies off headboard.left");
    d = crateBed();
    d["joints"][0]["base_pivot"] = {"bed.top", {0, 1850, 300}};
    EXPECT_EQ(testsupport::workslikeError(d),
              "joints[0].base_pivot: the pivots' faces must be parallel (coplanar)");
    d = crateBed();
    d["configurations"][0]["poses"]["head pivot right"]["angle"] = 80;
    EXPECT_EQ(testsupport::workslikeError(d),
              "configurations[0].poses: 'head pivot left' and 'head pivot right' move one part and must be "
              "posed alike");
}

TEST(DoublePivot, ItsBaseMustStandStillWhereItIsPosed)
{
    json d = crateBed();
    d["parts"].push_back(
        {{"name", "floor"},
         {"cuboids", {{{"name", "floor"}, {"min", {0, 0, -20}}, {"max", {1000, 2000, 0}}}}}});
    d["joints"].push_back({{"name", "castor"}, {"type", "slide"}, {"part", "bed"}, {"axis", "y"}});
    d["configurations"][0]["poses"]["castor"] = 100;
    EXPECT_EQ(testsupport::workslikeError(d),
              "configurations[0].poses: 'foot pivot left' needs its base 'bed' to stand still, but 'castor' "
              "moves it");
}

TEST(FourBar, TwoLinksOfOnePartMoveAsOneLinkageAndStayOnTheirBranch)
{
    const std::string data = std::string(FABGUIDE_SOURCE_DIR) + "/tests/data/workslike/";
    // Posed where the four-bar arrives when its front link turns 40°: placed as modelled.
    function::Model same = io::readWorkslike(io::readJsonFile(data + "fold-down-table.workslike.json"));
    EXPECT_TRUE(function::placePivots(same).empty());
    // Posed where it could be assembled only on its other branch: it cannot get there without coming apart.
    function::Model other =
        io::readWorkslike(io::readJsonFile(data + "contradictory/four-bar-other-branch.workslike.json"));
    const std::vector<function::Unplaced> unplaced = function::placePivots(other);
    ASSERT_EQ(unplaced.size(), 1u);
    EXPECT_EQ(unplaced[0].joint, "front link");
    EXPECT_NE(
        unplaced[0].reason.find("the four-bar of 'front link' and 'back link' reaches 'folded' only on its "
                                "other assembly branch"),
        std::string::npos)
        << unplaced[0].reason;
}

TEST(FourBar, LinksThatWouldRunOverEachOthersPinsAreRefused)
{
    // A bedside lamp's arm posed as turned about its corner at the column's top: every place of a link's base
    // pivot along the column is near that corner, and the two links lie one along the other (before: solved,
    // then printed with the links through each other).
    function::Model lamp = io::readWorkslike(io::readJsonFile(
        std::string(FABGUIDE_SOURCE_DIR) +
        "/tests/data/workslike/contradictory/lamp-arm-turned-about-the-column-top.workslike.json"));
    const std::vector<function::Unplaced> unplaced = function::placePivots(lamp);
    ASSERT_EQ(unplaced.size(), 1u);
    EXPECT_EQ(unplaced[0].joint, "lower link");
    EXPECT_NE(unplaced[0].reason.find("has a link over the other's pin"), std::string::npos)
        << unplaced[0].reason;
    EXPECT_NE(unplaced[0].reason.find("wherever its pivots sit along their faces"), std::string::npos);
}

TEST(FourBar, LinksOnOppositeFacesMoveAsOneLinkageUnlessTheyDoubleOneLink)
{
    // A table's leaf carried by a link on its left and another on its right, elsewhere in the plane: one
    // four-bar (before: two lone links that moved the leaf two ways, and the print collided).
    const std::string data = std::string(FABGUIDE_SOURCE_DIR) + "/tests/data/printable/";
    function::Model table = io::readWorkslike(io::readJsonFile(data + "folding-table-leaf.workslike.json"));
    ASSERT_EQ(function::fourBarPartner(table, table.joints[0]), &table.joints[1]);
    EXPECT_TRUE(function::placePivots(table).empty());
    // Both links on the left, as first drawn: the lower one runs over the upper one's pin.
    function::Model drawn =
        io::readWorkslike(io::readJsonFile(data + "refused/folding-table-leaf-as-drawn.workslike.json"));
    const std::vector<function::Unplaced> unplaced = function::placePivots(drawn);
    ASSERT_EQ(unplaced.size(), 1u);
    EXPECT_NE(unplaced[0].reason.find("has a link over the other's pin"), std::string::npos)
        << unplaced[0].reason;
    // A bed's head carried by one link on each side, the right one drawn 3 mm off: one link doubled, placed
    // where its left half goes, not a four-bar.
    json d = crateBed();
    d["joints"][1]["pivot"][1][1] = d["joints"][1]["pivot"][1][1].get<double>() - 3;
    function::Model bed = io::readWorkslike(d);
    EXPECT_EQ(function::fourBarPartner(bed, bed.joints[0]), nullptr);
    ASSERT_TRUE(function::placePivots(bed).empty());
    const function::PivotPlane left = function::pivotPlane(bed, bed.joints[0]),
                               right = function::pivotPlane(bed, bed.joints[1]);
    EXPECT_EQ(left.pivot, right.pivot);
    EXPECT_EQ(left.basePivot, right.basePivot);
}
