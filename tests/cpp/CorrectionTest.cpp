// Algorithms 5 and 6 (thesis 5.3.5) on a small table: changes kept, constraints held, failures named.
#include "Design/Correction.h"
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace fabguide;
using namespace fabguide::material;

namespace {

/// A table top on two legs on the ground, flush with its ends, a shelf between the legs; `extra` constraints
/// first.
Design table(const nlohmann::json& extra = nlohmann::json::array(),
             const nlohmann::json& inner = nlohmann::json::array())
{
    nlohmann::json doc = {{"format", "fabguide.flatpack"},
                          {"boards", {{{"width", 1220}, {"height", 915}, {"thickness", 12}}}},
                          {"parts",
                           {{{"id", "top"}, {"min", {0, 0, 388}}, {"max", {700, 420, 400}}},
                            {{"id", "left"}, {"min", {0, 0, 0}}, {"max", {12, 420, 388}}},
                            {{"id", "right"}, {"min", {688, 0, 0}}, {"max", {700, 420, 388}}},
                            {{"id", "shelf"}, {"min", {12, 60, 150}}, {"max", {688, 360, 162}}}}},
                          {"constraints", extra},  // the legs stand on the ground (below)
                          {"inner_volumes", inner}};
    doc["constraints"].push_back({{"kind", "ground"}, {"parts", {"left", "right"}}});
    return io::readFlatpack(doc).design;
}

Eigen::VectorXd change(const Design& design, const std::string& board, int axis, double by)
{
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(design.boards.size()));
    for (size_t b = 0; b < design.boards.size(); ++b)
        if (design.boards[b].id == board)
            u[sizeVariable(static_cast<int>(b), axis)] = by;
    return u;
}

double size(const Eigen::VectorXd& X, int board, int axis)
{
    return X[sizeVariable(board, axis)];
}
double centre(const Eigen::VectorXd& X, int board, int axis)
{
    return X[centreVariable(board, axis)];
}

}  // namespace

TEST(CorrectionTest, WideningTheTopMovesALegAndWidensTheShelfAndKeepsTheChange)
{
    const Design design = table();
    const Eigen::VectorXd X = design.variables();
    const Eigen::VectorXd u = change(design, "top", 0, 40);
    const auto d = correctForDesignConstraints(design, {}, X, u);
    ASSERT_TRUE(d);
    const Eigen::VectorXd Y = X + u + *d;
    EXPECT_TRUE(unsatisfied(design, Y, 1e-9).empty());
    EXPECT_EQ((*d)[sizeVariable(0, 0)], 0.0);  // d_i = 0 where u_i != 0
    EXPECT_DOUBLE_EQ(size(Y, 0, 0), 740);
    // The legs stay flush with the top's ends and keep their size: positions move before lengths.
    EXPECT_DOUBLE_EQ(size(Y, 1, 2), 388);
    EXPECT_NEAR((centre(Y, 2, 0) - centre(Y, 1, 0)) - (centre(X, 2, 0) - centre(X, 1, 0)), 40, 1e-9);
    // The shelf snaps to both legs, so it must widen with them.
    EXPECT_NEAR(size(Y, 3, 0), 716, 1e-9);
    // Thicknesses never change.
    for (int b = 0; b < 4; ++b)
        EXPECT_DOUBLE_EQ(size(Y, b, design.boards[b].normal), 12);
}

TEST(CorrectionTest, AContradictoryChangeFailsAndNamesTheConstraint)
{
    const Design design =
        table({{{"kind", "fixed"}, {"ref", "shelf.size.x"}, {"name", "shelf fits the niche"}}});
    std::vector<std::string> broken;
    EXPECT_FALSE(
        correctForDesignConstraints(design, {}, design.variables(), change(design, "top", 0, 40), &broken));
    EXPECT_NE(std::find(broken.begin(), broken.end(), "shelf fits the niche"), broken.end()) << broken.size();
}

TEST(CorrectionTest, ARangeStopsTheChangeWhereItWouldBreak)
{
    const Design design = table({{{"kind", "range"}, {"ref", "top.size.x"}, {"max", 720}}});
    const CorrectedChange c = correctChange(design, design.variables(), change(design, "top", 0, 40));
    EXPECT_NEAR(c.alpha, 0.5, 1e-5);
    EXPECT_NEAR(size(c.X, 0, 0), 720, 1e-3);
    EXPECT_TRUE(ineffective(design, c.X).empty());
    EXPECT_TRUE(unsatisfied(design, c.X, 1e-9).empty());
    EXPECT_EQ(c.limits, std::vector<std::string>{"top.size.x <= 720"});
}

