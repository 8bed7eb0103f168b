#include "IO/Json.h"
#include "IO/PackFormat.h"

#include <gtest/gtest.h>

using namespace fabguide;
using nlohmann::json;

namespace {

json goodProblem()
{
    return json::parse(R"({
      "format": "fabguide.pack", "version": 1,
      "settings": {"resolution": 1, "kerf": 0.2, "spacing": 1, "trim": 5},
      "boards": [{"name": "poplar", "material": "poplar plywood", "width": 600, "height": 400, "thickness": 4, "count": 2}],
      "parts": [{"id": "lid", "width": 200, "height": 150, "quantity": 2, "orientations": [0, 180]},
                {"id": "side", "width": 120, "height": 80}]
    })");
}

/// The FormatError message for `document`, or "" if it reads.
std::string errorOf(const json& document)
{
    try {
        io::readPackProblem(document);
    } catch (const io::FormatError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(PackFormat, ReadsEveryField)
{
    const material::PackProblem p = io::readPackProblem(goodProblem());
    EXPECT_DOUBLE_EQ(p.settings.kerf, 0.2);
    EXPECT_DOUBLE_EQ(p.settings.trim, 5);
    ASSERT_EQ(p.boards.size(), 1u);
    EXPECT_EQ(p.boards[0].material, "poplar plywood");
    EXPECT_EQ(p.boards[0].count, 2);
    ASSERT_EQ(p.parts.size(), 2u);
    EXPECT_EQ(p.parts[0].orientations, (std::vector<int>{0, 180}));
    EXPECT_EQ(p.parts[1].orientations, (std::vector<int>{0, 90, 180, 270}));
    EXPECT_EQ(p.parts[1].quantity, 1);
    EXPECT_EQ(p.boards[0].grain, material::Grain::None);
    EXPECT_FALSE(p.parts[0].followsGrain);
}

TEST(PackFormat, ReadsGrain)
{
    json d = goodProblem();
    d["boards"][0]["grain"] = "height";
    d["parts"][1]["follow_grain"] = true;
    const material::PackProblem p = io::readPackProblem(d);
    EXPECT_EQ(p.boards[0].grain, material::Grain::AlongHeight);
    EXPECT_TRUE(p.parts[1].followsGrain);
    material::OrderingSearchOptions options;
    options.iterations = 20;
    const json layout = io::layoutToJson(material::pack(p, options), p, io::PartNames::Ids);
    EXPECT_EQ(layout["boards"][0]["grain"], "height");
    for (const json& placement : layout["placements"])
        if (placement["part"] == "side") {
            EXPECT_EQ(placement["rotation"].get<int>() % 180, 90);
        }
}

TEST(PackFormat, ErrorsNameTheOffendingField)
{
    json d = goodProblem();
    d["parts"][1].erase("width");
    EXPECT_EQ(errorOf(d), "parts[1].width: missing (a number is required)");

    d = goodProblem();
    d["parts"][0]["height"] = -3;
    EXPECT_EQ(errorOf(d), "parts[0].height: must be greater than 0, got -3");

    d = goodProblem();
    d["parts"][0]["width"] = "wide";
    EXPECT_EQ(errorOf(d), "parts[0].width: must be a number, got \"wide\"");

    d = goodProblem();
    d["parts"][0]["orientations"] = {0, 45};
    EXPECT_EQ(errorOf(d), "parts[0].orientations[1]: must be 0, 90, 180 or 270, got 45");

    d = goodProblem();
    d["boards"][0]["count"] = 0;
    EXPECT_EQ(errorOf(d), "boards[0].count: must be a positive number of boards, or -1 for unlimited");

    d = goodProblem();
    d["settings"]["kerf"] = -1;
    EXPECT_EQ(errorOf(d), "settings.kerf: must be at least 0, got -1");

    d = goodProblem();
    d["boards"][0]["grain"] = "diagonal";
    EXPECT_EQ(errorOf(d), "boards[0].grain: must be \"none\", \"width\" or \"height\", got \"diagonal\"");

    d = goodProblem();
    d["version"] = 7;
    EXPECT_EQ(errorOf(d), "version: this FabGuide reads version 1, the file is version 7");

    d = goodProblem();
    d["boards"] = json::array();
    EXPECT_EQ(errorOf(d), "boards: at least one master board is needed");

    EXPECT_EQ(errorOf(json::array()), "document: must be a JSON object");
}

TEST(PackFormat, AGridCellLargerThanABoardIsRefused)
{
    json d = goodProblem();
    d["settings"]["resolution"] = 500;  // the board is 600 x 400: not one cell across it
    EXPECT_EQ(errorOf(d),
              "settings.resolution: a cell of 500 mm is larger than master board 'poplar' (600 x 400 mm, "
              "boards[0])");
    d["settings"]["resolution"] = 400;
    EXPECT_EQ(errorOf(d).find("settings.resolution"), std::string::npos) << "one cell fits";
}

TEST(PackFormat, AMisspeltKeyIsNamedWithTheKeyMeant)
{
    json d = goodProblem();
    d["settings"]["kerff"] = 0.3;  // ignored without a word, the kerf would be 0.2
    EXPECT_EQ(errorOf(d), "settings.kerff: no such key; did you mean \"kerf\"?");
    d = goodProblem();
    d["boards"][0]["colour"] = "red";
    EXPECT_EQ(errorOf(d),
              "boards[0].colour: no such key (known: name, material, width, height, thickness, count, "
              "cost, grain)");
}

TEST(PackFormat, ErrorsCarryTheirFieldPath)
{
    const io::FormatError kerf("settings.kerf", "must be at least 0, got -1");
    EXPECT_EQ(kerf.field(), "settings.kerf");
    EXPECT_STREQ(kerf.what(), "settings.kerf: must be at least 0, got -1");
    EXPECT_EQ(kerf.inFile("job.json").field(), "settings.kerf");
    EXPECT_STREQ(kerf.inFile("job.json").what(), "job.json: settings.kerf: must be at least 0, got -1");
    EXPECT_EQ(io::FormatError("body 'lid': a union failed").field(), "");
    try {
        io::checkNumbers(json::parse(R"({"parts": [{"width": 1e9}]})"));
        ADD_FAILURE() << "1e9 mm read";
    } catch (const io::FormatError& e) {
        EXPECT_EQ(e.field(), "parts[0].width");
    }
}

TEST(PackFormat, ReadsOrDatasetsStripInstances)
{
    const json instance = json::parse(R"({"Name": "t", "Objects": [{"Length": 20, "Height": 20}],
      "Items": [{"Length": 10, "Height": 5, "Demand": 3}, {"Length": 2, "Height": 7}]})");
    const material::PackProblem p = io::readStripInstance(instance);
    EXPECT_TRUE(p.strip);
    EXPECT_DOUBLE_EQ(p.boards[0].width, 20);
    ASSERT_EQ(p.parts.size(), 2u);
    EXPECT_EQ(p.parts[0].quantity, 3);
    EXPECT_EQ(p.parts[1].quantity, 1);
    EXPECT_THROW(io::readStripInstance(json::parse(R"({"Objects": [], "Items": []})")), io::FormatError);
}

TEST(PackFormat, LayoutJsonFollowsTheContract)
{
    const json instance = json::parse(R"({"Objects": [{"Length": 10, "Height": 10}],
      "Items": [{"Length": 10, "Height": 3, "Demand": 2}, {"Length": 5, "Height": 4, "Demand": 2}]})");
    const material::PackProblem problem = io::readStripInstance(instance);
    material::OrderingSearchOptions options;
    options.iterations = 50;
    const json out = io::layoutToJson(material::pack(problem, options), problem, io::PartNames::Indices);
    EXPECT_DOUBLE_EQ(out["strip_height"].get<double>(), 10);
    ASSERT_EQ(out["placements"].size(), 4u);
    for (const json& p : out["placements"]) {
        for (const char* key : {"part", "board", "x", "y", "rotation", "width", "height"})
            EXPECT_TRUE(p.contains(key)) << key;
        EXPECT_TRUE(p["part"].is_number_integer());
    }
    EXPECT_EQ(out["boards"][0]["width"], 10);
}

