// The flat-pack format's versions (App/IO/FlatpackFormat.h, docs/formats.md): a file an older FabGuide wrote
// reads as the same design, is written back in this version's form, and its mistakes are named as it has
// them.
#include "IO/FlatpackFormat.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace fabguide;

namespace {

nlohmann::json read(const std::string& path)
{
    std::ifstream in(std::string(FABGUIDE_SOURCE_DIR) + "/" + path);
    return nlohmann::json::parse(in);
}

/// The pairs (written by version 1, the same design as this version writes it) kept in the repository.
const std::vector<std::pair<std::string, std::string>> kPairs = {
    {"tests/data/flatpack/version-1/coffee-table.flatpack.json", "examples/coffee-table.flatpack.json"},
    {"tests/data/flatpack/version-1/sideboard-18-6mm.flatpack.json",
     "tests/data/flatpack/sideboard-18-6mm.flatpack.json"}};

std::string errorOf(const nlohmann::json& document)
{
    try {
        io::readFlatpack(document);
    } catch (const io::FormatError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(FlatpackFormatTest, AVersion1FileIsTheDesignThisVersionWrites)
{
    for (const auto& [old, current] : kPairs) {
        EXPECT_EQ(io::currentFlatpack(read(old)), read(current)) << old;
        EXPECT_EQ(io::readFlatpack(read(old)).design.variables(),
                  io::readFlatpack(read(current)).design.variables())
            << old;
    }
}

TEST(FlatpackFormatTest, AVersion1FileWithoutItsVersionIsKnownByItsBoxes)
{
    nlohmann::json old = read(kPairs[0].first);
    old.erase("version");
    EXPECT_EQ(io::currentFlatpack(old), read(kPairs[0].second));
}

TEST(FlatpackFormatTest, AVersion1FileIsWrittenBackInThisVersionsForm)
{
    const nlohmann::json old = read(kPairs[0].first);
    const io::FlatpackDesign f = io::readFlatpack(old);
    const nlohmann::json written = io::withParts(old, f.design, f.design.variables());
    EXPECT_EQ(written, read(kPairs[0].second));
}

TEST(FlatpackFormatTest, AVersion1FilesMistakesAreNamedAsItHasThem)
{
    nlohmann::json old = read(kPairs[0].first);
    old["inner_volumes"][0]["size"][1] = -50;
    EXPECT_EQ(errorOf(old), "inner_volumes[0].size: every side must be longer than 0");
    old = read(kPairs[0].first);
    old["parts"][1].erase("position");
    EXPECT_EQ(errorOf(old), "parts[1].position: missing (an array is required)");
}

TEST(FlatpackFormatTest, ABoxIsRefusedUnlessItsMaxIsBeyondItsMinAlongEveryAxis)
{
    nlohmann::json current = read(kPairs[0].second);
    current["inner_volumes"][0]["max"][1] = current["inner_volumes"][0]["min"][1];
    EXPECT_EQ(errorOf(current), "inner_volumes[0].max: must exceed min along every axis");
    current = read(kPairs[0].second);
    current["parts"][0]["max"] = {720, 450};
    EXPECT_EQ(errorOf(current), "parts[0].max: must be [x, y, z], got [720,450]");
}

TEST(FlatpackFormatTest, ANewerVersionIsRefusedSayingWhichThisOneReads)
{
    nlohmann::json newer = read(kPairs[0].second);
    newer["version"] = io::kFlatpackFormatVersion + 1;
    EXPECT_EQ(errorOf(newer), "version: this FabGuide reads version 2, the file is version 3");
}

TEST(FlatpackFormatTest, TheNormalFormWritesEveryDefaultTheReaderTakes)
{
    const nlohmann::json given = {
        {"format", "fabguide.flatpack"},
        {"version", 2},
        {"boards", {{{"width", 1000}, {"height", 600}, {"thickness", 12}}}},
        {"parts",
         {{{"id", "top"}, {"min", {0, 0, 400}}, {"max", {600, 400, 412}}, {"follow_grain", true}},
          {{"id", "side"}, {"min", {0, 0, 0}}, {"max", {12, 400, 400}}}}},
        {"constraints",
         {{{"kind", "range"}, {"ref", "top.size.x"}, {"fraction", 0.5}},
          {{"kind", "fixed"}, {"ref", "side.size.z"}},
          {{"kind", "sum"}, {"lhs", {"top.size.y"}}, {"rhs", {"side.size.z"}}},
          {{"kind", "symmetric"}, {"refs", {"side.centre.y", "top.centre.y"}}},
          {{"kind", "ground"}, {"parts", {"side"}}}}},
        {"inner_volumes", {{{"on", "top"}, {"min", {0, 0, 412}}, {"max", {300, 300, 600}}}}}};
    const nlohmann::json normal = io::readFlatpack(given).document;
    EXPECT_EQ(normal["boards"][0], (nlohmann::json{{"name", "board"},
                                                   {"material", ""},
                                                   {"width", 1000.0},
                                                   {"height", 600.0},
                                                   {"thickness", 12.0},
                                                   {"count", 1},
                                                   {"cost", 1.0},
                                                   {"grain", "none"}}));
    EXPECT_EQ(normal["parts"][0],
              (nlohmann::json{{"id", "top"},
                              {"min", {0, 0, 400}},
                              {"max", {600, 400, 412}},
                              {"quantity", 1},
                              {"grain", "x"}}));  // follow_grain: the first axis of its face
    EXPECT_EQ(normal["parts"][1]["grain"], "free");
    EXPECT_EQ(normal["settings"]["resolution"], 0.5);
    EXPECT_EQ(normal["settings"]["snap"], true);
    EXPECT_EQ(normal["settings"]["max_growth"], 1.5);
    EXPECT_FALSE(normal["settings"].contains("min_length"));  // twice each board's thickness
    const nlohmann::json& c = normal["constraints"];
    EXPECT_EQ(c[0],
              (nlohmann::json{{"kind", "range"}, {"ref", "top.size.x"}, {"min", 300.0}, {"max", 900.0}}));
    EXPECT_EQ(c[1]["value"], 400.0);
    EXPECT_EQ(c[2]["offset"], 0.0);
    EXPECT_EQ(c[3]["about"], 200.0);
    EXPECT_EQ(c[4]["level"], 0.0);
    EXPECT_EQ(normal["inner_volumes"][0]["name"], "inner volume 1");
    EXPECT_EQ(normal["title"], "");
}

TEST(FlatpackFormatTest, EveryBundledDesignIsTheSameDesignReadFromItsNormalForm)
{
    std::vector<std::string> paths;
    for (const char* folder : {"examples", "tests/data/flatpack", "tests/data/flatpack/version-1"})
        for (const auto& entry :
             std::filesystem::directory_iterator(std::string(FABGUIDE_SOURCE_DIR) + "/" + folder))
            if (entry.path().string().find(".flatpack.json") != std::string::npos)
                paths.push_back(std::string(folder) + "/" + entry.path().filename().string());
    ASSERT_GE(paths.size(), 20u);
    const auto named = [](const std::vector<material::DesignConstraint>& constraints,
                          const Eigen::VectorXd& X) {
        std::vector<std::pair<std::string, double>> values;
        for (const material::DesignConstraint& c : constraints)
            values.emplace_back(c.name, c.expression.value(X));
        return values;
    };
    for (const std::string& path : paths) {
        const io::FlatpackDesign given = io::readFlatpack(read(path));
        const io::FlatpackDesign normal = io::readFlatpack(given.document);
        EXPECT_EQ(normal.document, given.document) << path;  // the normal form of a normal form is itself
        // The same constraints: by name, and by value at the design and at other values of its variables.
        Eigen::VectorXd X = given.design.variables();
        for (int k = 0; k < 2; ++k, X += Eigen::VectorXd::LinSpaced(X.size(), 1.0, 7.0)) {
            EXPECT_EQ(named(normal.design.equalities, X), named(given.design.equalities, X)) << path;
            EXPECT_EQ(named(normal.design.bounds, X), named(given.design.bounds, X)) << path;
        }
    }
}
