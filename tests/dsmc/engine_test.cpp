// The DSMC engine (dsmc/engine.hpp) against exact statistics of the hard-sphere kernel
// (docs/model.md §4) and the limits of the collision rule. Every stochastic assertion states its
// sample (N, collisions, replicas) and its tolerance in standard errors; seeds are fixed.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/observables/moments.hpp"

#include "engine_test_support.hpp"
#include "test_stats.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <vector>

namespace roughgas {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

using test::make_engine;
using test::moments_of;
using test::total_energy;

using test::MeanErr;
using test::mean_err;

SpeciesSpec unit_grain(double T = 1, double T_rot = 1) {
    SpeciesSpec s; // m = 1, R = 0.5 (sigma = 1), q = 0.4
    s.temperature = T;
    s.rotational_temperature = T_rot;
    return s;
}

// nu = 2 C/(N t) of an elastic smooth gas in equilibrium, over the exact 4 n sigma^2 sqrt(pi T/m),
// with T of the replica's own state (conserved) and the finite-N factor (N - 1)/N of the pair count.
double elastic_rate_ratio(std::int64_t N, std::int64_t collisions, double step, std::uint64_t replica,
                          int classes = 4) {
    auto e = make_engine<SmoothAoS>({unit_grain()}, N, std::vector{make_smooth_constant(1.0)},
                                    EngineOptions{1.0, step, 7, replica, classes});
    const double T = moments_of(e).all.T_tr;
    e.run_collisions(collisions);
    const double nu = 2.0 * static_cast<double>(e.collisions()) / static_cast<double>(N) / e.time();
    const double exact = 4.0 * 1.0 * 1.0 * std::sqrt(std::numbers::pi * T / 1.0) * (N - 1.0) / N;
    return nu / exact;
}

TEST(Engine, ElasticCollisionRateIsExact) {
    // N = 1e4, 60 collisions per particle (3e5 collisions) per replica, 16 replicas: the replica
    // spread (0.17% per replica) gives a standard error of about 0.045% on the mean, so a majorant
    // that loses 0.25% of the collisions fails this 3-sigma test. Finite-N effects of the
    // closed system (fixed energy and momentum) are O(1/N): measured +0.6% at N = 100, +0.1% at
    // N = 1e3, below 3e-4 at N = 1e4 (100 replicas: 0.99973 +- 0.00017).
    // With one speed class (the plain vmax_a + vmax_b bound) and with four (the default).
    for (int classes : {1, 4}) {
        std::vector<double> r;
        for (std::uint64_t k = 0; k < 16; ++k)
            r.push_back(elastic_rate_ratio(10000, 300000, 1.0, k, classes));
        const MeanErr m = mean_err(r);
        std::printf(
            "  %d speed classes: nu/nu_exact = %.5f +- %.5f (16 replicas, N = 1e4, 3e5 collisions each)\n",
            classes, m.mean, m.err);
        EXPECT_NEAR(m.mean, 1.0, 3 * m.err) << classes << " classes";
        EXPECT_LT(m.err, 1.2e-3) << "the test must be able to see a 0.25% bias";
    }
}

TEST(Engine, CollisionCountDoesNotDependOnTheStepLength) {
    // Equilibrium, steps of 0.02 and 20 mean free times: 16 replicas each (N = 1e4, 2e5 collisions);
    // the two means agree within 4 combined standard errors (about 0.08% each). 16, not 8: the
    // standard error is itself estimated from the replicas, and with 8 of them (7 degrees of
    // freedom) a 4-error deviation happens by chance in 0.5 % of the seeds (seen when the collision
    // stream changed: 4.4 errors at 8 replicas, 1.2 errors at 40 with the same code); with 16 it is 0.1 %.
    std::vector<double> short_steps, long_steps;
    for (std::uint64_t k = 0; k < 16; ++k) {
        short_steps.push_back(elastic_rate_ratio(10000, 200000, 0.02, 100 + k));
        long_steps.push_back(elastic_rate_ratio(10000, 200000, 20.0, 200 + k));
    }
    const MeanErr a = mean_err(short_steps), b = mean_err(long_steps);
    std::printf("  step 0.02: %.5f +- %.5f   step 20: %.5f +- %.5f\n", a.mean, a.err, b.mean, b.err);
    EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.err, b.err));
    EXPECT_NEAR(a.mean, 1.0, 4 * a.err);
    EXPECT_NEAR(b.mean, 1.0, 4 * b.err);
}

