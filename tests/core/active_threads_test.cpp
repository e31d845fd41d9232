// ActiveThreads: all threads work while they get their CPUs; a window whose threads waited for
// CPUs takes the surplus out; one thread more is tried after a wait that doubles while the tries
// fail and starts over when one holds; the waits are spread so that runs started together try at
// different moments.
#include "roughgas/core/active_threads.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace roughgas {
namespace {

constexpr double w = ActiveThreads::window;
constexpr double limit = ActiveThreads::lost_limit;

// The waits exactly as stated, for the tests of the schedule.
ActiveThreads exact(int threads) { return ActiveThreads(threads, 0, false); }

TEST(ActiveThreads, AllThreadsWorkWhileTheyGetTheirCpus) {
    ActiveThreads a = exact(4);
    for (int k = 1; k <= 200; ++k) // at the limit, 4 x 0.15 CPUs: kept
        ASSERT_EQ(a.after_window(k % 2 == 0 ? 4 * limit : 0.02, k * w), 4) << "window " << k;
}

TEST(ActiveThreads, AWaitingWindowTakesTheSurplusOutAndKeepsOne) {
    ActiveThreads two = exact(2);
    EXPECT_EQ(two.after_window(0.8, w), 1);     // one thread too many per core: 0.8 CPUs waited
    EXPECT_EQ(two.after_window(0.9, 2 * w), 1); // never below one
    ActiveThreads eight = exact(8);
    EXPECT_EQ(eight.after_window(3.4, w), 5);                 // 3.4 CPUs' worth of waiting: 3 threads out
    EXPECT_EQ(eight.after_window(5 * limit + 0.01, 2 * w), 4); // a little over 5 threads' limit: one out
    EXPECT_EQ(eight.after_window(4 * limit, 3 * w), 4);       // at 4 threads' limit: kept
    ActiveThreads one = exact(1);
    EXPECT_EQ(one.after_window(5.0, w), 1);
}

TEST(ActiveThreads, TriesOneMoreAfterAWaitThatDoublesWhileTheTriesFail) {
    ActiveThreads a = exact(2);
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
        wait = std::min(2 * wait, ActiveThreads::longest_probe);      // 1, 2, 4, 8, 8, 8 s
    }
}

TEST(ActiveThreads, ATryThatHoldsKeepsItsThreadAndTriesTheNextAtOnce) {
    ActiveThreads a = exact(8);
    ASSERT_EQ(a.after_window(6.6, w), 1); // 7 out
    double t = w + ActiveThreads::first_probe;
    ASSERT_EQ(a.after_window(0.0, t), 2);
    for (int k = 3; k <= 8; ++k) // each try holds: one more per window
        ASSERT_EQ(a.after_window(0.05, t += w), k);
    EXPECT_EQ(a.after_window(0.05, t += w), 8);
    // A new load after tries that held starts again from the first wait.
    ASSERT_EQ(a.after_window(1.3, t += w), 7);
    const double drop = t;
    ASSERT_EQ(a.after_window(0.0, drop + ActiveThreads::first_probe - 0.01), 7);
    EXPECT_EQ(a.after_window(0.0, drop + ActiveThreads::first_probe), 8);
}

// With spread waits, each wait lies within +-25 % of its value, and two teams with different seeds
// try at different moments.
TEST(ActiveThreads, SpreadWaitsStayWithinAQuarterAndDifferBetweenTeams) {
    const double dt = 1e-3;
    const auto first_try = [&](std::uint64_t seed) {
        ActiveThreads a(2, seed);
        EXPECT_EQ(a.after_window(0.8, 0.0), 1);
        for (double t = dt;; t += dt)
            if (a.after_window(0.0, t) == 2)
                return t;
    };
    double lo = 1e9, hi = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        const double t = first_try(seed);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    EXPECT_GE(lo, 0.75 * ActiveThreads::first_probe - dt);
    EXPECT_LE(hi, 1.25 * ActiveThreads::first_probe + dt);
    EXPECT_GT(hi - lo, 0.4 * ActiveThreads::first_probe); // spread over most of +-25 %
}

} // namespace
} // namespace roughgas
