// The recompute of a flat-pack design (App/Api/DesignEdit.h) on the bundled coffee table: an edit kept, held
// by a range, a constraint just added satisfied, an overflow absorbed or undone; every design it ends with is
// read back as every command reads it (its constraints hold) and every layout keeps each board on a sheet.
#include "Api/DesignEdit.h"
#include "Design/Correction.h"
#include "IO/FlatpackFormat.h"
#include "Layout/Docking.h"

#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <stdexcept>

using namespace fabguide;

namespace {

nlohmann::json read(const std::string& path)
{
    std::ifstream in(std::string(FABGUIDE_SOURCE_DIR) + "/" + path);
    return nlohmann::json::parse(in);
}

nlohmann::json coffeeTable()
{
    return read("examples/coffee-table.flatpack.json");
}

/// The part `id` of a design document.
template <typename Json>
Json& part(Json& design, const std::string& id)
{
    for (Json& p : design["parts"])
        if (p["id"] == id)
            return p;
    throw std::out_of_range(id);
}

double size(const nlohmann::json& design, const std::string& id, int axis)
{
    const nlohmann::json& p = part(design, id);
    return p["max"][axis].get<double>() - p["min"][axis].get<double>();
}

/// The part `id` drawn `length` long along `axis`, from the same lower corner.
void resize(nlohmann::json& design, const std::string& id, int axis, double length)
{
    nlohmann::json& p = part(design, id);
    p["max"][axis] = p["min"][axis].get<double>() + length;
}

/// The edit of `valid` (parts) into `drawn`, or `drawn` alone.
api::DesignEdit edit(const nlohmann::json& drawn, std::optional<nlohmann::json> valid = std::nullopt)
{
    api::DesignEdit e;
    e.design = drawn;
    e.valid = std::move(valid);
    return e;
}

/// The design without the constraints of `kind`.
nlohmann::json without(nlohmann::json design, const std::string& kind)
{
    nlohmann::json kept = nlohmann::json::array();
    for (const nlohmann::json& c : design["constraints"])
        if (c["kind"] != kind)
            kept.push_back(c);
    design["constraints"] = kept;
    return design;
}

/// The design as it ends satisfies its constraints, and its layout places every board.
void expectValidAndLaidOut(const api::DesignEditReport& report)
{
    EXPECT_NO_THROW(io::readFlatpack(report.design));
    ASSERT_TRUE(report.laidOut.is_object());
    EXPECT_EQ(report.laidOut["layout"]["placements"].size(), report.design["parts"].size());
    EXPECT_GT(report.laidOut["usage"].get<double>(), 0);
}

}  // namespace

TEST(DesignEditTest, TheDesignAsDrawnIsLaidOutUnchanged)
{
    const nlohmann::json drawn = coffeeTable();
    const api::DesignEditReport report = api::editDesign(edit(drawn));
    EXPECT_EQ(report.design, drawn);
    EXPECT_EQ(report.kept, 1);
    EXPECT_FALSE(report.satisfied || report.absorbed);
    EXPECT_TRUE(report.undone.empty() && report.warning.empty());
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, AWiderTopIsKeptAndTheLegsAndShelfFollowWithTheMagazines)
{
    const nlohmann::json valid = coffeeTable();
    nlohmann::json drawn = valid;
    resize(drawn, "top", 0, 760);
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid["parts"]));
    EXPECT_NEAR(report.kept, 1, 1e-9);
    EXPECT_NEAR(size(report.design, "top", 0), 760, 1e-6);
    EXPECT_NEAR(size(report.design, "shelf", 0), 760 - 24, 1e-6);
    // The magazines' space rests on the shelf: it moved with the shelf's nearer face.
    const double shelfLeft = part(report.design, "shelf")["min"][0].get<double>();
    EXPECT_NEAR(report.design["inner_volumes"][0]["min"][0].get<double>() - shelfLeft, 210 - 12, 1e-6);
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, AValidStateAnOlderVersionWroteIsKeptFrom)
{
    // A FreeCAD document saved by FabGuide 0.x keeps its valid boards as format version 1 wrote them.
    const nlohmann::json valid = read("tests/data/flatpack/version-1/coffee-table.flatpack.json");
    nlohmann::json drawn = coffeeTable();
    resize(drawn, "top", 0, 760);
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid["parts"]));
    EXPECT_TRUE(report.warning.empty()) << report.warning;
    EXPECT_NEAR(size(report.design, "shelf", 0), 760 - 24, 1e-6);
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, AnEditPastARangeIsKeptAsFarAsTheRangeAllows)
{
    const nlohmann::json valid = coffeeTable();
    nlohmann::json drawn = valid;
    resize(drawn, "top", 0, 2000);  // the range allows 720 x 1.25 = 900
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid["parts"]));
    EXPECT_LT(report.kept, 1);
    EXPECT_FALSE(report.limits.empty());
    EXPECT_NEAR(size(report.design, "top", 0), 900, 1e-3);
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, WithoutKeepingEditsTheBoardsAreTakenAsDrawnAndMovedOnlyToSatisfyTheConstraints)
{
    const nlohmann::json valid = coffeeTable();
    nlohmann::json drawn = valid;
    resize(drawn, "left", 2, 380);  // the legs are equal: the other one follows, or this one goes back
    api::DesignEdit asDrawn = edit(drawn, valid["parts"]);
    asDrawn.keepEdits = false;
    const api::DesignEditReport report = api::editDesign(asDrawn);
    EXPECT_TRUE(report.satisfied);
    EXPECT_EQ(report.kept, 1);
    EXPECT_NEAR(size(report.design, "left", 2), size(report.design, "right", 2), 1e-6);
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, AnOverflowIsAbsorbedByThePartsSharingItsLine)
{
    const nlohmann::json valid = without(coffeeTable(), "range");
    nlohmann::json drawn = valid;
    resize(drawn, "top", 0, 1000);  // no layout fits it with the others as they are
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid["parts"]));
    EXPECT_TRUE(report.absorbed);
    EXPECT_FALSE(report.snapped.empty());
    EXPECT_NEAR(size(report.design, "top", 0), 1000, 1e-6);
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, AnEditLargerThanEveryBoardIsUndoneWithTheReason)
{
    const nlohmann::json valid = without(without(coffeeTable(), "range"), "symmetric");
    nlohmann::json drawn = valid;
    resize(drawn, "shelf", 1, 1300);
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid["parts"]));
    EXPECT_EQ(report.undone, "part 'shelf' is larger than every master board");
    EXPECT_EQ(report.design["parts"], valid["parts"]);
    EXPECT_TRUE(report.laidOut.is_null());
}

