#include "roughgas/core/worker_team.hpp"

#include "roughgas/core/run_delay.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

namespace roughgas {

namespace {

// A short spin before sleeping: a job of the collision loop follows the previous one within
// microseconds when the machine is idle (a futex wake costs a few microseconds more), and a spin
// this short costs a shared core nothing noticeable.
constexpr int spin_iterations = 2000;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Waits until `a` differs from `old`: spins briefly, yields a few times (a thread of another
// process on this core gets it), then sleeps on a futex.
template <class T> void wait_while_equal(const std::atomic<T>& a, T old) {
    for (int i = 0; i < spin_iterations; ++i) {
        if (a.load(std::memory_order_acquire) != old)
            return;
        cpu_relax();
    }
    for (int i = 0; i < 4; ++i) {
        if (a.load(std::memory_order_acquire) != old)
            return;
        std::this_thread::yield();
    }
    while (a.load(std::memory_order_acquire) == old)
        a.wait(old, std::memory_order_acquire);
}

} // namespace

WorkerTeam::WorkerTeam(int threads, Load load)
    : blocks_(std::make_unique<Block[]>(static_cast<std::size_t>(std::max(threads, 1)))), active_(std::max(threads, 1)),
      follow_load_(load == Load::followed && threads > 1),
      active_threads_(threads, static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                                   reinterpret_cast<std::uintptr_t>(this)),
      worker_tids_(std::make_unique<std::atomic<int>[]>(static_cast<std::size_t>(std::max(threads, 1)))) {
    for (int t = 1; t < threads; ++t)
        workers_.emplace_back([this, t] { worker_loop(static_cast<std::size_t>(t)); });
}

WorkerTeam::~WorkerTeam() {
    stop_.store(true, std::memory_order_release);
    generation_.fetch_add(1, std::memory_order_acq_rel);
    generation_.notify_all();
    active_.store(std::numeric_limits<int>::max(), std::memory_order_release); // wakes the resting
    active_.notify_all();
    for (std::thread& w : workers_)
        w.join();
}

// A block's claim word: generation (24 bits) | first unclaimed unit (20 bits) | end of the
// unclaimed units (20 bits). A claim is valid only for the job it names, and a job's call and
// context are read after a successful claim, when the job cannot have ended (its claimed unit is
// not done), so they are that job's.
namespace {
constexpr std::uint64_t unit_bits = 20;
constexpr std::uint64_t unit_mask = (std::uint64_t{1} << unit_bits) - 1;
std::uint64_t claim_word(std::uint64_t generation, std::uint64_t first, std::uint64_t end) {
    return ((generation & 0xffffffULL) << (2 * unit_bits)) | (first << unit_bits) | end;
}
} // namespace

// Claims one unit of `block` (its front for its owner, its back for the others) and runs it; false
// when the block has none left or belongs to another job (this worker woke late).
bool WorkerTeam::run_unit(std::uint64_t generation, std::size_t self, std::size_t block) {
    std::atomic<std::uint64_t>& claim = blocks_[block].claim;
    std::uint64_t c = claim.load(std::memory_order_acquire);
    std::uint64_t unit = 0;
    for (;;) {
        const std::uint64_t first = (c >> unit_bits) & unit_mask, end = c & unit_mask;
        if ((c >> (2 * unit_bits)) != (generation & 0xffffffULL) || first >= end)
            return false;
        const bool front = block == self;
        if (claim.compare_exchange_weak(c, front ? c + (std::uint64_t{1} << unit_bits) : c - 1,
                                        std::memory_order_acq_rel, std::memory_order_acquire)) {
            unit = front ? first : end - 1;
            break;
        }
    }
    const Call call = call_.load(std::memory_order_acquire);
    void* const ctx = ctx_.load(std::memory_order_acquire);
    const std::size_t units = units_.load(std::memory_order_acquire);
    try {
        call(ctx, static_cast<std::size_t>(unit));
    } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex_);
        if (!error_)
            error_ = std::current_exception();
    }
    if (done_.fetch_add(1, std::memory_order_acq_rel) + 1 == units)
        done_.notify_one();
    return true;
}

void WorkerTeam::work(std::uint64_t generation, std::size_t self) {
    const auto T = static_cast<std::size_t>(threads());
    for (std::size_t k = 0; k < T; ++k) {
        const std::size_t block = (self + k) % T;
        while (run_unit(generation, self, block)) {
        }
    }
}

