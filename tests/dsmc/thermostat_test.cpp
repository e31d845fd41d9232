// The thermostat's kicks (dsmc/thermostat.hpp) and a driven engine (dsmc/engine.hpp, "Thermostat"):
// the zero-sum bridge's law, momentum and energy to round-off, the injected energy, and the
// Langevin bath's equilibrium. Every stochastic assertion states its sample and its tolerance in
// standard errors; seeds are fixed.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/core/bytes.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/core/normal.hpp"
#include "roughgas/dsmc/thermostat.hpp"
#include "roughgas/observables/moments.hpp"

#include "engine_test_support.hpp"
#include "test_stats.hpp"
#include "thermostat_specs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <cstring>
#include <limits>
#include <vector>

namespace roughgas {
namespace {

using test::MeanErr;
using test::grain;
using test::langevin;
using test::mean_err;
using test::white_noise;

constexpr std::int64_t forever = std::numeric_limits<std::int64_t>::max();

using test::make_engine;
using test::moments_of;
using test::total_energy;

// Per species, the total momentum and the total spin angular momentum.
template <class E> std::vector<std::pair<Vec3, Vec3>> momenta(const E& e) {
    std::vector<std::pair<Vec3, Vec3>> p;
    for (const auto& b : e.species()) {
        Vec3 P{}, L{};
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i) {
            P += b.grain.mass * e.store().v(i);
            L += b.moment_of_inertia() * e.store().w(i);
        }
        p.push_back({P, L});
    }
    return p;
}

TEST(ZeroSumKicks, DrawsSumToTheTotalAndHaveTheConditionedLaw) {
    // n iid N(0, s^2) conditioned on summing to 0: each draw has variance s^2 (1 - 1/n), any two
    // the covariance -s^2/n, whatever their place in the sequence. 40000 trials of n = 5: the
    // variances' standard errors are ~0.7 %, the covariances' ~0.006 s^2; tolerance 5 of them.
    constexpr std::size_t n = 5, trials = 40000;
    const double s = 1.7;
    CollisionRng rng = make_collision_stream(StreamKey{3, Stream::test, 0, 0, 0});
    double sum2[n] = {}, cov01 = 0, cov24 = 0, worst_sum = 0;
    std::vector<Vec3> x;
    for (std::size_t t = 0; t < trials; ++t) {
        const Vec3 shift = draw_zero_sum(n, Vec3{}, s, rng, x);
        for (Vec3& y : x)
            y += shift;
        Vec3 total{};
        for (std::size_t k = 0; k < n; ++k) {
            total += x[k];
            sum2[k] += x[k].x * x[k].x;
        }
        cov01 += x[0].y * x[1].y;
        cov24 += x[2].z * x[4].z;
        worst_sum = std::max(worst_sum, norm(total));
    }
    EXPECT_LT(worst_sum, 1e-14);
    const double var = s * s * (1 - 1.0 / n);
    for (std::size_t k = 0; k < n; ++k)
        EXPECT_NEAR(sum2[k] / trials / var, 1.0, 5 * std::sqrt(2.0 / trials)) << "draw " << k;
    for (double c : {cov01, cov24})
        EXPECT_NEAR(c / trials, -s * s / n, 5 * s * s / std::sqrt(static_cast<double>(trials)));
    // A given total: the draws' sum is it, their mean total/n.
    const Vec3 shift = draw_zero_sum(7, Vec3{7, -14, 3.5}, s, rng, x);
    Vec3 total{};
    for (const Vec3& y : x)
        total += y + shift;
    EXPECT_LT(norm(total - Vec3{7, -14, 3.5}), 1e-13);
}

TEST(ZeroSumKicks, ChunkSumsHaveTheLawOfSumsOfZeroSumDraws) {
    // Chunks of 3, 2, 4 of 9 zero-sum draws of scale s: chunk c's sum has variance s^2 n_c (9 - n_c)/9.
    // 40000 trials: standard errors ~0.7 %, tolerance 5 of them; the sums close to round-off.
    const std::vector<std::size_t> sizes{3, 2, 4};
    constexpr std::size_t trials = 40000;
    CollisionRng rng = make_collision_stream(StreamKey{4, Stream::test, 0, 0, 0});
    std::vector<double> sum2(3, 0.0);
    for (std::size_t t = 0; t < trials; ++t) {
        const std::vector<Vec3> c = chunk_sums(sizes, 1.0, rng);
        ASSERT_LT(norm(c[0] + c[1] + c[2]), 1e-14);
        for (std::size_t k = 0; k < 3; ++k)
            sum2[k] += c[k].x * c[k].x;
    }
    for (std::size_t k = 0; k < 3; ++k) {
        const double nc = static_cast<double>(sizes[k]);
        EXPECT_NEAR(sum2[k] / trials / (nc * (9 - nc) / 9), 1.0, 5 * std::sqrt(2.0 / trials)) << "chunk " << k;
    }
}

TEST(Thermostat, KickVariancesIntegrateTheSchedule) {
    // White noise over [0.5, 3] of a schedule 2 on [0, 1), 0.5 from 1 on: int = 2 x 0.5 + 0.5 x 2 = 2.
    SpeciesThermostat th;
    th.drive.t = {0, 1};
    th.drive.value = {2, 0.5};
    th.rotational_share = 0.25;
    const double m = 2, I = 0.2;
    SpeciesKick k = species_kick(ThermostatKind::white_noise, th, m, I, 0.5, 3.0);
    EXPECT_DOUBLE_EQ(k.var_v, 0.75 * 2.0);
    EXPECT_DOUBLE_EQ(k.var_w, 0.25 * m / I * 2.0);
    // Langevin with a constant bath: the exact Ornstein-Uhlenbeck step, variance (T_b/m)(1 - a^2).
    th.drive.t = {0};
    th.drive.value = {3};
    th.friction = 0.7;
    th.rotational_friction = 0;
    k = species_kick(ThermostatKind::langevin, th, m, I, 1.0, 1.4);
    const double a = std::exp(-0.7 * 0.4);
    EXPECT_DOUBLE_EQ(k.decay_v, a);
    EXPECT_NEAR(k.var_v, 3.0 / m * (1 - a * a), 1e-15);
    EXPECT_EQ(k.decay_w, 1.0); // no rotational friction: the spins feel no bath
    EXPECT_EQ(k.var_w, 0.0);
}

TEST(DrivenEngine, KicksKeepTheMomentumToRoundOff) {
    // A rough inelastic mixture (masses 1 and 3) under white noise with a rotational share: after
    // 20 steps of kicks and collisions the total momentum is what the collisions alone leave (~0 from
    // the start, ~1e-16 per grain per step of round-off), never the kicks' random sum (~sqrt(N xi0^2 t)
    // ~ 10). The engine's recentring (above 1e-10 of the thermal speed) never fires.
    const std::int64_t N = 4000;
    std::vector<SpeciesSpec> sp{grain(), grain(1, 1, 3)};
    sp[0].fraction = sp[1].fraction = 0.5;
    auto e = make_engine<RoughPacked, true>(sp, N, std::vector(3, make_rough_constant(0.8, 0.3)),
                                            EngineOptions{1.0, 1.0, 11, 0});
    e.set_thermostat(white_noise(0.5, 0.3, 2));
    e.run(forever, 20.0, IgnoreCollisions{});
    ASSERT_GT(e.counters().steps, 10);
    EXPECT_EQ(e.counters().recentrings, 0);
    const double thermal = std::sqrt(moments_of(e).all.T_tr);
    Vec3 P{};
    for (const auto& [P_s, L_s] : momenta(e))
        P += P_s;
    EXPECT_LT(norm(P), 1e-12 * static_cast<double>(N) * thermal);
    // Each species' kicks sum to zero on their own: kicks in steps of 1e-6 mean free times, with
    // no collision between them (checked), leave every species' momentum and spin unchanged, though
    // they heat the gas from T_tr = 1 to about 2.
    auto f = make_engine<RoughPacked, true>(sp, N, std::vector(3, make_rough_constant(0.8, 0.3)),
                                            EngineOptions{1.0, 1e-6, 12, 0});
    const auto before = momenta(f);
    f.set_thermostat(white_noise(1e6, 0.3, 2));
    f.run(forever, 1.5e-6, IgnoreCollisions{});
    ASSERT_GT(f.counters().steps, 5);
    ASSERT_EQ(f.collisions(), 0);
    EXPECT_GT(moments_of(f).all.T_tr, 1.5); // from 1: the kicks did act
    const auto after = momenta(f);
    for (std::size_t s = 0; s < 2; ++s) {
        EXPECT_LT(norm(after[s].first - before[s].first), 1e-12 * static_cast<double>(N) * thermal) << s;
        EXPECT_LT(norm(after[s].second - before[s].second), 1e-12 * static_cast<double>(N) * thermal) << s;
    }
}

TEST(DrivenEngine, ExactEnergyInjectsTheIntendedEnergyToRoundOff) {
    // Elastic grains (alpha = 1 and beta = -1 or 1: every collision keeps the energy to round-off)
    // under white noise with exact_energy: the energy is the initial one plus N (3/2) m xi0^2 for
    // every unit of kicked time, to round-off over some 10^5 collisions.
    const std::int64_t N = 2000;
    const double xi2 = 0.8;
    {
        auto e = make_engine<SmoothAoS>({grain()}, N, std::vector{make_smooth_constant(1.0)},
                                        EngineOptions{1.0, 1.0, 5, 0});
        e.set_thermostat(white_noise(xi2, 0.0, 1, true));
        const double E0 = total_energy(e);
        e.run(forever, 30.0, IgnoreCollisions{});
        EXPECT_GT(e.collisions(), 50 * N);
        const double want = E0 + 1.5 * N * xi2 * e.kicked_until();
        EXPECT_NEAR(total_energy(e) / want, 1.0, 1e-11);
    }
    {
        // Rough: the share eps goes to the spins, exactly too (T_rot's energy checked on its own
        // would mix in the collisions' exchange; the total is exact).
        auto e = make_engine<RoughPacked>({grain()}, N, std::vector{make_rough_constant(1.0, 1.0)},
                                          EngineOptions{1.0, 1.0, 6, 0});
        e.set_thermostat(white_noise(xi2, 0.4, 1, true));
        const double E0 = total_energy(e);
        e.run(forever, 30.0, IgnoreCollisions{});
        const double want = E0 + 1.5 * N * xi2 * e.kicked_until();
        EXPECT_NEAR(total_energy(e) / want, 1.0, 1e-11);
    }
}

TEST(DrivenEngine, InjectedEnergyMatchesTheStrengthWithinStatistics) {
    // Without exact_energy the injection is exact in expectation: 16 replicas of an elastic rough
    // gas (N = 1000) kicked over t ~ 5 with eps = 0.5. The energy gained over N (3/2) xi0^2 t_kick
    // is 1 in the mean; tolerance 4 standard errors of the replicas (each ~1 % here).
    const std::int64_t N = 1000;
    const double xi2 = 1.0;
    std::vector<double> ratio;
    for (std::uint64_t r = 0; r < 16; ++r) {
        auto e = make_engine<RoughPacked>({grain()}, N, std::vector{make_rough_constant(1.0, 1.0)},
                                          EngineOptions{1.0, 1.0, 9, r});
        e.set_thermostat(white_noise(xi2, 0.5));
        const double E0 = total_energy(e);
        e.run(forever, 5.0, IgnoreCollisions{});
        ratio.push_back((total_energy(e) - E0) / (1.5 * N * xi2 * e.kicked_until()));
    }
    const MeanErr m = mean_err(ratio);
    EXPECT_NEAR(m.mean, 1.0, 4 * m.err) << "err " << m.err;
    EXPECT_LT(m.err, 0.02); // the test resolves a 10 % error
}

// An elastic gas in a Langevin bath at T_b started ten times hotter: after 12 relaxation times
// 1/(2 gamma) its temperatures are T_b and its cumulants zero. The Maxwellian at T_b is a fixed
// point of both the exact Ornstein-Uhlenbeck step and of elastic collisions, so the splitting leaves
// it unchanged: the tolerances are statistical only. Averages over R replicas of the final state,
// tolerance 4 standard errors.
template <class Store, bool Mixture, class Policy>
void expect_bath_equilibrium(std::vector<SpeciesSpec> species, std::vector<Policy> policies, double gamma_rot,
                             const char* what) {
    const std::int64_t N = 2000;
    const double T_b = 1.0, gamma = 0.5;
    const std::size_t S = species.size();
    std::vector<std::vector<double>> T_tr(S), T_rot(S), a20(S), a02(S);
    for (std::uint64_t r = 0; r < 12; ++r) {
        auto e = make_engine<Store, Mixture>(species, N, policies, EngineOptions{1.0, 1.0, 21, r});
        e.set_thermostat(langevin(T_b, gamma, gamma_rot, S));
        e.run(forever, 12.0 / gamma, IgnoreCollisions{});
        const Moments m = moments_of(e);
        for (std::size_t s = 0; s < S; ++s) {
            const GroupMoments& g = Mixture ? m.species[s] : m.all;
            T_tr[s].push_back(g.T_tr);
            T_rot[s].push_back(g.T_rot);
            a20[s].push_back(g.a20);
            a02[s].push_back(g.a02);
        }
    }
    for (std::size_t s = 0; s < S; ++s) {
        for (const auto& [name, x, want] : {std::tuple{"T_tr", &T_tr[s], T_b}, std::tuple{"T_rot", &T_rot[s], T_b},
                                            std::tuple{"a20", &a20[s], 0.0}, std::tuple{"a02", &a02[s], 0.0}}) {
            const MeanErr m = mean_err(*x);
            EXPECT_NEAR(m.mean, want, 4 * m.err) << what << ", species " << s << ": " << name << " err " << m.err;
        }
        // The replicas scatter as a canonical gas of N_s grains does, T_b sqrt(2/(3 N_s)) (within 1.6 x:
        // the spread of 12 replicas' spread), and the test resolves some 3-5 % of T_b.
        const double N_s = static_cast<double>(N) * species[s].fraction;
        EXPECT_LT(mean_err(T_tr[s]).err, 1.6 * T_b * std::sqrt(2.0 / (3.0 * N_s * 12))) << what;
    }
}

TEST(DrivenEngine, LangevinBathMakesSmoothGrainsMaxwellianAtItsTemperature) {
    // Smooth grains: the spins never collide; the rotational friction alone brings them to T_b.
    expect_bath_equilibrium<SmoothAoS, false>({grain(10, 10)}, std::vector{make_smooth_constant(1.0)}, 0.5,
                                              "smooth");
}

TEST(DrivenEngine, LangevinBathMakesRoughGrainsMaxwellianAtItsTemperature) {
    // Perfectly rough elastic grains, the bath on the translations only: the spins reach T_b through
    // the collisions (equipartition) from T_rot = 0.1 T_b.
    expect_bath_equilibrium<RoughPacked, false>({grain(10, 0.1)}, std::vector{make_rough_constant(1.0, 1.0)}, 0.0,
                                                "rough");
}

TEST(DrivenEngine, LangevinBathMakesAMixtureMaxwellianAtItsTemperature) {
    std::vector<SpeciesSpec> sp{grain(10, 1, 1), grain(5, 20, 4)};
    sp[0].fraction = 0.6;
    sp[1].fraction = 0.4;
    sp[1].radius = 0.7;
    expect_bath_equilibrium<RoughPacked, true>(sp, std::vector(3, make_rough_constant(1.0, 1.0)), 0.3, "mixture");
}


TEST(DrivenMoments, TheKickMapMovesEveryMomentAsKickingTheGrainsDoes) {
    // A rough gas with cumulants (a cooled rough state) kicked by hand with one Langevin step of a bath
    // at T_b = 2 (v and omega decayed, then Gaussians added). moments_at_drive_time with the same step
    // (as a lag of the kicks) predicts the kicked grains' moments: N = 2e5 grains, tolerance 5
    // sampling errors of a cumulant near a Maxwellian (sqrt(8/N) ~ 0.006), and T within 5e-3.
    const std::int64_t N = 200000;
    auto e = make_engine<RoughPacked>({grain(1, 3)}, N, std::vector{make_rough_constant(0.6, 0.4)},
                                      EngineOptions{1.0, 1.0, 31, 0});
    e.run_collisions(4 * N); // cumulants away from 0
    const auto slices = species_slices(e.species());
    const Moments before = moments_of(e);
    ASSERT_GT(std::abs(before.all.a20) + std::abs(before.all.a11), 0.02);
    ThermostatSpec th = langevin(1.0, 0.0, 0.0);
    const double gamma = 0.5, gamma_rot = 0.25, tau = 0.45;
    th.species[0].friction = gamma;
    th.species[0].rotational_friction = gamma_rot;
    th.species[0].drive.value = {2.0};
    const SpeciesKick k = species_kick(th.kind, th.species[0], 1.0, slices[0].moment_of_inertia, 0.0, tau);
    CollisionRng rng = make_collision_stream(StreamKey{5, Stream::test, 0, 0, 0});
    const ZigguratNormal normal;
    for (std::size_t i = 0; i < e.particles(); ++i) {
        const double sv = std::sqrt(k.var_v), sw = std::sqrt(k.var_w);
        e.store().v(i) = k.decay_v * e.store().v(i) + Vec3{sv * normal(rng), sv * normal(rng), sv * normal(rng)};
        e.store().w(i) = k.decay_w * e.store().w(i) + Vec3{sw * normal(rng), sw * normal(rng), sw * normal(rng)};
    }
    const Moments after = moments_of(e);
    // The row at t = tau of a gas whose kicks reached only t = 0: the map forward over [0, tau].
    const Moments predicted = moments_at_drive_time(before, slices, th, tau, 0.0);
    EXPECT_NEAR(predicted.all.T_tr / after.all.T_tr, 1.0, 5e-3);
    EXPECT_NEAR(predicted.all.T_rot / after.all.T_rot, 1.0, 5e-3);
    for (const auto& [name, p, a] : {std::tuple{"a20", predicted.all.a20, after.all.a20},
                                     std::tuple{"a02", predicted.all.a02, after.all.a02},
                                     std::tuple{"a11", predicted.all.a11, after.all.a11},
                                     std::tuple{"A_cw", predicted.all.A_cw, after.all.A_cw}})
        EXPECT_NEAR(p, a, 5 * std::sqrt(8.0 / N)) << name; // cumulant errors ~sqrt(8/N) near a Maxwellian
    // The inverse: a gas ahead of its row by the same step gives back the moments before.
    const Moments back = moments_at_drive_time(predicted, slices, th, 0.0, tau);
    EXPECT_NEAR(back.all.T_tr / before.all.T_tr, 1.0, 1e-12);
    EXPECT_NEAR(back.all.a20, before.all.a20, 1e-12);
    EXPECT_NEAR(back.all.a11, before.all.a11, 1e-12);
    EXPECT_NEAR(back.all.A_cw, before.all.A_cw, 1e-12);
}

TEST(DrivenMoments, RowsCarryNoSawtoothOfTheKicks) {
    // Smooth grains, alpha = 0.7, white noise, steps of one mean free time: within a step the grains'
    // T_tr falls by ~17 % (the kicks come at its start). Rows taken at 2000 points spread over the steps'
    // phases: the grains' T_tr in the first half of the steps exceeds the second half's by ~8 %, the
    // rows' (moments_at_drive_time) agree within 4 standard errors of the halves' difference.
    const std::int64_t N = 20000;
    auto e = make_engine<SmoothAoS>({grain()}, N, std::vector{make_smooth_constant(0.7)},
                                    EngineOptions{1.0, 1.0, 41, 0});
    const ThermostatSpec th = white_noise(1.0, 0.0);
    e.set_thermostat(th);
    e.run_collisions(30 * N);
    const auto slices = species_slices(e.species());
    std::vector<double> raw[2], row[2];
    for (int k = 0; k < 2000; ++k) {
        e.run_collisions(e.collisions() + N / 7 + 13); // about 0.29 steps apart: every phase
        const Moments m = moments_of(e);
        const int half = e.kicked_until() > e.time() ? 0 : 1; // kicks ahead: the step's first half
        raw[half].push_back(m.all.T_tr);
        row[half].push_back(moments_at_drive_time(m, slices, th, e.time(), e.kicked_until()).all.T_tr);
    }
    const MeanErr r0 = mean_err(raw[0]), r1 = mean_err(raw[1]), c0 = mean_err(row[0]), c1 = mean_err(row[1]);
    EXPECT_GT(r0.mean / r1.mean, 1.05); // the sawtooth the rows must not show
    const double err = std::hypot(c0.err, c1.err) / c1.mean;
    EXPECT_NEAR(c0.mean / c1.mean, 1.0, 4 * err) << "err " << err;
    EXPECT_LT(err, 0.005);
}

template <class E> bool same_particles(const E& a, const E& b) {
    for (std::size_t i = 0; i < a.particles(); ++i)
        for (const auto& [x, y] : {std::pair{a.store().v(i), b.store().v(i)}, {a.store().w(i), b.store().w(i)}})
            if (std::memcmp(&x, &y, sizeof x) != 0)
                return false;
    return true;
}

TEST(DrivenEngine, KicksDoNotDependOnTheThreadsAndResumeBitForBit) {
    // Groups of a step on one or two threads, and a run saved and resumed mid-step: the same bits.
    const std::int64_t N = 40000; // several chunks per species
    const EngineOptions opt{1.0, 1.0, 13, 2, 2, 4, 1};
    const auto make = [&](int threads) {
        EngineOptions o = opt;
        o.threads = threads;
        auto e = make_engine<RoughPacked>({grain()}, N, std::vector{make_rough_constant(0.7, 0.2)}, o);
        e.set_thermostat(white_noise(0.6, 0.2, 1, true));
        return e;
    };
    auto a = make(1);
    auto b = make(2);
    a.run_collisions(3 * N + 5);
    b.run_collisions(3 * N + 5);
    ByteWriter w;
    a.save_state(w);
    const std::string saved = w.take();
    auto c = make(2);
    ByteReader r(saved);
    c.load_state(r);
    EXPECT_EQ(r.remaining(), 0u);
    for (auto* e : {&a, &b, &c})
        e->run(forever, e->time() + 7.3, IgnoreCollisions{});
    EXPECT_TRUE(same_particles(a, b));
    EXPECT_EQ(a.kicked_until(), b.kicked_until());
    EXPECT_EQ(a.step_length(), b.step_length());
    EXPECT_TRUE(same_particles(a, c));
    EXPECT_EQ(a.kicked_until(), c.kicked_until());
    // The kicks are within about half a step of the time (see "Thermostat" in dsmc/engine.hpp).
    EXPECT_LT(std::abs(a.kicked_until() - a.time()), a.step_length());
}

} // namespace
} // namespace roughgas
