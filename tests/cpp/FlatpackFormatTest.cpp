// The flat-pack format's versions (App/IO/FlatpackFormat.h, docs/formats.md): a file an older FabGuide wrote
// reads as the same design, is written back in this version's form, and its mistakes are named as it has
// them.
#include "IO/FlatpackFormat.h"

#include <gtest/gtest.h>

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