TEST(Engine, ColdStartCountsEveryCollision) {
    // A cold start: T_tr = 1e-4, T_rot = 1, perfectly rough and elastic (alpha = beta = 1). Collisions
    // hand rotational energy to the translation and the collision rate grows 70-fold within the
    // run, far above the bounds a step starts with: grains are promoted to faster classes and the
    // bounds raised thousands of times. Collisions up to t = 10 (about 0.7 initial mean free times,
    // 40 collisions per particle): with steps of 0.01 current mean free times (the bounds refreshed
    // ~4000 times) and of 100 initial ones (one step: the bounds grow only by the exact in-step raises),
    // with 4 speed classes and with 1. 6 replicas each, N = 1e4: means within 4 combined standard
    // errors. A bound that is not raised (acceptance clipped at 1) undercounts here by a large factor.
    const auto count = [](double step, int classes, std::uint64_t replica) {
        auto e =
            make_engine<RoughAoS>({unit_grain(1e-4, 1.0)}, 10000, std::vector{make_rough_constant(1.0, 1.0)},
                                  EngineOptions{1.0, step, 8, replica, classes});
        e.run(std::numeric_limits<std::int64_t>::max(), 10.0, IgnoreCollisions{});
        return std::array{static_cast<double>(e.collisions()), static_cast<double>(e.counters().bound_raises),
                          static_cast<double>(e.counters().promotions),
                          static_cast<double>(e.counters().range_moves)};
    };
    std::vector<double> fine, coarse, plain;
    std::array<double, 4> sum{};
    for (std::uint64_t k = 0; k < 6; ++k) {
        fine.push_back(count(1e-2, 4, 300 + k)[0]);
        const auto c = count(100.0, 4, 400 + k);
        coarse.push_back(c[0]);
        for (int q = 0; q < 4; ++q)
            sum[q] += c[q] / 6;
        plain.push_back(count(100.0, 1, 500 + k)[0]);
    }
    const MeanErr a = mean_err(fine), b = mean_err(coarse), p = mean_err(plain);
    std::printf("  collisions to t = 10: step 0.01: %.0f +- %.0f, one step: %.0f +- %.0f, one step and "
                "class: %.0f +- %.0f\n"
                "  (one step: %.0f bound raises, %.0f promotions, %.0f block boundaries moved per run)\n",
                a.mean, a.err, b.mean, b.err, p.mean, p.err, sum[1], sum[2], sum[3]);
    EXPECT_GT(b.mean, 20000) << "the avalanche should take place";
    EXPECT_GT(sum[2], 1000) << "the test should exercise promotions";
    EXPECT_GT(sum[3], 100) << "the test should move block boundaries under pre-drawn candidates";
    EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.err, b.err));
    EXPECT_NEAR(p.mean, b.mean, 4 * std::hypot(p.err, b.err));
}

TEST(Engine, ImpactSpeedFollowsTheExactLaw) {
    // Elastic equilibrium at temperature T, equal masses m: over collisions, g_n = |g_c . n| has the
    // Rayleigh law P(g_n > x) = exp(-x^2 m/(4T)) (g_c Gaussian with variance 2T/m per component,
    // weighted by |g_c . n| and the cosine law). So u = exp(-g_n^2 m/(4T)) is uniform: chi-square over
    // 20 bins of 2e5 collisions (N = 1e5) below 43.82 (p = 1e-3, 19 dof).
    auto e = make_engine<SmoothAoS>({unit_grain()}, 100000, std::vector{make_smooth_constant(1.0)},
                                    EngineOptions{1.0, 1.0, 9, 0});
    const double T = moments_of(e).all.T_tr;
    std::vector<long> bins(20, 0);
    long n = 0;
    e.run(200000, inf, [&](const CollisionRecord& r, std::size_t) {
        const double u = std::exp(-r.g_n * r.g_n / (4.0 * T));
        bins[std::min(19, static_cast<int>(u * 20))]++;
        ++n;
    });
    const double expect = n / 20.0;
    double chi2 = 0;
    for (long b : bins)
        chi2 += (b - expect) * (b - expect) / expect;
    std::printf("  chi-square of the g_n law: %.2f (19 dof, threshold 43.82)\n", chi2);
    EXPECT_LT(chi2, 43.82);
}

