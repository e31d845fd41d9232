// Moments of physics.md §5 (observables/moments.hpp) on configurations with exact values.
#include "roughgas/observables/moments.hpp"

#include "roughgas/core/rng.hpp"

#include <gtest/gtest.h>

#include <boost/random/normal_distribution.hpp>

#include <cmath>
#include <vector>

namespace roughgas {
namespace {

Vec3Column col(const std::vector<Vec3>& v) {
    return column_of(v.data(), 0);
}

// Velocities +-s e_x, +-s e_y, +-s e_z (all speeds equal) shifted by u; omega parallel to c.
void shell(std::vector<Vec3>& v, std::vector<Vec3>& w, double s, double ws, Vec3 u) {
    const Vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& d : e)
        for (double sign : {1.0, -1.0}) {
            v.push_back(u + (sign * s) * d);
            w.push_back((sign * ws) * d);
        }
}

TEST(Moments, ExactValuesOfAShellDistribution) {
    // All |c| = s: <c^4> = <c^2>^2, so <c*^4> = (3/2)^2 and a20 = (4/15)(9/4) - 1 = -2/5; likewise
    // a02 = -2/5, a11 = (4/9)(9/4) - 1 = 0, and omega parallel to c gives A_cw = 1 - 1/3 = 2/3.
    std::vector<Vec3> v, w;
    shell(v, w, 2.0, 3.0, {0.5, -0.25, 4.0});
    const double m = 1.5, J = 0.2;
    const SpeciesSlice sp{0, v.size(), m, J};
    const Moments mo = compute_moments(col(v), col(w), {&sp, 1});
    EXPECT_NEAR(mo.mean_velocity.z, 4.0, 1e-15);
    EXPECT_NEAR(mo.all.T_tr, m * 4.0 / 3.0, 1e-14);
    EXPECT_NEAR(mo.all.T_rot, J * 9.0 / 3.0, 1e-14);
    EXPECT_NEAR(mo.all.theta, (J * 9.0) / (m * 4.0), 1e-14);
    EXPECT_NEAR(mo.all.a20, -0.4, 1e-14);
    EXPECT_NEAR(mo.all.a02, -0.4, 1e-14);
    EXPECT_NEAR(mo.all.a11, 0.0, 1e-14);
    EXPECT_NEAR(mo.all.A_cw, 2.0 / 3.0, 1e-14);
    EXPECT_NEAR(mo.species[0].a20, -0.4, 1e-14);
}

TEST(Moments, ScaleFreeAtFortyDecadesBelow) {
    // The cumulants are computed on reduced speeds: scaling every c by 1e-25 and omega by 1e-30
    // (T by 1e-50 and 1e-60) leaves them unchanged to round-off; T scales exactly.
    Rng rng = make_stream(31, Stream::test, 0, 0);
    boost::random::normal_distribution<double> normal;
    std::vector<Vec3> v(10000), w(10000), vs(10000), ws(10000);
    for (std::size_t i = 0; i < v.size(); ++i) {
        v[i] = {normal(rng), normal(rng), normal(rng)};
        w[i] = {normal(rng) + 0.3 * v[i].x, normal(rng), normal(rng)}; // a correlated omega
        vs[i] = 1e-25 * v[i];
        ws[i] = 1e-30 * w[i];
    }
    const SpeciesSlice sp{0, v.size(), 1.0, 0.1};
    const Moments a = compute_moments(col(v), col(w), {&sp, 1}),
                  b = compute_moments(col(vs), col(ws), {&sp, 1});
    EXPECT_NEAR(b.all.T_tr / a.all.T_tr, 1e-50, 1e-62);
    EXPECT_NEAR(b.all.T_rot / a.all.T_rot, 1e-60, 1e-72);
    EXPECT_NEAR(b.all.a20, a.all.a20, 1e-12);
    EXPECT_NEAR(b.all.a02, a.all.a02, 1e-12);
    EXPECT_NEAR(b.all.a11, a.all.a11, 1e-12);
    EXPECT_NEAR(b.all.A_cw, a.all.A_cw, 1e-12);
    EXPECT_GT(a.all.A_cw, 0.01); // the correlation is seen
}

TEST(Moments, MixtureUsesTheCentreOfMassAndEachSpeciesTemperature) {
    // Species 1: shell of speed 1 around +u1, mass 1; species 2: shell of speed 1 around -u1/2,
    // mass 2: the centre of mass is at rest, each species drifts relative to it.
    std::vector<Vec3> v, w;
    const Vec3 u1{0.2, 0, 0};
    shell(v, w, 1.0, 1.0, u1);
    shell(v, w, 1.0, 1.0, -0.5 * u1);
    const SpeciesSlice sp[2] = {{0, 6, 1.0, 0.1}, {6, 6, 2.0, 0.1}};
    const Moments m = compute_moments(col(v), col(w), sp);
    EXPECT_NEAR(m.mean_velocity.x, 0.0, 1e-16);
    // T of species 1: (1/3) <|c|^2> with c = +-e + u1: <|c|^2> = 1 + 0.04.
    EXPECT_NEAR(m.species[0].T_tr, 1.04 / 3.0, 1e-14);
    EXPECT_NEAR(m.species[1].T_tr, 2.0 * 1.01 / 3.0, 1e-14);
    EXPECT_NEAR(m.all.T_tr, 0.5 * (m.species[0].T_tr + m.species[1].T_tr), 1e-14);
    EXPECT_EQ(m.all.count, 12u);
}

TEST(Moments, MaxwellianMixtureOfUnequalGrainsHasZeroCumulantsOverAll) {
    // Two species at the same T_tr = T_rot = 1 with masses 1 and 8 and moments of inertia 0.1 and
    // 3.2, each Maxwellian: the mixture as a whole is Maxwellian in the reduced variables, so every
    // mixture-wide cumulant and A_cw is 0 up to sampling noise. Standard errors with N = 1e5 grains:
    // a20, a02: sd((4/15) c*^4) = (4/15) sqrt(945/16 - 225/16) = 1.79, se = 0.0057; a11: similar;
    // A_cw: sd((c*.w*)^2)/(9/4) = 1.5/2.25, se = 0.0021. Tolerance 0.03 is >= 5 se; a definition
    // over the raw c and omega gives A_cw = 0.25 here (the light grains are fast in both).
    Rng rng = make_stream(32, Stream::test, 0, 0);
    boost::random::normal_distribution<double> normal;
    const std::size_t n = 50000;
    const double m[2] = {1.0, 8.0}, J[2] = {0.1, 3.2};
    std::vector<Vec3> v, w;
    for (int s = 0; s < 2; ++s)
        for (std::size_t i = 0; i < n; ++i) {
            const double sv = 1.0 / std::sqrt(m[s]), sw = 1.0 / std::sqrt(J[s]);
            v.push_back({sv * normal(rng), sv * normal(rng), sv * normal(rng)});
            w.push_back({sw * normal(rng), sw * normal(rng), sw * normal(rng)});
        }
    const SpeciesSlice sp[2] = {{0, n, m[0], J[0]}, {n, n, m[1], J[1]}};
    const Moments mo = compute_moments(col(v), col(w), sp);
    EXPECT_NEAR(mo.all.T_tr, 1.0, 0.02);
    EXPECT_NEAR(mo.all.T_rot, 1.0, 0.02);
    EXPECT_NEAR(mo.all.a20, 0.0, 0.03);
    EXPECT_NEAR(mo.all.a02, 0.0, 0.03);
    EXPECT_NEAR(mo.all.a11, 0.0, 0.03);
    EXPECT_NEAR(mo.all.A_cw, 0.0, 0.03);
    for (const GroupMoments& g : mo.species)
        EXPECT_NEAR(g.A_cw, 0.0, 0.03);
}

TEST(Moments, NoRotationGivesNaNForRotationalCumulants) {
    std::vector<Vec3> v, w;
    shell(v, w, 1.0, 0.0, {});
    const SpeciesSlice sp{0, v.size(), 1.0, 0.1};
    const Moments m = compute_moments(col(v), col(w), {&sp, 1});
    EXPECT_EQ(m.all.T_rot, 0.0);
    EXPECT_EQ(m.all.theta, 0.0);
    EXPECT_TRUE(std::isnan(m.all.a02));
    EXPECT_TRUE(std::isnan(m.all.a11));
    EXPECT_TRUE(std::isnan(m.all.A_cw));
    EXPECT_NEAR(m.all.a20, -0.4, 1e-14);
}

} // namespace
} // namespace roughgas
