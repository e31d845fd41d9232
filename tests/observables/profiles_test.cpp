// Profiles (observables/profiles.hpp) of hand-placed grains: each field against its definition;
// the middle-of-flight sampling moves grains between bins; an empty bin has n = 0 and NaN fields.
#include "roughgas/core/worker_team.hpp"
#include "roughgas/observables/profiles.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace roughgas {
namespace {

std::vector<SpeciesBlock> species(std::int64_t n, double mass, double radius, double q) {
    SpeciesSpec s;
    s.mass = mass;
    s.radius = radius;
    s.inertia = q;
    return make_species_blocks({s}, n);
}

// n grains around the centre of the unit cube (within `spread` of it along each axis) drifting at
// (300, -200, 100) with velocities and spins spread uniformly over [-1, 1) about it.
void drifting_gas(std::size_t n, double spread, std::vector<Vec3>& x, std::vector<Vec3>& v, std::vector<Vec3>& w) {
    x.resize(n);
    v.resize(n);
    w.resize(n);
    std::uint64_t r = 12345;
    const auto uniform = [&] { // in [-1, 1)
        r = r * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(r >> 11) * 0x1p-52 - 1.0;
    };
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = {0.5 + spread * uniform(), 0.5 + spread * uniform(), 0.5 + spread * uniform()};
        v[i] = {300 + uniform(), -200 + uniform(), 100 + uniform()};
        w[i] = {uniform(), uniform(), uniform()};
    }
}

TEST(Profiles, FieldsFollowTheirDefinitions) {
    // Three grains of mass 2 in bin 0 of [0, 4) along y (bins of 2), none in bin 1.
    const std::vector<SpeciesBlock> b = species(3, 2.0, 0.5, 0.4);
    const double J = 0.4 * 2.0 * 0.25;
    const std::vector<Vec3> x = {{0.3, 0.5, 7}, {9, 1.0, 1}, {0, 1.9, 2}};
    const std::vector<Vec3> v = {{1, 0, 0}, {-1, 2, 0}, {3, 1, -3}};
    const std::vector<Vec3> w = {{0, 0, 1}, {0, 2, 0}, {3, 0, 0}};
    ProfileGeometry g;
    g.axis = 1;
    g.bins = 2;
    g.length = 4;
    g.bin_volume = 8;
    g.weight = 4; // n = 3 x 4 / 8
    g.periodic = false;
    const std::vector<Virial> virial = {Virial{1, 2, 3, 4, 5, 6}, Virial{}};
    const std::vector<double> p = compute_profiles(g, x, v, w, b, virial, 0.5);
    ASSERT_EQ(p.size(), 2 * profile_field_count);
    const auto f = [&](int bin, const std::string& name) {
        for (std::size_t k = 0; k < profile_field_count; ++k)
            if (name == profile_fields[k])
                return p[static_cast<std::size_t>(bin) * profile_field_count + k];
        ADD_FAILURE() << name;
        return 0.0;
    };
    EXPECT_DOUBLE_EQ(f(0, "n"), 1.5);
    const Vec3 u{1, 1, -1}; // mean of v
    EXPECT_DOUBLE_EQ(f(0, "u_x"), u.x);
    EXPECT_DOUBLE_EQ(f(0, "u_y"), u.y);
    EXPECT_DOUBLE_EQ(f(0, "u_z"), u.z);
    double cc = 0, pxy = 0, E_rot = 0;
    Vec3 q{};
    for (std::size_t i = 0; i < 3; ++i) {
        const Vec3 c = v[i] - u;
        cc += 2 * norm2(c);
        pxy += 2 * c.x * c.y;
        q += (0.5 * 2 * norm2(c) + 0.5 * J * norm2(w[i])) * c;
        E_rot += J * norm2(w[i]);
    }
    EXPECT_NEAR(f(0, "T_tr"), cc / 9, 1e-14);
    EXPECT_NEAR(f(0, "T_rot"), E_rot / 9, 1e-14);
    EXPECT_NEAR(f(0, "theta"), E_rot / cc, 1e-14);
    EXPECT_NEAR(f(0, "P_xy"), 0.5 * pxy, 1e-14); // F / V_b = 1/2
    EXPECT_NEAR(f(0, "q_y"), 0.5 * q.y, 1e-14);
    EXPECT_NEAR(f(0, "Pc_xy"), 0.5 * 4 / 0.5, 1e-14);
    EXPECT_NEAR(f(0, "omega_x"), 1.0, 1e-14);
    EXPECT_EQ(f(1, "n"), 0.0);
    EXPECT_TRUE(std::isnan(f(1, "T_tr")));
    // No interval: the collisional part is undefined.
    EXPECT_TRUE(std::isnan(compute_profiles(g, x, v, w, b, virial, std::nan(""))[profile_collisional_first]));
}

