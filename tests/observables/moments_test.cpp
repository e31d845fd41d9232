// Moments of docs/model.md §5 (observables/moments.hpp) on configurations with exact values.
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

// A two-species gas of 30001 + 20000 grains (several chunks, the last ones partial), far from
// Maxwellian and drifting by 1e3 thermal speeds, against the definitions summed in long double.
struct DriftingMixture {
    std::vector<Vec3> v, w;
    std::vector<SpeciesSlice> sp{{0, 30001, 1.0, 0.1}, {30001, 20000, 3.0, 0.4}};
    DriftingMixture() {
        Rng rng = make_stream(33, Stream::test, 0, 0);
        boost::random::normal_distribution<double> normal;
        const Vec3 drift{1e3, -2e3, 5e2};
        for (const SpeciesSlice& s : sp)
            for (std::size_t i = 0; i < s.count; ++i) {
                const double e = std::exp(0.5 * normal(rng)); // a spread of speeds: a20 > 0
                v.push_back(drift + Vec3{e * normal(rng), e * normal(rng), e * normal(rng)});
                w.push_back({normal(rng) + 0.5 * v.back().y, normal(rng), e * normal(rng)});
            }
    }
};

TEST(Moments, ChunkedSumsMatchTheDefinitionsInLongDouble) {
    const DriftingMixture g;
    const Moments m = compute_moments(col(g.v), col(g.w), g.sp);
    long double P[3] = {0, 0, 0}, M = 0;
    for (const SpeciesSlice& s : g.sp)
        for (std::size_t i = s.offset; i < s.offset + s.count; ++i) {
            P[0] += s.mass * static_cast<long double>(g.v[i].x);
            P[1] += s.mass * static_cast<long double>(g.v[i].y);
            P[2] += s.mass * static_cast<long double>(g.v[i].z);
            M += s.mass;
        }
    const long double u[3] = {P[0] / M, P[1] / M, P[2] / M};
    EXPECT_NEAR(m.mean_velocity.x, static_cast<double>(u[0]), 1e-12 * 1e3);
    for (std::size_t k = 0; k < g.sp.size(); ++k) {
        const SpeciesSlice& s = g.sp[k];
        long double c2 = 0, w2 = 0, c4 = 0;
        for (std::size_t i = s.offset; i < s.offset + s.count; ++i) {
            const long double cx = g.v[i].x - u[0], cy = g.v[i].y - u[1], cz = g.v[i].z - u[2];
            const long double cc = cx * cx + cy * cy + cz * cz;
            c2 += cc;
            c4 += cc * cc;
            w2 += static_cast<long double>(norm2(g.w[i]));
        }
        const long double n = s.count, T = s.mass * c2 / (3 * n), Tr = s.moment_of_inertia * w2 / (3 * n);
        const long double a20 = (4.0L / 15) * (c4 / n) * (s.mass / (2 * T)) * (s.mass / (2 * T)) - 1;
        // The drift is 1e3 thermal speeds, so u carries a rounding error of 1e3 eps; the
        // temperature about it is still correct to ~1e-13 relative.
        EXPECT_NEAR(m.species[k].T_tr / static_cast<double>(T), 1.0, 1e-11) << k;
        EXPECT_NEAR(m.species[k].T_rot / static_cast<double>(Tr), 1.0, 1e-13) << k;
        EXPECT_NEAR(m.species[k].a20, static_cast<double>(a20), 1e-10) << k;
        EXPECT_GT(m.species[k].a20, 0.1) << k; // the spread of speeds is seen
    }
}

TEST(Moments, SameBitsOnAnyThreadCount) {
    // The chunks and the order their sums are added in depend on the species' ranges only.
    const DriftingMixture g;
    const Moments a = compute_moments(col(g.v), col(g.w), g.sp, 1);
    for (int threads : {2, 3, 7}) {
        const Moments b = compute_moments(col(g.v), col(g.w), g.sp, threads);
        EXPECT_EQ(a.mean_velocity.x, b.mean_velocity.x);
        for (std::size_t k = 0; k < 2; ++k) {
            EXPECT_EQ(a.species[k].T_tr, b.species[k].T_tr);
            EXPECT_EQ(a.species[k].T_rot, b.species[k].T_rot);
            EXPECT_EQ(a.species[k].a20, b.species[k].a20);
            EXPECT_EQ(a.species[k].A_cw, b.species[k].A_cw);
        }
        EXPECT_EQ(a.all.T_tr, b.all.T_tr);
        EXPECT_EQ(a.all.a11, b.all.a11);
    }
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
