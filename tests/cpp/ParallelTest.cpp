#include "Core/Parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

using fabguide::runAll;

TEST(Parallel, EndsWhenTheFirstThreadDoesEveryTaskBeforeTheNextStarts)
{
    // Tasks that end at once: a thread may take them all before the next is started (that once hung).
    for (int round = 0; round < 2000; ++round) {
        std::atomic<int> ran{0};
        int reported = 0;
        const auto task = [&](int) { ++ran; };
        const auto report = [&](int) { ++reported; };
        runAll(2, 2, task, report);
        ASSERT_EQ(ran, 2);
        ASSERT_EQ(reported, 2);
    }
}

TEST(Parallel, RunsEveryTaskOnceAndReportsEachOnTheCallersThread)
{
    std::vector<std::atomic<int>> runs(50);
    std::vector<int> reported;
    const auto task = [&](int t) { ++runs[t]; };
    const auto report = [&](int t) { reported.push_back(t); };
    runAll(50, 3, task, report);
    for (const std::atomic<int>& r : runs)
        EXPECT_EQ(r, 1);
    EXPECT_EQ(reported.size(), 50u);
}

TEST(Parallel, ATaskThatThrowsIsRethrownOnTheCaller)
{
    const auto task = [](int t) {
        if (t == 1)
            throw std::runtime_error("task 1");
    };
    const auto report = [](int) {};
    EXPECT_THROW(runAll(4, 2, task, report), std::runtime_error);
}
