// The grouped engine (dsmc/engine.hpp, "Groups"): a per-step random partition of the grains into
// groups that collide independently, in parallel. What must hold: the collision statistics stay
// exact (rate of every pair, the |g.n| law, the relaxation of the state), and the trajectory depends
// on the seed and the group count only: never on the thread count nor on where run() pauses.
// Every stochastic assertion states its sample and its tolerance in standard errors; seeds are fixed.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/observables/moments.hpp"

#include "test_stats.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

namespace roughgas {
namespace {

template <class Store, class Policy>
Engine<Store, Policy, false> make_engine(std::int64_t N, Policy policy, EngineOptions opt, double T_rot = 1) {
    SpeciesSpec s; // m = 1, R = 0.5 (sigma = 1), q = 0.4, T = 1
    s.rotational_temperature = T_rot;
    const auto blocks = make_species_blocks({s}, N);
    Store store(static_cast<std::size_t>(N));
    init_maxwellian(store, blocks, opt.seed, opt.replica);
    return Engine<Store, Policy, false>(blocks, {policy}, std::move(store), opt);
}

template <class E> Moments moments_of(const E& e) {
    const auto& b = e.species()[0];
    const std::vector<SpeciesSlice> slices = {{b.offset, b.count, b.grain.mass, b.moment_of_inertia()}};
    return compute_moments(e.store().velocities(), e.store().angular_velocities(), slices);
}

using test::MeanErr;
using test::mean_err;

EngineOptions grouped(std::uint64_t seed, std::uint64_t replica, int groups, int threads, double step = 1.0) {
    return EngineOptions{1.0, step, seed, replica, 2, groups, threads};
}

template <class E> ::testing::AssertionResult same_state(const E& a, const E& b) {
    if (a.time() != b.time() || a.collisions() != b.collisions())
        return ::testing::AssertionFailure() << "t " << a.time() << " vs " << b.time() << ", collisions "
                                             << a.collisions() << " vs " << b.collisions();
    for (std::size_t i = 0; i < a.particles(); ++i)
        if (std::memcmp(&a.store().v(i), &b.store().v(i), sizeof(Vec3)) != 0 ||
            std::memcmp(&a.store().w(i), &b.store().w(i), sizeof(Vec3)) != 0)
            return ::testing::AssertionFailure() << "grain " << i << " differs: v.x " << a.store().v(i).x << " vs " << b.store().v(i).x << ", w.x " << a.store().w(i).x << " vs " << b.store().w(i).x;
    return ::testing::AssertionSuccess();
}

// Collisions binned by u = exp(-g_n^2/(4T)), uniform for the exact law (engine_test.cpp); forkable,
// so that every group (and thread) fills its own bins.
struct ImpactBins {
    double T = 1;
    std::vector<long> bins = std::vector<long>(20, 0);
    void operator()(const CollisionRecord& r, std::size_t) {
        const double u = std::exp(-r.g_n * r.g_n / (4.0 * T));
        ++bins[std::min(19, static_cast<int>(u * 20))];
    }
    ImpactBins fork() const { return ImpactBins{T}; }
    void merge(const ImpactBins& o) {
        for (std::size_t k = 0; k < bins.size(); ++k)
            bins[k] += o.bins[k];
    }
};

TEST(Groups, TrajectoryDoesNotDependOnTheThreads) {
    // Rough inelastic gas, N = 2e4 in 8 groups: 1 and 2 threads, run to a collision count (the
    // phases and the serial tail) and then to a time, end in bitwise the same state.
    auto a = make_engine<RoughAoS>(20000, make_rough_constant(0.8, 0.4), grouped(5, 0, 8, 1));
    auto b = make_engine<RoughAoS>(20000, make_rough_constant(0.8, 0.4), grouped(5, 0, 8, 2));
    for (auto* e : {&a, &b}) {
        e->run_collisions(60000);
        EXPECT_EQ(e->collisions(), 60000);
        e->run(std::numeric_limits<std::int64_t>::max(), e->time() + 0.7, IgnoreCollisions{});
    }
    EXPECT_TRUE(same_state(a, b));
    EXPECT_EQ(a.counters().candidates, b.counters().candidates);
    EXPECT_EQ(a.counters().overshoots, 0);
    EXPECT_GT(a.counters().steps, 4);
}

TEST(Groups, PausingDoesNotChangeTheTrajectory) {
    // As for one group (engine_test.cpp): a grouped run paused 50 times, at collision counts and at
    // times, ends bitwise where an unpaused one does; the collision stops are exact.
    auto a = make_engine<RoughAoS>(5000, make_rough_constant(0.9, 0.3), grouped(17, 0, 4, 2, 0.7));
    auto b = make_engine<RoughAoS>(5000, make_rough_constant(0.9, 0.3), grouped(17, 0, 4, 2, 0.7));
    a.run_collisions(50000);
    for (int k = 1; k <= 25; ++k) {
        b.run_collisions(k * 2000 - 7);
        EXPECT_EQ(b.collisions(), k * 2000 - 7);
        b.run(std::numeric_limits<std::int64_t>::max(), b.time() + 1e-3, IgnoreCollisions{});
    }
    b.run_collisions(50000);
    EXPECT_EQ(a.collisions(), 50000);
    EXPECT_TRUE(same_state(a, b));
}

TEST(Groups, RunAboutStopsAtTimesAndExactlyAtTheTarget) {
    // Engine::run_about, the stretches of run_replica between rows: about n collisions by a time stop
    // (one phase per step instead of halving phases), never past the target, which it meets exactly.
    // Its pauses are times chosen from the run's own rate: the trajectory must be bitwise that of an
    // unpaused run on one thread, and it must take fewer phases than stretches stopped at counts.
    const std::int64_t target = 60000, n = 5000;
    auto a = make_engine<RoughAoS>(20000, make_rough_constant(0.9, 0.3), grouped(29, 0, 8, 1));
    auto b = make_engine<RoughAoS>(20000, make_rough_constant(0.9, 0.3), grouped(29, 0, 8, 2));
    auto c = make_engine<RoughAoS>(20000, make_rough_constant(0.9, 0.3), grouped(29, 0, 8, 2));
    a.run_collisions(target);
    int stretches = 0, by_time = 0;
    while (b.collisions() < target) {
        const std::int64_t before = b.collisions();
        const StopReason r = b.run_about(n, target, IgnoreCollisions{});
        ASSERT_LE(b.collisions(), target);
        ASSERT_GE(b.collisions(), std::min(target, before + n / 4)); // progress, whatever the rate did
        by_time += r == StopReason::time;
        ++stretches;
        c.run_collisions(std::min(target, c.collisions() + n));
    }
    EXPECT_EQ(b.collisions(), target);
    EXPECT_GT(by_time, 5);   // most stretches ended at a time ...
    EXPECT_GT(stretches, 7); // ... of about n collisions each (12 expected)
    EXPECT_LT(stretches, 20);
    EXPECT_LT(b.counters().phases, c.counters().phases / 2);
    EXPECT_EQ(b.counters().overshoots, 0);
    EXPECT_TRUE(same_state(a, b));
    EXPECT_TRUE(same_state(a, c));
    // A rate that falls a thousandfold (every velocity scaled down; the groups' rates are refreshed
    // only by the step start the run begins with, so the time stop is a thousand times too short):
    // the count finishes the stretch, which still advances by n.
    auto e = make_engine<RoughAoS>(20000, make_rough_constant(0.9, 0.3), grouped(29, 0, 8, 2));
    e.run_collisions(5000);
    for (std::size_t i = 0; i < e.particles(); ++i) {
        e.store().v(i) *= 1e-3;
        e.store().w(i) *= 1e-3;
    }
    e.restart_step();
    EXPECT_EQ(e.run_about(n, target, IgnoreCollisions{}), StopReason::collisions);
    EXPECT_EQ(e.collisions(), 5000 + n);
    // A gas in which no collision can happen (every grain at rest): `stalled`, not an endless loop.
    auto d = make_engine<RoughAoS>(20000, make_rough_constant(0.9, 0.3), grouped(29, 0, 8, 2));
    d.run_collisions(5000);
    for (std::size_t i = 0; i < d.particles(); ++i)
        d.store().v(i) = Vec3{};
    d.restart_step();
    EXPECT_EQ(d.run_about(n, target, IgnoreCollisions{}), StopReason::stalled);
}

TEST(Groups, PhasesStopExactlyInAHeatingGas) {
    // The phases of a run to a collision target aim at half the remaining collisions, predicted
    // from the current candidate rate and acceptance (engine.hpp, "Stopping in a grouped run"). A gas
    // whose translational temperature grows (T_rot = 30 T_tr, perfectly rough: T_tr rises about
    // tenfold towards equipartition, so the acceptance and the candidate rate grow within a step) is
    // where a prediction could pass its target: 60 targets of 800 collisions each must be met
    // exactly, with no overshoot, and the trajectory must be bitwise that of an unpaused run on one
    // thread. (Aiming each phase at all of the remainder fails here.)
    auto a = make_engine<RoughAoS>(20000, make_rough_constant(0.99, 1.0), grouped(23, 0, 8, 1), 30.0);
    auto b = make_engine<RoughAoS>(20000, make_rough_constant(0.99, 1.0), grouped(23, 0, 8, 2), 30.0);
    const double T0 = moments_of(b).all.T_tr;
    for (int k = 1; k <= 60; ++k) {
        b.run_collisions(k * 800);
        ASSERT_EQ(b.collisions(), k * 800);
    }
    a.run_collisions(60 * 800);
    EXPECT_EQ(a.counters().overshoots, 0);
    EXPECT_EQ(b.counters().overshoots, 0);
    EXPECT_GT(b.counters().phases, 60);
    EXPECT_GT(moments_of(b).all.T_tr, 5.0 * T0); // the gas did heat
    EXPECT_TRUE(same_state(a, b));
}

TEST(Groups, CollisionRateIsExact) {
    // Elastic smooth gas in equilibrium, N = 1e4 in 8 groups (1250 grains each, rates x 8),
    // 2 threads: nu = 2 C/(N t) over the exact 4 n sigma^2 sqrt(pi T/m) (N - 1)/N. 16 replicas of 3e5
    // collisions: standard error ~0.05% on the mean (as engine_test.cpp's ungrouped test); within
    // 3 standard errors. Also with 64 groups of ~156 grains: the expected rate of each pair does not
    // depend on the group size.
    for (int G : {8, 64}) {
        std::vector<double> r;
        for (std::uint64_t k = 0; k < 16; ++k) {
            auto e = make_engine<SmoothAoS>(10000, make_smooth_constant(1.0), grouped(7, k, G, 2));
            const double T = moments_of(e).all.T_tr;
            e.run_collisions(300000);
            const double nu = 2.0 * static_cast<double>(e.collisions()) / 1e4 / e.time();
            r.push_back(nu / (4.0 * std::sqrt(std::numbers::pi * T) * (1e4 - 1.0) / 1e4));
        }
        const MeanErr m = mean_err(r);
        std::printf("  %d groups: nu/nu_exact = %.5f +- %.5f (16 replicas, N = 1e4, 3e5 collisions each)\n", G,
                    m.mean, m.err);
        EXPECT_NEAR(m.mean, 1.0, 3 * m.err) << G << " groups";
        EXPECT_LT(m.err, 1.2e-3) << "the test must be able to see a 0.25% bias";
    }
}

TEST(Groups, ImpactSpeedFollowsTheExactLaw) {
    // The |g_c . n| law of engine_test.cpp with 16 groups on 2 threads (forked observers): chi-square
    // over 20 bins of 2e5 collisions (N = 1e5) below 43.82 (p = 1e-3, 19 dof).
    auto e = make_engine<SmoothAoS>(100000, make_smooth_constant(1.0), grouped(9, 0, 16, 2));
    ImpactBins obs{moments_of(e).all.T_tr};
    e.run(200000, std::numeric_limits<double>::infinity(), obs);
    long n = 0;
    for (long b : obs.bins)
        n += b;
    ASSERT_EQ(n, 200000);
    const double expect = n / 20.0;
    double chi2 = 0;
    for (long b : obs.bins)
        chi2 += (b - expect) * (b - expect) / expect;
    std::printf("  chi-square of the g_n law, 16 groups: %.2f (19 dof, threshold 43.82)\n", chi2);
    EXPECT_LT(chi2, 43.82);
}

TEST(Groups, RelaxationDoesNotDependOnTheGroups) {
    // Rough inelastic gas (alpha = 0.8, beta = 0.4) started with theta = 0.1: theta and T_tr after 3
    // collisions per particle (far from the steady state, so the test sees the rate of every energy
    // exchange) with 1 group and with 32 groups of ~625 grains (a strong partition). N = 2e4, 12
    // replicas each; means within 4 combined standard errors (each about 0.1%).
    const auto measure = [](int G, std::uint64_t replica) {
        auto e = make_engine<RoughAoS>(20000, make_rough_constant(0.8, 0.4), grouped(11, replica, G, 2), 0.1);
        e.run_collisions(30000);
        const Moments m = moments_of(e);
        return std::pair(m.all.theta, m.all.T_tr);
    };
    std::vector<double> th1, th32, T1, T32;
    for (std::uint64_t k = 0; k < 12; ++k) {
        const auto [a, b] = measure(1, k);
        th1.push_back(a);
        T1.push_back(b);
        const auto [c, d] = measure(32, 100 + k);
        th32.push_back(c);
        T32.push_back(d);
    }
    const MeanErr a = mean_err(th1), b = mean_err(th32), c = mean_err(T1), d = mean_err(T32);
    std::printf("  theta: 1 group %.5f +- %.5f, 32 groups %.5f +- %.5f; T_tr: %.5f +- %.5f, %.5f +- %.5f\n",
                a.mean, a.err, b.mean, b.err, c.mean, c.err, d.mean, d.err);
    EXPECT_GT(std::abs(a.mean - 0.1), 50 * a.err) << "theta must have moved";
    EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.err, b.err));
    EXPECT_NEAR(c.mean, d.mean, 4 * std::hypot(c.err, d.err));
}

