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

// Against an independent evaluation of the same formulas: scripts/linear_theory_reference.py, which
// works in dimensional units (arbitrary n, sigma, m, T), forms the linearised equations per unit
// time, divides by nu_c and calls numpy.linalg.eigvals; its L_par is the zero of the largest real
// part found by bisection, not the closed form. Printed to 15 digits.
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

// Rough grains, alpha = beta = 1: Pidduck's elastic perfectly rough gas. No cooling (theta = 1,
// zeta* = zeta_U = mu* = 0, no finite L_par), and the first approximations of Chapman & Cowling (1970)
// for the conductivity and the bulk viscosity, with K = q:
//   kappa/kappa_0 = 12 (1 + K)^2 (37 + 151 K + 50 K^2)/(25 (12 + 75 K + 101 K^2 + 102 K^3)),
//   eta_b/eta_0 = (1 + K)^2/(10 K).
// Its modes: at any k the eigenvalues are the roots of l^3 - tr l^2 + pairs l - det with
// tr = -(P/2 kappa* + E') x^2, pairs = (4/3) c^2 + (P/2) kappa* E' x^4, det = -(P/2) kappa* c^2 x^2,
// E' = E eta* + (5 pi/32) eta_b*: the (4/3) c^2 is the adiabatic speed of six degrees of freedom,
// sqrt(4 T/(3 m)) (gamma = 4/3), against sqrt(5 T/(3 m)) for smooth grains. At small k: sound at that
// speed damped at {[(4/3) eta + eta_b]/(m n) + (gamma - 1) kappa/(n c_p)} k^2/2 (c_p = 4), the heat mode
// -kappa k^2/(n c_p).
TEST(LongitudinalModes, ElasticPerfectlyRoughGasIsPidduckGas) {
    for (const double K : {0.1, 0.4, 1.0}) {
        const LongitudinalModeTheory t = rough_longitudinal_modes(1.0, 1.0, K);
        EXPECT_NEAR(t.shear.theta, 1.0, 1e-15) << K;
        EXPECT_EQ(t.shear.zeta_star, 0.0) << K;
        EXPECT_NEAR(t.zeta_u, 0.0, 1e-15) << K;
        EXPECT_NEAR(t.mu_star, 0.0, 1e-15) << K;
        EXPECT_TRUE(std::isinf(t.critical_length)) << K;
        const double kappa = 12 * (1 + K) * (1 + K) * (37 + 151 * K + 50 * K * K) /
                             (25 * (12 + 75 * K + 101 * K * K + 102 * K * K * K));
        EXPECT_NEAR(t.kappa_star, kappa, 1e-13) << K;
        EXPECT_NEAR(t.bulk_viscosity_star, (1 + K) * (1 + K) / (10 * K), 1e-13) << K;
        EXPECT_NEAR(t.shear.eta_star, 6 * (1 + K) * (1 + K) / (6 + 13 * K), 1e-13) << K;

        const double P = 25 * pi / 64,
                     Ep = 5 * pi / 24 * t.shear.eta_star + 5 * pi / 32 * t.bulk_viscosity_star;
        for (const double x : {0.05, 0.3, 1.0}) {
            const LongitudinalModeRates e = longitudinal_mode_rates(t, x);
            const std::complex<double> l1 = e.heat, l2 = e.sound[0], l3 = e.sound[1];
            const double c2 = pi / 8 * x * x, x2 = x * x, h = P / 2 * t.kappa_star;
            const double sum = -(h + Ep) * x2, pairs = 4.0 / 3.0 * c2 + h * Ep * x2 * x2,
                         product = -h * c2 * x2;
            EXPECT_NEAR(std::abs((l1 + l2 + l3) / sum - 1.0), 0.0, 1e-12) << K << " " << x;
            EXPECT_NEAR(std::abs((l1 * l2 + l1 * l3 + l2 * l3) / pairs - 1.0), 0.0, 1e-12) << K << " " << x;
            EXPECT_NEAR(std::abs(l1 * l2 * l3 / product - 1.0), 0.0, 1e-12) << K << " " << x;
        }
        const double x = 1e-3, c = std::sqrt(pi / 8) * x;
        const LongitudinalModeRates r = longitudinal_mode_rates(t, x);
        const double heat = -0.75 * P / 2 * t.kappa_star * x * x; // -kappa k^2/(4 n nu_M)
        const double gamma = (Ep * x * x - heat / 3) / 2;
        EXPECT_NEAR(r.heat.real() / heat, 1.0, 1e-5) << K;
        EXPECT_NEAR(r.sound[0].imag() / c, std::sqrt(4.0 / 3.0), 1e-6) << K;
        EXPECT_NEAR(-r.sound[0].real() / gamma, 1.0, 1e-5) << K;
    }
    EXPECT_THROW(rough_longitudinal_modes(0.9, -1.1, 0.4), std::invalid_argument);
    EXPECT_THROW(rough_longitudinal_modes(0.9, 1.1, 0.4), std::invalid_argument);
    EXPECT_THROW(rough_longitudinal_modes(1.1, 0.0, 0.4), std::invalid_argument);
    EXPECT_THROW(rough_longitudinal_modes(0.9, 0.0, 0.0), std::invalid_argument);
}