// A bin drifting at a hundred times its thermal speed: its temperature, shear stress and heat flux
// (moments about the bin's own flow) against the definitions summed in long double about the
// exact mean, to 1e-12 relative: no cancellation of the drift's square against the spread's.
TEST(Profiles, ADriftingBinKeepsItsMomentsToRoundOff) {
    const std::size_t n = 1000;
    const std::vector<SpeciesBlock> b = species(static_cast<std::int64_t>(n), 1.5, 0.5, 0.4);
    std::vector<Vec3> x, v, w;
    drifting_gas(n, 0.4, x, v, w);
    ProfileGeometry g; // one bin of the unit cube
    const std::vector<double> p = compute_profiles(g, x, v, w, b, {Virial{}}, 0.5);
    const auto f = [&](const std::string& name) {
        for (std::size_t k = 0; k < profile_field_count; ++k)
            if (name == profile_fields[k])
                return p[k];
        ADD_FAILURE() << name;
        return 0.0;
    };
    const long double m = 1.5, J = 0.4 * 1.5 * 0.25;
    long double u[3] = {0, 0, 0};
    for (const Vec3& q : v) {
        u[0] += q.x;
        u[1] += q.y;
        u[2] += q.z;
    }
    for (long double& c : u)
        c /= n;
    long double cc = 0, cxy = 0, qx = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const long double c[3] = {v[i].x - u[0], v[i].y - u[1], v[i].z - u[2]};
        const long double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        const long double w2 = static_cast<long double>(norm2(w[i]));
        cc += m * c2;
        cxy += m * c[0] * c[1];
        qx += (0.5L * m * c2 + 0.5L * J * w2) * c[0];
    }
    const double T = static_cast<double>(cc / (3 * n)), Pxy = static_cast<double>(cxy), q = static_cast<double>(qx);
    EXPECT_NEAR(f("T_tr"), T, 1e-12 * T);
    EXPECT_NEAR(f("P_xy"), Pxy, 1e-12 * n * T);
    EXPECT_NEAR(f("q_x"), q, 1e-12 * n * std::pow(T, 1.5));
}

