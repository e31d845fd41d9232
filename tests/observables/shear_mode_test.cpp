// The Navier-Stokes shear mode of the homogeneous cooling state (observables/shear_mode.hpp): the
// elastic and quasi-elastic limits exactly, and the coefficients against an independent evaluation.
#include "roughgas/observables/shear_mode.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace roughgas {
namespace {

// Elastic grains: no cooling, the first Sonine viscosity, no instability.
TEST(ShearMode, ElasticGasHasNoCriticalLength) {
    const ShearModeTheory t = smooth_shear_mode(1.0);
    EXPECT_EQ(t.a2, 0.0);
    EXPECT_EQ(t.zeta_star, 0.0);
    EXPECT_EQ(t.eta_star, 1.0);
    EXPECT_EQ(t.growth, 0.0);
    EXPECT_TRUE(std::isinf(t.critical_length));
    // A wave decays at the viscous rate eta_0 k^2/(n m) per collision frequency nu_M:
    // (5 pi/32) (k lambda)^2.
    EXPECT_NEAR(shear_mode_rate(t, 0.2), -5 * std::numbers::pi / 32 * 0.04, 1e-15);
    EXPECT_THROW(smooth_shear_mode(-0.1), std::invalid_argument);
    EXPECT_TRUE(std::isfinite(smooth_shear_mode(0.0).critical_length)); // a valid case: alpha = 0
    EXPECT_THROW(smooth_shear_mode(1.1), std::invalid_argument);
}

// As alpha -> 1: a2 -> 0, eta* -> 1, zeta* -> (5/12)(1 - alpha^2), so that
// L_c sqrt(1 - alpha^2) -> (5 pi^(3/2)/4) sqrt(12/5) lambda = 10.78 lambda; the growth rate at
// k -> 0 is half the cooling rate per collision, (1 - alpha^2)/6.
TEST(ShearMode, QuasiElasticLimit) {
    const double alpha = 0.99999, e = 1 - alpha * alpha;
    const ShearModeTheory t = smooth_shear_mode(alpha);
    const double limit = 5 * std::pow(std::numbers::pi, 1.5) / 4 * std::sqrt(12.0 / 5);
    EXPECT_NEAR(t.critical_length * std::sqrt(e) / limit, 1.0, 1e-4);
    EXPECT_NEAR(t.growth / (e / 6), 1.0, 1e-4);
    EXPECT_NEAR(shear_mode_rate(t, 2 * std::numbers::pi / t.critical_length), 0.0, 1e-15);
}

// Against a separate evaluation of the same formulas (scripts/linear_theory_reference.py; its
// cooling rate and a2 also re-derived there from exact collision integrals of the first Sonine
// distribution): a2, eta*, the growth rate at k -> 0 per collision and L_c / lambda, to 5 digits.
TEST(ShearMode, CoefficientsOfTheFirstSonineTheory) {
    const struct {
        double alpha, a2, eta_star, growth, critical_length;
    } rows[] = {
        {0.95, -0.00973, 1.02103, 0.01621, 34.926}, {0.90, -0.01456, 1.04332, 0.03155, 25.303},
        {0.80, -0.01258, 1.09222, 0.05981, 18.804}, {0.70, +0.00131, 1.14786, 0.08503, 16.175},
        {0.60, +0.02386, 1.21160, 0.10730, 14.803}, {0.50, +0.05246, 1.28506, 0.12664, 14.046},
    };
    for (const auto& r : rows) {
        const ShearModeTheory t = smooth_shear_mode(r.alpha);
        EXPECT_NEAR(t.a2, r.a2, 6e-6) << r.alpha;
        EXPECT_NEAR(t.eta_star, r.eta_star, 6e-6) << r.alpha;
        EXPECT_NEAR(t.growth, r.growth, 6e-6) << r.alpha;
        EXPECT_NEAR(t.critical_length, r.critical_length, 6e-4) << r.alpha;
    }
}

// Rough grains: beta = -1 is the smooth theory; elastic perfectly rough grains do not cool and have
// Pidduck's viscosity 6 (1 + q)^2/(6 + 13 q) eta_0; theta is the cooling state's (Maxwellian
// approximation, observables/theory.hpp).
TEST(ShearMode, RoughGrainsLimits) {
    const ShearModeTheory smooth = smooth_shear_mode(0.9), same = rough_shear_mode(0.9, -1.0, 0.4);
    EXPECT_EQ(same.critical_length, smooth.critical_length);
    EXPECT_EQ(same.a2, smooth.a2);
    const ShearModeTheory pidduck = rough_shear_mode(1.0, 1.0, 0.4);
    EXPECT_EQ(pidduck.zeta_star, 0.0);
    EXPECT_TRUE(std::isinf(pidduck.critical_length));
    EXPECT_NEAR(pidduck.eta_star, 6 * 1.4 * 1.4 / (6 + 13 * 0.4), 1e-14);
    EXPECT_NEAR(pidduck.theta, 1.0, 1e-14);
    EXPECT_NEAR(rough_shear_mode(0.9, 0.5, 0.4).theta, theta_fixed_point(0.9, 0.5, 0.4), 0.0);
    EXPECT_THROW(rough_shear_mode(0.9, 1.5, 0.4), std::invalid_argument);
}

// Against the independent evaluation of scripts/rough_linear_theory_reference.py (theta by
// bisection on the two temperatures' cooling rates, the viscosity from its moment equation, both
// from collision integrals by quadrature; L_c by bisection): theta, eta*, the growth rate at k -> 0
// per collision and L_c / lambda for q = 2/5, printed there to 15 digits; and the "dual role" of
// roughness at alpha = 0.9: medium roughness (beta = 0) more unstable than smooth grains, nearly
// perfect roughness less.
TEST(ShearMode, RoughGrainsCoefficients) {
    const struct {
        double alpha, beta, theta, eta_star, growth, critical_length;
    } rows[] = {
        {0.9, -0.5, 0.342626873322036, 1.10004270765229, 0.072970859920731, 17.0920777142791},
        {0.9, 0.0, 0.573791953697339, 1.13761954113892, 0.093782586608934, 15.3321209295584},
        {0.9, 1.0, 1.12312379718081, 1.03734832265247, 0.0149151296352645, 36.7124701179501},
        {0.8, 0.5, 1.04288161138069, 1.12189223950688, 0.0924325297412739, 15.3365604252327},
        {0.7, 0.9, 1.33229945780165, 1.04210414201517, 0.0532448624944228, 19.4751819509379},
        {0.5, -0.5, 8.51740662898457, 1.15576134811038, 0.0967907599576141, 15.2118470827122},
    };
    for (const auto& r : rows) {
        const ShearModeTheory t = rough_shear_mode(r.alpha, r.beta, 0.4);
        EXPECT_NEAR(t.theta / r.theta, 1.0, 1e-12) << r.alpha << " " << r.beta;
        EXPECT_NEAR(t.eta_star / r.eta_star, 1.0, 1e-12) << r.alpha << " " << r.beta;
        EXPECT_NEAR(t.growth / r.growth, 1.0, 1e-12) << r.alpha << " " << r.beta;
        EXPECT_NEAR(t.critical_length / r.critical_length, 1.0, 1e-11) << r.alpha << " " << r.beta;
    }
    const double smooth = smooth_shear_mode(0.9).critical_length;
    EXPECT_LT(rough_shear_mode(0.9, 0.0, 0.4).critical_length, 0.7 * smooth);
    EXPECT_GT(rough_shear_mode(0.9, 1.0, 0.4).critical_length, 1.4 * smooth);
}

// The Enskog equation: phi = 0 with chi = 1 is the dilute theory to the last bit, whatever alpha.
TEST(ShearMode, EnskogAtZeroDensityIsTheBoltzmannTheory) {
    for (const double alpha : {0.0, 0.3, 0.5, 0.9, 0.99, 1.0}) {
        const ShearModeTheory e = enskog_shear_mode(alpha, 0.0, 1.0), b = smooth_shear_mode(alpha);
        EXPECT_EQ(e.a2, b.a2) << alpha;
        EXPECT_EQ(e.zeta_star, b.zeta_star) << alpha;
        EXPECT_EQ(e.eta_star, b.eta_star) << alpha;
        EXPECT_EQ(e.growth, b.growth) << alpha;
        EXPECT_EQ(e.damping, b.damping) << alpha;
        EXPECT_EQ(e.critical_length, b.critical_length) << alpha;
        EXPECT_EQ(e.phi, 0.0);
        EXPECT_EQ(e.chi, 1.0);
    }
    EXPECT_THROW(enskog_shear_mode(0.9, 1.0, 2.0), std::invalid_argument);
    EXPECT_THROW(enskog_shear_mode(0.9, 0.2, 0.0), std::invalid_argument);
    EXPECT_THROW(enskog_shear_mode(1.1, 0.2, 2.0), std::invalid_argument);
}

// Elastic grains: no cooling, and Enskog's first Sonine viscosity
// eta* = (1 + (8/5) phi chi)^2/chi + (768/(25 pi)) phi^2 chi (observables/enskog_usf_theory.hpp),
// with Carnahan & Starling's chi and with a chi of its own.
TEST(ShearMode, EnskogElasticViscosity) {
    const struct {
        double phi, chi;
    } rows[] = {{0.05, carnahan_starling_chi(0.05)}, {0.2, carnahan_starling_chi(0.2)},
                {0.4, carnahan_starling_chi(0.4)}, {0.1, 2.5}};
    for (const auto& r : rows) {
        const ShearModeTheory t = enskog_shear_mode(1.0, r.phi, r.chi);
        const double x = 1 + 1.6 * r.phi * r.chi;
        const double enskog = x * x / r.chi + 768 / (25 * std::numbers::pi) * r.phi * r.phi * r.chi;
        EXPECT_NEAR(t.eta_star / enskog, 1.0, 1e-14) << r.phi;
        EXPECT_EQ(t.zeta_star, 0.0);
        EXPECT_TRUE(std::isinf(t.critical_length));
        // The wave decays at eta k^2/(n m) per collision frequency chi nu_M.
        EXPECT_NEAR(shear_mode_rate(t, 0.2), -5 * std::numbers::pi / 32 * enskog / r.chi * 0.04, 1e-14);
    }
}

// alpha = 0.9, phi = 0.2, chi = (1 - phi/2)/(1 - phi)^3 = 0.9/0.512 = 1.7578125, by hand from
// Garzo & Dufty (1999): a2 = -0.01456040 (dilute), zeta* = chi 0.07895054 = 0.13878024,
// nu_eta* = chi 1.1100 (1 - a2/32) = 1.95198, the kinetic factor 1 + (2/5) 1.9 1.7 phi chi =
// 1.45421875, eta_k* = 1.45421875/(nu_eta* - zeta*/2) = 0.86312713, kappa* = (128/(5 pi)) 0.04 chi 1.9
// (1 - a2/16) = 1.08961048, eta* = eta_k* (1 + (4/5) 1.9 phi chi = 1.534375) + (3/5) kappa* =
// 1.97812698; per collision growth (2/5) zeta*/(chi (1 - a2/16)) = 0.03155150 (the dilute one),
// damping (5 pi/32) eta*/(chi (1 - a2/16)) = 0.55189502, L_c = 2 pi sqrt(damping/growth) = 26.27835
// lambda (dilute: 25.30265).
TEST(ShearMode, EnskogHandValue) {
    const double chi = carnahan_starling_chi(0.2);
    EXPECT_NEAR(chi, 1.7578125, 1e-15); // 0.8^3 is not exact in binary
    const ShearModeTheory t = enskog_shear_mode(0.9, 0.2, chi);
    EXPECT_NEAR(t.a2, -0.0145603992367533, 1e-15);
    EXPECT_NEAR(t.zeta_star, 0.138780238606341, 1e-14);
    EXPECT_NEAR(t.eta_star, 1.97812697861431, 1e-13);
    EXPECT_NEAR(t.growth, 0.0315515016424214, 1e-15);
    EXPECT_NEAR(t.damping, 0.551895022547988, 1e-14);
    EXPECT_NEAR(t.critical_length, 26.2783498483491, 1e-11);
    EXPECT_NEAR(t.growth, smooth_shear_mode(0.9).growth, 1e-16); // chi cancels from the growth
    EXPECT_NEAR(shear_mode_rate(t, 2 * std::numbers::pi / t.critical_length), 0.0, 1e-15);
    // Denser and more inelastic: alpha = 0.5, phi = 0.3 falls below the dilute 14.05 lambda.
    EXPECT_NEAR(enskog_shear_mode(0.5, 0.3, carnahan_starling_chi(0.3)).critical_length, 13.2416134752355, 1e-11);
    EXPECT_NEAR(enskog_shear_mode(0.9, 0.4, carnahan_starling_chi(0.4)).critical_length, 36.8127201759377, 1e-11);
}

// A run's theory: a cooling box of the Enskog equation gets enskog_shear_mode at its phi and chi
// (smooth grains only), the Boltzmann equation's stays the dilute one.
TEST(ShearMode, EnskogTheoryOfARun) {
    RunSpec spec;
    spec.species.push_back(SpeciesSpec{});
    spec.species[0].radius = 0.5;
    spec.density = 0.2 / (std::numbers::pi / 6); // phi = 0.2 at sigma = 1
    spec.pairs = {ConstantRestitution{0.9, -1}};
    spec.domain = DomainSpec{};
    const std::optional<ShearModeTheory> dilute = shear_mode_theory(spec);
    ASSERT_TRUE(dilute);
    EXPECT_EQ(dilute->critical_length, smooth_shear_mode(0.9).critical_length);
    spec.enskog = EnskogSpec{};
    const std::optional<ShearModeTheory> dense = shear_mode_theory(spec);
    ASSERT_TRUE(dense);
    EXPECT_NEAR(dense->phi, 0.2, 1e-15);
    EXPECT_NEAR(dense->chi, 1.7578125, 1e-13);
    EXPECT_NEAR(dense->critical_length, 26.2783498483491, 1e-10);
    spec.enskog->model = PairCorrelationModel::constant;
    spec.enskog->chi = 2.5;
    EXPECT_EQ(shear_mode_theory(spec)->critical_length, enskog_shear_mode(0.9, dense->phi, 2.5).critical_length);
    spec.pairs = {ConstantRestitution{0.9, 0.0}};
    EXPECT_FALSE(shear_mode_theory(spec)); // rough grains: no Enskog viscosity here
}

} // namespace
} // namespace roughgas
