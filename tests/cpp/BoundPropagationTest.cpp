#include "Function/BoundPropagation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace fabguide;
using namespace fabguide::function;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(BoundPropagation, CarriesBoundsAlongAChainAndASum)
{
    // x0 >= 100, x1 = x0 + 50, x0 + x1 + x2 = 1000, x2 >= 0: x1 >= 150, x2 <= 750. Boxes alone give x0 <= 850
    // (1000 - 150 - 0); that the chain makes it 475 takes a linear programme.
    const std::vector<LinearConstraint> rows = {{{{0, 1.0}}, 100, kInf, ""},
                                                {{{1, 1.0}, {0, -1.0}}, 50, 50, ""},
                                                {{{0, 1.0}, {1, 1.0}, {2, 1.0}}, 1000, 1000, ""},
                                                {{{2, 1.0}}, 0, kInf, ""}};
    const std::vector<Interval> x = propagatedBounds(rows, 4);
    EXPECT_DOUBLE_EQ(x[0].lower, 100);
    EXPECT_DOUBLE_EQ(x[1].lower, 150);
    EXPECT_DOUBLE_EQ(x[2].upper, 750);
    EXPECT_DOUBLE_EQ(x[0].upper, 850);
    EXPECT_DOUBLE_EQ(x[1].upper, 900);
    EXPECT_TRUE(std::isinf(x[3].lower) && std::isinf(x[3].upper));  // in no row: the whole line
}

TEST(BoundPropagation, ANegativeCoefficientTurnsTheBoundAndAVariableTwiceInARowStaysValid)
{
    // -2 x0 <= -10 (x0 >= 5); x1 - x1 + x0 <= 7 names x1 twice, free: its two unbounded terms hide x0 <= 7
    // (a weaker bound, never a wrong one), and x1 stays free.
    const std::vector<LinearConstraint> rows = {{{{0, -2.0}}, -kInf, -10, ""},
                                                {{{1, 1.0}, {1, -1.0}, {0, 1.0}}, -kInf, 7, ""}};
    const std::vector<Interval> x = propagatedBounds(rows, 2);
    EXPECT_DOUBLE_EQ(x[0].lower, 5);
    EXPECT_GE(x[0].upper, 7);
    EXPECT_TRUE(std::isinf(x[1].lower) && std::isinf(x[1].upper));
}

TEST(BoundPropagation, RowsThatCannotHoldLeaveAnEmptyIntervalAndSweepsAreBounded)
{
    // x0 >= x1 + 1 and x1 >= x0 + 1 with x0 in [0, 10]: each sweep narrows a little, forever without a cap.
    const std::vector<LinearConstraint> rows = {
        {{{0, 1.0}}, 0, 10, ""}, {{{0, 1.0}, {1, -1.0}}, 1, kInf, ""}, {{{1, 1.0}, {0, -1.0}}, 1, kInf, ""}};
    const std::vector<Interval> x = propagatedBounds(rows, 2, 50);
    EXPECT_GT(x[0].lower, x[0].upper);
}
