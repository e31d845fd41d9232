// WorkerTeam: every unit of every job runs exactly once, whatever thread runs it and however the
// threads are scheduled; exceptions reach the caller; a job ends when its units are done, not when
// every thread has arrived; jobs go to fewer threads while the team's threads wait for CPUs.
#include "roughgas/core/worker_team.hpp"

#include "roughgas/core/run_delay.hpp"

#include "busy_machine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <stdexcept>
#include <thread>
#include <vector>

namespace roughgas {
namespace {

TEST(WorkerTeam, EveryUnitOfEveryJobRunsOnce) {
    for (const int threads : {1, 2, 3, 5}) {
        WorkerTeam team(threads);
        EXPECT_EQ(team.threads(), threads);
        std::vector<std::atomic<int>> runs(257);
        // Many short jobs back to back (where a late worker could meet the next job) and a few
        // large ones; unit counts 1, 2, ..., 257.
        for (int job = 0; job < 4000; ++job) {
            const std::size_t units = 1 + static_cast<std::size_t>(job) % runs.size();
            for (std::size_t u = 0; u < units; ++u)
                runs[u].store(0, std::memory_order_relaxed);
            team.for_each(units, [&](std::size_t u) { runs[u].fetch_add(1, std::memory_order_relaxed); });
            for (std::size_t u = 0; u < units; ++u)
                ASSERT_EQ(runs[u].load(), 1) << "threads " << threads << ", job " << job << ", unit " << u;
        }
    }
}

TEST(WorkerTeam, TheFirstExceptionReachesTheCallerAndTheTeamGoesOn) {
    for (const int threads : {1, 2}) {
        SCOPED_TRACE(threads);
        WorkerTeam team(threads);
        std::atomic<int> ran{0};
        EXPECT_THROW(team.for_each(16,
                                   [&](std::size_t u) {
                                       ran.fetch_add(1);
                                       if (u == 7)
                                           throw std::runtime_error("unit 7");
                                   }),
                     std::runtime_error);
        EXPECT_EQ(ran.load(), 16); // the other units still ran
        ran = 0;
        team.for_each(16, [&](std::size_t) { ran.fetch_add(1); });
        EXPECT_EQ(ran.load(), 16);
    }
}

// A unit that takes long on one thread does not hold up the rest: the other threads take every
// other unit meanwhile (dynamic claiming), so the job takes about the long unit's time.
TEST(WorkerTeam, UnitsAreClaimedDynamically) {
    WorkerTeam team(2, WorkerTeam::Load::ignored); // both threads work even on a busy test machine
    std::vector<std::thread::id> who(41);
    team.for_each(who.size(), [&](std::size_t u) {
        if (u == 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        else
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        who[u] = std::this_thread::get_id();
    });
    int with_unit_0 = 0;
    for (std::size_t u = 1; u < who.size(); ++u)
        with_unit_0 += who[u] == who[0];
    EXPECT_LE(with_unit_0, 5) << "the thread with the 200 ms unit also ran " << with_unit_0 << " of the 2 ms units";
}

// Each thread claims its own share first, from its front and in order (the caller's share is units
// [0, U/2) of two threads); the others take a share's units only from its back. So the units the
// caller ran of its own share are 0, 1, ..., k - 1 in that order, and what it took of the worker's
// share is that share's last units, from the end down, however the two threads are scheduled.
TEST(WorkerTeam, EachThreadClaimsItsOwnShareFromTheFrontAndTheOthersFromTheBack) {
    WorkerTeam team(2, WorkerTeam::Load::ignored);
    for (int job = 0; job < 20; ++job) {
        const std::size_t U = 40;
        std::vector<std::thread::id> who(U);
        std::vector<std::size_t> caller_order, worker_order;
        std::mutex m;
        const std::thread::id caller = std::this_thread::get_id();
        team.for_each(U, [&](std::size_t u) {
            std::this_thread::sleep_for(std::chrono::microseconds(job % 2 == 0 ? 500 : 20));
            who[u] = std::this_thread::get_id();
            const std::lock_guard<std::mutex> lock(m);
            (who[u] == caller ? caller_order : worker_order).push_back(u);
        });
        // The worker likewise: its own share from U/2 up, then the caller's from its back.
        std::size_t j = 0;
        while (j < worker_order.size() && worker_order[j] == U / 2 + j)
            ++j;
        for (std::size_t i = j; i < worker_order.size(); ++i)
            EXPECT_LT(worker_order[i], U / 2) << "job " << job << ": the worker's own units out of order";
        for (std::size_t i = j + 1; i < worker_order.size(); ++i)
            EXPECT_LT(worker_order[i], worker_order[i - 1]) << "job " << job << ": not taken from the back";
        std::size_t k = 0; // the caller's own units first: 0, 1, ..., k - 1
        while (k < caller_order.size() && caller_order[k] == k)
            ++k;
        for (std::size_t u = k; u < U / 2; ++u)
            EXPECT_NE(who[u], caller) << "job " << job << ": unit " << u << " of the caller's share out of order";
        for (std::size_t i = k; i < caller_order.size(); ++i) // then the worker's share from its back
            EXPECT_EQ(caller_order[i], U - 1 - (i - k)) << "job " << job;
    }
}

// Runs one job of `units` units on the team: each unit once (checked), and returns how many distinct
// threads ran its units.
int threads_of_one_job(WorkerTeam& team, std::size_t units) {
    std::vector<std::atomic<int>> runs(units);
    std::vector<std::thread::id> who(units);
    team.for_each(units, [&](std::size_t u) {
        runs[u].fetch_add(1, std::memory_order_relaxed);
        who[u] = std::this_thread::get_id();
        for (int spin = 0; spin < 2000; ++spin)
            asm volatile("" : "+r"(spin)); // a little work, not optimised away
    });
    for (std::size_t u = 0; u < units; ++u)
        EXPECT_EQ(runs[u].load(), 1) << "unit " << u;
    std::sort(who.begin(), who.end());
    return static_cast<int>(std::unique(who.begin(), who.end()) - who.begin());
}

// On a machine with no CPU to spare (threads spinning, twice as many as the CPUs) the team's
// threads wait for time slices, and the team hands its jobs to fewer of them: no job runs on more
// threads than the team counts as active, and that count falls below the team's size.
TEST(WorkerTeam, HandsItsJobsToFewerThreadsWhileTheyWaitForCpus) {
    if (!run_delay_ns(this_thread_id()))
        GTEST_SKIP() << "this kernel does not report run-queue waits (/proc/self/task/*/schedstat)";
    WorkerTeam team(3);
    int fewest = 3;
    const BusyMachine busy;
    const auto t0 = std::chrono::steady_clock::now();
    for (int job = 0; std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10) && (fewest == 3 || job < 200); ++job) {
        const int threads = threads_of_one_job(team, 64);
        ASSERT_LE(threads, team.active_threads()) << "job " << job; // the count is set before a job, not during it
        fewest = std::min(fewest, team.active_threads());
    }
    EXPECT_LT(fewest, 3) << "the team kept all 3 threads working on a machine without a CPU to spare";
}

// The threads beyond the active count rest and take no unit; one active thread runs every unit in
// the caller and still reports the first exception after running them all; a team destroyed while
// a worker rests ends.
TEST(WorkerTeam, OnlyTheActiveThreadsTakeUnits) {
    for (int round = 0; round < 20; ++round) {
        WorkerTeam team(3, WorkerTeam::Load::ignored);
        team.set_active_threads(2);
        EXPECT_EQ(team.active_threads(), 2);
        for (int job = 0; job < 50; ++job)
            ASSERT_LE(threads_of_one_job(team, 40), 2) << "round " << round << ", job " << job;
        team.set_active_threads(1);
        EXPECT_EQ(threads_of_one_job(team, 40), 1);
        std::atomic<int> ran{0};
        EXPECT_THROW(team.for_each(16,
                                   [&](std::size_t u) {
                                       ran.fetch_add(1);
                                       if (u == 3 || u == 9)
                                           throw std::runtime_error("unit " + std::to_string(u));
                                   }),
                     std::runtime_error);
        EXPECT_EQ(ran.load(), 16);
        team.set_active_threads(0); // clamped to 1
        EXPECT_EQ(team.active_threads(), 1);
        team.set_active_threads(2); // the third worker rests when the team ends
        EXPECT_LE(threads_of_one_job(team, 40), 2);
    }
}

TEST(WorkerTeam, RefusesMoreUnitsThanItCanCount) {
    WorkerTeam team(2);
    EXPECT_THROW(team.for_each(std::size_t{1} << 20, [](std::size_t) {}), std::length_error);
}

} // namespace
} // namespace roughgas
