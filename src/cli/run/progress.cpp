#include "run/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace roughgas::cli {
namespace {

std::string duration(double s) {
    if (!(s >= 0) || s > 1e8)
        return "?";
    const auto t = static_cast<long long>(s + 0.5);
    if (t >= 3600)
        return fmt::format("{}h{:02}m", t / 3600, (t % 3600) / 60);
    if (t >= 60)
        return fmt::format("{}m{:02}s", t / 60, t % 60);
    return fmt::format("{}s", t);
}

} // namespace

ProgressLine::ProgressLine(std::ostream* out, int replicas, bool terminal, double interval_seconds,
                           double log_interval_seconds)
    : out_(out), start_(std::chrono::steady_clock::now()), last_draw_(start_), terminal_(terminal),
      interval_(terminal ? interval_seconds : log_interval_seconds),
      done_(static_cast<std::size_t>(replicas), 0.0), end_(static_cast<std::size_t>(replicas), 0.0),
      collisions_(static_cast<std::size_t>(replicas), 0.0) {}

double ProgressLine::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double ProgressLine::collisions() const {
    std::lock_guard lock(mutex_);
    return std::accumulate(collisions_.begin(), collisions_.end(), 0.0);
}

void ProgressLine::update(int r, double done, double end, double collisions) {
    std::lock_guard lock(mutex_);
    const auto k = static_cast<std::size_t>(r);
    done_[k] = done;
    end_[k] = end;
    collisions_[k] = collisions;
    const auto now = std::chrono::steady_clock::now();
    if (out_ && std::chrono::duration<double>(now - last_draw_).count() >= interval_) {
        last_draw_ = now;
        draw(false);
    }
}

void ProgressLine::finish() {
    std::lock_guard lock(mutex_);
    if (finished_)
        return;
    finished_ = true;
    if (out_)
        draw(true); // a run shorter than the interval still reports its rate once
}

// Time to go: the work left times the time per unit of work so far. Work is measured in
// collisions per particle, whose cost is the same early and late in a cooling run.
void ProgressLine::draw(bool final) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double done = std::accumulate(done_.begin(), done_.end(), 0.0);
    // Every replica runs to the same end; those not started yet have reported none.
    const double total = *std::max_element(end_.begin(), end_.end()) * static_cast<double>(end_.size());
    const double coll = std::accumulate(collisions_.begin(), collisions_.end(), 0.0);
    const double f = total > 0 ? std::min(1.0, done / total) : 0.0;
    const double to_go = f > 0 ? s * (1 - f) / f : -1.0;
    std::string line =
        fmt::format("roughgas run: {:5.1f}%  {:.3g} collisions/s  {} elapsed  {} to go", 100 * f,
                    s > 0 ? coll / s : 0.0, duration(s), final ? "0s" : duration(to_go));
    if (!terminal_) {
        *out_ << line << '\n' << std::flush;
        drawn_ = true;
        return;
    }
    const std::size_t w = line.size();
    if (w < width_)
        line.append(width_ - w, ' '); // blank what a longer line left
    width_ = std::max(width_, w);
    *out_ << '\r' << line << (final ? "\n" : "") << std::flush;
    drawn_ = true;
}

} // namespace roughgas::cli