// beta = -1 is the smooth theory, the same numbers to the last bit (as rough_shear_mode).
TEST(LongitudinalModes, SmoothRoughGrainsAreSmoothGrains) {
    for (const double alpha : {1.0, 0.9, 0.5}) {
        const LongitudinalModeTheory r = rough_longitudinal_modes(alpha, -1.0, 0.4);
        const LongitudinalModeTheory s = smooth_longitudinal_modes(alpha);
        EXPECT_EQ(r.kappa_star, s.kappa_star);
        EXPECT_EQ(r.mu_star, s.mu_star);
        EXPECT_EQ(r.bulk_viscosity_star, 0.0);
        EXPECT_EQ(r.zeta_u, 0.0);
        EXPECT_EQ(r.shear.a2, s.shear.a2);
        for (const double x : {0.1, 0.3})
            EXPECT_EQ(longitudinal_mode_rates(r, x).heat, longitudinal_mode_rates(s, x).heat);
    }
}

// k -> 0 for rough grains: the same triangular M and eigenvalues +zeta/(2 nu_c), 0, -zeta/(2 nu_c)
// (nu_c = nu_M at T_tr; zeta/(2 nu_c) = (2/5) zeta* = the shear mode's growth), the zero eigenvector
// (1, -2, 0) leaving n sqrt(T), hence the cooling, unchanged.
TEST(LongitudinalModes, RoughSmallWaveNumbersTendToTheCoolingRates) {
    const double cases[][3] = {{0.9, 0.0, 0.4}, {0.8, 0.5, 0.4}, {0.5, -0.5, 0.25}, {0.9, 1.0, 1.0}};
    for (const auto& p : cases) {
        const LongitudinalModeTheory t = rough_longitudinal_modes(p[0], p[1], p[2]);
        const double half_zeta = 0.4 * t.shear.zeta_star;
        EXPECT_EQ(half_zeta, t.shear.growth);
        for (const double x : {0.0, 1e-6}) {
            const LongitudinalModeRates r = longitudinal_mode_rates(t, x);
            EXPECT_NEAR(r.heat.real(), half_zeta, 1e-10) << p[0] << " " << p[1] << " " << x;
            EXPECT_NEAR(r.sound[0].real(), 0.0, 1e-10) << p[0] << " " << p[1] << " " << x;
            EXPECT_NEAR(r.sound[1].real(), -half_zeta, 1e-10) << p[0] << " " << p[1] << " " << x;
            EXPECT_EQ(r.sound[0].imag(), 0.0);
        }
        const Eigen::Matrix3cd m = longitudinal_mode_matrix(t, 0.0);
        const Eigen::Vector3cd same_zeta(1, -2, 0);
        EXPECT_LT((m * same_zeta).norm(), 1e-16);
    }
}

