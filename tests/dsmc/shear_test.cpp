// Uniform shear flow (dsmc/shear.hpp, observables/pressure.hpp, the shear branch of run_replica):
// the streaming step and its Strang schedule are exact with collisions off, the pressure tensor
// and reduced quantities follow their definitions, and a shear run is deterministic.
// The statistical properties (symmetry, energy balance, elastic limit, splitting order) are in
// tests/validation/usf_test.cpp.
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/shear.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/observables/pressure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <utility>
#include <vector>

namespace roughgas {
namespace {

std::vector<SpeciesSlice> slices_of(const std::vector<SpeciesBlock>& blocks) {
    std::vector<SpeciesSlice> s;
    for (const auto& b : blocks)
        s.push_back({b.offset, b.count, b.grain.mass, b.moment_of_inertia()});
    return s;
}

// Collisions off: the Strang schedule of n steps (merged half-streams) streams exactly n h, and
// V_x(t) = V_x(0) - a t V_y(0) to round-off; V_y, V_z, omega untouched; the kinetic pressure
// tensor follows the free-streaming solution P_xy(t) = P_xy(0) - a t P_yy(0),
// P_xx(t) = P_xx(0) - 2 a t P_xy(0) + a^2 t^2 P_yy(0).
TEST(ShearStream, ExactWithCollisionsOff) {
    const std::vector<SpeciesSpec> species = {SpeciesSpec{}};
    const auto blocks = make_species_blocks(species, 5000);
    RoughAoS store(5000);
    init_maxwellian(store, blocks, 7, 0);
    for (std::size_t i = 0; i < store.size(); ++i) // a non-zero P_xy(0)
        store.v(i).x += 0.3 * store.v(i).y;
    const RoughAoS start = store;
    const auto slices = slices_of(blocks);
    const double V = 5000.0; // density 1
    const PressureTensor P0 = pressure_tensor(start.velocities(), slices, V, Vec3{});
    const double a = 0.7, h = 0.013;
    int collide_calls = 0;
    double collide_time = 0;
    PressureTensor sums; // what the last stream gathered: the pressure tensor times V after it
    for (int n : {1, 2, 37}) {
        store = start;
        collide_calls = 0;
        collide_time = 0;
        const std::int64_t steps = strang_steps(
            [&] { return h; }, [&](double s) { sums = stream_shear(store, a, s, slices); },
            [&](double dt) {
                ++collide_calls;
                collide_time += dt;
                return dt;
            },
            [&] { return collide_calls >= n; });
        EXPECT_EQ(steps, n);
        EXPECT_NEAR(collide_time, n * h, 1e-15 * n);
        const double t = n * h;
        double worst = 0;
        for (std::size_t i = 0; i < store.size(); ++i) {
            const Vec3 v0 = start.v(i), v = store.v(i);
            const double exact = v0.x - a * t * v0.y;
            worst = std::max(worst, std::abs(v.x - exact) / (std::abs(v0.x) + a * t * std::abs(v0.y)));
            ASSERT_EQ(v.y, v0.y);
            ASSERT_EQ(v.z, v0.z);
            ASSERT_EQ(store.w(i), start.w(i));
        }
        // each of the n + 1 streams rounds once per grain: a few ulps per step
        EXPECT_LT(worst, 4e-16 * (n + 1)) << "n = " << n;
        const PressureTensor P = pressure_tensor(store.velocities(), slices, V, Vec3{});
        const double tol = 1e-13 * P0.yy;
        EXPECT_NEAR(P.xy, P0.xy - a * t * P0.yy, tol);
        EXPECT_NEAR(P.xx, P0.xx - 2 * a * t * P0.xy + a * a * t * t * P0.yy, tol);
        EXPECT_NEAR(P.yy, P0.yy, tol);
        EXPECT_NEAR(P.zz, P0.zz, tol);
        EXPECT_NEAR(P.xz, P0.xz - a * t * P0.yz, tol);
        EXPECT_NEAR(P.yz, P0.yz, tol);
        for (auto [gathered, direct] : {std::pair{sums.xx, P.xx}, {sums.yy, P.yy}, {sums.zz, P.zz},
                                         {sums.xy, P.xy}, {sums.xz, P.xz}, {sums.yz, P.yz}})
            EXPECT_NEAR(gathered / V, direct, tol);
    }
}

// The step length is what it claims: after the stream of (h_prev + h)/2 that precedes the step, the
// collision frequency nu_ref sqrt(T'/T) times h is tau (checked by streaming a copy: T' measured,
// not predicted), from a* = a/nu_ref = 1e-6 (h = tau/nu_ref) to 1e6 (the stream heats the gas by
// ~1e9 first).
TEST(ShearStream, StepLengthIsTauMeanFreeTimesAfterItsStream) {
    const std::vector<SpeciesSpec> species = {SpeciesSpec{}};
    const auto blocks = make_species_blocks(species, 4000);
    const auto slices = slices_of(blocks);
    RoughAoS start(4000);
    init_maxwellian(start, blocks, 11, 0);
    for (std::size_t i = 0; i < start.size(); ++i) // a sheared state: P_xy < 0
        start.v(i).x -= 0.4 * start.v(i).y;
    const PressureTensor P = pressure_tensor(start.velocities(), slices, 1.0, Vec3{});
    const double nu_ref = 2.0, tau = 0.2;
    for (double a_star : {1e-6, 0.5, 3.0, 1e3, 1e6})
        for (double h_prev : {0.0, 0.07}) {
            const double a = a_star * nu_ref;
            const double h = strang_step_length(tau, nu_ref, P, a, h_prev);
            RoughAoS store = start;
            const PressureTensor Q = stream_shear(store, a, 0.5 * (h_prev + h), slices);
            const double ratio = (Q.xx + Q.yy + Q.zz) / (P.xx + P.yy + P.zz);
            EXPECT_NEAR(h * nu_ref * std::sqrt(ratio), tau, 1e-9 * tau) << "a* = " << a_star << ", h_prev = " << h_prev;
            if (a_star == 1e-6 && h_prev == 0) {
                EXPECT_NEAR(h, tau / nu_ref, 1e-6 * tau / nu_ref);
            }
        }
    EXPECT_THROW(strang_step_length(tau, 0.0, P, 1.0, 0.0), std::runtime_error);
    EXPECT_THROW(strang_step_length(tau, nu_ref, PressureTensor{}, 1.0, 0.0), std::runtime_error);
}

// Steps of varying length: every collide(h_k) sits between half of the previous and half of its
// own step's stream (stream (h_{k-1} + h_k)/2 between them), so each step is a symmetric Strang step.
TEST(ShearStream, VaryingStepsStaySymmetric) {
    const std::vector<double> h = {0.5, 0.25, 0.125, 1.0, 0.75};
    std::size_t asked = 0;
    std::vector<double> streams, collides;
    const std::int64_t steps = strang_steps(
        [&] { return h.at(asked++); }, [&](double s) { streams.push_back(s); },
        [&](double dt) {
            collides.push_back(dt);
            return dt;
        },
        [&] { return collides.size() == h.size(); });
    EXPECT_EQ(steps, static_cast<std::int64_t>(h.size()));
    EXPECT_EQ(asked, h.size()); // one step() per step, none after the last
    EXPECT_EQ(collides, h);
    ASSERT_EQ(streams.size(), h.size() + 1);
    EXPECT_EQ(streams.front(), 0.5 * h.front());
    for (std::size_t k = 1; k < h.size(); ++k)
        EXPECT_EQ(streams[k], 0.5 * (h[k - 1] + h[k]));
    EXPECT_EQ(streams.back(), 0.5 * h.back());
}

// A step cut short (collide advanced h' < h) ends with a stream of h' - h/2: streams and
// collisions still cover the same time.
TEST(ShearStream, CutStepStreamsWhatItCollided) {
    std::vector<double> streams;
    int calls = 0;
    strang_steps([] { return 1.0; }, [&](double s) { streams.push_back(s); },
                 [&](double h) { return ++calls == 2 ? 0.25 * h : h; }, [&] { return calls == 3; });
    EXPECT_EQ(streams, (std::vector<double>{0.5, 1.0, 0.25 - 0.5 + 0.5, 0.5}));
    double total = 0;
    for (double x : streams)
        total += x;
    EXPECT_EQ(total, 1.0 + 0.25 + 1.0);
}

// A step() that takes the owed stream may do it itself before it decides its length (run.cpp does
// so in fast transients): the merged stream is then split into that owed part and the new step's
// h/2, and streams and collisions still cover the same time.
TEST(ShearStream, StepMayDoTheOwedStreamFirst) {
    std::vector<double> streams;
    const std::vector<double> h = {1.0, 0.5, 0.25};
    std::size_t asked = 0, collided = 0;
    strang_steps(
        [&](double& pending) {
            if (asked == 1) { // before the second step: stream what the first still owes
                streams.push_back(pending);
                pending = 0;
            }
            return h.at(asked++);
        },
        [&](double s) { streams.push_back(s); },
        [&](double dt) {
            ++collided;
            return dt;
        },
        [&] { return collided == h.size(); });
    EXPECT_EQ(streams, (std::vector<double>{0.5, 0.5, 0.25, 0.375, 0.125}));
    double total = 0;
    for (double x : streams)
        total += x;
    EXPECT_EQ(total, 1.0 + 0.5 + 0.25);
}

// Streaming by -s undoes streaming by s (the group property the merged half-steps rely on).
TEST(ShearStream, NegativeTimeInverts) {
    RoughAoS store(3);
    store.v(0) = {1.0, 2.0, 3.0};
    store.v(1) = {-0.5, 0.25, 1.0};
    store.v(2) = {0.0, -4.0, 0.0};
    const RoughAoS start = store;
    const SpeciesSlice one[] = {{0, 3, 1.0, 0.1}};
    stream_shear(store, 2.0, 0.125, one);
    EXPECT_EQ(store.v(0).x, 1.0 - 0.5);
    stream_shear(store, 2.0, -0.125, one);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(store.v(i), start.v(i));
}

TEST(Pressure, TraceIsThreeNT) {
    std::vector<SpeciesSpec> species = {SpeciesSpec{}, SpeciesSpec{}};
    species[0].fraction = 0.3;
    species[1].fraction = 0.7;
    species[1].name = "b";
    species[1].mass = 4;
    species[1].temperature = 2;
    const auto blocks = make_species_blocks(species, 3000);
    RoughAoS store(3000);
    init_maxwellian(store, blocks, 3, 0);
    const auto slices = slices_of(blocks);
    const double density = 2.5, V = 3000 / density;
    const Moments m = compute_moments(store.velocities(), store.angular_velocities(), slices);
    const PressureTensor P = pressure_tensor(store.velocities(), slices, V, m.mean_velocity);
    EXPECT_NEAR(P.xx + P.yy + P.zz, 3 * density * m.all.T_tr, 1e-12 * P.xx);
}

TEST(Pressure, NuAndReducedQuantities) {
    // equal spheres: nu = (16/5) n sigma^2 sqrt(pi T/m)
    const UsfSpecies one{1.0, 2.0, 0.5};
    const double n = 0.3, T = 1.7;
    const double expected = 16.0 / 5.0 * n * 1.0 * std::sqrt(std::numbers::pi * T / 2.0);
    EXPECT_NEAR(usf_nu(std::span(&one, 1), n, T), expected, 1e-14 * expected);
    // two identical species are one
    const UsfSpecies two[] = {{0.4, 2.0, 0.5}, {0.6, 2.0, 0.5}};
    EXPECT_NEAR(usf_nu(two, n, T), expected, 1e-14 * expected);
    const PressureTensor P{1.2, 0.9, 0.9, -0.3, 0.0, 0.0};
    const UsfReduced r = usf_reduced(P, 0.5, 2.0, 1.0, 1.0);
    EXPECT_EQ(r.a_star, 0.25);
    EXPECT_EQ(r.eta_star, 0.3 / 0.25);
    EXPECT_NEAR(r.N1_star, 0.3, 1e-15);
    EXPECT_EQ(r.N2_star, 0.0);
}

RunSpec shear_spec(PairRestitution model, std::uint64_t seed = 11) {
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {model};
    s.particles = 2000;
    s.end = 3;
    s.output_times = {1, 2, 3};
    s.seed = seed;
    s.shear = ShearSpec{0.5, 0.2};
    return s;
}

std::vector<std::vector<double>> run_rows(const RunSpec& spec, ReplicaSummary* summary = nullptr) {
    const auto tables = RestitutionTables::build(spec);
    std::vector<std::vector<double>> rows;
    run_replica(
        spec, *tables, 0, [&](std::span<const double> r) { rows.emplace_back(r.begin(), r.end()); }, {},
        summary);
    return rows;
}

TEST(ShearRun, ColumnsAndRows) {
    const RunSpec s = shear_spec(ConstantRestitution{0.9, 0.0});
    const auto cols = dsmc_columns(s);
    ASSERT_GE(cols.size(), 30u);
    EXPECT_EQ(cols[10].name, "E_diss_rate");
    EXPECT_EQ(cols[11].name, "P_xx");
    EXPECT_EQ(cols[14].name, "P_xy");
    EXPECT_EQ(cols[20].name, "a_star");
    EXPECT_EQ(cols[21].name, "eta_star");
    EXPECT_EQ(cols[25].name, "P_xy_star");
    EXPECT_EQ(cols[29].name, "N2_star");
    ReplicaSummary summary;
    const auto rows = run_rows(s, &summary);
    ASSERT_EQ(rows.size(), 4u);
    // The streaming keeps the mean peculiar velocity at 0 (sum m V_y = 0): the engine's recentring
    // (a Galilean shift, dsmc/engine.hpp) only ever sees round-off, never a drift the shear made.
    EXPECT_LT(summary.max_mean_drift, 1e-12);
    EXPECT_GE(summary.steps, 12); // an engine step per Strang step: 3 mean free times / h = 0.2 ~ 15
    for (std::size_t k = 1; k < rows.size(); ++k) { // rows at or just after the output times
        EXPECT_GE(rows[k][1], static_cast<double>(k));
        EXPECT_LT(rows[k][1], static_cast<double>(k) + 0.25);
        EXPECT_LT(rows[k][14], 0.0) << "the shear stress has the sign of -a";
    }
}

TEST(ShearRun, SameSeedSameRunOtherSeedOtherRun) {
    for (PairRestitution m :
         {PairRestitution{ConstantRestitution{0.9, -1.0}}, PairRestitution{ConstantRestitution{0.8, 0.5}}}) {
        const auto a = run_rows(shear_spec(m)), b = run_rows(shear_spec(m)), c = run_rows(shear_spec(m, 12));
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t k = 0; k < a.size(); ++k)
            EXPECT_EQ(std::memcmp(a[k].data(), b[k].data(), a[k].size() * sizeof(double)), 0);
        EXPECT_NE(a.back()[14], c.back()[14]);
    }
}

} // namespace
} // namespace roughgas