TEST(PackFormat, UnreadableFilesAreNamed)
{
    EXPECT_THROW(io::readJsonFile("/nonexistent/x.pack.json"), io::FormatError);
}

TEST(PackFormat, LayoutsReadBackAsWritten)
{
    const material::PackProblem problem = io::readPackProblem(goodProblem());
    material::OrderingSearchOptions options;
    options.iterations = 30;
    const material::Layout layout = material::pack(problem, options);
    const json written = io::layoutToJson(layout, problem, io::PartNames::Ids);
    const material::Layout read = io::readLayout(written, problem, io::PartNames::Ids);
    ASSERT_EQ(read.placements.size(), layout.placements.size());
    for (size_t i = 0; i < read.placements.size(); ++i) {
        EXPECT_EQ(read.placements[i].part, layout.placements[i].part);
        EXPECT_DOUBLE_EQ(read.placements[i].x, layout.placements[i].x);
        EXPECT_EQ(read.placements[i].rotation, layout.placements[i].rotation);
    }
    EXPECT_NEAR(read.usage(), layout.usage(), 1e-9);
    EXPECT_EQ(io::layoutToJson(read, problem, io::PartNames::Ids), written);

    json bad = written;
    bad["placements"][0]["part"] = "drawer";
    EXPECT_THROW(io::readLayout(bad, problem, io::PartNames::Ids), io::FormatError);
}

