// Smooth spheres under white noise in the first Sonine approximation (observables/white_noise_sonine.hpp):
// van Noije & Ernst's a2 against the moment equations, and the steady temperature.
#include "roughgas/observables/driven_steady_state.hpp"
#include "roughgas/observables/sonine_rates.hpp"
#include "roughgas/observables/theory.hpp"
#include "roughgas/observables/white_noise_sonine.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace roughgas {
namespace {

TEST(WhiteNoiseSonine, A2SolvesTheFirstSonineEquation) {
    // Smooth spheres under white noise: R_c4 = 5 R_c2 (white_noise_sonine.hpp) with the linear rates
    // of sonine_rates.hpp at beta = -1 (checked against sympy and quadrature in sonine_theory_test):
    // R_c4 - 5 R_c2 is linear in a20, so its root is -(its value at 0)/(its slope).
    for (double alpha : {0.0, 0.3, 0.5, 0.7, 0.9, 0.99}) {
        const SonineRates r = sonine_rates(alpha, -1.0, 0.4, 1.0);
        const double at0 = r.c4.one - 5 * r.c2.one, slope = r.c4.a20 - 5 * r.c2.a20;
        EXPECT_NEAR(white_noise_a2(alpha), -at0 / slope, 1e-14) << alpha;
    }
    // d dimensions: the moment ratios mu_2 ~ 1 + 3 a2/16, mu_4 ~ (d + 3/2 + alpha^2) + K a2 of van Noije &
    // Ernst (white_noise_sonine.hpp; at d = 3 the sonine_rates above) give the white noise's a2 from
    // mu_4 = (d + 2) mu_2, and from mu_4 = (d + 2)(1 + a2) mu_2 (linearised) the cooling state's published
    // 16 (1 - alpha)(1 - 2 alpha^2)/(9 + 24d - (41 - 8d) alpha + 30 alpha^2 (1 - alpha)): one K for both.
    for (int d : {2, 3})
        for (double alpha : {0.0, 0.4, 0.8, 0.95}) {
            const double K = 3.0 / 32 * (10 * d + 39 + 10 * alpha * alpha) + (d - 1) / (1 - alpha);
            const double rhs = 0.5 - alpha * alpha; // (d + 2) - (d + 3/2 + alpha^2)
            EXPECT_NEAR(white_noise_a2(alpha, d), rhs / (K - 3.0 * (d + 2) / 16), 1e-15) << d << " " << alpha;
            const double cooling = 16 * (1 - alpha) * (1 - 2 * alpha * alpha) /
                                   (9 + 24 * d - (41 - 8 * d) * alpha + 30 * alpha * alpha * (1 - alpha));
            EXPECT_NEAR(cooling, rhs / (K - 19.0 * (d + 2) / 16), 1e-15) << d << " " << alpha;
            if (d == 3) { // the same K as the rates of sonine_rates.hpp
                const SonineRates r = sonine_rates(alpha, -1.0, 0.4, 1.0);
                EXPECT_NEAR(r.c4.a20 / r.c2.one, K, 1e-12) << alpha;
                EXPECT_NEAR(r.c4.one / r.c2.one, d + 1.5 + alpha * alpha, 1e-12) << alpha;
            }
        }
    // a2 = 0 at alpha = 1/sqrt(2) and at alpha = 1; its value at alpha = 0.9 (d = 3):
    // 16 (0.1)(1 - 1.62)/(241 - 159.3 + 2.43) = -0.992/84.13.
    EXPECT_NEAR(white_noise_a2(1 / std::sqrt(2.0)), 0.0, 1e-15);
    EXPECT_EQ(white_noise_a2(1.0), 0.0);
    EXPECT_NEAR(white_noise_a2(0.9), -0.992 / 84.13, 1e-15);
    // d = 2, alpha = 0.5: 16 (0.5)(0.5)/(73 + 112 - 24 - 52.5 + 3.75) = 4/112.25.
    EXPECT_NEAR(white_noise_a2(0.5, 2), 4 / 112.25, 1e-15);
}

TEST(WhiteNoiseSonine, SteadyTemperatureBalancesTheSonineCoolingRate) {
    // m xi^2 = zeta(T) T with zeta = G A sqrt(T)(1 + 3 a2/16): the Maxwellian steady T of smooth
    // spheres times (1 + 3 a2/16)^{-2/3}.
    const double m = 1.5, sigma = 0.8, n = 0.4, xi2 = 2.0;
    for (double alpha : {0.5, 0.9}) {
        const WhiteNoiseSonineState s = white_noise_sonine_state(alpha, m, sigma, n, xi2);
        const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, -1.0, 0.4, m, sigma, n);
        const double zeta = c.G * c.A * std::sqrt(s.T_tr) * (1 + 3 * s.a2 / 16);
        EXPECT_NEAR(zeta * s.T_tr / (m * xi2), 1.0, 1e-14);
        const double maxwellian = white_noise_steady_state(alpha, -1.0, 0.4, m, sigma, n, xi2).T_tr;
        EXPECT_NEAR(s.T_tr / maxwellian, std::pow(1 + 3 * s.a2 / 16, -2.0 / 3.0), 1e-14);
        // per collision of the Sonine distribution, nu_M (1 - a2/16): (2/3) R_c2/(1 - a2/16)
        const SonineRates r = sonine_rates(alpha, -1.0, 0.4, 1.0);
        EXPECT_NEAR(s.zeta_star, (2.0 / 3.0) * r.c2.at(s.a2, 0, 0) / (1 - s.a2 / 16), 1e-14);
    }
}

} // namespace
} // namespace roughgas
