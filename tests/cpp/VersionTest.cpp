#include "Core/Version.h"

#include <gtest/gtest.h>

#include <regex>

TEST(Version, IsSemanticVersion)
{
    EXPECT_TRUE(std::regex_match(fabguide::version(), std::regex(R"(\d+\.\d+\.\d+)")));
}

TEST(Version, ReportsTheLibrariesTheCoreIsBuiltWith)
{
    const auto deps = fabguide::dependencyVersions();
    ASSERT_EQ(deps.size(), 4u);
    EXPECT_EQ(deps[0].first, "Eigen");
    EXPECT_EQ(deps[0].second.rfind("3.", 0), 0u);
    EXPECT_EQ(deps[1].first, "OpenCASCADE");
    EXPECT_EQ(deps[1].second.rfind("7.", 0), 0u);
    for (const auto& [library, version] : deps)
        EXPECT_TRUE(std::regex_match(version, std::regex(R"(\d+\.\d+\.\d+)"))) << library << " " << version;
}