TEST(CorrectionTest, AnInnerVolumeIsKeptFreeByHoldingThePartThatWouldEnterIt)
{
    // Space for magazines on the shelf. Raising the shelf 50 mm pushes the volume into the top: the top is
    // held on the volume and rises with it (the legs grow); with the table height capped, the shelf stops.
    const nlohmann::json magazines = {
        {"name", "magazines"}, {"on", "shelf"}, {"min", {100, 80, 162}}, {"max", {400, 280, 362}}};
    Eigen::VectorXd u = Eigen::VectorXd::Zero(24);
    u[centreVariable(3, 2)] = 50;

    const Design free = table(nlohmann::json::array(), nlohmann::json::array({magazines}));
    const CorrectedChange raised = correctChange(free, free.variables(), u);
    EXPECT_EQ(raised.alpha, 1);
    EXPECT_NEAR(centre(raised.X, 3, 2), 206, 1e-9);
    EXPECT_NEAR(lowerFace(0, 2).value(raised.X), 412, 1e-6);  // the top rests on the volume
    EXPECT_NEAR(size(raised.X, 1, 2), 412, 1e-6);
    EXPECT_TRUE(ineffective(free, raised.X).empty());
    EXPECT_TRUE(unsatisfied(free, raised.X, 1e-9).empty());

    const Design capped =
        table(nlohmann::json::array({{{"kind", "range"}, {"ref", "top.max.z"}, {"max", 400}}}),
              nlohmann::json::array({magazines}));
    const CorrectedChange stopped = correctChange(capped, capped.variables(), u);
    EXPECT_LT(stopped.alpha, 1);
    EXPECT_NEAR(centre(stopped.X, 3, 2), 156 + 26, 1e-3);  // the volume's top at the top's underside
    EXPECT_TRUE(ineffective(capped, stopped.X).empty());
    EXPECT_TRUE(unsatisfied(capped, stopped.X, 1e-9).empty());
    EXPECT_FALSE(stopped.limits.empty());
}

TEST(CorrectionTest, NoBoardShrinksBelowTheMinimumLength)
{
    nlohmann::json doc = {{"format", "fabguide.flatpack"},
                          {"settings", {{"min_length", 100}}},
                          {"boards", {{{"width", 1220}, {"height", 915}, {"thickness", 12}}}},
                          {"parts", {{{"id", "shelf"}, {"min", {0, 0, 0}}, {"max", {300, 250, 12}}}}}};
    const Design design = io::readFlatpack(doc).design;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
    u[sizeVariable(0, 1)] = -200;  // to 50 mm
    const CorrectedChange c = correctChange(design, design.variables(), u);
    EXPECT_NEAR(size(c.X, 0, 1), 100, 1e-3);
    EXPECT_EQ(c.limits, std::vector<std::string>{"shelf.size.y >= 100"});
}

TEST(CorrectionTest, TheFormatNamesWhatItCannotRead)
{
    const auto error = [](const nlohmann::json& extra) {
        try {
            table(extra);
        } catch (const io::FormatError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error({{{"kind", "equal"}, {"refs", {"top.size.x", "leg.size.z"}}}}),
              "constraints[0].refs[1]: no part \"leg\"");
    EXPECT_EQ(
        error({{{"kind", "bend"}}}),
        "constraints[0].kind: unknown constraint \"bend\" (equal, sum, fixed, symmetric, ground, coplanar, "
        "snap, range)");
    EXPECT_EQ(error({{{"kind", "fixed"}, {"ref", "top.size.x"}, {"value", 650}, {"name", "top 650"}}}),
              "the design does not satisfy its own constraints: top 650");
    try {
        table({{{"kind", "fixed"}, {"ref", "top.size.x"}, {"value", 650}, {"name", "top 650"}}});
        ADD_FAILURE() << "no ConstraintError";
    } catch (const io::ConstraintError& e) {
        EXPECT_EQ(e.names, std::vector<std::string>{"top 650"});
    }
    EXPECT_EQ(error({{{"kind", "snap"}, {"parts", {"shelf", "top"}}}}),
              "constraints[0]: shelf and top do not touch");
    try {
        table(nlohmann::json::array(), {{{"on", "shelf"}, {"min", {20, 60, 162}}, {"max", {120, 10, 242}}}});
        ADD_FAILURE() << "a negative inner volume read";
    } catch (const io::FormatError& e) {
        EXPECT_STREQ(e.what(), "inner_volumes[0].max: must exceed min along every axis");
    }
    try {  // the top enters the books' space: the message says by what, `names` the volume's own name
        table(nlohmann::json::array(),
              {{{"name", "books"}, {"on", "shelf"}, {"min", {20, 60, 162}}, {"max", {120, 260, 462}}}});
        ADD_FAILURE() << "no ConstraintError";
    } catch (const io::ConstraintError& e) {
        EXPECT_STREQ(e.what(), "the design does not satisfy its own constraints: books (entered by top)");
        EXPECT_EQ(e.names, std::vector<std::string>{"books"});
    }
}
