// The pack use case (App/Api/Pack.h): the job's settings as its document says them unless overridden, and a
// layout of every part.
#include "Api/Pack.h"

#include <gtest/gtest.h>

using namespace fabguide;

namespace {

api::PackJob job()
{
    api::PackJob j;
    j.document = nlohmann::json::parse(R"({
      "format": "fabguide.pack", "version": 1,
      "settings": {"resolution": 1, "kerf": 3, "trim": 5, "stages": 2},
      "boards": [{"name": "birch", "width": 1200, "height": 600, "thickness": 18, "count": 3}],
      "parts": [{"id": "side", "width": 500, "height": 300, "quantity": 4},
                {"id": "shelf", "width": 560, "height": 280, "quantity": 3}]
    })");
    j.search.iterations = 20;
    j.search.timeLimit = 60;  // bounded by the iterations
    return j;
}

}  // namespace

TEST(PackJobTest, TheDocumentsSettingsHoldUnlessTheJobOverridesThem)
{
    const api::PackReport asFiled = api::pack(job());
    EXPECT_EQ(asFiled.problem.settings.cuts, material::Cuts::Free);
    EXPECT_EQ(asFiled.problem.settings.stages, 2);
    EXPECT_FALSE(asFiled.problem.settings.commonLine);
    EXPECT_TRUE(asFiled.layout.sawCuts.empty());
    EXPECT_EQ(asFiled.layout.placements.size(), 7u);

    api::PackJob saw = job();
    saw.cuts = material::Cuts::Guillotine;
    saw.stages = 3;
    saw.firstCut = material::FirstCut::Across;
    saw.rotationStep = 15;
    saw.commonLine = true;
    const api::PackReport sawn = api::pack(saw);
    EXPECT_EQ(sawn.problem.settings.cuts, material::Cuts::Guillotine);
    EXPECT_EQ(sawn.problem.settings.stages, 3);
    EXPECT_EQ(sawn.problem.settings.firstCut, material::FirstCut::Across);
    EXPECT_EQ(sawn.problem.settings.rotationStep, 15);
    EXPECT_TRUE(sawn.problem.settings.commonLine);
    EXPECT_FALSE(sawn.layout.sawCuts.empty());
    EXPECT_EQ(sawn.layout.placements.size(), 7u);
}
