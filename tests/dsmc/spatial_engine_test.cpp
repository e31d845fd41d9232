// The spatially resolved engine (dsmc/spatial_engine.hpp) in a periodic box: what must hold exactly
// (conservation, grains in the box, independence of the thread count) and the collision rate of
// an elastic gas for any cell size; a small box cools as the homogeneous gas (Haff's law).
#include "roughgas/dsmc/spatial_engine.hpp"
#include "spatial_test_support.hpp"

#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace roughgas {
namespace {

struct CountCollisions {
    std::int64_t n = 0;
    double dE = 0;
    void operator()(const CollisionRecord& r, std::size_t) {
        ++n;
        dE += r.dE_tr + r.dE_rot;
    }
    CountCollisions fork() const { return {}; }
    void merge(const CountCollisions& o) {
        n += o.n;
        dE += o.dE;
    }
};

std::vector<SpeciesBlock> one_species(std::int64_t n, double mass = 1, double radius = 0.5) {
    SpeciesSpec s;
    s.mass = mass;
    s.radius = radius;
    return make_species_blocks({s}, n);
}

using test::two_species;

// Mean free path of equal spheres, 1/(sqrt(2) pi n sigma^2).
double mean_free_path(double density, double sigma) {
    return 1.0 / (std::sqrt(2.0) * std::numbers::pi * density * sigma * sigma);
}

DomainSpec cube(double side, int cells) {
    DomainSpec d;
    d.size = {side, side, side};
    d.cells = {cells, cells, cells};
    return d;
}

using test::energy;
using test::momentum;

// The translational part alone (smooth grains keep their initial spins, which carry energy too).
template <class P> double translational_energy(const SpatialEngine<P>& e) {
    double E = 0;
    for (const SpeciesBlock& b : e.species())
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i)
            E += 0.5 * b.grain.mass * norm2(e.velocities()[i]);
    return E;
}

template <class P> void expect_inside(const SpatialEngine<P>& e, const DomainSpec& d) {
    for (const Vec3& x : e.positions()) {
        ASSERT_TRUE(x.x >= 0 && x.x < d.size[0] && x.y >= 0 && x.y < d.size[1] && x.z >= 0 && x.z < d.size[2])
            << x.x << " " << x.y << " " << x.z;
    }
}

// Elastic rough grains (alpha = 1, beta = 1 conserve the energy with the spins), a mixture: the
// momentum stays zero and the energy constant to round-off over 40 steps of many collisions per
// cell; no grain leaves the box; every grain sits in the cell its position says.
// Either partner selection.
TEST(SpatialEngine, ConservesMomentumAndEnergyAndKeepsGrainsInTheBox) {
    for (const PartnerSelection partners : {PartnerSelection::random, PartnerSelection::nearest}) {
        SCOPED_TRACE(partners == PartnerSelection::random ? "random partners" : "nearest partners");
        DomainSpec d = cube(20.0, 6);
        d.partners = partners;
        std::vector<SpeciesBlock> blocks = two_species(5000);
        const std::vector<PairType> types = make_pair_types(blocks);
        std::vector<AnyRoughPolicy> policies;
        for (std::size_t k = 0; k < types.size(); ++k)
            policies.push_back(to_any_rough(AnyPolicy(make_rough_constant(1.0, 1.0))));
        SpatialEngine<AnyRoughPolicy> e(d, blocks, policies, 0.05, 7, 0, 2);
        const Vec3 p0 = momentum(e);
        const double E0 = energy(e);
        EXPECT_LT(std::sqrt(norm2(p0)), 1e-10 * std::sqrt(2 * E0));
        CountCollisions count;
        for (int k = 0; k < 40; ++k) {
            e.step(0.5 / e.collision_frequency(), count);
            expect_inside(e, d);
        }
        EXPECT_GT(count.n, 40000); // about 4 collisions per grain
        const Vec3 p = momentum(e);
        EXPECT_LT(std::sqrt(norm2(p - p0)), 1e-12 * std::sqrt(2 * E0 * 5000));
        EXPECT_NEAR(energy(e) / E0, 1.0, 1e-12);
        for (std::size_t s = 0; s < 2; ++s)
            for (std::size_t c = 0; c < e.cells(); ++c) {
                const auto [first, last] = e.cell_range(s, c);
                for (std::size_t i = first; i < last; ++i)
                    ASSERT_EQ(e.cell_of(e.positions()[i]), c);
            }
    }
}

