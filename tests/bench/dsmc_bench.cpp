// Collisions per second of the DSMC collision loop.
// Run: build/tests/bench/dsmc_bench [--benchmark_filter=...] [--benchmark_repetitions=3]
//
// Each benchmark builds a homogeneous cooling gas (bench_gas.hpp: Maxwellian start, T = 1, n = 1,
// unit grains; the ice cases in SI units with speeds ~0.1 m/s), warms it up for half a collision per
// particle and then times chunks of about 1e5 collisions (N/2 with groups), run as run_replica runs
// between two output rows (Engine::run_about). items_per_second = collisions per second. Counters:
// acceptance = collisions/candidates of the majorant, bytes = bytes per particle of the store,
// bytes_total = with the engine's index array and scratch. Groups: auto_groups(N) unless given
// (what roughgas run uses); wall-clock time where threads vary (UseRealTime).
//
//   BM_Case<...>/N/T     the kernels run_replica selects: constant rough / smooth / elastic smooth,
//                        coulomb, viscoelastic and brilliantov from cached tables; T threads
//   BM_Threads<...>/N/G/T  G groups (1: none) on T threads
//   BM_StepStart<...>/N/T  the step start alone (partition, counting sort, bounds) on T threads
//   BM_Classes<...>/N/K  speed classes of the majorant (K = 1: the plain vmax_a + vmax_b bound)
//   BM_Layout<...>       the same rough and smooth constant kernels on the other particle layouts
//   BM_Skip<...>         what each compile-time skip is worth: the rough kernel at beta = -1 (omega
//                        loaded and updated by zero) vs the smooth kernel; the mixture kernel with one
//                        species (species look-ups); per-collision variant dispatch (AnyRoughPolicy);
//                        constant restitution in the ice gas of BM_Case_Brilliantov (the tables)
#include "bench_gas.hpp"

#include <benchmark/benchmark.h>

