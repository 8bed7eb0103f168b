// The thesis' works-like examples (Table 4.1) as fixtures in examples/*.workslike.json: each solves with
// every relationship holding, re-solves to itself, comes back near its solution when perturbed, and
// propagates a locked edit to the parts that depend on it.
#include "Function/Solve.h"
#include "IO/Json.h"
#include "IO/WorkslikeFormat.h"

#include <gtest/gtest.h>

#include <random>

using namespace fabguide;
using function::Side;

namespace {

function::Model example(const std::string& name)
{
    return io::readWorkslike(io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) + "/examples/" + name));
}

Eigen::VectorXd coordinates(const function::Model& m)
{
    Eigen::VectorXd x(6 * m.cuboids.size());
    for (size_t c = 0; c < m.cuboids.size(); ++c)
        for (int k = 0; k < 6; ++k)
            x[6 * c + k] = m.cuboids[c].coordinates[k];
    return x;
}

double at(const function::Model& m, const std::string& cuboid, Side side)
{
    for (const function::Cuboid& c : m.cuboids)
        if (c.name == cuboid)
            return c.at(side);
    throw std::invalid_argument(cuboid);
}

class Fixture : public testing::TestWithParam<const char*> {};

}  // namespace

TEST_P(Fixture, SolvesWithEveryRelationshipHolding)
{
    const function::Model model = example(GetParam());
    const function::SolveResult r = function::solve(model);
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    EXPECT_LE(function::violation(coordinates(r.model), function::constraints(r.model)), 1e-6);
}

TEST_P(Fixture, ReSolvingASolvedDesignChangesNothing)
{
    const function::SolveResult first = function::solve(example(GetParam()));
    ASSERT_TRUE(first.solved);
    const function::SolveResult again = function::solve(first.model);
    ASSERT_TRUE(again.solved);
    EXPECT_EQ(coordinates(again.model), coordinates(first.model));
}

TEST_P(Fixture, APerturbedGoodDesignComesBackNearIt)
{
    const function::SolveResult good = function::solve(example(GetParam()));
    ASSERT_TRUE(good.solved);
    function::Model perturbed = good.model;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> nudge(-2, 2);
    for (function::Cuboid& c : perturbed.cuboids)
        for (double& x : c.coordinates)
            x += nudge(random);
    perturbed.locks.clear();  // the locked coordinates moved too
    const function::SolveResult back = function::solve(perturbed);
    ASSERT_TRUE(back.solved);
    EXPECT_LE(function::violation(coordinates(back.model), function::constraints(back.model)), 1e-6);
    // Within the perturbation of where it was, coordinate by coordinate.
    EXPECT_LE((coordinates(back.model) - coordinates(good.model)).lpNorm<Eigen::Infinity>(), 4.0);
}

INSTANTIATE_TEST_SUITE_P(Table41, Fixture, testing::Values("cabinet.workslike.json"), [](const auto& info) {
    std::string name = info.param;
    return name.substr(0, name.find('.'));
});

TEST(Cabinet, WideningTheUpperCompartmentWidensBothDoorsEqually)
{
    function::Model model = function::solve(example("cabinet.workslike.json")).model;
    for (function::Cuboid& c : model.cuboids)
        if (c.name == "upper compartment")
            c.coordinates[static_cast<int>(Side::Right)] += 40;  // the user's edit, locked in the file
    const function::SolveResult r = function::solve(model);
    ASSERT_TRUE(r.solved) << testing::PrintToString(r.conflict);
    EXPECT_NEAR(at(r.model, "right door", Side::Right), 622, 1e-6);
    EXPECT_NEAR(at(r.model, "left door", Side::Right), 320, 1e-6);  // symmetric: 302 each
    EXPECT_NEAR(at(r.model, "right door", Side::Left), 320, 1e-6);
    EXPECT_NEAR(at(r.model, "carcass", Side::Right), 622, 1e-6);  // the carcass grows to hold it
}

TEST(Cabinet, DoorsTooWideToStowAreAConflictNamingWhy)
{
    function::Model model = example("cabinet.workslike.json");
    model.locks.push_back({function::Face{0, Side::Near}});  // the carcass no deeper than 400 …
    model.locks.push_back({function::Face{0, Side::Far}});
    for (function::Cuboid& c : model.cuboids)
        if (c.name == "upper compartment")  // … and the compartment 800 wide: 400 mm doors cannot turn in
            c.coordinates[static_cast<int>(Side::Right)] = 818;
    const function::SolveResult r = function::solve(model);
    ASSERT_FALSE(r.solved);
    EXPECT_EQ(r.conflict, (std::vector<std::string>{
                              "doors stow in the upper compartment", "doors cover the upper compartment",
                              "lock: upper compartment.left", "lock: upper compartment.right",
                              "lock: carcass.near", "lock: carcass.far"}))
        << "symmetry is not needed: 800 mm of doors have one at least 400 wide";
}
