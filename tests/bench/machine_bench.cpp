// What a random access costs on this machine: the latency the collision loop's grain loads meet
// (dsmc/engine.hpp prefetches them; this measures them unprefetched). Not project code under test:
// a probe that explains the DSMC benchmarks (docs/performance.md).
// Run: build/tests/bench/machine_bench
//
//   BM_Machine_RandomLoad/MiB    dependent loads along a random cycle through every cache line of a
//                                buffer of MiB on huge pages (core/huge_page_buffer.hpp), as the
//                                stores and the index array are: L2, L3 and memory latency
//   BM_Machine_PageSpread/pages  dependent loads along a random cycle through one line in each of
//                                `pages` 4 KiB pages of the same kind of buffer, the lines spread over
//                                the cache sets: 64 B per page, so the lines stay in L2 (256 KiB at
//                                4096 pages). Where the time per load jumps while the data still fits
//                                in L2, the address translations miss the TLB: beyond 3072 pages
//                                (Zen 4's L2 TLB) only if they are 4 KiB translations, i.e. if the
//                                hypervisor backs the guest's huge pages with small pages.
//   BM_Machine_LineTransfer      two threads hand one cache line back and forth (an atomic counter
//                                each waits for and then increments): the one-way time of a line
//                                between the cores that run them. On a VM it tells whether its two
//                                vCPUs share an L3 at the moment (tens of ns) or not (~150 ns and
//                                more), which the hypervisor may change from one second to the next.
// Counters: ns_per_load = wall time per dependent load; ns_one_way = half a round trip.
#include "roughgas/core/huge_page_buffer.hpp"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

#if defined(__linux__)
#include <sched.h>
#endif

namespace roughgas {
namespace {

constexpr std::size_t line = 64, page = 4096;

// Writes into buf a random cycle through the byte offsets `at`: each visited word holds the offset
// of the next. Returns the start.
std::size_t link_cycle(HugePageBuffer<std::uint64_t>& buf, const std::vector<std::size_t>& at) {
    std::vector<std::size_t> order(at.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
    for (std::size_t k = 0; k < order.size(); ++k)
        buf[at[order[k]] / sizeof(std::uint64_t)] = at[order[(k + 1) % order.size()]];
    return at[order[0]];
}

void chase(benchmark::State& state, HugePageBuffer<std::uint64_t>& buf, std::size_t start) {
    constexpr std::int64_t loads = 1 << 20;
    std::size_t x = start;
    for (std::int64_t k = 0; k < loads; ++k) // warm the caches and TLBs with one pass
        x = buf[x / sizeof(std::uint64_t)];
    for (auto _ : state) {
        for (std::int64_t k = 0; k < loads; ++k)
            x = buf[x / sizeof(std::uint64_t)];
        benchmark::DoNotOptimize(x);
    }
    state.SetItemsProcessed(state.iterations() * loads);
    state.counters["ns_per_load"] =
        benchmark::Counter(static_cast<double>(state.iterations() * loads),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Machine_RandomLoad(benchmark::State& state) {
    const std::size_t bytes = static_cast<std::size_t>(state.range(0)) << 20;
    HugePageBuffer<std::uint64_t> buf(bytes / sizeof(std::uint64_t));
    std::vector<std::size_t> at(bytes / line);
    for (std::size_t k = 0; k < at.size(); ++k)
        at[k] = k * line;
    chase(state, buf, link_cycle(buf, at));
}

void BM_Machine_PageSpread(benchmark::State& state) {
    const auto pages = static_cast<std::size_t>(state.range(0));
    HugePageBuffer<std::uint64_t> buf(pages * page / sizeof(std::uint64_t));
    std::vector<std::size_t> at(pages);
    for (std::size_t k = 0; k < pages; ++k)
        at[k] = k * page + (k % (page / line)) * line; // another set for each of 64 neighbours
    chase(state, buf, link_cycle(buf, at));
}

// CPUs this process may run on (its affinity mask, where the system has one).
int usable_cpus() {
#if defined(__linux__)
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0)
        return CPU_COUNT(&set);
#endif
    return static_cast<int>(std::thread::hardware_concurrency());
}

void BM_Machine_LineTransfer(benchmark::State& state) {
    constexpr std::int64_t rounds = 1 << 18;
    if (usable_cpus() < 2) { // two spinning threads on one CPU hand the line over once per time slice
        state.SkipWithError("needs two CPUs");
        return;
    }
    alignas(64) std::atomic<std::int64_t> turn{0};
    for (auto _ : state) {
        turn.store(0);
        std::thread other([&] { // odd turns
            for (std::int64_t k = 0; k < rounds; ++k) {
                while (turn.load(std::memory_order_acquire) != 2 * k + 1) {
                }
                turn.store(2 * k + 2, std::memory_order_release);
            }
        });
        for (std::int64_t k = 0; k < rounds; ++k) { // even turns
            turn.store(2 * k + 1, std::memory_order_release);
            while (turn.load(std::memory_order_acquire) != 2 * k + 2) {
            }
        }
        other.join();
    }
    state.counters["ns_one_way"] =
        benchmark::Counter(static_cast<double>(state.iterations() * rounds * 2),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_Machine_RandomLoad)->Arg(1)->Arg(4)->Arg(16)->Arg(64)->Arg(256)->UseRealTime();
BENCHMARK(BM_Machine_PageSpread)->Arg(1024)->Arg(2048)->Arg(4096)->Arg(8192)->Arg(16384)->UseRealTime();
BENCHMARK(BM_Machine_LineTransfer)->UseRealTime();

} // namespace
} // namespace roughgas
