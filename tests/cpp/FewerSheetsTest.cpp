// Saving a sheet: the least design's linear programme on a suite bookcase, and FEWERSHEETS on a
// suite TV bench that needs two sheets as drawn and one when its boards are a little smaller.
#include "Design/FewerSheets.h"
#include "Design/LeastDesign.h"
#include "Design/MinWastage.h"
#include "IO/FlatpackFormat.h"
#include "IO/Json.h"
#include "Layout/LowerBound.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

using namespace fabguide;
using namespace fabguide::material;

namespace {

io::FlatpackDesign suiteDesign(const std::string& name)
{
    return io::readFlatpack(io::readJsonFile(std::string(FABGUIDE_SOURCE_DIR) + "/tests/data/flatpack/" +
                                             name + ".flatpack.json"));
}

double area(const DesignSpace& design, const Eigen::VectorXd& X)
{
    const Eigen::VectorXd s = design.sizes(X);
    double a = 0;
    for (int i = 0; i < s.size(); i += 2)
        a += design.parts()[i / 2].quantity * s[i] * s[i + 1];
    return a;
}

/// X keeps every design and effectiveness constraint of `design`.
void expectValid(const Design& design, const Eigen::VectorXd& X)
{
    EXPECT_TRUE(unsatisfied(design, X).empty()) << unsatisfied(design, X).front();
    EXPECT_TRUE(ineffective(design, X).empty()) << ineffective(design, X).front().said();
}

}  // namespace

TEST(LeastDesignTest, ShrinksEveryPartToWhatItsConstraintsAllow)
{
    const io::FlatpackDesign f = suiteDesign("bookcase-1800");
    const Eigen::VectorXd X = f.design.variables();
    const auto least = leastDesign(f.design, X);
    ASSERT_TRUE(least);
    expectValid(f.design, *least);
    const ConstrainedDesign design(f.design);
    EXPECT_LT(area(design, *least), 0.95 * area(design, X));
    // The top narrower, but not below what the binders on the bottom (800 mm wide) leave; thicknesses stay.
    EXPECT_LT((*least)[sizeVariable(2, 0)], 864 - 1);
    EXPECT_GE((*least)[sizeVariable(2, 0)], 800);
    // The bottom and shelf 1 stay under the binders they hold (265 mm deep), and shelves 2-4 with
    // them, their depths equal; the sides may go from 300 to 280 mm deep.
    for (int b : {3, 5, 6, 7, 8})
        EXPECT_GE((*least)[sizeVariable(b, 1)], 265 - 1e-6) << f.design.boards[b].id;
    EXPECT_LT((*least)[sizeVariable(0, 1)], 300 - 1);
    for (size_t b = 0; b < f.design.boards.size(); ++b) {
        const int normal = f.design.boards[b].normal;
        EXPECT_EQ((*least)[sizeVariable(static_cast<int>(b), normal)],
                  X[sizeVariable(static_cast<int>(b), normal)]);
    }
    // Every design on the way is valid too (linear constraints; boards stay on their side of inner volumes).
    for (double t : {0.25, 0.5, 0.75})
        EXPECT_TRUE(design.between(X, *least, t)) << t;
}

TEST(LeastDesignTest, ShortestSidesBoundEveryDesignWhereSidesAreTied)
{
    // Two boards side by side whose widths add up to a third's fixed 1000 mm, each at least 100: the least
    // design takes one split of the 1000, the bound must take 100 for each (no design has either narrower).
    const io::FlatpackDesign f = io::readFlatpack(nlohmann::json::parse(R"({
        "format": "fabguide.flatpack", "version": 2,
        "boards": [{"width": 2440, "height": 1220, "thickness": 18}],
        "settings": {"min_length": 100},
        "parts": [{"id": "a", "min": [0, 0, 0], "max": [400, 300, 18]},
                  {"id": "b", "min": [400, 0, 0], "max": [1000, 300, 18]},
                  {"id": "c", "min": [0, 400, 0], "max": [1000, 700, 18]}],
        "constraints": [{"kind": "sum", "lhs": ["a.size.x", "b.size.x"], "rhs": ["c.size.x"]},
                        {"kind": "fixed", "ref": "c.size.x"}]})"));
    const ConstrainedDesign design(f.design);
    const Eigen::VectorXd X = design.start();
    const auto least = design.least(X, std::chrono::steady_clock::time_point::max());
    const auto shortest = design.shortestSides(X);
    ASSERT_TRUE(least && shortest);
    const Eigen::VectorXd leastSizes = design.sizes(*least);
    EXPECT_NEAR(leastSizes[0] + leastSizes[2], 1000, 1e-6);  // a's and b's widths (material-space x)
    EXPECT_NEAR((*shortest)[0], 100, 2e-3);
    EXPECT_NEAR((*shortest)[2], 100, 2e-3);
    EXPECT_NEAR((*shortest)[4], 1000, 2e-3);  // c's, fixed
    for (int side : {1, 3, 5})                // the depths, untied, shrink to the minimum alike
        EXPECT_NEAR((*shortest)[side], 100, 2e-3);
}

