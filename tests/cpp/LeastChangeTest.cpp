#include "Function/LeastChange.h"

#include <gtest/gtest.h>

#include <limits>

using namespace fabguide::function;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

LinearConstraint equal(std::vector<std::pair<int, double>> terms, double value, std::string source)
{
    return {std::move(terms), value, value, std::move(source)};
}
LinearConstraint atMost(std::vector<std::pair<int, double>> terms, double value, std::string source)
{
    return {std::move(terms), -kInf, value, std::move(source)};
}
}  // namespace

TEST(LeastChange, NothingToSatisfyKeepsTheDesign)
{
    const Eigen::VectorXd target = Eigen::Vector3d(1, 2, 3);
    const LeastChangeResult r = solveLeastChange(target, {});
    ASSERT_TRUE(r.solved);
    EXPECT_NEAR((r.x - target).norm(), 0, 1e-9);
}

TEST(LeastChange, AnEqualityIsMetByTheNearestPoint)
{
    // x0 + x1 = 10 from (0, 0): the projection is (5, 5).
    const LeastChangeResult r = solveLeastChange(Eigen::Vector2d(0, 0), {equal({{0, 1}, {1, 1}}, 10, "sum")});
    ASSERT_TRUE(r.solved);
    EXPECT_NEAR(r.x[0], 5, 1e-6);
    EXPECT_NEAR(r.x[1], 5, 1e-6);
    EXPECT_LE(r.violation, 1e-6);
}

TEST(LeastChange, InactiveInequalitiesChangeNothingActiveOnesBind)
{
    const Eigen::VectorXd target = Eigen::Vector2d(3, 8);
    const LeastChangeResult loose = solveLeastChange(target, {atMost({{0, 1}}, 5, "x0 at most 5")});
    EXPECT_NEAR((loose.x - target).norm(), 0, 1e-6);
    const LeastChangeResult tight =
        solveLeastChange(target, {atMost({{1, 1}, {0, -1}}, 1, "x1 - x0 at most 1")});
    ASSERT_TRUE(tight.solved);
    EXPECT_NEAR(tight.x[0], 5, 1e-6);  // (3, 8) projected onto x1 - x0 = 1
    EXPECT_NEAR(tight.x[1], 6, 1e-6);
}

TEST(LeastChange, AWarmStartGivesTheSameAnswer)
{
    const std::vector<LinearConstraint> rows{equal({{0, 1}, {1, -1}}, 2, "gap"),
                                             atMost({{2, 1}}, -1, "bound")};
    const Eigen::VectorXd target = Eigen::Vector3d(1, 1, 1);
    const LeastChangeResult cold = solveLeastChange(target, rows);
    const LeastChangeResult warm = solveLeastChange(target, rows, &cold.x);
    ASSERT_TRUE(cold.solved && warm.solved);
    EXPECT_NEAR((cold.x - warm.x).norm(), 0, 1e-6);
}

TEST(LeastChange, ConflictsAreNamedMinimally)
{
    const std::vector<LinearConstraint> rows{
        equal({{0, 1}}, 1, "lid height 1"), equal({{1, 1}}, 3, "unrelated"),
        equal({{0, 1}}, 2, "lid height 2"), atMost({{1, 1}}, 10, "roomy"),
        {{{0, 1}}, 0.5, kInf, ""},  // a minimum size: kept, never blamed
    };
    const LeastChangeResult r = solveLeastChange(Eigen::Vector2d(0, 0), rows);
    EXPECT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{"lid height 1", "lid height 2"}));
}

TEST(LeastChange, AConflictWithAMinimumSizeBlamesTheRelationship)
{
    const std::vector<LinearConstraint> rows{{{{0, 1}}, 1, kInf, ""}, atMost({{0, 1}}, 0.5, "too small")};
    const LeastChangeResult r = solveLeastChange(Eigen::VectorXd::Zero(1), rows);
    EXPECT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{"too small"}));
}

TEST(LeastOf, FindsEachVariablesLeastWherePropagationCannot)
{
    // x0 >= -100, x0 + x1 >= 10 and x0 >= x1: x0 is at least 5, though no row bounds it so alone; x1 is
    // unbounded below (no programme asked). x2 = 3 is fixed by its box; x3 and x4 are tied apart from the
    // others (x3 - x4 = 1, x4 >= 2).
    const std::vector<LinearConstraint> rows = {
        {{{0, 1.0}}, -100, kInf, "box"},       {{{0, 1.0}, {1, 1.0}}, 10, kInf, "a"},
        {{{0, 1.0}, {1, -1.0}}, 0, kInf, "b"}, equal({{2, 1.0}}, 3, "c"),
        equal({{3, 1.0}, {4, -1.0}}, 1, "d"),  {{{4, 1.0}}, 2, kInf, "e"}};
    const auto least = leastOf({0, 1, 2, 3}, rows, 5);
    ASSERT_TRUE(least);
    EXPECT_NEAR((*least)[0], 5, 2e-3);
    EXPECT_LE((*least)[0], 5);  // a bound: never above the least
    EXPECT_TRUE(std::isinf((*least)[1]) && (*least)[1] < 0);
    EXPECT_DOUBLE_EQ((*least)[2], 3);
    EXPECT_NEAR((*least)[3], 3, 2e-3);
}

TEST(LeastOf, RowsThatCannotHoldGiveNoBound)
{
    EXPECT_FALSE(leastOf({0}, {{{{0, 1.0}}, 5, kInf, "a"}, atMost({{0, 1.0}}, 4, "b")}, 1));
}