// Elastic hard spheres: a grain's collision rate is 4 n sigma^2 sqrt(pi T/m) exactly, whatever the
// cell size (here 0.4 and 2.5 mean free paths; 3 and 0.2 grains per cell on average), since a
// pair's rate in its cell is pi sigma^2 |g| F / V_c and a uniform gas fills the cells as a Poisson
// process. Measured over 8 collisions per grain of 20000 grains (~80000 collisions): relative
// standard error 1/sqrt(80000) = 0.35 %; the tolerance is 5 of them. The same with nearest
// partners: in a uniform gas the nearest grain's velocity is a random grain's.
TEST(SpatialEngine, ElasticCollisionRateIsExactForAnyCellSize) {
    const double n = 0.01, sigma = 1.0, T = 1.0, m = 1.0;
    const double lambda = mean_free_path(n, sigma);
    const double nu = 4 * n * sigma * sigma * std::sqrt(std::numbers::pi * T / m);
    for (const PartnerSelection partners : {PartnerSelection::random, PartnerSelection::nearest})
        for (const double cell : {0.4, 2.5}) {
            const int cells = 5;
            DomainSpec d = cube(cells * cell * lambda, cells);
            d.partners = partners;
            std::vector<SpeciesBlock> blocks = one_species(20000, m, sigma / 2);
            SpatialEngine<SmoothConstant> e(d, blocks, {make_smooth_constant(1.0)}, n, 3, 0, 1);
            CountCollisions count;
            const double dt = 0.25 / nu;
            for (int k = 0; k < 32; ++k)
                e.step(dt, count);
            const double rate = 2.0 * static_cast<double>(count.n) / (20000.0 * e.time());
            // T drifts from 1 only by the sample's own temperature (the initial state's 20000 grains).
            const double T_sample = 2 * translational_energy(e) / (3 * 20000.0);
            const double expected = nu * std::sqrt(T_sample / T);
            EXPECT_NEAR(rate / expected, 1.0, 5.0 / std::sqrt(static_cast<double>(count.n)))
                << cell << " mean free paths, "
                << (partners == PartnerSelection::random ? "random" : "nearest") << " partners";
        }
}

// Nearest partners in a cell of three grains (one cell, elastic smooth grains, steps of 0.02 mean
// free times, so that most steps hold no collision or one): a step's collision is known from the two
// grains whose velocities changed (free flight leaves them alone; a step with three changed is
// skipped and forgets what came before it). The partner of a candidate's first grain is the nearer of
// the other two unless that one is its most recent partner: the same pair therefore never collides
// twice in a row, however many steps lie between (the exclusion lives in the grains, not the step),
// and each collision's pair is the choice of one of its two grains at the positions of that step.
// With random partners the same pair follows itself in a third of the collisions (5 standard errors
// allowed), which shows that the repeats would be seen.
TEST(SpatialEngine, NearestPartnersExcludeTheMostRecentPartnerAcrossSteps) {
    for (const PartnerSelection partners : {PartnerSelection::random, PartnerSelection::nearest}) {
        SCOPED_TRACE(partners == PartnerSelection::random ? "random partners" : "nearest partners");
        DomainSpec d = cube(10.0, 1);
        d.partners = partners;
        SpatialEngine<SmoothConstant> e(d, one_species(3), {make_smooth_constant(1.0)}, 0.05, 17, 0, 1);
        CountCollisions count;
        constexpr int none = -1;
        std::array<int, 3> last{none, none, none}; // each grain's most recent partner, where known
        int previous_pair = none, pairs = 0, repeats = 0, checked = 0;
        for (int k = 0; k < 60000 && pairs < 1500; ++k) {
            const std::vector<Vec3> before = e.velocities();
            e.step(0.02 / e.collision_frequency(), count);
            std::vector<int> changed;
            for (int i = 0; i < 3; ++i)
                if (e.velocities()[i].x != before[i].x || e.velocities()[i].y != before[i].y ||
                    e.velocities()[i].z != before[i].z)
                    changed.push_back(i);
            if (changed.empty())
                continue;
            if (changed.size() != 2) {
                last = {none, none, none};
                previous_pair = none;
                continue;
            }
            const int i = changed[0], j = changed[1], pair = i + j - 1; // 0: {0,1}, 1: {0,2}, 2: {1,2}
            if (partners == PartnerSelection::nearest && last[i] != none && last[j] != none) {
                const auto choice = [&](int a) {
                    const int b = (a + 1) % 3, c = (a + 2) % 3;
                    if (last[a] == b)
                        return c;
                    if (last[a] == c)
                        return b;
                    const std::vector<Vec3>& x = e.positions();
                    return norm2(x[b] - x[a]) < norm2(x[c] - x[a]) ? b : c;
                };
                EXPECT_TRUE(choice(i) == j || choice(j) == i) << "step " << k << ": grains " << i << ", " << j;
                ++checked;
            }
            if (previous_pair != none) {
                ++pairs;
                repeats += pair == previous_pair;
            }
            previous_pair = pair;
            last[i] = j;
            last[j] = i;
        }
        ASSERT_GE(pairs, 1000);
        if (partners == PartnerSelection::nearest) {
            EXPECT_EQ(repeats, 0);
            EXPECT_GE(checked, 1000);
        } else {
            const double f = static_cast<double>(repeats) / pairs;
            EXPECT_NEAR(f, 1.0 / 3, 5 * std::sqrt(2.0 / 9 / pairs)) << repeats << " of " << pairs;
        }
    }
}