TEST(Groups, RunReplicaIsByteIdenticalOnOneAndTwoThreads) {
    // run_replica (the driver of roughgas run) with 8 groups: rows bitwise equal with threads = 1
    // and 2; with 1 group a different (equally valid) trajectory.
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {ConstantRestitution{0.9, 0.5}};
    s.particles = 20000;
    s.end = 3;
    s.output_times = {1, 2, 3};
    s.seed = 42;
    s.groups = 8;
    const auto rows = [&](int threads, int groups) {
        RunSpec t = s;
        t.threads = threads;
        t.groups = groups;
        const auto tables = RestitutionTables::build(t);
        std::vector<std::vector<double>> out;
        ReplicaSummary summary;
        run_replica(
            t, *tables, 0, [&](std::span<const double> r) { out.emplace_back(r.begin(), r.end()); }, {}, &summary);
        EXPECT_EQ(summary.groups, groups);
        return out;
    };
    const auto a = rows(1, 8), b = rows(2, 8), c = rows(1, 1);
    ASSERT_EQ(a.size(), 4u);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        ASSERT_EQ(a[k].size(), b[k].size());
        EXPECT_EQ(std::memcmp(a[k].data(), b[k].data(), a[k].size() * sizeof(double)), 0) << "row " << k;
    }
    EXPECT_NE(a.back()[2], c.back()[2]);
    EXPECT_EQ(a.back()[1], 3.0); // rows at exact collision counts, grouped or not
    EXPECT_EQ(c.back()[1], 3.0);
}

TEST(Groups, AutomaticCountDependsOnTheParticlesOnly) {
    EXPECT_EQ(auto_groups(1000), 1);
    EXPECT_EQ(auto_groups(32767), 1);
    EXPECT_EQ(auto_groups(32768), 2);
    EXPECT_EQ(auto_groups(100000), 4);
    EXPECT_EQ(auto_groups(1000000), 32);
    EXPECT_EQ(auto_groups(std::int64_t{1} << 40), 4096);
}

} // namespace
} // namespace roughgas