TEST(Engine, ElasticPerfectlyRoughConservesEnergyAndEquilibrates) {
    // alpha = 1, beta = 1: every collision conserves the energy exactly (docs/model.md §3), so the total
    // changes by round-off only (1e5 ... 1e6 collisions of ~1e-16 relative each: < 1e-12). From
    // theta = 0.2 the gas relaxes to equipartition theta = 1 and to Maxwellians: N = 1e5, after 10
    // collisions per particle. With the total energy fixed, theta fluctuates by 2/sqrt(3N) = 0.37%
    // (tolerance 1.5% = 4 sigma); a20, a02 by (4/15) sqrt(45/N) = 0.0057 (tolerance 0.023);
    // A_cw by (2/3)/sqrt(N) = 0.0021 (tolerance 0.0085).
    auto e = make_engine<RoughAoS>({unit_grain(1.0, 0.2)}, 100000, std::vector{make_rough_constant(1.0, 1.0)},
                                   EngineOptions{1.0, 1.0, 10, 0});
    const double E0 = total_energy(e);
    EXPECT_NEAR(moments_of(e).all.theta, 0.2, 0.01);
    e.run_collisions(500000);
    const double E1 = total_energy(e);
    const Moments m = moments_of(e);
    std::printf("  |dE/E| = %.2e, theta = %.4f, a20 = %.4f, a02 = %.4f, a11 = %.4f, A_cw = %.4f\n",
                std::abs(E1 / E0 - 1), m.all.theta, m.all.a20, m.all.a02, m.all.a11, m.all.A_cw);
    EXPECT_LT(std::abs(E1 / E0 - 1), 1e-12);
    EXPECT_NEAR(m.all.theta, 1.0, 0.015);
    EXPECT_NEAR(m.all.a20, 0.0, 0.023);
    EXPECT_NEAR(m.all.a02, 0.0, 0.023);
    EXPECT_NEAR(m.all.A_cw, 0.0, 0.0085);
}