// Rough grains against an independent evaluation: scripts/rough_linear_theory_reference.py, which
// computes the collision integrals over the two-temperature Maxwellian by quadrature (checked there
// by Monte Carlo quadrature of the collision rule), finds theta by bisection, solves the
// Chapman-Enskog moment equations for the coefficients, forms the linearised equations per unit time
// in dimensional units (arbitrary n, sigma, m, T), divides by the collision frequency at T_tr and
// calls numpy.linalg.eigvals; its L_par is the zero of the largest real part found by bisection, not
// the closed form. Printed to 15 digits.
TEST(LongitudinalModes, RoughAgreesWithAnIndependentEvaluation) {
    const struct {
        double alpha, beta, q, theta, bulk, zeta_u, kappa_star, mu_star, critical_length;
    } coefficients[] = {
        {0.9, 0.0, 0.4, 0.57379195369734, 0.773546927069087, -0.0418223190918003, 2.21362487517707,
         0.821298618244803, 18.9639685956272},
        {0.8, 0.5, 0.4, 1.04288161138069, 0.682666069033868, -0.0842462500042194, 2.01298653879339,
         0.728989548245939, 18.3438042593184},
        {0.9, 1.0, 0.4, 1.12312379718081, 0.501294113297044, -0.0280382500695763, 1.54954960159827,
         0.0835550750253214, 48.7946809246332},
        {0.7, -0.5, 0.5, 4.88472002389261, 2.39368957613371, -0.315441740184627, 1.66310151356788,
         0.581604726029841, 16.9955761565218},
    };
    for (const auto& c : coefficients) {
        const LongitudinalModeTheory t = rough_longitudinal_modes(c.alpha, c.beta, c.q);
        EXPECT_NEAR(t.shear.theta / c.theta, 1.0, 1e-13) << c.alpha << " " << c.beta;
        EXPECT_NEAR(t.bulk_viscosity_star / c.bulk, 1.0, 1e-12) << c.alpha << " " << c.beta;
        EXPECT_NEAR(t.zeta_u / c.zeta_u, 1.0, 1e-12) << c.alpha << " " << c.beta;
        EXPECT_NEAR(t.kappa_star / c.kappa_star, 1.0, 1e-12) << c.alpha << " " << c.beta;
        EXPECT_NEAR(t.mu_star / c.mu_star, 1.0, 1e-12) << c.alpha << " " << c.beta;
        EXPECT_NEAR(t.critical_length / c.critical_length, 1.0, 1e-11) << c.alpha << " " << c.beta;
    }
    // Heat mode, sound[0] (Re, Im), sound[1] (Re, Im) per collision per particle.
    const struct {
        double alpha, beta, q, k_lambda, heat, re0, im0, re1, im1;
    } rows[] = {
        {0.9, 0.0, 0.4, 0.02, 9.301658663991931e-02, -1.709600245126340e-03, 0.000000000000000e+00,
         -9.230000536298411e-02, 0.000000000000000e+00},
        {0.9, 0.0, 0.4, 0.1, 7.675463240939351e-02, -5.079005330708611e-02, 4.220741303835123e-02,
         -5.079005330708614e-02, -4.220741303835122e-02},
        {0.9, 0.0, 0.4, 0.3, 1.124951143987744e-02, -1.173393896414427e-01, 1.982598622519835e-01,
         -1.173393896414429e-01, -1.982598622519837e-01},
        {0.8, 0.5, 0.4, 0.02, 9.180184476759408e-02, -1.732246485862200e-03, 0.000000000000000e+00,
         -9.099141138070477e-02, 0.000000000000000e+00},
        {0.8, 0.5, 0.4, 0.1, 7.826813531748872e-02, -5.065673139590423e-02, 4.094229750143974e-02,
         -5.065673139590422e-02, -4.094229750143973e-02},
        {0.8, 0.5, 0.4, 0.3, 1.578464396219014e-02, -1.115962956155342e-01, 1.890619173503831e-01,
         -1.115962956155341e-01, -1.890619173503829e-01},
        {0.9, 1.0, 0.4, 0.02, 1.343683033375239e-02, -7.093576524765028e-03, 1.094697268904875e-02,
         -7.093576524765028e-03, -1.094697268904875e-02},
        {0.9, 1.0, 0.4, 0.1, 4.631019281756874e-03, -1.169454358809928e-02, 6.987966525455580e-02,
         -1.169454358809929e-02, -6.987966525455588e-02},
        {0.9, 1.0, 0.4, 0.3, -5.035737870890336e-02, -5.923261617053591e-02, 2.069842874058401e-01,
         -5.923261617053580e-02, -2.069842874058400e-01},
        {0.7, -0.5, 0.5, 0.02, 9.011232828314984e-02, -1.760851953652908e-03, 0.000000000000000e+00,
         -8.952266984651257e-02, 0.000000000000000e+00},
        {0.7, -0.5, 0.5, 0.1, 7.782440340347314e-02, -5.355212066443241e-02, 3.706562249438553e-02,
         -5.355212066443239e-02, -3.706562249438552e-02},
        {0.7, -0.5, 0.5, 0.3, 2.219485493129779e-02, -1.428566981299118e-01, 1.700395855516958e-01,
         -1.428566981299117e-01, -1.700395855516958e-01},
    };
    for (const auto& r : rows) {
        const LongitudinalModeTheory t = rough_longitudinal_modes(r.alpha, r.beta, r.q);
        const LongitudinalModeRates e = longitudinal_mode_rates(t, r.k_lambda);
        EXPECT_NEAR(e.heat.real(), r.heat, 1e-13) << r.alpha << " " << r.beta << " " << r.k_lambda;
        EXPECT_EQ(e.heat.imag(), 0.0);
        EXPECT_NEAR(e.sound[0].real(), r.re0, 1e-13) << r.alpha << " " << r.beta << " " << r.k_lambda;
        EXPECT_NEAR(e.sound[0].imag(), r.im0, 1e-13) << r.alpha << " " << r.beta << " " << r.k_lambda;
        EXPECT_NEAR(e.sound[1].real(), r.re1, 1e-13) << r.alpha << " " << r.beta << " " << r.k_lambda;
        EXPECT_NEAR(e.sound[1].imag(), r.im1, 1e-13) << r.alpha << " " << r.beta << " " << r.k_lambda;
        const Eigen::ComplexEigenSolver<Eigen::Matrix3cd> solver(longitudinal_mode_matrix(t, r.k_lambda));
        for (const std::complex<double> l : {e.heat, e.sound[0], e.sound[1]}) {
            double nearest = 1;
            for (int j = 0; j < 3; ++j)
                nearest = std::min(nearest, std::abs(solver.eigenvalues()(j) - l));
            EXPECT_LT(nearest, 1e-13) << r.alpha << " " << r.beta << " " << r.k_lambda;
        }
    }
}

