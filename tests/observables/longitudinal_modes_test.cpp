// The Navier-Stokes longitudinal modes of the homogeneous cooling state
// (observables/longitudinal_modes.hpp): the elastic limit and k -> 0 exactly, the coefficients and
// eigenvalues against an independent evaluation, and the critical length of the density instability.
#include "roughgas/observables/longitudinal_modes.hpp"

#include "roughgas/observables/shear_mode.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace roughgas {
namespace {

constexpr double pi = std::numbers::pi;

// Elastic grains: the first Sonine kappa_0 and no mu; the modes of the elastic Navier-Stokes
// equations. Their small-k series (heat: -D_T k^2, sound: the adiabatic speed sqrt(5 T/(3 m)) and the
// Navier-Stokes damping Gamma k^2, and the next orders, from the series solution of the
// dispersion relation below, solved order by order in x) hold at k lambda = 1e-3 to round-off; at any k, the
// three eigenvalues are the roots of the dispersion relation
//   l (l + P x^2)(l + E x^2) + (5/3) c^2 l + P c^2 x^2 = 0,   c^2 = (pi/8) x^2, x = k lambda,
// (P = 25 pi/64, E = 5 pi/24 as in the header), whose sum, pairwise products and product are checked.
TEST(LongitudinalModes, ElasticGasHasSoundAtTheAdiabaticSpeed) {
    const LongitudinalModeTheory t = smooth_longitudinal_modes(1.0);
    EXPECT_EQ(t.kappa_star, 1.0);
    EXPECT_EQ(t.mu_star, 0.0);
    EXPECT_TRUE(std::isinf(t.critical_length));

    const double x = 1e-3;
    const LongitudinalModeRates r = longitudinal_mode_rates(t, x);
    const double heat = -15 * pi / 64 * x * x - 75 * pi * pi / 16384 * std::pow(x, 4); // -D_T k^2 + ...
    EXPECT_EQ(r.heat.imag(), 0.0);
    EXPECT_NEAR(r.heat.real() / heat, 1.0, 1e-12);
    const double speed = std::sqrt(5.0 / 3.0) * std::sqrt(pi / 8); // sqrt(5/3) sqrt(T/m), per nu_M/lambda
    const double gamma = (5 * pi / 24 + 0.4 * 25 * pi / 64) / 2;   // [(4/3) eta_0/(m n) + (2/3) D_T]/2
    EXPECT_NEAR(gamma, 35 * pi / 192, 1e-15);
    const std::complex<double> sound(-gamma * x * x + 75 * pi * pi / 32768 * std::pow(x, 4),
                                     speed * x -
                                         275 * std::sqrt(30.0) * std::pow(pi, 1.5) / 36864 * std::pow(x, 3));
    EXPECT_NEAR(std::abs(r.sound[0] / sound - 1.0), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(r.sound[1] / std::conj(sound) - 1.0), 0.0, 1e-12);

    for (const double k : {0.05, 0.3, 1.0}) {
        const LongitudinalModeRates e = longitudinal_mode_rates(t, k);
        const std::complex<double> l1 = e.heat, l2 = e.sound[0], l3 = e.sound[1];
        const double P = 25 * pi / 64, E = 5 * pi / 24, c2 = pi / 8 * k * k, x2 = k * k;
        const double sum = -(P + E) * x2, pairs = P * E * x2 * x2 + 5.0 / 3.0 * c2, product = -P * c2 * x2;
        EXPECT_NEAR(std::abs((l1 + l2 + l3) / sum - 1.0), 0.0, 1e-12) << k;
        EXPECT_NEAR(std::abs((l1 * l2 + l1 * l3 + l2 * l3) / pairs - 1.0), 0.0, 1e-12) << k;
        EXPECT_NEAR(std::abs(l1 * l2 * l3 / product - 1.0), 0.0, 1e-12) << k;
    }
    EXPECT_THROW(smooth_longitudinal_modes(-0.1), std::invalid_argument);
    EXPECT_THROW(smooth_longitudinal_modes(1.1), std::invalid_argument);
}

// k -> 0: M is triangular and its eigenvalues are fixed by the cooling rate alone: +zeta/(2 nu_c)
// (the heat mode; at k = 0 a uniform flow against the decaying thermal speed), 0 (the perturbation
// theta = -2 rho that leaves n sqrt(T), hence zeta, unchanged) and -zeta/(2 nu_c) (a temperature
// perturbation). zeta/(2 nu_c) is the shear mode's growth at k = 0.
TEST(LongitudinalModes, SmallWaveNumbersTendToTheCoolingRates) {
    for (const double alpha : {0.95, 0.9, 0.7, 0.5, 0.2}) {
        const LongitudinalModeTheory t = smooth_longitudinal_modes(alpha);
        const double half_zeta = 0.4 * t.shear.zeta_star / (1 - t.shear.a2 / 16); // zeta/(2 nu_c)
        EXPECT_NEAR(half_zeta, t.shear.growth, 1e-16);
        for (const double x : {0.0, 1e-6}) {
            const LongitudinalModeRates r = longitudinal_mode_rates(t, x);
            EXPECT_NEAR(r.heat.real(), half_zeta, 1e-10) << alpha << " " << x;
            EXPECT_NEAR(r.sound[0].real(), 0.0, 1e-10) << alpha << " " << x;
            EXPECT_NEAR(r.sound[1].real(), -half_zeta, 1e-10) << alpha << " " << x;
            EXPECT_EQ(r.heat.imag(), 0.0);
            EXPECT_EQ(r.sound[0].imag(), 0.0); // the sound pair forms only at finite k
        }
        const Eigen::Matrix3cd m = longitudinal_mode_matrix(t, 0.0);
        EXPECT_EQ(m(1, 0).real(), -2 * half_zeta); // -zeta/nu_c: the density dependence of the cooling
        const Eigen::Vector3cd same_zeta(1, -2, 0);
        EXPECT_LT((m * same_zeta).norm(), 1e-16) << alpha;
    }
}

// The labels: at alpha = 0.9 the sound pair is real (two relaxing modes) below k lambda = 0.02336
// and a conjugate pair above; the heat mode stays the real one, continuous across.
TEST(LongitudinalModes, SoundPairFormsAtAFiniteWaveNumber) {
    const LongitudinalModeTheory t = smooth_longitudinal_modes(0.9);
    const LongitudinalModeRates below = longitudinal_mode_rates(t, 0.0233);
    const LongitudinalModeRates above = longitudinal_mode_rates(t, 0.0234);
    EXPECT_EQ(below.sound[0].imag(), 0.0);
    EXPECT_EQ(below.sound[1].imag(), 0.0);
    EXPECT_GT(below.heat.real(), below.sound[0].real());
    EXPECT_GT(below.sound[0].real(), below.sound[1].real());
    EXPECT_GT(above.sound[0].imag(), 0.0);
    EXPECT_EQ(above.sound[1], std::conj(above.sound[0]));
    EXPECT_EQ(above.heat.imag(), 0.0);
    EXPECT_NEAR(above.heat.real(), below.heat.real(), 1e-4);
    // Where the pair forms, both of its members meet at one real part.
    EXPECT_NEAR(below.sound[0].real(), above.sound[0].real(), 2e-3);
    EXPECT_NEAR(below.sound[1].real(), above.sound[0].real(), 2e-3);
}

// Against an independent evaluation of the same formulas: a separate numpy script that works in
// dimensional units (arbitrary n, sigma, m, T), forms the linearised equations per unit time, divides
// by nu_c and calls numpy.linalg.eigvals; its L_par is the zero of the largest real part found by
// root bracketing (scipy brentq), not the closed form. Printed to 15 digits.
TEST(LongitudinalModes, AgreesWithAnIndependentEvaluation) {
    const struct {
        double alpha, kappa_star, mu_star, critical_length;
    } coefficients[] = {
        {0.95, 1.02826137812558, 0.0536762268662818, 53.9528578806745},
        {0.9, 1.06849059806951, 0.115695080263091, 38.2320106437325},
        {0.8, 1.18602405025471, 0.271520692204458, 27.2059901252101},
        {0.7, 1.35796748323858, 0.483734610137198, 22.3195667657693},
        {0.5, 1.91142129168051, 1.17491363578577, 16.8129147072985},
    };
    for (const auto& c : coefficients) {
        const LongitudinalModeTheory t = smooth_longitudinal_modes(c.alpha);
        EXPECT_NEAR(t.kappa_star, c.kappa_star, 1e-13) << c.alpha;
        EXPECT_NEAR(t.mu_star, c.mu_star, 1e-13) << c.alpha;
        EXPECT_NEAR(t.critical_length / c.critical_length, 1.0, 1e-11) << c.alpha;
    }
    // Heat mode, sound[0] (Re, Im), sound[1] (Re, Im) per collision per particle.
    const struct {
        double alpha, k_lambda, heat, re0, im0, re1, im1;
    } rows[] = {
        {0.95, 0.1, 2.642309581514036e-03, -1.096593603882454e-02, 7.874012799810673e-02,
         -1.096593603882454e-02, -7.874012799810673e-02},
        {0.95, 0.3, -5.564092072119588e-02, -5.898257087200956e-02, 2.334190901385935e-01,
         -5.898257087200956e-02, -2.334190901385935e-01},
        {0.9, 0.1, 1.326992808255995e-02, -1.659633220186582e-02, 7.479243529945069e-02,
         -1.659633220186582e-02, -7.479243529945069e-02},
        {0.9, 0.3, -4.540104371845617e-02, -6.695179158604492e-02, 2.295583250750264e-01,
         -6.695179158604492e-02, -2.295583250750264e-01},
        {0.8, 0.1, 3.855920692396445e-02, -3.012271588023054e-02, 6.351526206163503e-02,
         -3.012271588023054e-02, -6.351526206163503e-02},
        {0.8, 0.3, -2.626835669645220e-02, -8.445383341600926e-02, 2.193088893217288e-01,
         -8.445383341600926e-02, -2.193088893217288e-01},
        {0.7, 0.1, 6.513218969012601e-02, -4.465583869248085e-02, 4.986215738544309e-02,
         -4.465583869248085e-02, -4.986215738544309e-02},
        {0.7, 0.3, -7.663133633806734e-03, -1.049761278098569e-01, 2.054128362957352e-01,
         -1.049761278098569e-01, -2.054128362957352e-01},
        {0.5, 0.1, 1.092139764756621e-01, -4.361466623168801e-02, 0.0, -9.757147690830145e-02, 0.0},
        {0.5, 0.3, 3.083436040681031e-02, -1.592919301928779e-01, 1.630434671761252e-01,
         -1.592919301928779e-01, -1.630434671761252e-01},
    };
    for (const auto& r : rows) {
        const LongitudinalModeTheory t = smooth_longitudinal_modes(r.alpha);
        const LongitudinalModeRates e = longitudinal_mode_rates(t, r.k_lambda);
        EXPECT_NEAR(e.heat.real(), r.heat, 1e-13) << r.alpha << " " << r.k_lambda;
        EXPECT_EQ(e.heat.imag(), 0.0);
        EXPECT_NEAR(e.sound[0].real(), r.re0, 1e-13) << r.alpha << " " << r.k_lambda;
        EXPECT_NEAR(e.sound[0].imag(), r.im0, 1e-13) << r.alpha << " " << r.k_lambda;
        EXPECT_NEAR(e.sound[1].real(), r.re1, 1e-13) << r.alpha << " " << r.k_lambda;
        EXPECT_NEAR(e.sound[1].imag(), r.im1, 1e-13) << r.alpha << " " << r.k_lambda;
        // The complex matrix has the same spectrum (a general complex eigensolver, no real form).
        const Eigen::ComplexEigenSolver<Eigen::Matrix3cd> solver(longitudinal_mode_matrix(t, r.k_lambda));
        for (const std::complex<double> l : {e.heat, e.sound[0], e.sound[1]}) {
            double nearest = 1;
            for (int j = 0; j < 3; ++j)
                nearest = std::min(nearest, std::abs(solver.eigenvalues()(j) - l));
            EXPECT_LT(nearest, 1e-13) << r.alpha << " " << r.k_lambda;
        }
    }
}

// The density (clustering) instability: the largest real part of the three eigenvalues is positive
// for k below k_par = 2 pi/L_par (boxes longer than L_par) and negative above, through the real heat
// mode, whose eigenvalue vanishes at k_par.
TEST(LongitudinalModes, HeatModeGrowsInBoxesLongerThanTheCriticalLength) {
    for (const double alpha : {0.99, 0.9, 0.7, 0.5, 0.3}) {
        const LongitudinalModeTheory t = smooth_longitudinal_modes(alpha);
        const double k_par = 2 * pi / t.critical_length;
        EXPECT_GT(longitudinal_max_rate(t, k_par * (1 - 1e-6)), 0.0) << alpha;
        EXPECT_LT(longitudinal_max_rate(t, k_par * (1 + 1e-6)), 0.0) << alpha;
        EXPECT_NEAR(longitudinal_mode_rates(t, k_par).heat.real(), 0.0, 1e-14) << alpha;
        for (int j = 1; j <= 50; ++j) {
            EXPECT_GT(longitudinal_max_rate(t, k_par * j / 51.0), 0.0) << alpha << " " << j;
            EXPECT_LT(longitudinal_max_rate(t, k_par * (1 + j / 10.0)), 0.0) << alpha << " " << j;
        }
    }
    // Below alpha = 0.1878 the first Sonine mu* exceeds kappa*: no k stabilises the heat mode.
    const LongitudinalModeTheory strong = smooth_longitudinal_modes(0.15);
    EXPECT_GT(strong.mu_star, strong.kappa_star);
    EXPECT_EQ(strong.critical_length, 0.0);
    for (const double k : {0.1, 1.0, 3.0})
        EXPECT_GT(longitudinal_max_rate(strong, k), 0.0) << k;
}

// The shear mode goes unstable first (in the shorter box): L_c < L_par, with
// L_par/L_c = sqrt(5 (kappa* - mu*)/(2 eta*)) > 1 for alpha > 0.3747. At alpha = 0.9,
// L_c = 25.30 lambda and L_par = 38.23 lambda; as alpha -> 1 the ratio tends to sqrt(5/2).
// Below alpha = 0.3747 the first Sonine theory reverses the order.
TEST(LongitudinalModes, ShearModeGoesUnstableFirst) {
    const LongitudinalModeTheory t = smooth_longitudinal_modes(0.9);
    EXPECT_NEAR(t.shear.critical_length, 25.3027, 1e-4);
    EXPECT_NEAR(t.critical_length, 38.2320, 1e-4);
    for (const double alpha : {0.99, 0.9, 0.8, 0.6, 0.4}) {
        const LongitudinalModeTheory m = smooth_longitudinal_modes(alpha);
        EXPECT_GT(m.critical_length, m.shear.critical_length) << alpha;
        const double ratio = std::sqrt(2.5 * (m.kappa_star - m.mu_star) / m.shear.eta_star);
        EXPECT_NEAR(m.critical_length / m.shear.critical_length, ratio, 1e-12) << alpha;
    }
    const LongitudinalModeTheory reversed = smooth_longitudinal_modes(0.35);
    EXPECT_LT(reversed.critical_length, reversed.shear.critical_length);

    const double alpha = 0.99999, e = 1 - alpha * alpha;
    const LongitudinalModeTheory q = smooth_longitudinal_modes(alpha);
    const double limit = 5 * std::pow(pi, 1.5) / 4 * std::sqrt(12.0 / 5) * std::sqrt(2.5);
    EXPECT_NEAR(q.critical_length * std::sqrt(e) / limit, 1.0, 1e-4);
}

} // namespace
} // namespace roughgas
