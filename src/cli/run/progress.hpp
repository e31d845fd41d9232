#pragma once
// The progress line of `roughgas run` on stderr: collisions per second and time to go, rewritten
// in place with '\r' at most every `interval` seconds on a terminal; when stderr is a file or a
// pipe (a batch job's log), a complete line at most every `log_interval` seconds instead.
// Thread-safe: replicas running in parallel report their own progress and the line shows the sum.
#include <chrono>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <vector>

namespace roughgas::cli {

class ProgressLine {
  public:
    // `replicas` reports, each going from 0 to `end` collisions per particle (the time clock: from 0
    // to `end` in time; the time to go then assumes a constant cost per unit time, which a cooling
    // gas, colliding ever less often, beats). `out` null: silent.
    ProgressLine(std::ostream* out, int replicas, bool terminal, double interval_seconds = 0.25,
                 double log_interval_seconds = 10);
    // Replica `r` has done `done` of `end` collisions per particle, `collisions` collisions.
    void update(int r, double done, double end, double collisions);
    // Ends the line (a newline after the last update), once.
    void finish();
    double seconds() const; // since construction
    double collisions() const;

  private:
    void draw(bool final);
    std::ostream* out_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    bool terminal_;
    double interval_;
    mutable std::mutex mutex_;
    std::vector<double> done_, end_, collisions_;
    bool drawn_ = false, finished_ = false;
    std::size_t width_ = 0;
};

} // namespace roughgas::cli
