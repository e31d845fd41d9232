// ActiveThreads: all threads work while they get their CPUs; a window whose threads waited for
// CPUs takes the surplus out; one thread more is tried after a wait that doubles while the tries
// fail and starts over when one holds.
#include "roughgas/core/active_threads.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace roughgas {
namespace {

constexpr double w = ActiveThreads::window;
constexpr double limit = ActiveThreads::lost_limit;

TEST(ActiveThreads, AllThreadsWorkWhileTheyGetTheirCpus) {
    ActiveThreads a(4);
    for (int k = 1; k <= 200; ++k)
        ASSERT_EQ(a.after_window(k % 2 == 0 ? limit : 0.02, k * w), 4) << "window " << k; // at the limit: kept
}

TEST(ActiveThreads, AWaitingWindowTakesTheSurplusOutAndKeepsOne) {
    ActiveThreads two(2);
    EXPECT_EQ(two.after_window(0.8, w), 1); // one thread too many per core: 0.8 CPUs waited
    EXPECT_EQ(two.after_window(0.9, 2 * w), 1); // never below one
    ActiveThreads eight(8);
    EXPECT_EQ(eight.after_window(3.4, w), 5); // 3.4 CPUs' worth of waiting: 3 threads out
    EXPECT_EQ(eight.after_window(limit + 0.01, 2 * w), 4); // a little over the limit: one out
    ActiveThreads one(1);
    EXPECT_EQ(one.after_window(5.0, w), 1);
}

TEST(ActiveThreads, TriesOneMoreAfterAWaitThatDoublesWhileTheTriesFail) {
    ActiveThreads a(2);
    double t = w;
    ASSERT_EQ(a.after_window(0.8, t), 1);
    double wait = ActiveThreads::first_probe;
    for (int attempt = 0; attempt < 7; ++attempt) {
        const double drop = t;
        // No try before the wait is over (the gas runs on one thread, which waits for nothing).
        while (t + w < drop + wait - 1e-9) {
            t += w;
            ASSERT_EQ(a.after_window(0.01, t), 1) << "attempt " << attempt << " at " << t - drop << " s";
        }
        t = drop + wait;
        ASSERT_EQ(a.after_window(0.01, t), 2) << "attempt " << attempt; // the try
        t += w;
        ASSERT_EQ(a.after_window(0.7, t), 1) << "attempt " << attempt; // it failed
        wait = std::min(2 * wait, ActiveThreads::longest_probe); // 1, 2, 4, 8, 8, 8 s
    }
}

TEST(ActiveThreads, ATryThatHoldsKeepsItsThreadAndTriesTheNextAtOnce) {
    ActiveThreads a(8);
    ASSERT_EQ(a.after_window(6.6, w), 1); // 7 out
    double t = w + ActiveThreads::first_probe;
    ASSERT_EQ(a.after_window(0.0, t), 2);
    for (int k = 3; k <= 8; ++k) // each try holds: one more per window
        ASSERT_EQ(a.after_window(0.05, t += w), k);
    EXPECT_EQ(a.after_window(0.05, t += w), 8);
    // A new load after tries that held starts again from the first wait.
    ASSERT_EQ(a.after_window(1.2, t += w), 7);
    const double drop = t;
    ASSERT_EQ(a.after_window(0.0, drop + ActiveThreads::first_probe - 0.01), 7);
    EXPECT_EQ(a.after_window(0.0, drop + ActiveThreads::first_probe), 8);
}

} // namespace
} // namespace roughgas