// The multiset of the grains' omega, bitwise (grains move within the store: engine.hpp).
std::vector<std::array<std::uint64_t, 3>> omega_bits(const auto& store) {
    std::vector<std::array<std::uint64_t, 3>> out;
    for (std::size_t i = 0; i < store.size(); ++i) {
        const Vec3& w = store.w(i);
        out.push_back({std::bit_cast<std::uint64_t>(w.x), std::bit_cast<std::uint64_t>(w.y),
                       std::bit_cast<std::uint64_t>(w.z)});
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(Engine, SmoothCollisionsNeverChangeOmega) {
    // beta = -1: in the rough kernel (omega loaded, updated by exactly zero) and in the smooth kernel
    // (omega never touched), every omega is bitwise unchanged after 1e5 inelastic collisions (as a
    // multiset: grains are re-sorted by speed).
    auto rough = make_engine<RoughAoS>({unit_grain()}, 10000, std::vector{make_rough_constant(0.7, -1.0)},
                                       EngineOptions{1.0, 1.0, 11, 0});
    auto smooth = make_engine<SmoothAoS>({unit_grain()}, 10000, std::vector{make_smooth_constant(0.7)},
                                         EngineOptions{1.0, 1.0, 11, 0});
    const auto w_rough = omega_bits(rough.store()), w_smooth = omega_bits(smooth.store());
    rough.run_collisions(100000);
    smooth.run_collisions(100000);
    EXPECT_TRUE(omega_bits(rough.store()) == w_rough);
    EXPECT_TRUE(omega_bits(smooth.store()) == w_smooth);
    // The same random stream and the same alpha: both kernels produce nearly the same velocities
    // (the rough rule rounds (m_eff/m)(a n - 0 g^T) in another order than the smooth one).
    EXPECT_NEAR(moments_of(rough).all.T_tr, moments_of(smooth).all.T_tr, 1e-9 * moments_of(smooth).all.T_tr);
}

TEST(Engine, ElasticSmoothGasStaysMaxwellian) {
    // alpha = 1, beta = -1 from a Maxwellian: a20 stays 0 within its sampling error (4/15) sqrt(45/N)
    // = 0.0057 for N = 1e5, at 5 times over 10 collisions per particle (tolerance 4 sigma each).
    auto e = make_engine<SmoothAoS>({unit_grain()}, 100000, std::vector{make_smooth_constant(1.0)},
                                    EngineOptions{1.0, 1.0, 12, 0});
    for (int k = 1; k <= 5; ++k) {
        e.run_collisions(k * 100000);
        const double a20 = moments_of(e).all.a20;
        EXPECT_NEAR(a20, 0.0, 0.023) << "after " << 2 * k << " collisions per particle";
    }
}

TEST(Engine, CumulantsDoNotDependOnTheStepLength) {
    // Homogeneous cooling, alpha = 0.5, beta = 0 (rough), after 4 collisions per particle: a20,
    // theta and the elapsed time with steps of 0.02 and 2 mean free times. 4 replicas each of
    // N = 1e5: a20 has a sampling error of ~0.006 per replica, so the 4-sigma band of the
    // difference (~0.02) would see a20 halved (what forbidding repeated collisions in a
    // step does at alpha = 0.5).
    struct Result {
        std::vector<double> a20, theta, t;
    };
    const auto run = [](double step, std::uint64_t seed) {
        Result r;
        for (std::uint64_t k = 0; k < 4; ++k) {
            auto e = make_engine<RoughAoS>({unit_grain()}, 100000, std::vector{make_rough_constant(0.5, 0.0)},
                                           EngineOptions{1.0, step, seed, k});
            e.run_collisions(200000);
            const Moments m = moments_of(e);
            r.a20.push_back(m.all.a20);
            r.theta.push_back(m.all.theta);
            r.t.push_back(e.time());
        }
        return r;
    };
    const Result fine = run(0.02, 13), coarse = run(2.0, 14);
    for (auto [name, a, b] :
         {std::tuple{"a20", fine.a20, coarse.a20}, std::tuple{"theta", fine.theta, coarse.theta},
          std::tuple{"t", fine.t, coarse.t}}) {
        const MeanErr x = mean_err(a), y = mean_err(b);
        std::printf("  %-5s step 0.02: %.5f +- %.5f   step 2: %.5f +- %.5f\n", name, x.mean, x.err, y.mean,
                    y.err);
        EXPECT_NEAR(x.mean, y.mean, 4 * std::hypot(x.err, y.err)) << name;
    }
}

TEST(Engine, SmoothSpheresFollowHaffsLaw) {
    // alpha = 0.8, smooth. Maxwellian cooling rate (derived from docs/model.md §3 and §4): each collision
    // loses (m/4)(1 - alpha^2) g_n^2 with <g_n^2> = 4T/m over collisions (Rayleigh law above), so
    // dT/dt = -zeta T with zeta = (1 - alpha^2) nu/3, nu = 4 n sigma^2 sqrt(pi T/m); hence Haff's law
    // T = T0/(1 + t/t0)^2 with t0 = 2/zeta(T0). The Sonine correction to zeta is 3 a2/16 with
    // a2 = -0.0126 at alpha = 0.8, -0.24%, so T (1 + t/t0)^2/T0 should tend to ~1.005 at late
    // times; the sampling error of T is sqrt(2/(3N)) = 0.37% for N = 5e4. Tolerance 2% for
    // t > 5 t0 (T fell by 40 and more) up to 60 collisions per particle (T/T0 ~ 1e-3).
    const std::int64_t N = 50000;
    auto e = make_engine<SmoothAoS>({unit_grain()}, N, std::vector{make_smooth_constant(0.8)},
                                    EngineOptions{1.0, 1.0, 15, 0});
    const double T0 = moments_of(e).all.T_tr;
    const double nu0 = 4.0 * std::sqrt(std::numbers::pi * T0) * (N - 1.0) / N;
    const double t0 = 2.0 / ((1 - 0.64) * nu0 / 3.0);
    int checked = 0;
    for (int k = 1; k <= 30; ++k) {
        e.run_collisions(k * N); // 2 collisions per particle per output
        const double t = e.time(), T = moments_of(e).all.T_tr;
        const double haff = T * (1 + t / t0) * (1 + t / t0) / T0;
        if (t > 5 * t0) {
            ++checked;
            EXPECT_NEAR(haff, 1.0, 0.02) << "t/t0 = " << t / t0 << " T/T0 = " << T / T0;
        }
        if (k % 10 == 0)
            std::printf("  t/t0 = %6.2f  T/T0 = %.3e  T (1 + t/t0)^2/T0 = %.4f\n", t / t0, T / T0, haff);
    }
    EXPECT_GT(checked, 10);
}

TEST(Engine, MixtureCollisionRatesAreExact) {
    // Binary elastic smooth mixture at one temperature T = 1: A (m = 1, R = 0.5), B (m = 4, R = 1),
    // half each, n = 1. Pair (a, b) collides at the rate P_ab pi sigma_ab^2 <g_ab>/V per unit time,
    // <g_ab> = sqrt((8/pi) T (1/m_a + 1/m_b)), P_ab the number of distinct pairs. 32 replicas of
    // N = 1e4 for 30 collisions per particle; each pair type within 3.5 standard errors: with the
    // error estimated from the replicas (Student t, 31 degrees of freedom) a correct engine fails one
    // of the three in 0.4 % of the seeds. (With 8 replicas and 3 errors it would be 6 %: with other
    // collision streams 2 of 10 seeds failed; pooled over the 10: 0.9997 +- 0.0005.)
    SpeciesSpec A = unit_grain(), B = unit_grain();
    A.name = "A";
    A.fraction = 0.5;
    B.name = "B";
    B.mass = 4;
    B.radius = 1;
    B.fraction = 0.5;
    std::vector<std::vector<double>> ratio(3);
    for (std::uint64_t k = 0; k < 32; ++k) {
        auto e = make_engine<SmoothAoS, true>({A, B}, 10000, std::vector(3, make_smooth_constant(1.0)),
                                              EngineOptions{1.0, 1.0, 16, k});
        const Moments m0 = moments_of(e);
        std::vector<double> counts(3, 0.0);
        e.run(150000, inf, [&](const CollisionRecord&, std::size_t type) { counts[type] += 1; });
        for (const PairType& p : e.pair_types()) {
            const double Ta = m0.species[p.a].T_tr, Tb = m0.species[p.b].T_tr; // elastic: conserved in total
            const double mean_g =
                std::sqrt(8.0 / std::numbers::pi *
                          (Ta / e.species()[p.a].grain.mass + Tb / e.species()[p.b].grain.mass));
            const double rate = p.pairs * p.pc.cross_section * mean_g / e.volume();
            ratio[pair_index(p.a, p.b, 2)].push_back(counts[pair_index(p.a, p.b, 2)] / e.time() / rate);
        }
    }
    for (int t = 0; t < 3; ++t) {
        const MeanErr m = mean_err(ratio[t]);
        std::printf("  pair type %d: rate/exact = %.4f +- %.4f\n", t, m.mean, m.err);
        EXPECT_NEAR(m.mean, 1.0, 3.5 * m.err) << "pair type " << t;
    }
}

TEST(Engine, StepIsTheRequestedFractionOfTheMeanFreeTime) {
    // Grains of unit-free size in SI-like units (m = 4e-3, R = 0.01, T = 4e-5): a step of 0.5 mean
    // free times is 0.5/nu with nu = 4 n sigma^2 sqrt(pi T/m) (Maxwellian, the state's T); so a
    // run of 20 collisions per particle takes about 40 steps.
    SpeciesSpec s;
    s.mass = 4e-3;
    s.radius = 0.01;
    s.temperature = s.rotational_temperature = 4e-5;
    const double n = 1e4;
    auto e = make_engine<RoughAoS>({s}, 10000, std::vector{make_rough_constant(1.0, 1.0)},
                                   EngineOptions{n, 0.5, 18, 0});
    const double T = moments_of(e).all.T_tr;
    e.run_collisions(1);
    const double nu = 4.0 * n * 0.02 * 0.02 * std::sqrt(std::numbers::pi * T / 4e-3);
    EXPECT_NEAR(e.step_length() * nu, 0.5, 0.005);
    e.run_collisions(100000);
    EXPECT_NEAR(static_cast<double>(e.counters().steps), 40.0, 2.0);
}

TEST(Engine, PausingDoesNotChangeTheTrajectory) {
    // run() stops after a collision count or before a time and resumes with the pending candidate:
    // a run paused 50 times ends bitwise where an unpaused one does.
    auto a = make_engine<RoughAoS>({unit_grain()}, 5000, std::vector{make_rough_constant(0.9, 0.3)},
                                   EngineOptions{1.0, 0.7, 17, 0});
    auto b = make_engine<RoughAoS>({unit_grain()}, 5000, std::vector{make_rough_constant(0.9, 0.3)},
                                   EngineOptions{1.0, 0.7, 17, 0});
    a.run_collisions(50000);
    for (int k = 1; k <= 25; ++k) {
        b.run_collisions(k * 2000 - 7);
        b.run(std::numeric_limits<std::int64_t>::max(), b.time() + 1e-3, IgnoreCollisions{});
    }
    b.run_collisions(50000);
    EXPECT_EQ(a.time(), b.time());
    for (std::size_t i = 0; i < 5000; ++i) {
        ASSERT_EQ(std::memcmp(&a.store().v(i), &b.store().v(i), sizeof(Vec3)), 0);
        ASSERT_EQ(std::memcmp(&a.store().w(i), &b.store().w(i), sizeof(Vec3)), 0);
    }
}

} // namespace
} // namespace roughgas
