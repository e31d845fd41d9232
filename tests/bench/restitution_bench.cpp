// Restitution tables: look-up cost (ns per call) with the measured maximum error against the
// direct integrator, and build times. Run: build/tests/bench/restitution_bench
#include "roughgas/restitution/normal_table.hpp"
#include "roughgas/restitution/tangential_table.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace roughgas {
namespace {

ContactPair ice_fig2c() {
    const double R = 0.01, m = 4.0 / 3.0 * std::numbers::pi * R * R * R * 1000.0;
    // Brilliantov et al. (1996) Fig. 2c: zeta0 = 1e-3 R_eff, mu = sqrt(1e-3)
    Material mat{1e10, 0.3, 5.3e-5, std::sqrt(1e-3), 1e-3 * R / 2};
    return make_contact_pair(mat, {}, m, R, 0.4, m, R, 0.4);
}

TangentialTableOptions fig2_range() {
    TangentialTableOptions opt;
    opt.g_min = 1e-3; // 0.1 cm/s .. 1 m/s
    opt.g_max = 1.0;
    return opt;
}

const NormalTable& normal_table() {
    static const NormalTable t = NormalTable::build({});
    return t;
}
const TangentialTable& tangential_table() {
    static const TangentialTable t = TangentialTable::build(ice_fig2c(), fig2_range());
    return t;
}

void BM_NormalTableLookup(benchmark::State& state) {
    const NormalTable& t = normal_table();
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> lw(std::log(1e-16), std::log(1e4));
    std::vector<double> w(4096);
    for (auto& x : w) x = std::exp(lw(rng));
    double worst = 0;
    const DirectNormal direct{t.model(), {1e-13, 1e-15}};
    for (int i = 0; i < 2000; ++i) worst = std::max(worst, std::abs(t.eps_n(w[i]) / direct.eps_n(w[i]) - 1));
    std::size_t i = 0;
    double sum = 0;
    for (auto _ : state) {
        sum += t.eps_n(w[i++ & 4095]);
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations());
    state.counters["max_rel_err"] = worst;
}
BENCHMARK(BM_NormalTableLookup);

void BM_TangentialTableLookup(benchmark::State& state) {
    const TangentialTable& t = tangential_table();
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> lg(std::log(1e-3), std::log(1.0)), lr(std::log(1e-2), std::log(1e2));
    std::vector<std::pair<double, double>> g(4096);
    for (auto& [gn, gt] : g) {
        gn = std::exp(lg(rng));
        gt = gn * std::exp(lr(rng));
    }
    double worst = 0;
    int fallbacks = 0;
    const DirectTangential direct{t.pair(), t.options().tol};
    for (int i = 0; i < 1000; ++i) {
        worst = std::max(worst, std::abs(t.eps_t(g[i].first, g[i].second) - direct.eps_t(g[i].first, g[i].second)));
        fallbacks += std::isnan(t.lookup(g[i].first, g[i].second));
    }
    std::size_t i = 0;
    double sum = 0;
    for (auto _ : state) {
        const auto& q = g[i++ & 4095];
        sum += t.eps_t(q.first, q.second);
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations());
    state.counters["max_abs_err"] = worst;
    state.counters["direct_fraction"] = fallbacks / 1000.0;
}
BENCHMARK(BM_TangentialTableLookup);

void BM_NormalTableBuild(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(NormalTable::build({}).intervals());
}
BENCHMARK(BM_NormalTableBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_TangentialTableBuild(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(TangentialTable::build(ice_fig2c(), fig2_range()).stats());
}
BENCHMARK(BM_TangentialTableBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
} // namespace roughgas