// The results do not depend on the thread count: the same state bit for bit after 10 steps (with
// nearest partners on the second pass).
TEST(SpatialEngine, ThreadCountDoesNotChangeTheResults) {
    for (const PartnerSelection partners : {PartnerSelection::random, PartnerSelection::nearest}) {
        DomainSpec d = cube(30.0, 12);
        d.partners = partners;
        std::vector<SpeciesBlock> blocks = one_species(20000);
        std::vector<std::vector<Vec3>> v;
        for (int threads : {1, 2}) {
            SpatialEngine<RoughConstant> e(d, blocks, {make_rough_constant(0.8, 0.3)}, 0.1, 5, 2, threads);
            CountCollisions count;
            for (int k = 0; k < 10; ++k)
                e.step(0.3 / e.collision_frequency(), count);
            v.push_back(e.velocities());
        }
        ASSERT_EQ(v[0].size(), v[1].size());
        for (std::size_t i = 0; i < v[0].size(); ++i)
            ASSERT_TRUE(v[0][i].x == v[1][i].x && v[0][i].y == v[1][i].y && v[0][i].z == v[1][i].z) << i;
    }
}

// A box far below the instability length (1.2 mean free paths, alpha = 0.9) stays homogeneous and
// cools by Haff's law, T(t) = T0 / (1 + t/t0)^2 with t0 from the Maxwellian collision frequency
// (observables/theory.hpp). Tolerance: 4 standard errors of the mean of 4 replicas of 10000 grains
// (each T to sqrt(2/(3N)) = 0.82 %, so 0.41 % for the mean) plus 0.5 % for the Maxwellian
// approximation (the cooling rate's Sonine correction 3 a2/16 with |a2| = 0.015 at alpha = 0.9,
// accumulated over the run's factor 3 in T) and the step's discreteness (steps of 0.1 mean free
// times, rates evaluated at each step's start).
TEST(SpatialEngine, SmallBoxCoolsByHaffsLaw) {
    const double n = 0.05, alpha = 0.9, sigma = 1.0;
    const int N = 10000;
    const DomainSpec d = cube(1.2 * mean_free_path(n, sigma), 4);
    double ratio = 0, cooled = 0;
    for (std::uint64_t r = 0; r < 4; ++r) {
        SpatialEngine<SmoothConstant> e(d, one_species(N, 1.0, sigma / 2), {make_smooth_constant(alpha)}, n,
                                        11, r, 1);
        const double E0 = translational_energy(e), T0 = 2 * E0 / (3.0 * N); // the sample's own start
        CountCollisions count;
        while (e.collisions() < N * 25) // 50 collisions per grain
            e.step(0.1 / e.collision_frequency(), count);
        const double T = 2 * translational_energy(e) / (3.0 * N);
        ratio += T / haff_temperature(e.time(), T0, alpha, 1.0, sigma, n) / 4;
        cooled += T / T0 / 4;
        EXPECT_NEAR(count.dE, translational_energy(e) - E0, 1e-9 * E0); // the records account for every loss
    }
    EXPECT_LT(cooled, 0.35);
    EXPECT_NEAR(ratio, 1.0, 4 * 0.0041 + 0.005) << "T/T0 = " << cooled;
}