TEST(Profiles, OnATeamTheSameForAnyThreadsAndAsTheSerialPassToRoundOff) {
    // On a team the grains are summed in fixed units (at least 65536 grains each), added in unit
    // order about the bins' flows: the same bits on 1, 2 or 3 threads, and the serial pass's
    // profiles to round-off, here for two species drifting at 300 times their thermal speed (a
    // merge that left out a unit's flow about the bin's, M d d, would be off by 1e-6 in T).
    const std::size_t n = 300000;
    SpeciesSpec heavy, light;
    heavy.mass = 1.5;
    heavy.radius = 0.5;
    heavy.inertia = 0.4;
    light.mass = 0.5;
    light.radius = 0.3;
    light.inertia = 0.4;
    heavy.fraction = light.fraction = 0.5;
    const std::vector<SpeciesBlock> b = make_species_blocks({heavy, light}, static_cast<std::int64_t>(n));
    std::vector<Vec3> x, v, w;
    drifting_gas(n, 0.5, x, v, w);
    ProfileGeometry g;
    g.bins = 5;
    g.bin_volume = 0.2;
    const std::vector<Virial> virial(5);
    const std::vector<double> serial = compute_profiles(g, x, v, w, b, virial, 0.5);
    const auto same = [](const std::vector<double>& a, const std::vector<double>& c) {
        if (a.size() != c.size())
            return false;
        for (std::size_t k = 0; k < a.size(); ++k)
            if (!(a[k] == c[k] || (std::isnan(a[k]) && std::isnan(c[k]))))
                return false;
        return true;
    };
    std::vector<double> first;
    for (int threads : {1, 2, 3}) {
        WorkerTeam team(threads);
        const std::vector<double> p = compute_profiles(g, x, v, w, b, virial, 0.5, &team);
        if (first.empty())
            first = p;
        EXPECT_TRUE(same(p, first)) << threads << " threads";
    }
    const auto field = [&](const std::vector<double>& p, std::size_t bin, const std::string& name) {
        for (std::size_t k = 0; k < profile_field_count; ++k)
            if (name == profile_fields[k])
                return p[bin * profile_field_count + k];
        ADD_FAILURE() << name;
        return 0.0;
    };
    for (std::size_t bin = 0; bin < 5; ++bin) {
        const double N_b = field(serial, bin, "n") * g.bin_volume, T = field(serial, bin, "T_tr");
        EXPECT_EQ(field(first, bin, "n"), field(serial, bin, "n"));
        EXPECT_NEAR(field(first, bin, "u_x"), field(serial, bin, "u_x"), 1e-13 * 300);
        EXPECT_NEAR(field(first, bin, "T_tr"), T, 1e-12 * T);
        EXPECT_NEAR(field(first, bin, "T_rot"), field(serial, bin, "T_rot"), 1e-12 * T);
        EXPECT_NEAR(field(first, bin, "P_xy"), field(serial, bin, "P_xy"), 1e-12 * N_b * T / g.bin_volume);
        EXPECT_NEAR(field(first, bin, "q_x"), field(serial, bin, "q_x"), 1e-12 * N_b * std::pow(T, 1.5) / g.bin_volume);
    }
}

TEST(Profiles, GrainsAreTakenInTheMiddleOfTheFlight) {
    const std::vector<SpeciesBlock> b = species(2, 1.0, 0.5, 0.4);
    const std::vector<Vec3> x = {{1.9, 0, 0}, {0.1, 0, 0}}, w(2);
    const std::vector<Vec3> v = {{1, 0, 0}, {-1, 0, 0}};
    ProfileGeometry g; // x in [0, 4), bins of 2, periodic
    g.bins = 2;
    g.length = 4;
    g.half_flight = 0.2; // grain 0 moves to 2.1 (bin 1); grain 1 to -0.1 = 3.9 (bin 1)
    const std::vector<double> p = compute_profiles(g, x, v, w, b, {Virial{}, Virial{}}, 1.0);
    EXPECT_EQ(p[0], 0.0);
    EXPECT_EQ(p[profile_field_count], 2.0);
    // Along a walled axis the grain leaving through 0 is reflected: at 0.1 in bin 0, moving at +1.
    g.periodic = false;
    const std::vector<double> q = compute_profiles(g, x, v, w, b, {Virial{}, Virial{}}, 1.0);
    EXPECT_EQ(q[0], 1.0);
    EXPECT_EQ(q[1], 1.0); // u_x of bin 0
    // Gravity: the velocity at mid-flight.
    g.gravity = {0, 0, -10};
    const std::vector<double> r = compute_profiles(g, x, v, w, b, {Virial{}, Virial{}}, 1.0);
    EXPECT_DOUBLE_EQ(r[3], -2.0); // u_z of bin 0: -10 x 0.2
}

} // namespace
} // namespace roughgas
