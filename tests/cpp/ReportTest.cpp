#include "IO/Json.h"
#include "IO/Report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace fabguide;
using namespace fabguide::material;

namespace {

/// Two sheets: a 300 x 100 shelf banded along both long edges on the first, a 200 x 200 square with a
/// 50 x 50 hole on the second.
std::pair<PackProblem, Layout> twoSheets()
{
    PackProblem p;
    p.boards = {{"birch", "birch plywood", 1000, 500, 18, -1, Grain::AlongWidth, 40}};
    p.parts = {rectangularPart("shelf", 300, 100), rectangularPart("square", 200, 200)};
    p.parts[0].edgeBanding = {"oak 1 mm", "oak 1 mm", "", ""};
    p.parts[1].outline.holes.push_back({{75, 75}, {75, 125}, {125, 125}, {125, 75}});
    Layout layout;
    layout.sheets = {p.boards[0], p.boards[0]};
    layout.placements = {{0, 0, 10, 10, 0, 300, 100}, {1, 1, 10, 10, 0, 200, 200}};
    return {p, layout};
}

std::string readAll(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(Report, TotalsAddUpTheSheetsPartsCutsAndBanding)
{
    auto [p, layout] = twoSheets();
    Totals t = totals(layout, p);
    EXPECT_EQ(t.sheets, 2);
    EXPECT_EQ(t.parts, 2);
    EXPECT_DOUBLE_EQ(t.sheetArea, 2 * 1000 * 500);
    EXPECT_DOUBLE_EQ(t.partArea, 300 * 100 + 200 * 200 - 50 * 50);
    EXPECT_DOUBLE_EQ(t.cost, 80);
    EXPECT_DOUBLE_EQ(t.cutLength, 2 * (300 + 100) + 4 * 200 + 4 * 50);  // outlines and the hole
    ASSERT_EQ(t.banding.size(), 1u);
    EXPECT_EQ(t.banding[0].first, "oak 1 mm");
    EXPECT_DOUBLE_EQ(t.banding[0].second, 600);
    layout.sawCuts = {{{"1", 1, false, {0, 115}, {1000, 115}}}, {}};  // a guillotine layout: the saw's cuts
    EXPECT_DOUBLE_EQ(totals(layout, p).cutLength, 1000);
}

TEST(Report, APdfOfSheetsAndCutListAndSvgPagesAlike)
{
    const auto [p, layout] = twoSheets();
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "fabguide-report-test";
    std::filesystem::create_directories(folder);
    io::writeReport(layout, p, "two sheets", (folder / "report.pdf").string());
    const std::string pdf = readAll(folder / "report.pdf");
    EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
    const std::vector<std::string> svgs = io::reportSvgs(layout, p, "two sheets");
    ASSERT_EQ(svgs.size(), 3u);  // a page per sheet, then the cut list with the totals
    for (const std::string& svg : svgs)
        EXPECT_NE(svg.find("<svg"), std::string::npos);
    io::writeLabels(layout, p, (folder / "labels.pdf").string());
    EXPECT_EQ(readAll(folder / "labels.pdf").rfind("%PDF-", 0), 0u);
    EXPECT_THROW(io::writeLabels(layout, p, (folder / "tiny.pdf").string(), 10, 5), io::FormatError);
    EXPECT_FALSE(std::filesystem::exists(folder / "tiny.pdf"));
    std::filesystem::remove_all(folder);
}
