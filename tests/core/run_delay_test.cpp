// The run-queue wait of a thread as the kernel reports it: parsed from schedstat's line, read for a
// thread of this process, and growing while the thread is runnable but has no CPU.
#include "roughgas/core/run_delay.hpp"

#include "busy_machine.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace roughgas {
namespace {

TEST(RunDelay, IsTheSecondFieldOfSchedstat) {
    EXPECT_EQ(run_delay_of_schedstat("3329624 7155 12\n"), 7155);
    EXPECT_EQ(run_delay_of_schedstat("12345678901234 9876543210987 42"), 9876543210987);
    EXPECT_EQ(run_delay_of_schedstat(""), std::nullopt);
    EXPECT_EQ(run_delay_of_schedstat("3329624 7155"), std::nullopt); // a field short
    EXPECT_EQ(run_delay_of_schedstat("3329624 x 12"), std::nullopt);
    EXPECT_EQ(run_delay_of_schedstat("3329624 -5 12"), std::nullopt);
    EXPECT_EQ(run_delay_of_schedstat("0 0 0"), std::nullopt); // a kernel without scheduler statistics
}

// Threads that spin, twice as many as the machine has CPUs, each wait about half of their time on
// the run queue: this thread, spinning among them, must be seen waiting.
TEST(RunDelay, GrowsWhileTheThreadWaitsForACpu) {
    const std::optional<std::int64_t> before = run_delay_ns(this_thread_id());
    if (!before)
        GTEST_SKIP() << "this kernel does not report run-queue waits (/proc/self/task/*/schedstat)";
    const auto t0 = std::chrono::steady_clock::now();
    std::int64_t waited = 0;
    {
        const BusyMachine busy;
        while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5) && waited < 10'000'000) { // 10 ms
            const std::optional<std::int64_t> now = run_delay_ns(this_thread_id());
            ASSERT_TRUE(now.has_value());
            waited = *now - *before;
        }
    }
    EXPECT_GE(waited, 10'000'000) << "waited " << waited * 1e-6 << " ms for a CPU among spinning threads in 5 s";
}

} // namespace
} // namespace roughgas
