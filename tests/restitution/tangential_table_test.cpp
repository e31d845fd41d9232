// The eps^T table of one pair against the direct integrator (required: <= 1e-4 absolute everywhere,
// including near the onset of asperity breaking), on Brilliantov et al. (1996) Fig. 2c's ice parameters.
#include "roughgas/restitution/tangential_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace roughgas {
namespace {

// Ice (Brilliantov et al. (1996) sec. III): Y = 10 GPa, nu = 0.3, R = 1 cm, 1000 kg/m^3, q = 2/5;
// zeta_0 = 1e-3 R_eff (Fig. 2c) and mu = sqrt(zeta_0/R_eff) (the paper's mu = alpha sqrt(zeta_0),
// alpha = 1, with zeta_0 in units of R_eff: this puts mu in the paper's interval [1e-2, 1]).
ContactPair ice_pair(double zeta0_over_R_eff, double A) {
    const double R = 0.01, m = 4.0 / 3.0 * std::numbers::pi * R * R * R * 1000.0;
    Material mat;
    mat.young_modulus = 1e10;
    mat.poisson_ratio = 0.3;
    mat.dissipation = A;
    mat.asperity = zeta0_over_R_eff * R / 2;
    mat.friction = std::sqrt(zeta0_over_R_eff);
    return make_contact_pair(mat, {}, m, R, 0.4, m, R, 0.4);
}

TangentialTableOptions fig2_range() {
    TangentialTableOptions opt;
    opt.g_min = 1e-3; // 0.1 cm/s .. 10 m/s: from nearly smooth contacts to several spring periods per contact
    opt.g_max = 10.0;
    return opt;
}

const TangentialTable& fig2c_table() {
    static const TangentialTable table = TangentialTable::build(ice_pair(1e-3, 1e-5), fig2_range());
    return table;
}

TEST(TangentialTable, MatchesDirectPathEverywhere) {
    const TangentialTable& table = fig2c_table();
    const DirectTangential direct{table.pair(), Tolerance{1e-10, 1e-12}};
    const auto& s = table.stats();
    std::printf("  built in %.2f s: samples %zu/%zu/%zu, leaves %zu/%zu/%zu, direct leaves %zu/%zu/%zu\n",
                s.build_seconds, s.critical.samples, s.unbroken.samples, s.breaking.samples, s.critical.leaves,
                s.unbroken.leaves, s.breaking.leaves, s.critical.direct_leaves, s.unbroken.direct_leaves,
                s.breaking.direct_leaves);
    std::mt19937_64 rng(7);
    const double lo = std::log(table.options().g_min), hi = std::log(table.options().g_max);
    std::uniform_real_distribution<double> lg(lo, hi), lr(std::log(1e-3), std::log(1e3)), side(-8, -1);
    double worst = 0, worst_gn = 0, worst_gt = 0;
    int fallbacks = 0, n = 0;
    auto check = [&](double g_n, double g_t) {
        ++n;
        if (std::isnan(table.lookup(g_n, g_t))) ++fallbacks;
        const double err = std::abs(table.eps_t(g_n, g_t) - direct.eps_t(g_n, g_t));
        if (err > worst) { worst = err; worst_gn = g_n; worst_gt = g_t; }
    };
    // 1e4 points spread over the plane, and 2000 within 1e-8..1e-1 (relative) of the onset line.
    for (int i = 0; i < 10000; ++i) {
        const double g_n = std::exp(lg(rng));
        check(g_n, g_n * std::exp(lr(rng)));
    }
    for (int i = 0; i < 2000; ++i) {
        const double g_n = std::exp(lg(rng));
        const double d = std::pow(10.0, side(rng));
        check(g_n, table.critical_speed(g_n) * (i % 2 ? 1 + d : 1 - d));
    }
    std::printf("  worst |eps_t table - direct| = %.3g at g_N = %.6g, g_T = %.6g; direct fallbacks %d of %d\n", worst,
                worst_gn, worst_gt, fallbacks, n);
    EXPECT_LE(worst, 1e-4) << "g_N = " << worst_gn << " g_T = " << worst_gt;
}

TEST(TangentialTable, KnowsTheOnsetOfBreaking) {
    const TangentialTable& table = fig2c_table();
    const double g_n = 3.0;
    const TangentialParameters p = tangential_parameters(table.pair(), g_n);
    // Just below the onset nothing breaks and eps^T is the no-break (linear) value; at g_N = 3 m/s
    // the asperity spring reverses the tangential motion there (eps^T < 0, the paper's Fig. 2c). Just above
    // the onset an asperity breaks as the motion stops: eps^T jumps to about 0.
    const double g_cr = table.critical_speed(g_n);
    EXPECT_NEAR(g_cr / g_n, critical_ratio(p), 1e-6 * critical_ratio(p));
    const auto below = integrate_tangential(p, g_cr / g_n * (1 - 1e-4));
    const auto above = integrate_tangential(p, g_cr / g_n * (1 + 1e-4));
    EXPECT_EQ(below.breaks, 0);
    EXPECT_LT(below.eps_t, -0.5);
    EXPECT_GE(above.breaks, 1);
    EXPECT_GT(above.eps_t - below.eps_t, 0.5) << "the onset is a jump";
    EXPECT_NEAR(table.eps_t(g_n, g_cr * (1 - 1e-4)), below.eps_t, 1e-4);
    EXPECT_NEAR(table.eps_t(g_n, g_cr * (1 + 1e-4)), above.eps_t, 1e-4);
}

// The look-up's branches (tangential_table.hpp: y = c g_N/g_T against the onset band): g_T = 0 is
// below the onset (y = +inf) and gives the no-break value; within the relative band of 1e-6 around
// the onset the look-up declines (NaN: eps_t then integrates directly), on both sides; 1e-5 below it
// it gives the no-break value. (Just above it the breaking table may hold direct cells of its own:
// the jump as the spring stops the sliding, tangential_table.hpp.)
TEST(TangentialTable, LookUpBranchesOnTheOnsetBand) {
    const TangentialTable& table = fig2c_table();
    ASSERT_EQ(table.options().onset_band, 1e-6);
    for (double g_n : {2e-3, 0.03, 0.5, 3.0}) {
        const TangentialParameters p = tangential_parameters(table.pair(), g_n);
        ASSERT_FALSE(std::isnan(table.lookup(g_n, 0.0))) << g_n;
        EXPECT_NEAR(table.lookup(g_n, 0.0), integrate_tangential(p, 0.0).eps_t, 1e-4) << g_n;
        const double g_cr = table.critical_speed(g_n);
        for (double d : {-1e-7, 1e-7})
            EXPECT_TRUE(std::isnan(table.lookup(g_n, g_cr * (1 + d)))) << g_n << " " << d;
        EXPECT_NEAR(table.lookup(g_n, g_cr * (1 - 1e-5)), table.lookup(g_n, 0.0), 1e-12) << g_n;
    }
}

TEST(TangentialTable, IsEvenInTangentialSpeed) {
    const TangentialTable& table = fig2c_table();
    for (double g_n : {2e-3, 0.03, 0.5, 3.0})
        for (double g_t : {1e-4, 0.01, 0.2, 3.0}) EXPECT_EQ(table.eps_t(g_n, g_t), table.eps_t(g_n, -g_t));
}

TEST(TangentialTable, RoundTripsThroughSerializedForm) {
    const TangentialTable& table = fig2c_table();
    const TangentialTable copy = TangentialTable::deserialize(table.pair(), table.options(), table.serialize());
    for (double g_n : {2e-3, 0.03, 0.5})
        for (double g_t : {1e-4, 0.01, 0.2, 3.0}) EXPECT_EQ(copy.eps_t(g_n, g_t), table.eps_t(g_n, g_t));
    auto truncated = table.serialize();
    truncated.resize(truncated.size() / 2);
    EXPECT_THROW(TangentialTable::deserialize(table.pair(), table.options(), truncated), std::runtime_error);
}

TEST(TangentialTable, CacheKeyChangesWithEveryPairParameter) {
    const TangentialTable& table = fig2c_table();
    TangentialTableOptions opt = table.options();
    ContactPair p = table.pair();
    const std::string key = table.cache_key();
    // Deserialising is cheap; the key must differ for any parameter change.
    for (double ContactPair::*field : {&ContactPair::m_eff, &ContactPair::R_eff, &ContactPair::kappa, &ContactPair::rho,
                                       &ContactPair::A, &ContactPair::mu, &ContactPair::zeta0}) {
        ContactPair q = p;
        q.*field *= 1.0 + 1e-12;
        EXPECT_NE(TangentialTable::deserialize(q, opt, table.serialize()).cache_key(), key);
    }
}

} // namespace
} // namespace roughgas