// A state saved after 6 steps and restored into a new engine continues bit for bit as the
// engine that never stopped (positions, velocities, spins; the streams are keyed by the step).
// Rough grains (their spins sorted with them) and smooth ones (spins by identity, saved in store order).
template <class Policy> void expect_save_and_restore_continue(const Policy& policy) {
    for (const PartnerSelection partners : {PartnerSelection::random, PartnerSelection::nearest}) {
        SCOPED_TRACE(partners == PartnerSelection::random ? "random partners" : "nearest partners");
        DomainSpec d = cube(25.0, 5);
        d.partners = partners; // nearest: the grains' identities and last partners are part of the state
        SpatialEngine<Policy> a(d, one_species(4000), {policy}, 0.1, 9, 1, 1);
        CountCollisions count;
        for (int k = 0; k < 6; ++k)
            a.step(0.25 / a.collision_frequency(), count);
        ByteWriter w;
        a.save(w);
        SpatialEngine<Policy> b(d, one_species(4000), {policy}, 0.1, 9, 1, 2);
        ByteReader r(w.bytes());
        b.restore(r);
        EXPECT_EQ(r.remaining(), 0u);
        for (int k = 0; k < 6; ++k) {
            const double dt = 0.25 / a.collision_frequency();
            ASSERT_EQ(dt, 0.25 / b.collision_frequency());
            a.step(dt, count);
            b.step(dt, count);
        }
        EXPECT_EQ(a.collisions(), b.collisions());
        for (std::size_t i = 0; i < a.particles(); ++i)
            ASSERT_TRUE(a.positions()[i].x == b.positions()[i].x && a.velocities()[i].y == b.velocities()[i].y &&
                        a.angular_velocities()[i].z == b.angular_velocities()[i].z)
                << i;
    }
}

TEST(SpatialEngine, SaveAndRestoreContinueTheSameTrajectory) {
    expect_save_and_restore_continue(make_rough_constant(0.7, 0.2));
    expect_save_and_restore_continue(make_smooth_constant(0.7));
}

// Smooth grains' spins stay where the start put them, the sort moving the grains' identities
// instead (dsmc/spatial_engine.hpp); read through angular_velocities() each is still its grain's.
// In a gas too dilute for any collision a grain's velocity is constant, so spins started equal to
// the velocities stay equal, grain by grain, through steps that carry the grains across cells, and
// through a save and restore into another engine, whose checkpoint holds the spins in store order.
TEST(SpatialEngine, SmoothGrainsKeepTheirSpinsThroughTheSort) {
    const DomainSpec d = cube(25.0, 5);
    const double dilute = 1e-12; // mean free path 2e11 box lengths
    const SpatialEngine<SmoothConstant> start(d, one_species(3000), {make_smooth_constant(0.9)}, dilute, 9, 0, 1);
    GrainState g = start.grain_state();
    g.w = g.v;
    const GrainStateSource from = [&](int) { return g; };
    SpatialEngine<SmoothConstant> a(d, one_species(3000), {make_smooth_constant(0.9)}, dilute, 9, 0, 2,
                                    CollisionKernel::hard_sphere, from);
    const auto expect_spins_are_velocities = [](SpatialEngine<SmoothConstant>& e) {
        const std::vector<Vec3>& w = e.angular_velocities();
        for (std::size_t i = 0; i < e.particles(); ++i)
            ASSERT_TRUE(w[i].x == e.velocities()[i].x && w[i].y == e.velocities()[i].y &&
                        w[i].z == e.velocities()[i].z)
                << i;
    };
    CountCollisions count;
    std::size_t moved = 0; // grains away from their initial store index, summed over the steps
    for (int k = 0; k < 4; ++k) {
        a.step(3.0, count); // about 3 length units at unit thermal speed: cells are 5 long
        for (std::size_t i = 0; i < a.particles(); ++i)
            moved += a.velocities()[i].x != g.v[i].x;
        expect_spins_are_velocities(a);
    }
    EXPECT_EQ(count.n, 0);
    EXPECT_GT(moved, a.particles()); // most grains, in most steps
    ByteWriter w;
    a.save(w);
    SpatialEngine<SmoothConstant> b(d, one_species(3000), {make_smooth_constant(0.9)}, dilute, 9, 0, 1);
    ByteReader r(w.bytes());
    b.restore(r);
    EXPECT_EQ(r.remaining(), 0u);
    b.step(3.0, count);
    expect_spins_are_velocities(b);
    EXPECT_EQ(count.n, 0);
}

