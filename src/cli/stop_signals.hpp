#pragma once
// SIGINT and SIGTERM during `roughgas run` (README "Checkpoints and restart"): the first asks the
// run to stop at its next boundary (a checkpoint, the CSV so far, exit 128 + the signal's number),
// a second one ends the process at once (the signal's default action).
//
// No signal handler and no global: while a StopSignals exists both signals are blocked in the
// thread that made it and in every thread started after (threads inherit the mask: make it before
// the first OpenMP region, so that no pool thread takes the default action), and one thread of its
// own waits for them in sigwait() and sets a flag this object owns. The replicas poll requested()
// at their chunk boundaries, never in the collision loop.
#include <atomic>
#include <csignal>
#include <string>
#include <thread>

namespace roughgas::cli {

class StopSignals {
  public:
    StopSignals();
    // Restores the mask: a signal that came while it was being destroyed then takes its default action.
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    bool requested() const { return signal_.load(std::memory_order_acquire) != 0; }
    int signal() const { return signal_.load(std::memory_order_acquire); } // 0: none yet
    std::string name() const;                                              // "SIGINT", "SIGTERM"

  private:
    void wait();
    sigset_t set_{}, old_{};
    std::atomic<int> signal_{0};
    std::atomic<bool> closing_{false};
    std::thread waiter_;
};

} // namespace roughgas::cli
