#pragma once
// How many of a team's threads take work, from the time they spent waiting for a CPU.
//
// Why. On a machine with fewer free cores than the team has threads (two runs started together, a
// run beside a compile), every job of the team ends only when the unit held by a thread waiting for
// its time slice is done: the other threads of the job sleep meanwhile, and the run pays a share
// of every time slice of the other processes. Two runs of two threads each on two cores, every
// thread working, take 1.1-1.3x the time of the same runs with one thread each (docs/performance.md,
// "Runs on a shared machine"). The team therefore
// watches how long its threads were runnable but not running (their run-queue wait, run_delay.hpp)
// per window of wall time, and hands work only to as many threads as the machine runs:
//  - a window whose threads waited more than `lost_limit` CPUs per active thread (0.15: two idle
//    threads wait 0.01-0.05 CPUs' worth together, mostly waking up; two threads with one core
//    between them 0.8) takes that many threads out of the work, rounded, at least one, keeping one;
//  - after about `first_probe` seconds the team tries one thread more for a window; if that window
//    waits too, it goes back and tries again after about twice as long (at most `longest_probe`
//    seconds), so a lasting load costs a window in every few seconds, and a load that ends is
//    noticed within seconds. Each wait is drawn within +-25 % of its value, so that runs started
//    together do not try at the same moments (and fail together, leaving a core idle).
// Results never depend on it: which thread runs a unit does not matter (worker_team.hpp).
#include "roughgas/core/rng.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace roughgas {

class ActiveThreads {
  public:
    static constexpr double window = 0.05;       // seconds of wall time per measurement
    static constexpr double lost_limit = 0.15;   // CPUs of waiting per active thread that are too many
    static constexpr double first_probe = 0.5;   // seconds before one more thread is tried
    static constexpr double longest_probe = 8.0; // the longest wait between tries
    static constexpr double spread = 0.25;       // waits drawn in (1 - spread, 1 + spread) times theirs

    // `seed` draws the waits' spread; `spread_waits` = false gives the waits exactly (tests).
    explicit ActiveThreads(int threads, std::uint64_t seed = 0, bool spread_waits = true)
        : threads_(std::max(threads, 1)), active_(threads_), draw_(seed), spread_(spread_waits) {}

    int threads() const { return threads_; }
    int active() const { return active_; }

    // After a window that ended at `now` (seconds, any origin), whose threads together waited
    // `lost` times its wall time for a CPU: the threads that take work in the next window.
    int after_window(double lost, double now) {
        if (lost > lost_limit * active_ && active_ > 1) {
            const int surplus = std::max(1, static_cast<int>(std::lround(lost)));
            active_ = std::max(1, active_ - surplus);
            probe_wait_ = probing_ ? std::min(2 * probe_wait_, longest_probe) : first_probe;
            probing_ = false;
            next_probe_ = now + probe_wait_ * factor();
            return active_;
        }
        if (probing_) { // the thread tried got its CPU: keep it, and try the next one soon
            probing_ = false;
            probe_wait_ = first_probe;
        }
        if (active_ < threads_ && now >= next_probe_) {
            ++active_;
            probing_ = true;
        }
        return active_;
    }

  private:
    // A factor in (1 - spread, 1 + spread) (splitmix64), or 1.
    double factor() {
        if (!spread_)
            return 1.0;
        auto next = [this] { return splitmix64(draw_); };
        return 1.0 + spread * uniform_pm1(next);
    }

    int threads_;
    int active_;
    std::uint64_t draw_;
    bool spread_;
    bool probing_ = false; // the last window ran one thread more than the one before, as a try
    double probe_wait_ = first_probe;
    double next_probe_ = 0;
};

} // namespace roughgas