// The same with walls (a diffuse one draws random numbers in the flight), gravity, two species and
// the slabs of the local collision frequency along y: the steps' lengths, taken from the cells' sums
// of the last collision phase in the run and recomputed from the restored grains in the other, are
// the same to the bit, and so is the rest of the trajectory.
TEST(SpatialEngine, SaveAndRestoreContinueTheSameTrajectoryWithWallsAndAMixture) {
    DomainSpec d = cube(25.0, 5);
    d.boundary = {Boundary::periodic, Boundary::walls, Boundary::periodic};
    d.wall_lower = {WallKind::diffuse, 1.0, {0, 0, 0}, 1, -1};
    d.wall_upper = {WallKind::specular, 1.0, {0, 0, 0}, 1, -1};
    d.gravity = {0, -0.05, 0};
    d.profile_axis = 1;
    const std::vector<RoughConstant> policies(3, make_rough_constant(0.8, 0.3));
    using Engine = SpatialEngine<RoughConstant, true>;
    Engine a(d, two_species(4000), policies, 0.1, 5, 0, 1);
    CountCollisions count;
    for (int k = 0; k < 6; ++k)
        a.step(0.25 / a.collision_frequency(), count);
    ByteWriter w;
    a.save(w);
    Engine b(d, two_species(4000), policies, 0.1, 5, 0, 2);
    ByteReader r(w.bytes());
    b.restore(r);
    EXPECT_EQ(r.remaining(), 0u);
    for (int k = 0; k < 6; ++k) {
        const double nu = a.collision_frequency();
        ASSERT_EQ(nu, b.collision_frequency()) << k;
        a.step(0.25 / nu, count);
        b.step(0.25 / nu, count);
    }
    EXPECT_EQ(a.collisions(), b.collisions());
    for (std::size_t i = 0; i < a.particles(); ++i)
        ASSERT_TRUE(a.positions()[i].y == b.positions()[i].y && a.velocities()[i].x == b.velocities()[i].x &&
                    a.angular_velocities()[i].z == b.angular_velocities()[i].z)
            << i;
}