void WorkerTeam::worker_loop(std::size_t self) {
    worker_tids_[self].store(this_thread_id(), std::memory_order_release);
    std::uint64_t seen = 0;
    for (;;) {
        wait_while_equal(generation_, seen);
        seen = generation_.load(std::memory_order_acquire);
        if (stop_.load(std::memory_order_acquire))
            return;
        // Not among the active threads: rest until the team takes this thread back. A job the
        // team publishes meanwhile has no units for it (run_job), and the others take them all.
        for (int a = active_.load(std::memory_order_acquire); a <= static_cast<int>(self);
             a = active_.load(std::memory_order_acquire))
            active_.wait(a, std::memory_order_acquire);
        if (stop_.load(std::memory_order_acquire))
            return;
        work(seen, self);
    }
}

void WorkerTeam::set_active_threads(int n) {
    n = std::clamp(n, 1, threads());
    if (n != active_.load(std::memory_order_relaxed)) {
        active_.store(n, std::memory_order_release);
        active_.notify_all(); // the workers resting on it
    }
}

// Ends the current window when it has lasted ActiveThreads::window: the team's run-queue wait over
// the window gives the threads that take the next jobs. The caller's own wait counts only when the
// same thread began the window (a team may be driven from different threads in turn).
void WorkerTeam::follow_load() {
    const auto now = std::chrono::steady_clock::now();
    if (window_caller_ != 0 && now - window_start_ < std::chrono::duration<double>(ActiveThreads::window))
        return;
    const int caller = this_thread_id();
    std::optional<std::int64_t> delay = run_delay_ns(caller);
    if (!delay && !delays_read_) { // the kernel does not say: every thread takes work, as without watching
        follow_load_ = false;
        set_active_threads(threads());
        return;
    }
    for (std::size_t t = 1; delay && t < static_cast<std::size_t>(threads()); ++t) {
        const int tid = worker_tids_[t].load(std::memory_order_acquire);
        // A worker not started yet, or without CPU time counted yet (schedstat's zeros), begins
        // the window again; so does a read that failed (no file descriptor left, ...).
        const std::optional<std::int64_t> d = tid != 0 ? run_delay_ns(tid) : std::nullopt;
        delay = d ? std::optional<std::int64_t>(*delay + *d) : std::nullopt;
    }
    if (!delay) { // no measurement: the next one after a window, as a new beginning
        window_caller_ = -1;
        window_start_ = now;
        return;
    }
    delays_read_ = true;
    if (window_caller_ == caller) {
        const double wall = std::chrono::duration<double>(now - window_start_).count();
        const double lost = static_cast<double>(*delay - window_delay_) * 1e-9 / wall;
        set_active_threads(active_threads_.after_window(lost, std::chrono::duration<double>(now.time_since_epoch()).count()));
    }
    window_caller_ = caller;
    window_start_ = now;
    window_delay_ = *delay;
}

void WorkerTeam::run_job(std::size_t units, Call call, void* ctx) {
    if (units > unit_mask)
        throw std::length_error("WorkerTeam: more than 2^20 - 1 units in one job");
    if (follow_load_)
        follow_load();
    const auto active = static_cast<std::size_t>(active_.load(std::memory_order_relaxed));
    if (active == 1) {
        run_inline(units, [&](std::size_t u) { call(ctx, u); });
        return;
    }
    const std::uint64_t generation = generation_.load(std::memory_order_relaxed) + 1;
    call_.store(call, std::memory_order_relaxed);
    ctx_.store(ctx, std::memory_order_relaxed);
    units_.store(units, std::memory_order_relaxed);
    done_.store(0, std::memory_order_relaxed);
    // The active threads' shares; the others' are empty (they rest, or wake late and find none).
    const auto T = static_cast<std::size_t>(threads());
    for (std::size_t t = 0; t < T; ++t) {
        const std::size_t first = t < active ? units * t / active : 0, end = t < active ? units * (t + 1) / active : 0;
        blocks_[t].claim.store(claim_word(generation, first, end), std::memory_order_release);
    }
    generation_.store(generation, std::memory_order_release);
    generation_.notify_all();
    work(generation, 0);
    // Every unit is claimed; wait for those still running on a worker.
    for (std::size_t d = done_.load(std::memory_order_acquire); d != units; d = done_.load(std::memory_order_acquire))
        wait_while_equal(done_, d);
    if (error_) {
        std::exception_ptr e;
        {
            const std::lock_guard<std::mutex> lock(error_mutex_);
            e = std::exchange(error_, nullptr);
        }
        std::rethrow_exception(e);
    }
}

} // namespace roughgas
