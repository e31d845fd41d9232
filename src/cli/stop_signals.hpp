#pragma once
// SIGINT and SIGTERM during `roughgas run` (docs/running.md) and `roughgas sweep`:
// the first asks the command to stop at its next boundary (run: a checkpoint and the CSV so far;
// sweep: the finished points' files; exit 128 + the signal's number), a second one ends the process
// at once (the signal's default action).
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
    // `on_first`: what the command says on stderr when the first signal comes, after
    // "roughgas COMMAND: SIGNAME: ", e.g. "roughgas run: SIGINT: stopping at the next step, ...".
    // `repeat_ends_now` false (under an MPI launcher, which may deliver one stop as SIGINT then
    // SIGTERM, and kills the ranks itself after its timeout): later signals are ignored.
    StopSignals(std::string command, std::string on_first, bool repeat_ends_now = true);
    // Restores the mask: a signal that came while it was being destroyed then takes its default action.
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    bool requested() const { return signal_.load(std::memory_order_acquire) != 0; }
    int signal() const { return signal_.load(std::memory_order_acquire); } // 0: none yet
    std::string name() const;                                              // "SIGINT", "SIGTERM"
    static std::string name_of(int signal);                                // the same for a number

  private:
    void wait();
    std::string command_, on_first_;
    bool repeat_ends_now_ = true;
    sigset_t set_{}, old_{};
    std::atomic<int> signal_{0};
    std::atomic<bool> closing_{false};
    std::thread waiter_;
};

} // namespace roughgas::cli