// A state to start from (RunSpec::initial_state): its grains' velocities and spins are taken as
// they are, with their positions when the state's box has the engine's size (the same (x, v) pairs,
// in cell order) and at new uniform positions otherwise; a sheared box adds its flow
// u_x = a (y - L_y/2) (and removes the total momentum) and gives it back in grain_state() (the
// velocities about the flow).
TEST(SpatialEngine, StartsFromAGivenState) {
    const DomainSpec d = cube(25.0, 5);
    SpatialEngine<RoughConstant> a(d, one_species(3000), {make_rough_constant(0.7, 0.2)}, 0.1, 9, 0, 1);
    CountCollisions count;
    for (int k = 0; k < 4; ++k)
        a.step(0.25 / a.collision_frequency(), count);
    const GrainState g = a.grain_state();
    const auto pairs = [](const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
        std::vector<std::array<double, 4>> p;
        for (std::size_t i = 0; i < x.size(); ++i)
            p.push_back({x[i].x, x[i].y, v[i].x, v[i].z});
        std::sort(p.begin(), p.end());
        return p;
    };
    DomainSpec same = d, other = cube(30.0, 5), sheared = d;
    const GrainStateSource from = [&](int) { return g; };
    const CollisionKernel hs = CollisionKernel::hard_sphere;
    sheared.shear_rate = 0.01;
    SpatialEngine<RoughConstant> b(same, one_species(3000), {make_rough_constant(0.7, 0.2)}, 0.1, 9, 3, 1, hs, from);
    EXPECT_EQ(pairs(b.positions(), b.velocities()), pairs(g.x, g.v));
    SpatialEngine<RoughConstant> c(other, one_species(3000), {make_rough_constant(0.7, 0.2)}, 0.1, 9, 3, 1, hs,
                                   from);
    EXPECT_NE(pairs(c.positions(), c.velocities()), pairs(g.x, g.v));
    std::vector<std::array<double, 3>> vg, vc; // the same velocities and spins, other positions
    for (std::size_t i = 0; i < g.v.size(); ++i) {
        vg.push_back({g.v[i].x, g.v[i].y, g.w[i].z});
        vc.push_back({c.velocities()[i].x, c.velocities()[i].y, c.angular_velocities()[i].z});
    }
    std::sort(vg.begin(), vg.end());
    std::sort(vc.begin(), vc.end());
    EXPECT_EQ(vg, vc);
    SpatialEngine<RoughConstant, true> e(sheared, one_species(3000), {make_rough_constant(0.7, 0.2)}, 0.1, 9, 3, 1,
                                         hs, from);
    const GrainState back = e.grain_state();
    for (std::size_t i = 0; i < g.v.size(); ++i) {
        const double flow = 0.01 * (e.positions()[i].y - 12.5);
        ASSERT_NEAR(e.velocities()[i].x - back.v[i].x, flow, 1e-15) << i;
    }
    // The same grains about the flow, up to the flow's mean over the grains (removed with the
    // momentum: the start has none), the same for every grain.
    const auto p = pairs(back.x, back.v), q = pairs(g.x, g.v);
    ASSERT_EQ(p.size(), q.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_TRUE(p[i][0] == q[i][0] && p[i][1] == q[i][1]) << i;
        ASSERT_NEAR(p[i][2] - q[i][2], p[0][2] - q[0][2], 1e-12) << i;
        ASSERT_NEAR(p[i][3], q[i][3], 1e-12) << i;
    }
    EXPECT_LT(std::abs(p[0][2] - q[0][2]), 0.01 * 12.5 * 0.1); // a few per cent of the flow's amplitude
}

// The initial waves (InitialSpec): at t = 0 each mode's amplitude is what was asked, within the
// sampling noise of 100000 grains (5 standard errors: sqrt(2 T/(m N)) = 0.0045 for u_wave,
// sqrt(2/N) = 0.0045 for n_wave, sqrt(4/(3N)) = 0.0037 for e_wave), the others near 0; the total
// momentum is zero.
TEST(SpatialEngine, InitialWavesHaveTheirAmplitudes) {
    const int N = 100000;
    const double A = 0.2;
    struct Want {
        Perturbation mode;
        double u, n, e;
    };
    for (const Want& w : {Want{Perturbation::transverse, A, 0, 0}, Want{Perturbation::longitudinal, A, 0, 0},
                          Want{Perturbation::density, 0, A, A}, Want{Perturbation::temperature, 0, 0, A}}) {
        DomainSpec d = cube(40.0, 4);
        d.size[1] = 20.0;
        d.initial = {w.mode, A, {1, 2, 0}};
        const SpatialEngine<RoughConstant> e(d, one_species(N), {make_rough_constant(1.0, 1.0)}, 0.1, 3, 0,
                                             1);
        const std::array<double, 3> a = e.wave_amplitudes();
        const int mode = static_cast<int>(w.mode);
        EXPECT_NEAR(a[0], w.u, 5 * 0.0045) << mode;
        EXPECT_NEAR(a[1], w.n, 5 * 0.0045) << mode;
        EXPECT_NEAR(a[2], w.e, 5 * 0.0037) << mode;
        EXPECT_LT(std::sqrt(norm2(momentum(e))), 1e-9 * N);
    }
}

} // namespace
} // namespace roughgas