TEST(LeastDesignTest, ShortestSidesAreNoLongerThanAnyDesignOnTheWayToTheLeast)
{
    // An independent check of the bound on suite designs: every side of every design between the user's
    // and the least one (all valid), and of some of CHANGEPARTSIZES' steps from it, is at least the bound's.
    for (const char* name :
         {"cube-unit-3x3", "kitchen-run", "wardrobe", "bookcase-1800", "sideboard-18-6mm"}) {
        const io::FlatpackDesign f = suiteDesign(name);
        const ConstrainedDesign design(f.design);
        const Eigen::VectorXd X = design.start();
        const auto least = design.least(X, std::chrono::steady_clock::time_point::max());
        const auto shortest = design.shortestSides(X);
        ASSERT_TRUE(least && shortest) << name;
        std::vector<Eigen::VectorXd> designs = {X, *least};
        for (double t : {0.25, 0.5, 0.75})
            if (const auto d = design.between(X, *least, t))
                designs.push_back(*d);
        for (int size = 0; size < shortest->size(); size += 29) {
            Eigen::VectorXd change = Eigen::VectorXd::Zero(shortest->size());
            change[size] = -0.5 * design.sizes(X)[size];
            if (const auto d = design.changePartSizes(X, change))
                designs.push_back(*d);
        }
        for (const Eigen::VectorXd& d : designs) {
            const Eigen::VectorXd sizes = design.sizes(d);
            for (int side = 0; side < sizes.size(); ++side)
                EXPECT_GE(sizes[side], (*shortest)[side]) << name << " side " << side;
        }
        // Where nothing ties the sides apart from their boxes the bound is the least design itself: these
        // suite designs need as many sheets by the bound as by the least design's area.
        const MaterialSpace material(f.boards, f.settings, design.parts());
        EXPECT_EQ(sheetsByArea(material.problem(*shortest)),
                  sheetsByArea(material.problem(design.sizes(*least))))
            << name;
    }
}

namespace {

/// A suite design laid out as the user drew it, and what FEWERSHEETS makes of it in 5 s.
struct Saving {
    explicit Saving(const std::string& name)
        : f(suiteDesign(name)),
          design(f.design),
          material(f.boards, f.settings, design.parts()),
          start(layOut(design, material, 1)),
          saved(fewerSheets(design, material, start, 1,
                            std::chrono::steady_clock::now() + std::chrono::seconds(5)))
    {
    }
    io::FlatpackDesign f;
    ConstrainedDesign design;
    MaterialSpace material;
    DesignLayout start;
    SavedSheets saved;
};

}  // namespace

TEST(FewerSheetsTest, FindsTheLeastShrinkThatSavesASheet)
{
    const Saving s("tv-bench");
    const io::FlatpackDesign& f = s.f;
    const ConstrainedDesign& design = s.design;
    const DesignLayout& start = s.start;
    ASSERT_EQ(start.figures.sheets, 2);
    const std::vector<DesignLayout>& found = s.saved.designs;
    ASSERT_EQ(found.size(), 1u);
    const DesignLayout& saved = found.front();
    EXPECT_EQ(saved.figures.sheets, 1);
    EXPECT_TRUE(saved.layout.unplaced.empty());
    expectValid(f.design, saved.X);
    // Nearer the design than the least one: some part keeps more than its least size.
    const Eigen::VectorXd least = *design.least(start.X, std::chrono::steady_clock::time_point::max());
    EXPECT_GT(area(design, saved.X), area(design, least) + 1e4);
    EXPECT_LT(area(design, saved.X), area(design, start.X));
}

TEST(FewerSheetsTest, FindsNothingWhereTheLeastDesignNeedsAsManySheets)
{
    // The cube unit's boards are held by equal lengths and a fixed outer size: shrunk they still need two.
    const Saving s("cube-unit-3x3");
    ASSERT_EQ(s.start.figures.sheets, 2);
    EXPECT_TRUE(s.saved.designs.empty());
    ASSERT_TRUE(s.saved.least);
    EXPECT_EQ(s.saved.least->figures.sheets, 2);
}

TEST(FewerSheetsTest, ParametricDesignsShrinkThroughChangePartSizes)
{
    // Two 1000 x h panels, h in [300, 700] from 500: two sheets of 1000 x 600 as designed, one at h <= 294.
    const ParametricDesign design(
        {{"panel", 2}},
        [](const Eigen::VectorXd& x) {
            Eigen::VectorXd s(2);
            s << 1000, x[0];
            return s;
        },
        Eigen::VectorXd::Constant(1, 500), Eigen::VectorXd::Constant(1, 250),
        Eigen::VectorXd::Constant(1, 700));
    const MaterialSpace material({{"mdf", "mdf", 1000, 600, 12, 3}}, {1.0, 0, 0, 0}, design.parts());
    const DesignLayout start = layOut(design, material, 1);
    ASSERT_EQ(start.figures.sheets, 2);
    const auto found =
        fewerSheets(design, material, start, 1, std::chrono::steady_clock::now() + std::chrono::seconds(5))
            .designs;
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found.front().figures.sheets, 1);
    EXPECT_LE(found.front().X[0], 300);
    EXPECT_GE(found.front().X[0], 250);
}

TEST(ParametricDesignTest, ShortestSidesAreEachSidesLeastOverTheParameterBoxWhereSidesAreAffine)
{
    // A shelf of width w = a + b and depth 400 - a (a in [100, 300], b in [200, 500]): its least width is
    // 300, its least depth 100, at different corners. A side that is not affine (a²) gives no bound.
    const auto shelf = [](bool affine) {
        return ParametricDesign(
            {{"shelf", 1}},
            [affine](const Eigen::VectorXd& x) {
                Eigen::VectorXd s(2);
                s << x[0] + x[1], affine ? 400 - x[0] : x[0] * x[0] / 100;
                return s;
            },
            Eigen::Vector2d(200, 300), Eigen::Vector2d(100, 200), Eigen::Vector2d(300, 500));
    };
    const auto shortest = shelf(true).shortestSides(Eigen::Vector2d(200, 300));
    ASSERT_TRUE(shortest);
    EXPECT_NEAR((*shortest)[0], 300, 2e-3);
    EXPECT_NEAR((*shortest)[1], 100, 2e-3);
    EXPECT_LE((*shortest)[0], 300);
    EXPECT_FALSE(shelf(false).shortestSides(Eigen::Vector2d(200, 300)));
}