// The density instability of rough grains: the heat mode vanishes at k_par, the largest growth rate is
// positive below and negative above, and L_par/L_c = sqrt(5 (kappa* - mu*)/(4 eta*)) (the energy
// density 3 n T halves the conduction term against smooth grains' 5/2). At alpha = 0.9, q = 2/5 the shear
// mode goes unstable first for every beta: L_par = 22.78, 18.96, 20.74, 48.79 lambda against
// L_c = 17.09, 15.33, 16.73, 36.71 lambda for beta = -0.5, 0, 0.5, 1.
TEST(LongitudinalModes, RoughHeatModeGrowsInBoxesLongerThanTheCriticalLength) {
    const double betas[] = {-0.5, 0.0, 0.5, 1.0};
    const double l_par[] = {22.777, 18.964, 20.740, 48.795}, l_c[] = {17.092, 15.332, 16.731, 36.712};
    for (int i = 0; i < 4; ++i) {
        const LongitudinalModeTheory t = rough_longitudinal_modes(0.9, betas[i], 0.4);
        EXPECT_NEAR(t.critical_length, l_par[i], 1e-3) << betas[i];
        EXPECT_NEAR(t.shear.critical_length, l_c[i], 1e-3) << betas[i];
        const double ratio = std::sqrt(1.25 * (t.kappa_star - t.mu_star) / t.shear.eta_star);
        EXPECT_NEAR(t.critical_length / t.shear.critical_length, ratio, 1e-12) << betas[i];
        const double k_par = 2 * pi / t.critical_length;
        EXPECT_NEAR(longitudinal_mode_rates(t, k_par).heat.real(), 0.0, 1e-14) << betas[i];
        EXPECT_GT(longitudinal_max_rate(t, k_par * (1 - 1e-6)), 0.0) << betas[i];
        EXPECT_LT(longitudinal_max_rate(t, k_par * (1 + 1e-6)), 0.0) << betas[i];
        for (int j = 1; j <= 20; ++j) {
            EXPECT_GT(longitudinal_max_rate(t, k_par * j / 21.0), 0.0) << betas[i] << " " << j;
            EXPECT_LT(longitudinal_max_rate(t, k_par * (1 + j / 10.0)), 0.0) << betas[i] << " " << j;
        }
    }
}

} // namespace
} // namespace roughgas
