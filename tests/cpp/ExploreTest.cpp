// The exploration use case (App/Api/Explore.h) on the bundled coffee table: the search the CLI and the
// binding both run is MINWASTAGE on the design as read and held to its growth limit, and the drawn-equal
// constraints it is asked to keep hold in every suggestion file it gives.
#include "Api/Explore.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace fabguide;

namespace {

api::Exploring coffeeTable()
{
    std::ifstream in(std::string(FABGUIDE_SOURCE_DIR) + "/examples/coffee-table.flatpack.json");
    api::Exploring job{nlohmann::json::parse(in), {}, false};
    job.options.rounds = 1;
    job.options.tasksPerRound = 2;
    job.options.threads = 1;
    job.options.seed = 3;
    job.options.timeLimit = 600;  // bounded by the rounds and tasks
    return job;
}

std::vector<std::string> constraintNames(const nlohmann::json& document)
{
    std::vector<std::string> names;
    for (const nlohmann::json& c : document.value("constraints", nlohmann::json::array()))
        names.push_back(c.value("name", ""));
    return names;
}

}  // namespace

TEST(ExploreTest, TheExplorationIsMinWastageOnTheDesignAsReadAndHeldToItsGrowthLimit)
{
    const api::Exploring job = coffeeTable();
    const api::ExplorationReport report = api::explore(job);
    const io::FlatpackDesign f = io::readFlatpack(job.document);
    const material::ConstrainedDesign design(io::forSuggestions(f));
    const material::MaterialSpace material(f.boards, f.settings, design.parts());
    material::MinWastageOptions options = job.options;
    options.kept = f.kept;
    const material::Exploration direct = material::minWastage(design, material, options);

    EXPECT_TRUE(report.keptEqual.empty());
    EXPECT_EQ(report.document, job.document);
    EXPECT_EQ(report.exploration.start.X, direct.start.X);
    ASSERT_EQ(report.exploration.suggestions.size(), direct.suggestions.size());
    ASSERT_FALSE(direct.suggestions.empty());
    for (size_t k = 0; k < direct.suggestions.size(); ++k)
        EXPECT_EQ(report.exploration.suggestions[k].result.X, direct.suggestions[k].result.X);
}

TEST(ExploreTest, BoardsDrawnEqualAreKeptEqualInEverySuggestionFile)
{
    api::Exploring job = coffeeTable();
    job.keepDrawnEqual = true;
    const api::ExplorationReport report = api::explore(job);
    ASSERT_FALSE(report.keptEqual.empty());
    const std::vector<std::string> names = constraintNames(report.document);
    ASSERT_FALSE(report.exploration.suggestions.empty());
    for (const material::Suggestion& s : report.exploration.suggestions) {
        const nlohmann::json file = report.suggestionDocument(s);
        EXPECT_EQ(constraintNames(file), names);
        EXPECT_NO_THROW(io::readFlatpack(file));  // its constraints, the equal ones with them, hold
    }
    for (const nlohmann::json& equal : report.keptEqual)
        EXPECT_NE(std::find(names.begin(), names.end(), equal["name"].get<std::string>()), names.end());
}
