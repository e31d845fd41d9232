// The Enskog equation's steady uniform shear flow in Grad's approximation
// (observables/enskog_usf_theory.hpp): its dilute limit (the Boltzmann Grad USF, closed form), its elastic
// limit (Enskog's Navier-Stokes shear viscosity), the unsheared pressure, the energy balance of elastic
// collisions under shear, the small-shear coefficients of the collisional moments, and the steady balances
// themselves.
//
// Tolerances: at a* = 0 or phi = 0 the integrand over the contact direction is a polynomial of degree <= 6
// in n, which the quadrature integrates exactly, so those checks hold to rounding (1e-12 relative). With
// shear the quadrature converges to ~1e-14 (the integrand is entire in n); the steady a* is found to
// ~1e-15 relative. Limits taken at finite distance have their own error estimates, stated where used.
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/observables/enskog_pressure.hpp"
#include "roughgas/observables/enskog_usf_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace roughgas {
namespace {

constexpr double pi = std::numbers::pi;

// The dilute (Boltzmann) Grad USF of smooth inelastic spheres: the collisional moment of n m <V V> is
// -n T nu chi [beta c + zeta* I] with beta = (1 + alpha)(3 - alpha)/4 and zeta* = (5/12)(1 - alpha^2), so the
// yy and zz balances give P*_yy = P*_zz = 1 - zeta*/beta, the xy balance P*_xy = -a* P*_yy/(chi beta), and
// the energy balance -2 a* P*_xy = 3 chi zeta* the shear rate.
struct DiluteGrad {
    double a_star, eta_star, Pyy;
};
DiluteGrad dilute_grad(double alpha, double chi) {
    const double zeta = 5.0 / 12.0 * (1 - alpha * alpha), beta = (1 + alpha) * (3 - alpha) / 4;
    return {chi * beta * std::sqrt(1.5 * zeta / (beta - zeta)), (beta - zeta) / (chi * beta * beta),
            1 - zeta / beta};
}

// Enskog's Navier-Stokes shear viscosity of elastic hard spheres in the first Sonine approximation, over
// eta_0 = (5/16 sigma^2) sqrt(m T/pi): the kinetic part (1 + (8/5) phi chi)/chi, times (1 + (8/5) phi chi)
// for the collisional transfer of the kinetic stress, plus (3/5) kappa/eta_0 = (768/(25 pi)) phi^2 chi, the
// transfer by the shear of the pair at contact (kappa = (256/(5 pi)) phi^2 chi eta_0, the bulk viscosity).
double enskog_viscosity(double phi, double chi) {
    const double k = 1 + 1.6 * phi * chi;
    return k * k / chi + 768 / (25 * pi) * phi * phi * chi;
}

double relative(double x, double y) {
    return std::abs(x - y) / std::abs(y);
}

TEST(EnskogUsfTheory, DiluteLimitIsBoltzmannGrad) {
    // The closed form's values, also found by Monte Carlo of the collision rule
    // (scripts/enskog_usf_reference.py).
    EXPECT_NEAR(dilute_grad(0.9, 1).a_star, 0.3586985, 1e-7);
    EXPECT_NEAR(dilute_grad(0.9, 1).eta_star, 0.9229423, 1e-7);
    for (double alpha : {0.9, 0.7, 0.5, 0.0})
        for (double chi : {1.0, 2.3}) {
            const EnskogUsfState s = enskog_usf_grad(alpha, 0.0, chi);
            const DiluteGrad d = dilute_grad(alpha, chi);
            EXPECT_LT(relative(s.a_star, d.a_star), 1e-12) << alpha << " " << chi;
            EXPECT_LT(relative(s.eta_star, d.eta_star), 1e-12);
            EXPECT_NEAR(s.total.yy, d.Pyy, 1e-12);
            EXPECT_NEAR(s.total.zz, d.Pyy, 1e-12);
            EXPECT_NEAR(s.total.xx, 3 - 2 * d.Pyy, 1e-12);
            EXPECT_NEAR(s.N2, 0, 1e-12);
            EXPECT_EQ(s.collisional.xx, 0);
            EXPECT_EQ(s.collisional.xy, 0);
        }
    // phi -> 0 is continuous: the dense corrections are O(phi chi) (collisional transfer, coefficient ~ 1-4
    // in eta*), so at phi = 1e-6 they are below 1e-5.
    const EnskogUsfState s = enskog_usf_grad(0.7, 1e-6, 1.0);
    EXPECT_LT(relative(s.eta_star, dilute_grad(0.7, 1).eta_star), 1e-5);
    EXPECT_GT(relative(s.eta_star, dilute_grad(0.7, 1).eta_star), 1e-8);
}

TEST(EnskogUsfTheory, ElasticLimitIsEnskogNavierStokesViscosity) {
    for (double phi : {0.0, 0.1, 0.25, 0.4}) {
        const double chi = carnahan_starling_chi(phi);
        const double eta = enskog_viscosity(phi, chi);
        // eta*(alpha) approaches its elastic limit linearly in delta = 1 - alpha (a*^2 ~ delta); Richardson's
        // extrapolation from delta = 1e-4 and 2e-4 leaves O(delta^2) ~ 1e-8 relative.
        const EnskogUsfState s1 = enskog_usf_grad(1 - 1e-4, phi, chi),
                             s2 = enskog_usf_grad(1 - 2e-4, phi, chi);
        EXPECT_LT(relative(2 * s1.eta_star - s2.eta_star, eta), 1e-6) << phi;
        // Without extrapolation the slope shows: ~0.6 eta delta.
        EXPECT_GT(relative(s1.eta_star, eta), 1e-6);
        // Energy balance at Navier-Stokes order: a*^2 eta* = (3/2) chi zeta*, zeta* = (5/12)(1 - alpha^2).
        const double zeta = 5.0 / 12.0 * (1 - (1 - 1e-4) * (1 - 1e-4));
        EXPECT_LT(relative(s1.a_star * s1.a_star, 1.5 * chi * zeta / eta), 1e-3);
        // Normal stress differences are O(delta) (|N1| + |N2| ~ 2.5-4.6 delta up to phi = 0.4).
        EXPECT_LT(std::abs(s1.N1) + std::abs(s1.N2), 1e-3);
    }
    // Elastic spheres heat up without end: no steady state.
    EXPECT_THROW(enskog_usf_grad(1.0, 0.2, 1.5), std::invalid_argument);
}

TEST(EnskogUsfTheory, UnshearedPressureAndCooling) {
    const UsfTensor equilibrium{1, 1, 1, 0};
    for (double alpha : {0.3, 0.8, 1.0})
        for (double phi : {0.05, 0.25, 0.45}) {
            const double chi = carnahan_starling_chi(phi);
            const EnskogUsfMoments m = enskog_usf_collisional_moments(alpha, phi, chi, 0.0, equilibrium);
            // p_c = 2 (1 + alpha) phi chi n T, isotropic.
            for (double d : {m.collisional.xx, m.collisional.yy, m.collisional.zz})
                EXPECT_NEAR(d, 2 * (1 + alpha) * phi * chi, 1e-12);
            EXPECT_NEAR(m.collisional.xy, 0, 1e-14);
            // Maxwellian cooling: Lambda_ij = -n T zeta delta_ij, zeta = chi (5/12)(1 - alpha^2) nu.
            const double zeta = chi * 5.0 / 12.0 * (1 - alpha * alpha);
            for (double d : {m.production.xx, m.production.yy, m.production.zz})
                EXPECT_NEAR(d, -zeta, 1e-12);
            EXPECT_NEAR(m.production.xy, 0, 1e-14);
            if (alpha == 1.0) {
                EXPECT_NEAR(1 + m.collisional.xx, carnahan_starling_compressibility(phi), 1e-12);
            }
        }
}

TEST(EnskogUsfTheory, ShearWorkIsTheOnlyEnergyChangeOfElasticCollisions) {
    // tr Lambda = -2 a P^c_xy - (1 - alpha^2)(...): with alpha = 1 the kinetic energy changes only by the
    // work of the shear on the colliding pair, for any a* and any Grad distribution. This ties the
    // production's integrals (V_i Delta + Delta Delta) to the collisional transfer's (n Delta) and their
    // prefactors.
    const UsfTensor grad{1.3, 0.8, 0.9, -0.35};
    for (double phi : {0.1, 0.3})
        for (double a_star : {0.2, 1.0, 2.5}) {
            const double chi = carnahan_starling_chi(phi);
            const EnskogUsfMoments m = enskog_usf_collisional_moments(1.0, phi, chi, a_star, grad);
            const double trace = m.production.xx + m.production.yy + m.production.zz;
            EXPECT_NEAR(trace, -2 * a_star * m.collisional.xy, 1e-12 * std::abs(a_star * m.collisional.xy));
            EXPECT_GT(std::abs(trace), 1e-3); // the work is not trivially zero
            // Inelastic: the rest of the energy change is (1 - alpha^2) times one alpha-independent integral.
            const EnskogUsfMoments m5 = enskog_usf_collisional_moments(0.5, phi, chi, a_star, grad);
            const EnskogUsfMoments m8 = enskog_usf_collisional_moments(0.8, phi, chi, a_star, grad);
            const double loss5 =
                m5.production.xx + m5.production.yy + m5.production.zz + 2 * a_star * m5.collisional.xy;
            const double loss8 =
                m8.production.xx + m8.production.yy + m8.production.zz + 2 * a_star * m8.collisional.xy;
            EXPECT_LT(loss5, 0);
            EXPECT_NEAR(loss5 / (1 - 0.25), loss8 / (1 - 0.64), 1e-12 * std::abs(loss8));
        }
}

TEST(EnskogUsfTheory, SmallShearCoefficients) {
    // Taylor coefficients of the Maxwellian (c = 0) moments in A = a sigma sqrt(m/T) = a* (96/5)
    // phi/sqrt(pi), from the closed-form series of the contact integrals integrated over the sphere exactly
    // (sympy):
    //   Lambda*_xy = -(2/5)(1 + alpha)(3 alpha - 1) phi chi a*   (Garzo & Dufty's kinetic-viscosity factor),
    //   P*c_xy     = -(384/(25 pi))(1 + alpha) phi^2 chi a*      ((3/5) of the bulk viscosity),
    //   P*c_xx = P*c_yy = 2 (1 + alpha) phi chi + (3/35)(1 + alpha) phi chi A^2,
    //   P*c_zz         = 2 (1 + alpha) phi chi + (1/35)(1 + alpha) phi chi A^2.
    // Odd orders vanish in the normal stresses (A -> -A is the reflection x -> -x), even ones in the shear
    // stress, so each coefficient's truncation error is O(A^2) relative: a* = 1e-3 at phi = 0.3
    // (A ~ 3e-3) leaves ~1e-5, checked to 1e-4.
    const UsfTensor equilibrium{1, 1, 1, 0};
    const double phi = 0.3, chi = carnahan_starling_chi(phi), a_star = 1e-3;
    const double A = a_star * 96.0 / 5.0 * phi / std::sqrt(pi);
    for (double alpha : {0.4, 1.0}) {
        const EnskogUsfMoments m = enskog_usf_collisional_moments(alpha, phi, chi, a_star, equilibrium);
        const double p0 = 2 * (1 + alpha) * phi * chi;
        EXPECT_LT(relative(m.production.xy / a_star, -0.4 * (1 + alpha) * (3 * alpha - 1) * phi * chi), 1e-4);
        EXPECT_LT(relative(m.collisional.xy / a_star, -384 / (25 * pi) * (1 + alpha) * phi * phi * chi),
                  1e-4);
        EXPECT_LT(relative((m.collisional.xx - p0) / (A * A), 3.0 / 35.0 * (1 + alpha) * phi * chi), 1e-4);
        EXPECT_LT(relative((m.collisional.yy - p0) / (A * A), 3.0 / 35.0 * (1 + alpha) * phi * chi), 1e-4);
        EXPECT_LT(relative((m.collisional.zz - p0) / (A * A), 1.0 / 35.0 * (1 + alpha) * phi * chi), 1e-4);
    }
    // The kinetic stress's share of the transfer: d P*c_xy/d c_xy = (4/5)(1 + alpha) phi chi at a* = 0.
    const EnskogUsfMoments m = enskog_usf_collisional_moments(0.6, phi, chi, 0.0, UsfTensor{1, 1, 1, 0.01});
    EXPECT_NEAR(m.collisional.xy / 0.01, 0.8 * 1.6 * phi * chi, 1e-12);
}

TEST(EnskogUsfTheory, SteadyStateSatisfiesTheBalances) {
    for (double alpha : {0.9, 0.7, 0.5, 0.1})
        for (double phi : {0.1, 0.25, 0.45}) {
            const double chi = carnahan_starling_chi(phi);
            const EnskogUsfState s = enskog_usf_grad(alpha, phi, chi);
            const EnskogUsfMoments m = enskog_usf_collisional_moments(alpha, phi, chi, s.a_star, s.kinetic);
            const double scale = 1e-12 * (1 + s.a_star);
            EXPECT_NEAR(m.production.xx, 2 * s.a_star * s.kinetic.xy, scale);
            EXPECT_NEAR(m.production.yy, 0, scale);
            EXPECT_NEAR(m.production.zz, 0, scale);
            EXPECT_NEAR(m.production.xy, s.a_star * s.kinetic.yy, scale);
            EXPECT_NEAR(m.collisional.xx, s.collisional.xx, 1e-13 * s.total.xx);
            EXPECT_NEAR(m.collisional.xy, s.collisional.xy, 1e-13 * s.total.xx);
            EXPECT_NEAR(s.kinetic.xx + s.kinetic.yy + s.kinetic.zz, 3, 1e-13);
            EXPECT_EQ(s.total.xy, s.kinetic.xy + s.collisional.xy);
            EXPECT_EQ(s.eta_star, -s.total.xy / s.a_star);
            EXPECT_EQ(s.N1, s.total.xx - s.total.yy);
            EXPECT_EQ(s.N2, s.total.yy - s.total.zz);
            // The energy balance of the total stress: -2 a* P*_xy = 3 x (collisional loss) > 0.
            EXPECT_GT(s.a_star, 0);
            EXPECT_LT(s.total.xy, 0);
            EXPECT_GT(s.N1, 0);
        }
}

TEST(EnskogUsfTheory, AgreesWithMonteCarloOfTheCollisionRule) {
    // scripts/enskog_usf_reference.py at its defaults (8 scrambled Sobol sets of 2^21 pairs each): the same
    // Grad theory with the collisional moments sampled from the collision rule itself instead of the closed
    // forms and quadrature used here. Means and standard errors of a*, eta*, P*_xx, P*_yy, P*_zz; the
    // function must lie within 4 standard errors plus the printed rounding, 5e-6 (it lies within 1.8 standard
    // errors of all 116 numbers the script prints).
    struct Reference {
        double alpha, phi, value[5], error[5];
    };
    const Reference refs[] = {
        {0.9, 0.10, {0.37332, 1.14491, 1.65081, 1.43200, 1.42526}, {8.6e-5, 4.5e-4, 2.2e-4, 1.6e-4, 1.3e-4}},
        {0.9, 0.25, {0.31396, 2.68684, 3.17648, 3.03820, 2.93538}, {4.5e-5, 6.1e-4, 2.6e-4, 2.3e-4, 1.9e-4}},
        {0.7, 0.10, {0.68749, 0.96147, 1.88319, 1.25906, 1.24825}, {1.9e-4, 4.3e-4, 3.3e-4, 2.4e-4, 2.1e-4}},
        {0.7, 0.25, {0.59646, 2.33270, 3.36666, 2.96253, 2.68270}, {8.9e-5, 4.6e-4, 3.5e-4, 3.3e-4, 2.9e-4}},
        {0.5, 0.25, {0.84640, 2.01679, 3.54258, 2.87741, 2.45398}, {1.4e-4, 3.4e-4, 4.0e-4, 3.6e-4, 3.3e-4}},
    };
    for (const Reference& r : refs) {
        const EnskogUsfState s = enskog_usf_grad(r.alpha, r.phi, carnahan_starling_chi(r.phi));
        const double got[5] = {s.a_star, s.eta_star, s.total.xx, s.total.yy, s.total.zz};
        for (int k = 0; k < 5; ++k)
            EXPECT_NEAR(got[k], r.value[k], 4 * r.error[k] + 5e-6)
                << r.alpha << " " << r.phi << " quantity " << k;
    }
}

TEST(EnskogUsfTheory, RefusesUnphysicalInput) {
    EXPECT_THROW(enskog_usf_grad(-0.1, 0.1, 1.2), std::invalid_argument);
    EXPECT_THROW(enskog_usf_grad(0.5, 1.0, 1.2), std::invalid_argument);
    EXPECT_THROW(enskog_usf_grad(0.5, 0.1, 0.0), std::invalid_argument);
    EXPECT_THROW(enskog_usf_grad(std::nan(""), 0.1, 1.2), std::invalid_argument);
    EXPECT_THROW(enskog_usf_collisional_moments(0.5, 0.1, 1.2, -1.0, UsfTensor{1, 1, 1, 0}),
                 std::invalid_argument);
    EXPECT_THROW(enskog_usf_collisional_moments(0.5, 0.1, 1.2, 1.0, UsfTensor{1, 1, 2, 0}),
                 std::invalid_argument);
}

} // namespace
} // namespace roughgas
