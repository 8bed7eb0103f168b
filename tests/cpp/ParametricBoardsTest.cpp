// Parametric designs of boards: sides to material sizes along the grain, the thickness from the
// thinnest side, a grain through the thickness refused by name.
#include "Design/DesignSpace.h"

#include <gtest/gtest.h>

using namespace fabguide::material;

namespace {

/// A side (x: length L, y: height H, z: 12 mm) and a 6 mm bottom (L x L), parameters (L, H).
Eigen::VectorXd sides(const Eigen::VectorXd& X)
{
    Eigen::VectorXd s(6);
    s << X[0], X[1], 12, X[0], X[0], 6;
    return s;
}

ParametricDesign box(std::vector<int> grainAxes)
{
    return parametricBoards({{"side"}, {"bottom", 2}}, grainAxes, sides, Eigen::Vector2d(300, 170),
                            Eigen::Vector2d(200, 100), Eigen::Vector2d(400, 300));
}

}  // namespace

TEST(ParametricBoards, WidthRunsAlongTheGrainAndTheThinnestSideIsTheThickness)
{
    const ParametricDesign design = box({1, -1});
    EXPECT_EQ(design.sizes(Eigen::Vector2d(320, 150)), (Eigen::VectorXd(4) << 150, 320, 320, 320).finished());
    ASSERT_EQ(design.parts().size(), 2u);
    EXPECT_TRUE(design.parts()[0].followsGrain);
    EXPECT_EQ(design.parts()[0].thickness, 12);
    EXPECT_FALSE(design.parts()[1].followsGrain);
    EXPECT_EQ(design.parts()[1].thickness, 6);
    EXPECT_EQ(design.parts()[1].quantity, 2);
}

TEST(ParametricBoards, WithoutGrainTheFirstLongSideIsTheWidth)
{
    EXPECT_EQ(box({-1, -1}).sizes(Eigen::Vector2d(320, 150)),
              (Eigen::VectorXd(4) << 320, 150, 320, 320).finished());
}

TEST(ParametricBoards, AGrainThroughTheThicknessIsRefusedByName)
{
    try {
        box({2, -1});
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("part 'side'"), std::string::npos) << e.what();
    }
}