TEST(PackFormat, SawCutsAndTheirSettingsReadBackAsWritten)
{
    json doc = goodProblem();
    doc["settings"]["cuts"] = "guillotine";
    doc["settings"]["stages"] = 2;
    doc["settings"]["first_cut"] = "across";
    const material::PackProblem problem = io::readPackProblem(doc);
    EXPECT_EQ(problem.settings.cuts, material::Cuts::Guillotine);
    EXPECT_EQ(problem.settings.firstCut, material::FirstCut::Across);
    EXPECT_EQ(io::readPackProblem(io::problemToJson(problem)).settings.stages, 2);
    material::OrderingSearchOptions options;
    options.iterations = 10;
    const json written = io::layoutToJson(material::pack(problem, options), problem, io::PartNames::Ids);
    ASSERT_TRUE(written.contains("saw_cuts"));
    EXPECT_EQ(
        io::layoutToJson(io::readLayout(written, problem, io::PartNames::Ids), problem, io::PartNames::Ids),
        written);
    json bad = written;
    bad["saw_cuts"][0][0].erase("to");
    EXPECT_THROW(io::readLayout(bad, problem, io::PartNames::Ids), io::FormatError);
    doc["settings"]["first_cut"] = "sideways";
    EXPECT_EQ(errorOf(doc), "settings.first_cut: must be \"any\", \"along\" or \"across\", got \"sideways\"");
}

TEST(PackFormat, OutlinesThatCrossThemselvesHolesOutsideAndTwinIdsAreNamed)
{
    json doc = goodProblem();
    doc["parts"][0] = json::parse(R"({"id": "tie", "outline": [[0, 0], [300, 400], [300, 0], [0, 400]]})");
    EXPECT_EQ(errorOf(doc),
              "parts[0].outline: crosses itself (its edges from point 0 and from point 2 meet); "
              "draw it as one closed loop that does not touch itself");
    doc["parts"][0] = json::parse(R"({"id": "seat", "outline": [[0, 0], [300, 0], [300, 300], [0, 300]],
                                      "holes": [[[100, 100], [200, 100], [200, 200], [100, 200]],
                                                [[250, 100], [350, 100], [350, 200], [250, 200]]]})");
    EXPECT_EQ(errorOf(doc), "parts[0].holes[1]: crosses the outline; a hole must be inside the part");
    doc["parts"][0]["holes"][1] = json::parse("[[400, 100], [450, 100], [450, 200], [400, 200]]");
    EXPECT_EQ(errorOf(doc), "parts[0].holes[1]: lies outside the outline; a hole must be inside the part");
    const std::string touching =
        "parts[0].holes[1]: touches the outline; a hole must lie inside the part with "
        "material all round it (a notch is part of the outline)";
    doc["parts"][0]["holes"][1] = json::parse("[[250, 100], [300, 100], [300, 200], [250, 200]]");  // an edge
    EXPECT_EQ(errorOf(doc), touching);
    doc["parts"][0]["holes"][1] = json::parse("[[250, 0], [280, 50], [220, 50]]");  // a corner
    EXPECT_EQ(errorOf(doc), touching);
    doc["parts"][0]["holes"].erase(1);
    EXPECT_EQ(errorOf(doc), "");
    doc["parts"][1]["id"] = "seat";
    EXPECT_EQ(errorOf(doc), "parts[1].id: \"seat\" is used by parts[0] too; give each part its own id");
}

TEST(PackFormat, EdgeBandingReadsBackAsWrittenAndBadSidesAreNamed)
{
    json doc = goodProblem();
    doc["parts"][0]["edge_banding"] = {{"L1", "oak 1 mm"}, {"W2", "oak 2 mm"}};
    const material::PackProblem problem = io::readPackProblem(doc);
    EXPECT_EQ(problem.parts[0].edgeBanding, (std::array<std::string, 4>{"oak 1 mm", "", "", "oak 2 mm"}));
    EXPECT_EQ(problem.parts[1].edgeBanding, (std::array<std::string, 4>{}));
    EXPECT_EQ(io::readPackProblem(io::problemToJson(problem)).parts[0].edgeBanding,
              problem.parts[0].edgeBanding);
    doc["parts"][0]["edge_banding"] = {{"front", "oak 1 mm"}};
    EXPECT_EQ(errorOf(doc),
              "parts[0].edge_banding.front: not a side of the part; use L1, L2 (along its length), "
              "W1 or W2 (along its width)");
    doc["parts"][0]["edge_banding"] = {{"L2", ""}};
    EXPECT_EQ(errorOf(doc),
              "parts[0].edge_banding.L2: the band's name is empty (leave the side out for none)");
    doc["parts"][0]["edge_banding"] = json::array({"L1"});
    EXPECT_NE(errorOf(doc).find("parts[0].edge_banding: must map sides"), std::string::npos);
}
