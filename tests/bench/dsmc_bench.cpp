// Collisions per second of the DSMC collision loop (issue 3 "Speed", issue 5 items 1-3).
// Run: build/tests/bench/dsmc_bench [--benchmark_filter=...] [--benchmark_repetitions=3]
//
// Each benchmark builds a homogeneous cooling gas (Maxwellian start, T = 1, n = 1, unit grains;
// the ice cases in SI units with speeds ~0.1 m/s), warms it up for half a collision per particle
// and then times chunks of 1e5 collisions. items_per_second = collisions per second. Counters:
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
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/dsmc/tables.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

namespace roughgas {
namespace {

constexpr std::int64_t bench_chunk = 100000;

// A homogeneous gas of N grains of `species` at T = 1 (Maxwellian, seed 1), number density
// n = 1/sigma^3 (sigma = 2R), steps of one mean free time: what every benchmark here runs.
template <class Store, class Policy, bool Mixture>
Engine<Store, Policy, Mixture> make_bench_engine(std::int64_t N, const SpeciesSpec& species,
                                                 const Policy& policy, int classes, int groups, int threads) {
    const auto blocks = make_species_blocks({species}, N);
    Store store(static_cast<std::size_t>(N));
    init_maxwellian(store, blocks, 1, 0);
    return Engine<Store, Policy, Mixture>(
        blocks, {policy}, std::move(store),
        EngineOptions{1.0 / std::pow(2 * species.radius, 3), 1.0, 1, 0, classes, groups, threads});
}

template <class Store, class Policy, bool Mixture = false>
void run_bench(benchmark::State& state, const SpeciesSpec& species, const Policy& policy, int classes = 2,
               int groups = 0, int threads = 1) {
    const auto N = static_cast<std::int64_t>(state.range(0));
    if (groups == 0) // what run_replica uses (run_spec.hpp)
        groups = auto_groups(N);
    auto e = make_bench_engine<Store, Policy, Mixture>(N, species, policy, classes, groups, threads);
    // A grouped run meets a collision target in parallel phases and a short serial tail
    // (engine.hpp): chunks of at least a step (N/2 collisions), as run_replica uses.
    const std::int64_t chunk = groups > 1 ? std::max<std::int64_t>(bench_chunk, N / 2) : bench_chunk;
    e.run_collisions(N / 4); // half a collision per particle: steps, rings and pages warm
    // The gas cools; velocity-dependent restitution would drift out of its regime (and out of the
    // tangential table's range), so between timed chunks v and omega are scaled back to the initial
    // translational and rotational temperatures whenever one of them has halved (not timed).
    const auto temperatures = [&] {
        double v2 = 0, w2 = 0;
        for (std::size_t i = 0; i < e.store().size(); ++i) {
            v2 += norm2(e.store().v(i));
            w2 += norm2(e.store().w(i));
        }
        return std::pair(v2, w2); // proportional to T_tr and T_rot
    };
    const auto [v2_0, w2_0] = temperatures();
    const std::int64_t c0 = e.collisions(), k0 = e.counters().candidates;
    for (auto _ : state) {
        e.run_collisions(e.collisions() + chunk);
        state.PauseTiming();
        if (const auto [v2, w2] = temperatures(); v2 < 0.5 * v2_0 || w2 < 0.5 * w2_0) {
            const double fv = std::sqrt(v2_0 / v2), fw = w2 > 0 ? std::sqrt(w2_0 / w2) : 1.0;
            for (std::size_t i = 0; i < e.store().size(); ++i) {
                e.store().v(i) *= fv;
                e.store().w(i) *= fw;
            }
            e.restart_step();
        }
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

SpeciesSpec unit_grain() {
    return SpeciesSpec{};
}

// Ice (seed 000 Fig. 2c, the restitution benchmark's pair): R = 1 cm, A = 5.3e-5 s,
// zeta_0 = 1e-3 R_eff, mu = sqrt(1e-3); T such that each velocity component has rms 0.1 m/s.
ContactPair ice_pair() {
    const double R = 0.01, m = 4.0 / 3.0 * std::numbers::pi * R * R * R * 1000.0;
    const Material mat{1e10, 0.3, 5.3e-5, std::sqrt(1e-3), 1e-3 * R / 2};
    return make_contact_pair(mat, {}, m, R, 0.4, m, R, 0.4);
}
SpeciesSpec ice_grain() {
    const ContactPair p = ice_pair();
    SpeciesSpec s;
    s.mass = 2 * p.m_eff;
    s.radius = 2 * p.R_eff;
    s.temperature = s.rotational_temperature = s.mass * 0.01;
    return s;
}
const NormalTable& normal_table() {
    static const NormalTable t = NormalTable::build({});
    return t;
}
const TangentialTable& tangential_table() {
    static const TangentialTable t = [] {
        // g_N from 1e-6 m/s (as `roughgas run`, RunSpec::table_g_min) to 1 m/s (7 thermal speeds):
        // no collision of this gas falls back to the direct integrator (measured over 4e5). The
        // range below 1e-3 m/s adds nothing measurable to the build (0.7 s), but with g_min = 1e-3
        // 1.5e-4 of the collisions were integrated directly, at ~1 ms each: half the run time.
        TangentialTableOptions opt;
        opt.g_min = 1e-6;
        opt.g_max = 1.0;
        return TangentialTable::build(ice_pair(), opt);
    }();
    return t;
}

// /N/T: N particles, T threads; the store (StoreFor), the groups (auto_groups(N)) and the speed
// classes (2) that roughgas run uses; wall-clock time.
template <class Policy> void run_case(benchmark::State& s, const SpeciesSpec& species, const Policy& policy) {
    run_bench<StoreFor<Policy>>(s, species, policy, 2, 0, static_cast<int>(s.range(1)));
}
void BM_Case_RoughConstant(benchmark::State& s) {
    run_case(s, unit_grain(), make_rough_constant(0.9, 0.5));
}
void BM_Case_SmoothConstant(benchmark::State& s) {
    run_case(s, unit_grain(), make_smooth_constant(0.9));
}
void BM_Case_SmoothElastic(benchmark::State& s) {
    run_case(s, unit_grain(), make_smooth_constant(1.0));
}
void BM_Case_Coulomb(benchmark::State& s) {
    run_case(s, unit_grain(),
             make_coulomb(0.9, 0.5, 0.2, make_pair_constants({1, 0.5, 0.4}, {1, 0.5, 0.4}).kappa));
}
void BM_Case_ViscoelasticSmooth(benchmark::State& s) {
    run_case(s, ice_grain(), make_viscoelastic_smooth(normal_table(), ice_pair()));
}
void BM_Case_Viscoelastic(benchmark::State& s) {
    run_case(s, ice_grain(), make_viscoelastic(normal_table(), ice_pair(), 0.5));
}
void BM_Case_Brilliantov(benchmark::State& s) {
    run_case(s, ice_grain(), make_brilliantov(normal_table(), tangential_table(), ice_pair()));
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
// with about the mean coefficients that gas shows (alpha 0.22-0.24, beta -0.96 over 2e6 collisions,
// session 8), so that the gas cools and departs from a Maxwellian as it does (BM_Case_Brilliantov).
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
// The README table (scripts/bench_table.py): N = 1e4 .. 1e7 on 1 and 2 threads.
#define ROUGHGAS_CASE_SIZES                                                                              \
    ->ArgsProduct({{10000, 100000, 1000000, 10000000}, {1, 2}})                                           \
        ->Unit(benchmark::kMillisecond)                                                                   \
        ->UseRealTime()                                                                                   \
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