namespace roughgas {
namespace {

using bench::BenchGas;
using bench::ice_grain;
using bench::make_bench_engine;
using bench::unit_grain;

// Times chunks of the gas (bench_gas.hpp); items_per_second = collisions per second.
template <class Store, class Policy, bool Mixture = false>
void run_bench(benchmark::State& state, const SpeciesSpec& species, const Policy& policy, int classes = 2,
               int groups = 0, int threads = 1) {
    BenchGas<Store, Policy, Mixture> gas(state.range(0), species, policy, classes, groups, threads);
    const auto& e = gas.engine();
    const std::int64_t c0 = e.collisions(), k0 = e.counters().candidates;
    for (auto _ : state) {
        gas.run_chunk();
        state.PauseTiming();
        gas.rescale_if_cooled();
        state.ResumeTiming();
    }
    state.SetItemsProcessed(e.collisions() - c0);
    state.counters["acceptance"] =
        static_cast<double>(e.collisions() - c0) / static_cast<double>(e.counters().candidates - k0);
    state.counters["bytes"] = static_cast<double>(Store::bytes_per_particle);
    state.counters["bytes_total"] = static_cast<double>(e.bytes_per_particle());
    state.counters["promotions"] =
        static_cast<double>(e.counters().promotions) / static_cast<double>(e.collisions());
}

// /N/T: N particles, T threads; the store (StoreFor), the groups (auto_groups(N)) and the speed
// classes (2) that roughgas run uses; wall-clock time. The cases: bench_gas.hpp.
template <class Case> void run_case(benchmark::State& s) {
    using Policy = decltype(Case::policy());
    run_bench<StoreFor<Policy>>(s, Case::species(), Case::policy(), 2, 0, static_cast<int>(s.range(1)));
}
void BM_Case_RoughConstant(benchmark::State& s) {
    run_case<bench::RoughConstantCase>(s);
}
void BM_Case_SmoothConstant(benchmark::State& s) {
    run_case<bench::SmoothConstantCase>(s);
}
void BM_Case_SmoothElastic(benchmark::State& s) {
    run_case<bench::SmoothElasticCase>(s);
}
void BM_Case_Coulomb(benchmark::State& s) {
    run_case<bench::CoulombCase>(s);
}
void BM_Case_ViscoelasticSmooth(benchmark::State& s) {
    run_case<bench::ViscoelasticSmoothCase>(s);
}
void BM_Case_Viscoelastic(benchmark::State& s) {
    run_case<bench::ViscoelasticCase>(s);
}
void BM_Case_Brilliantov(benchmark::State& s) {
    run_case<bench::BrilliantovCase>(s);
}

// Speed classes of the majorant (engine.hpp): 1 = the plain vmax_a + vmax_b bound.
void BM_Classes_RoughConstant(benchmark::State& s) {
    run_bench<RoughPacked>(s, unit_grain(), make_rough_constant(0.9, 0.5), static_cast<int>(s.range(1)));
}
void BM_Classes_SmoothConstant(benchmark::State& s) {
    run_bench<SmoothAoS>(s, unit_grain(), make_smooth_constant(0.9), static_cast<int>(s.range(1)));
}

void BM_Layout_RoughAoS64(benchmark::State& s) {
    run_bench<RoughAoS>(s, unit_grain(), make_rough_constant(0.9, 0.5));
}
void BM_Layout_RoughSoA(benchmark::State& s) {
    run_bench<RoughSoA>(s, unit_grain(), make_rough_constant(0.9, 0.5));
}
void BM_Layout_SmoothPacked24(benchmark::State& s) {
    run_bench<SmoothPacked>(s, unit_grain(), make_smooth_constant(0.9));
}

void BM_Skip_RoughKernelAtBetaMinusOne(benchmark::State& s) {
    run_bench<RoughPacked>(s, unit_grain(), make_rough_constant(0.9, -1.0));
}
void BM_Skip_MixtureKernelOneSpecies(benchmark::State& s) {
    run_bench<RoughPacked, RoughConstant, true>(s, unit_grain(), make_rough_constant(0.9, 0.5));
}
// What the tables cost in the brilliantov case's own gas: the constant rough kernel on the ice grains
// with about the mean coefficients that gas shows (measured: alpha 0.22-0.24, beta -0.96 over 2e6
// collisions), so that the gas cools and departs from a Maxwellian as it does (BM_Case_Brilliantov).
void BM_Skip_TablesInTheIceGas(benchmark::State& s) {
    run_bench<RoughPacked>(s, ice_grain(), make_rough_constant(0.23, -0.96));
}
void BM_Skip_VariantPerCollision(benchmark::State& s) {
    run_bench<RoughPacked, AnyRoughPolicy, true>(s, unit_grain(),
                                                 AnyRoughPolicy{make_rough_constant(0.9, 0.5)});
}

// Groups and threads (engine.hpp, "Groups"): /N/G/T, wall-clock time (UseRealTime), so that
// items_per_second is collisions per second of the run on T threads.
void BM_Threads_RoughConstant(benchmark::State& s) {
    run_bench<RoughPacked>(s, unit_grain(), make_rough_constant(0.9, 0.5), 2, static_cast<int>(s.range(1)),
                           static_cast<int>(s.range(2)));
}
void BM_Threads_SmoothConstant(benchmark::State& s) {
    run_bench<SmoothAoS>(s, unit_grain(), make_smooth_constant(0.9), 2, static_cast<int>(s.range(1)),
                         static_cast<int>(s.range(2)));
}

// The step start alone (engine.hpp, begin_step: the partition, the counting sort, the bounds), /N/T:
// each iteration ends the step and takes one collision, which starts the next. Wall-clock time;
// grains_per_second = N / (time of one step start).
template <class Store, class Policy> void run_step_start(benchmark::State& state, const Policy& policy) {
    const auto N = static_cast<std::int64_t>(state.range(0));
    auto e = make_bench_engine<Store, Policy, false>(N, unit_grain(), policy, 2, auto_groups(N),
                                                     static_cast<int>(state.range(1)));
    e.run_collisions(N / 4);
    for (auto _ : state) {
        e.restart_step();
        e.run_collisions(e.collisions() + 1);
    }
    state.counters["grains_per_second"] =
        benchmark::Counter(static_cast<double>(N), benchmark::Counter::kIsIterationInvariantRate);
}
void BM_StepStart_RoughConstant(benchmark::State& s) {
    run_step_start<RoughPacked>(s, make_rough_constant(0.9, 0.5));
}
void BM_StepStart_SmoothConstant(benchmark::State& s) {
    run_step_start<SmoothAoS>(s, make_smooth_constant(0.9));
}

#define ROUGHGAS_SIZES ->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0)
// The table of docs/performance.md (scripts/bench_table.py): N = 1e4 .. 1e7 on 1 and 2 threads.
#define ROUGHGAS_CASE_SIZES                                                                                  \
    ->ArgsProduct({{10000, 100000, 1000000, 10000000}, {1, 2}})                                              \
        ->Unit(benchmark::kMillisecond)                                                                      \
        ->UseRealTime()                                                                                      \
        ->MinTime(2.0)
BENCHMARK(BM_Case_RoughConstant) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Case_SmoothConstant) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Case_SmoothElastic) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Case_Coulomb) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Case_ViscoelasticSmooth) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Case_Viscoelastic) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Case_Brilliantov) ROUGHGAS_CASE_SIZES;
BENCHMARK(BM_Classes_RoughConstant)
    ->ArgsProduct({{100000, 1000000}, {1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_Classes_SmoothConstant)
    ->ArgsProduct({{100000, 1000000}, {1, 2, 3, 4}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(BM_Threads_RoughConstant)
    ->ArgsProduct({{100000, 1000000}, {1, 4, 32}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_Threads_SmoothConstant)
    ->ArgsProduct({{100000, 1000000}, {1, 4, 32}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK(BM_StepStart_RoughConstant)
    ->ArgsProduct({{100000, 1000000, 10000000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_StepStart_SmoothConstant)
    ->ArgsProduct({{100000, 1000000, 10000000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);
BENCHMARK(BM_Layout_RoughAoS64) ROUGHGAS_SIZES;
BENCHMARK(BM_Layout_RoughSoA) ROUGHGAS_SIZES;
BENCHMARK(BM_Layout_SmoothPacked24) ROUGHGAS_SIZES;
BENCHMARK(BM_Skip_RoughKernelAtBetaMinusOne) ROUGHGAS_SIZES;
BENCHMARK(BM_Skip_MixtureKernelOneSpecies) ROUGHGAS_SIZES;
BENCHMARK(BM_Skip_VariantPerCollision) ROUGHGAS_SIZES;
BENCHMARK(BM_Skip_TablesInTheIceGas) ROUGHGAS_SIZES;

} // namespace
} // namespace roughgas