TEST(DesignEditTest, ADesignThatDoesNotFitWithNoEditToUndoIsRefused)
{
    nlohmann::json drawn = without(coffeeTable(), "range");
    resize(drawn, "shelf", 1, 1300);
    EXPECT_THROW(api::editDesign(edit(drawn)), material::PackingError);
    EXPECT_THROW(api::editDesign(edit(drawn, drawn["parts"])),
                 material::PackingError);  // nothing changed since
}

TEST(DesignEditTest, ConstraintsNoMoveSatisfiesAreNamed)
{
    nlohmann::json drawn = coffeeTable();
    drawn["constraints"].push_back(
        {{"kind", "fixed"}, {"ref", "top.size.x"}, {"value", 600}, {"name", "short"}});
    drawn["constraints"].push_back(
        {{"kind", "fixed"}, {"ref", "top.size.x"}, {"value", 800}, {"name", "long"}});
    try {
        api::editDesign(edit(drawn));
        FAIL() << "a contradiction was laid out";
    } catch (const io::ConstraintError& error) {
        EXPECT_NE(std::find(error.names.begin(), error.names.end(), "long"), error.names.end())
            << error.what();
    }
}

TEST(DesignEditTest, AValidStateThatNoLongerReadsIsSaidAndTheBoardsAreTakenAsDrawn)
{
    const nlohmann::json drawn = coffeeTable();
    nlohmann::json valid = drawn["parts"];
    valid[0]["max"] = "wide";
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid));
    EXPECT_NE(report.warning.find("parts[0].max"), std::string::npos) << report.warning;
    EXPECT_EQ(report.design, drawn);
    expectValidAndLaidOut(report);
}

TEST(DesignEditTest, WhatTheValidPartsDoNotSayIsTakenAsDrawn)
{
    const nlohmann::json valid = coffeeTable();
    nlohmann::json drawn = valid;
    resize(drawn, "top", 0, 760);
    part(drawn, "shelf")["grain"] = "y";  // set with the edit: the valid parts have none
    const api::DesignEditReport report = api::editDesign(edit(drawn, valid["parts"]));
    EXPECT_EQ(part(report.design, "shelf")["grain"], "y");
    EXPECT_NEAR(size(report.design, "shelf", 0), 760 - 24, 1e-6);
    expectValidAndLaidOut(report);

    resize(drawn, "shelf", 1, 1300);  // undone: the boards go back, the grain stays as drawn
    const api::DesignEditReport undone = api::editDesign(edit(without(drawn, "range"), valid["parts"]));
    ASSERT_FALSE(undone.undone.empty());
    EXPECT_EQ(part(undone.design, "shelf")["grain"], "y");
    EXPECT_EQ(part(undone.design, "shelf")["max"], part(valid, "shelf")["max"]);
}
