// Walls and gravity of the spatially resolved engine (collision/wall_rule.hpp,
// dsmc/spatial_engine.hpp): the wall collision rule exactly; a closed elastic box under gravity
// conserves kinetic plus potential energy to round-off and keeps every grain inside; diffuse walls
// bring a gas to their temperature and feel its pressure n T_w and hit rate n sqrt(T_w/(2 pi m));
// the thread count changes nothing.
#include "no_observer.hpp"
#include "roughgas/dsmc/spatial_engine.hpp"

#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/collision/wall_rule.hpp"
#include "roughgas/dsmc/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace roughgas {
namespace {

using test::NoObserver;

std::vector<SpeciesBlock> grains(std::int64_t n, double T = 1, double T_rot = 1) {
    SpeciesSpec s;
    s.temperature = T;
    s.rotational_temperature = T_rot;
    return make_species_blocks({s}, n);
}

Vec3 contact_velocity(const Vec3& v, const Vec3& w, double R, const Vec3& U, const Vec3& n) {
    return v - U - R * cross(w, n);
}

TEST(WallRule, RoughWallReversesTheContactVelocityByAlphaAndBeta) {
    Rng r = make_stream(StreamKey{1, Stream::test, 0, 0, 0});
    const GrainProperties g{1.7, 0.6, 0.35};
    const PairConstants pc = wall_pair_constants(g);
    const double J = g.inertia * g.mass * g.radius * g.radius;
    for (int k = 0; k < 200; ++k) {
        const double alpha = 0.2 + 0.8 * uniform01(r), beta = uniform_pm1(r);
        const int axis = k % 3;
        Vec3 n{};
        (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = k % 2 ? -1.0 : 1.0;
        Vec3 U{uniform_pm1(r), uniform_pm1(r), uniform_pm1(r)};
        (axis == 0 ? U.x : axis == 1 ? U.y : U.z) = 0;
        Vec3 v{uniform_pm1(r), uniform_pm1(r), uniform_pm1(r)}, w{uniform_pm1(r), uniform_pm1(r), uniform_pm1(r)};
        if (dot(v, n) > 0)
            v = v - 2.0 * dot(v, n) * n; // approaching the wall
        const Vec3 g0 = contact_velocity(v, w, g.radius, U, n);
        const Vec3 L0 = J * w + g.mass * g.radius * cross(n, v); // about the contact point r - R n
        collide_with_wall(pc, make_rough_constant(alpha, beta), v, w, U, n);
        const Vec3 g1 = contact_velocity(v, w, g.radius, U, n);
        const Vec3 gn0 = dot(g0, n) * n, gn1 = dot(g1, n) * n;
        const Vec3 d_n = gn1 + alpha * gn0, d_t = (g1 - gn1) + beta * (g0 - gn0);
        EXPECT_LT(std::sqrt(norm2(d_n)), 1e-13);
        EXPECT_LT(std::sqrt(norm2(d_t)), 1e-13);
        const Vec3 L1 = J * w + g.mass * g.radius * cross(n, v);
        EXPECT_LT(std::sqrt(norm2(L1 - L0)), 1e-13) << "angular momentum about the contact point";
    }
}

TEST(WallRule, DiffuseWallEmitsInwardsAtItsTemperature) {
    CollisionRng r = make_collision_stream(StreamKey{2, Stream::test, 0, 0, 0});
    const double T = 1.5, m = 2.0, J = 0.3;
    const Vec3 U{0.4, 0, -0.2};
    const int K = 400000;
    double vn = 0, vn2 = 0, vt = 0, vt2 = 0, w2 = 0;
    for (int k = 0; k < K; ++k) {
        Vec3 v{}, w{};
        emit_from_diffuse_wall<true>(r, T, m, J, U, 1, -1.0, v, w);
        ASSERT_LT(v.y, 0.0) << "the upper wall emits downwards";
        vn += -v.y;
        vn2 += v.y * v.y;
        vt += v.x;
        vt2 += (v.x - U.x) * (v.x - U.x);
        w2 += norm2(w);
    }
    // Flux-weighted half-Maxwellian: <s> = sqrt(pi T/(2m)), <s^2> = 2T/m; tangential N(U, T/m); omega N(0, T/J).
    const double c2 = T / m;
    EXPECT_NEAR(vn / K, std::sqrt(std::numbers::pi * c2 / 2), 5 * std::sqrt(c2 * (2 - std::numbers::pi / 2) / K));
    EXPECT_NEAR(vn2 / K, 2 * c2, 5 * 2 * c2 / std::sqrt(K));
    EXPECT_NEAR(vt / K, U.x, 5 * std::sqrt(c2 / K));
    EXPECT_NEAR(vt2 / K, c2, 5 * c2 * std::sqrt(2.0 / K));
    EXPECT_NEAR(w2 / (3 * K), T / J, 5 * (T / J) * std::sqrt(2.0 / (3 * K)));
}

// Elastic rough grains (alpha = 1, beta = 1) in a box closed by specular and elastic rough walls
// (beta_w = 1) on all sides, under an oblique gravity: the kinetic plus potential energy
// sum (m |v|^2/2 + J |omega|^2/2 - m g.x) stays constant to round-off, every grain stays inside.
TEST(SpatialWalls, ClosedElasticBoxUnderGravityConservesEnergyAndKeepsGrainsInside) {
    DomainSpec d;
    d.size = {12.0, 20.0, 8.0};
    d.cells = {3, 5, 2};
    d.boundary = {Boundary::walls, Boundary::walls, Boundary::walls};
    d.wall_lower.kind = WallKind::specular;
    d.wall_upper = {WallKind::rough, 1.0, {0, 0, 0}, 1.0, 1.0};
    d.gravity = {0.05, -0.4, 0.1};
    SpatialEngine<RoughConstant, true> e(d, grains(4000), {make_rough_constant(1.0, 1.0)}, 0.05, 5, 0, 2);
    const double J = e.species()[0].moment_of_inertia();
    const auto energy = [&] {
        double E = 0;
        for (std::size_t i = 0; i < e.particles(); ++i) {
            const Vec3& x = e.positions()[i];
            E += 0.5 * norm2(e.velocities()[i]) + 0.5 * J * norm2(e.angular_velocities()[i]) -
                 (d.gravity[0] * x.x + d.gravity[1] * x.y + d.gravity[2] * x.z);
        }
        return E;
    };
    const double E0 = energy();
    NoObserver obs;
    for (int s = 0; s < 60; ++s)
        e.step(0.7, obs);
    EXPECT_GT(e.collisions(), 10000);
    double hits = 0;
    for (const WallFlux& f : e.wall_fluxes())
        hits += f.hits;
    EXPECT_GT(hits, 10000);
    EXPECT_NEAR(energy(), E0, 1e-11 * std::abs(E0));
    for (const Vec3& x : e.positions())
        ASSERT_TRUE(x.x >= 0 && x.x <= d.size[0] && x.y >= 0 && x.y <= d.size[1] && x.z >= 0 && x.z <= d.size[2])
            << x.x << " " << x.y << " " << x.z;
}

// Elastic rough grains started hot (T_tr = 2, T_rot = 0.5) between diffuse walls at T_w = 1 normal to
// y (x, z periodic): both temperatures relax to T_w; then, over 250 time units, each wall is hit
// n sqrt(T_w/(2 pi m)) times per area and time and feels the pressure P_yy = n T_w, with no net
// energy flux and no shear stress (tolerances: 5 standard errors of the hits' Poisson count).
TEST(SpatialWalls, DiffuseWallsHoldTheirTemperatureAndFeelThePressure) {
    DomainSpec d;
    d.size = {20.0, 20.0, 20.0};
    d.cells = {2, 4, 2};
    d.boundary = {Boundary::periodic, Boundary::walls, Boundary::periodic};
    d.wall_lower = {WallKind::diffuse, 1.0, {0, 0, 0}, 1, -1};
    d.wall_upper = d.wall_lower;
    const std::int64_t N = 20000;
    const double n = 0.02;
    SpatialEngine<RoughConstant, true> e(d, grains(N, 2.0, 0.5), {make_rough_constant(1.0, 1.0)}, n, 9, 0, 2);
    NoObserver obs;
    for (int s = 0; s < 150; ++s) // 300 time units: some 20 wall-to-wall crossings
        e.step(2.0, obs);
    const double J = e.species()[0].moment_of_inertia();
    const auto temperatures = [&] {
        Vec3 u{};
        for (const Vec3& v : e.velocities())
            u += v;
        u = (1.0 / N) * u;
        double tr = 0, rot = 0;
        for (std::size_t i = 0; i < e.particles(); ++i) {
            tr += norm2(e.velocities()[i] - u);
            rot += J * norm2(e.angular_velocities()[i]);
        }
        return std::pair{tr / (3.0 * N), rot / (3.0 * N)};
    };
    const WallFluxes before = e.wall_fluxes();
    const double t0 = e.time();
    double T_tr = 0, T_rot = 0;
    for (int s = 0; s < 125; ++s) {
        e.step(2.0, obs);
        const auto [a, b] = temperatures();
        T_tr += a / 125;
        T_rot += b / 125;
    }
    // The time average over 125 samples of a sum over N grains: a relative spread of sqrt(2/(3N)) per
    // sample, the samples correlated over a wall-crossing time (~12 steps): 5 sigma with 10 samples.
    const double tol = 5 * std::sqrt(2.0 / (3.0 * N)) / std::sqrt(10.0);
    EXPECT_NEAR(T_tr, 1.0, tol);
    EXPECT_NEAR(T_rot, 1.0, tol);
    const double dt = e.time() - t0, area = d.size[0] * d.size[2];
    const double F = n * d.size[0] * d.size[1] * d.size[2] / N; // physical grains per simulated one
    for (int k : {2, 3}) {
        const WallFlux& f = e.wall_fluxes()[static_cast<std::size_t>(k)];
        const WallFlux& f0 = before[static_cast<std::size_t>(k)];
        const double H = f.hits - f0.hits;
        const double rate = H * F / (area * dt);
        const double expected = n * std::sqrt(1.0 / (2 * std::numbers::pi));
        EXPECT_NEAR(rate, expected, 5 * expected / std::sqrt(H)) << "wall " << k;
        const Vec3 p = f.momentum - f0.momentum;
        const double P_yy = std::abs(p.y) * F / (area * dt);
        // Each hit gives m (|v_in| + |v_out|) with a relative spread below 1/2.
        EXPECT_NEAR(P_yy, n, 5 * 0.5 * n / std::sqrt(H)) << "wall " << k;
        // Per hit m (v_x,in - v_x,out) has the spread sqrt(2 T/m), the energy exchanged one below 3 T.
        EXPECT_NEAR(p.x * F / (area * dt), 0.0, 5 * std::sqrt(2.0) * expected / std::sqrt(H)) << "wall " << k;
        EXPECT_NEAR((f.energy - f0.energy) * F / (area * dt), 0.0, 5 * 3.0 * expected / std::sqrt(H))
            << "wall " << k;
    }
}

// Diffuse moving walls and gravity draw random numbers in the flight: per chunk of grains and step,
// never per thread.
TEST(SpatialWalls, ThreadCountDoesNotChangeTheResults) {
    DomainSpec d;
    d.size = {30.0, 30.0, 30.0};
    d.cells = {3, 3, 3};
    d.boundary = {Boundary::walls, Boundary::walls, Boundary::periodic};
    d.wall_lower = {WallKind::diffuse, 1.0, {0, 0, 0.3}, 1, -1};
    d.wall_upper = {WallKind::rough, 1.0, {0, 0, -0.3}, 0.8, 0.4};
    d.gravity = {0, -0.02, 0};
    std::vector<std::vector<Vec3>> end;
    for (int threads : {1, 2}) {
        SpatialEngine<RoughConstant, true> e(d, grains(150000), {make_rough_constant(0.9, 0.2)}, 0.01, 4, 1, threads);
        NoObserver obs;
        for (int s = 0; s < 4; ++s)
            e.step(3.0, obs);
        end.push_back(e.positions());
        end.push_back(e.velocities());
        end.push_back(e.angular_velocities());
    }
    EXPECT_TRUE(end[0] == end[3]);
    EXPECT_TRUE(end[1] == end[4]);
    EXPECT_TRUE(end[2] == end[5]);
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// Lees-Edwards boundaries (run.kind = shear with [domain]): a sheared box of inelastic rough grains
// (alpha = 0.9, beta = 0) started near its steady temperature. Every grain stays in the box; the
// profile u_x(y) of the rows after 20 collisions per particle is the images' a (y - L_y/2) in every
// slab, the two touching y = 0 and y = L_y included (no kink at the images: 5 standard errors of
// the rows' scatter); 1 and 2 threads give the same bits.
TEST(LeesEdwards, FlowIsLinearAcrossTheImagesAndTheThreadsChangeNothing) {
    const double n = 0.02, a = 0.01, lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n);
    RunSpec spec;
    spec.species = {SpeciesSpec{}};
    spec.species[0].temperature = 0.0084;
    spec.species[0].rotational_temperature = 0.002;
    spec.pairs = {ConstantRestitution{0.9, 0.0}};
    spec.particles = 40000;
    spec.density = n;
    spec.seed = 3;
    for (int k = 1; k <= 40; ++k)
        spec.output_times.push_back(k);
    spec.end = 40;
    spec.shear = ShearSpec{a, 0.2};
    DomainSpec d;
    d.size = {4 * lambda, 4 * lambda, 4 * lambda};
    d.cells = {4, 16, 4};
    d.profile_axis = 1;
    d.shear_rate = a;
    spec.domain = d;
    const std::vector<Column> cols = replica_row_columns(spec);
    const auto col = [&](const std::string& name) {
        for (std::size_t j = 0; j < cols.size(); ++j)
            if (cols[j].name == name)
                return j;
        ADD_FAILURE() << name;
        return std::size_t{0};
    };
    std::vector<std::vector<std::vector<double>>> runs;
    for (int threads : {1, 2}) {
        spec.threads = threads;
        std::vector<std::vector<double>> rows;
        run_replica(spec, 0, [&](std::span<const double> row) { rows.emplace_back(row.begin(), row.end()); });
        runs.push_back(rows);
    }
    ASSERT_EQ(runs[0].size(), runs[1].size());
    for (std::size_t r = 0; r < runs[0].size(); ++r)
        for (std::size_t j = 0; j < cols.size(); ++j) { // the same bits (NaN where undefined)
            const double x = runs[0][r][j], y = runs[1][r][j];
            ASSERT_TRUE(x == y || (std::isnan(x) && std::isnan(y))) << "row " << r << " " << cols[j].name;
        }
    const std::vector<std::vector<double>>& rows = runs[0];
    const double dy = d.size[1] / d.cells[1];
    for (int b = 0; b < d.cells[1]; ++b) {
        std::vector<double> u;
        for (std::size_t r = 21; r < rows.size(); ++r)
            u.push_back(rows[r][col("bin" + std::to_string(b) + ".u_x")]);
        double mean = 0, ss = 0;
        for (double x : u)
            mean += x / static_cast<double>(u.size());
        for (double x : u)
            ss += (x - mean) * (x - mean);
        const double err = std::sqrt(ss / (static_cast<double>(u.size()) * static_cast<double>(u.size() - 1)));
        EXPECT_NEAR(mean, a * ((b + 0.5) * dy - 0.5 * d.size[1]), 5 * err) << "slab " << b;
    }
}

} // namespace
} // namespace roughgas
