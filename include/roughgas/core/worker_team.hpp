#pragma once
// A team of threads for the parallel loops of one replica: `for_each(units, fn)` calls fn(u) once
// for every work unit u in [0, units), on the calling thread and the team's workers, and returns
// when every unit is done.
//
// Why not an OpenMP parallel region. On a machine shared with other processes (a compile, a
// second run, a browser) a thread of ours is often waiting for a time slice. An OpenMP region ends
// when every thread has *arrived* at its barrier, and libgomp's waiting threads spin by default:
// a run on two threads beside one busy process took 10x its one-thread time (measured, N = 1e5,
// a row per collision per particle; docs/performance.md). Here:
//  - units are claimed dynamically, and a job is complete when every *unit* is done: a worker that
//    has not been scheduled yet holds no unit and delays nothing (the caller does its share);
//  - each thread first claims, in order, the units of its own share, a contiguous block (thread t
//    of T: units [U t/T, U (t+1)/T)), then takes the others' last units (from the back of their
//    blocks) once its own are done. The box solver's phases (flight, sort, collisions) split the
//    grain store into units in the same order, so on an idle machine a grain stays with one thread
//    from phase to phase and step to step: interleaved claims moved most grains between the two
//    vCPUs' caches at every phase (a cache line takes 235 ns from one vCPU to the other on the
//    machine of docs/performance.md). On a loaded machine the stealing balances the work as before;
//  - a thread with nothing to do spins only briefly, then yields and sleeps on a futex
//    (std::atomic::wait), so it leaves its core to whoever needs it;
//  - while the machine has no CPU for every thread of the team (its threads wait on the run
//    queue: active_threads.hpp), jobs go to fewer threads, down to the caller alone, and the
//    others sleep; the team tries its threads again after a while.
// Which thread runs a unit never matters for the results: callers give each unit its own outputs
// (and random streams keyed by the unit), combined in unit order.
#include "roughgas/core/active_threads.hpp"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace roughgas {

class WorkerTeam {
  public:
    // Whether the team hands work to fewer threads while they wait for CPUs (active_threads.hpp).
    enum class Load { followed, ignored };

    // `threads` - 1 workers (none for threads <= 1: for_each then runs every unit in the caller).
    explicit WorkerTeam(int threads, Load load = Load::followed);
    ~WorkerTeam();
    WorkerTeam(const WorkerTeam&) = delete;
    WorkerTeam& operator=(const WorkerTeam&) = delete;

    int threads() const { return static_cast<int>(workers_.size()) + 1; }
    // The threads that take the next job's units (the caller and the first workers).
    int active_threads() const { return active_.load(std::memory_order_relaxed); }
    // Hands the next jobs to the first n threads (n clamped to [1, threads()]; the others rest); a
    // team that follows the load sets it again at the end of its current window. Between jobs only.
    void set_active_threads(int n);

    // Calls fn(u) for u in [0, units), each once, on any of the team's threads; returns when all
    // are done. The first exception thrown by fn is rethrown here (the other units still run).
    // Not reentrant: fn must not call for_each of the same team.
    template <class F> void for_each(std::size_t units, F&& fn) {
        if (units == 0)
            return;
        if (workers_.empty() || units == 1) {
            run_inline(units, fn);
            return;
        }
        using Fn = std::remove_reference_t<F>;
        run_job(
            units, [](void* f, std::size_t u) { (*static_cast<Fn*>(f))(u); },
            const_cast<void*>(static_cast<const void*>(std::addressof(fn))));
    }

  private:
    using Call = void (*)(void*, std::size_t);
    void run_job(std::size_t units, Call call, void* ctx);
    // Every unit in the caller, in order; all run, and the first exception is rethrown after them.
    template <class F> static void run_inline(std::size_t units, F&& fn) {
        std::exception_ptr first;
        for (std::size_t u = 0; u < units; ++u) {
            try {
                fn(u);
            } catch (...) {
                if (!first)
                    first = std::current_exception();
            }
        }
        if (first)
            std::rethrow_exception(first);
    }
    void follow_load();                                      // once a window: the active threads
    void work(std::uint64_t generation, std::size_t self); // claims and runs units of the given job
    bool run_unit(std::uint64_t generation, std::size_t self, std::size_t block); // one unit of the block
    void worker_loop(std::size_t self);

    // Each thread's block of the job's units, its claim word (generation, first and end unit still
    // unclaimed; worker_team.cpp) in a cache line of its own: the owner claims at the front, the
    // others at the back.
    struct alignas(64) Block {
        std::atomic<std::uint64_t> claim{0};
    };
    // The job: published by storing its blocks' claim words, then the generation.
    std::atomic<Call> call_{nullptr};
    std::atomic<void*> ctx_{nullptr};
    std::atomic<std::size_t> units_{0};
    std::unique_ptr<Block[]> blocks_;
    std::atomic<std::uint64_t> generation_{0}; // the latest job; workers sleep on it
    std::atomic<std::size_t> done_{0};         // units of the current job completed
    std::atomic<bool> stop_{false};
    // The threads that take work (the first active_ of the team); workers beyond sleep on it.
    std::atomic<int> active_;
    // Watching the load (the caller's, between jobs): the workers' kernel thread ids (0 until
    // started), and the run-queue wait of the whole team when the current window began.
    bool follow_load_;
    ActiveThreads active_threads_;
    std::unique_ptr<std::atomic<int>[]> worker_tids_;
    std::chrono::steady_clock::time_point window_start_{};
    std::int64_t window_delay_ = 0;
    int window_caller_ = 0;   // 0: no window begun; -1: one begun without a measurement
    bool delays_read_ = false; // the kernel has reported the run-queue waits at least once
    std::mutex error_mutex_;
    std::exception_ptr error_;
    std::vector<std::thread> workers_;
};

} // namespace roughgas
