// The longitudinal modes of the homogeneous cooling state: observables/longitudinal_modes.hpp.
#include "roughgas/observables/longitudinal_modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace roughgas {
namespace {

constexpr double pi = std::numbers::pi;

// The entries of M without the factors i: M = D R D^-1 with R real, D = diag(1, 1, i).
Eigen::Matrix3d real_form(const LongitudinalModeTheory& t, double k_lambda) {
    const double x2 = k_lambda * k_lambda, c = std::sqrt(pi / 8) * k_lambda, z = 0.4 * t.shear.zeta_star;
    constexpr double P = 25 * pi / 64, E = 5 * pi / 24;
    Eigen::Matrix3d r;
    if (t.shear.beta > -1) { // rough grains: energy density 3 n T, p = 2 n T/(1 + theta), a2 = 0
        const double work = 2 / (3 * (1 + t.shear.theta)) + t.zeta_u;
        r << 0, 0, c,                                                                      // d rho/ds
            -2 * z - P / 2 * t.mu_star * x2, -z - P / 2 * t.kappa_star * x2, work * c,     // d theta/ds
            -c, -c, z - (E * t.shear.eta_star + 5 * pi / 32 * t.bulk_viscosity_star) * x2; // d w/ds
        return r;
    }
    r << 0, 0, c,                                                           // d rho/ds = -i c w
        -2 * z - P * t.mu_star * x2, -z - P * t.kappa_star * x2, 2 * c / 3, // d theta/ds
        -c, -c, z - E * t.shear.eta_star * x2;                              // d w/ds
    return r / (1 - t.shear.a2 / 16);
}

} // namespace

LongitudinalModeTheory smooth_longitudinal_modes(double alpha) {
    if (!(alpha >= 0 && alpha <= 1))
        throw std::invalid_argument("smooth_longitudinal_modes: alpha must be in [0, 1]");
    LongitudinalModeTheory t;
    t.shear = smooth_shear_mode(alpha);
    const double a2 = t.shear.a2, zeta = t.shear.zeta_star;
    const double nu_kappa = (1 + alpha) / 3 * (1 + 33 * (1 - alpha) / 16 + (19 - 3 * alpha) * a2 / 512);
    t.kappa_star = 2.0 / 3.0 * (1 + 2 * a2) / (nu_kappa - 2 * zeta);
    t.mu_star = (zeta * t.kappa_star + 2.0 / 3.0 * a2) / (nu_kappa - 1.5 * zeta);
    if (zeta == 0)
        t.critical_length = std::numeric_limits<double>::infinity();
    else if (t.kappa_star <= t.mu_star)
        t.critical_length = 0;
    else
        t.critical_length = 2 * pi / std::sqrt(128 / (125 * pi) * zeta / (t.kappa_star - t.mu_star));
    return t;
}

LongitudinalModeTheory rough_longitudinal_modes(double alpha, double beta, double q) {
    if (beta == -1)
        return smooth_longitudinal_modes(alpha);
    if (!(alpha >= 0 && alpha <= 1 && beta > -1 && beta <= 1 && q > 0))
        throw std::invalid_argument(
            "rough_longitudinal_modes: needs 0 <= alpha <= 1, -1 <= beta <= 1, q > 0");
    LongitudinalModeTheory t;
    t.shear = rough_shear_mode(alpha, beta, q);
    const double theta = t.shear.theta, zeta = t.shear.zeta_star;
    const double at = (1 + alpha) / 2, bt = q * (1 + beta) / (2 * (1 + q));
    const double A = (1 - alpha * alpha) / 4 + bt * (1 - bt), B = bt * bt / q, C = bt / q * (1 - bt / q);

    // The scalar part: the lag of T_tr/T_rot under compression.
    const double d_t = 5.0 / 6.0 * (B * (theta - 2) - 3 * A), d_r = 5.0 / 6.0 * (3 * B + C * (2 - theta));
    t.bulk_viscosity_star = 2.0 / 3.0 * theta / (d_r - theta * d_t - (1 + theta) * zeta / 2);
    t.zeta_u = (d_t + d_r) * t.bulk_viscosity_star / (1 + theta);

    // The heat flux: the translational and rotational fluxes' relaxation matrix N over nu_0.
    const double n_tt =
        (41 * (at + bt) - 33 * (at * at + bt * bt) - 16 * at * bt - 7 * bt * bt * theta / q) / 12;
    const double n_tr = -25.0 / 18.0 * bt * bt / q;
    const double n_rt = -5.0 / 12.0 * bt / q * (bt * theta / q + 3 * bt - theta);
    const double n_rr = 5.0 / 18.0 * (3 * (at + bt) - bt / q * (4 * at + 6 * bt - 7) - 3 * bt * bt / (q * q));
    // (N - s I)^-1 y by Cramer's rule.
    const auto solve = [&](double s, double y0, double y1) -> std::array<double, 2> {
        const double a = n_tt - s, d = n_rr - s, det = a * d - n_tr * n_rt;
        return {(d * y0 - n_tr * y1) / det, (a * y1 - n_rt * y0) / det};
    };
    const double norm = 8 / (15 * (1 + theta));
    const std::array<double, 2> k = solve(2 * zeta, norm * 2.5, norm * 1.5 * theta);
    const std::array<double, 2> m = solve(1.5 * zeta, k[0], k[1]);
    t.kappa_star = k[0] + k[1];
    t.mu_star = zeta * (m[0] + m[1]);
    if (zeta == 0)
        t.critical_length = std::numeric_limits<double>::infinity();
    else if (t.kappa_star <= t.mu_star)
        t.critical_length = 0;
    else
        t.critical_length = 2 * pi / std::sqrt(256 / (125 * pi) * zeta / (t.kappa_star - t.mu_star));
    return t;
}

std::optional<LongitudinalModeTheory> longitudinal_mode_theory(const RunSpec& spec) {
    const std::optional<ShearModeTheory> t = shear_mode_theory(spec);
    if (!t || spec.enskog) // the coefficients above are the dilute gas's
        return std::nullopt;
    return rough_longitudinal_modes(t->alpha, t->beta, spec.species[0].inertia);
}

Eigen::Matrix3cd longitudinal_mode_matrix(const LongitudinalModeTheory& t, double k_lambda) {
    const std::complex<double> i(0, 1);
    Eigen::Matrix3cd m = real_form(t, k_lambda).cast<std::complex<double>>();
    m(0, 2) *= -i; // in D R D^-1 the w column gains the factor 1/i = -i, the w row the factor i
    m(1, 2) *= -i;
    m(2, 0) *= i;
    m(2, 1) *= i;
    return m;
}

LongitudinalModeRates longitudinal_mode_rates(const LongitudinalModeTheory& t, double k_lambda) {
    const Eigen::EigenSolver<Eigen::Matrix3d> solver(real_form(t, k_lambda), false);
    if (solver.info() != Eigen::Success)
        throw std::runtime_error("longitudinal_mode_rates: the eigenvalue iteration did not converge");
    std::array<std::complex<double>, 3> e;
    for (int j = 0; j < 3; ++j)
        e[j] = solver.eigenvalues()(j);
    // Real eigenvalues first, the largest first; then a conjugate pair, Im > 0 first.
    std::ranges::sort(e, [](const std::complex<double>& a, const std::complex<double>& b) {
        if ((a.imag() == 0) != (b.imag() == 0))
            return a.imag() == 0;
        return a.imag() == 0 ? a.real() > b.real() : a.imag() > b.imag();
    });
    return {e[0], {e[1], e[2]}};
}

double longitudinal_max_rate(const LongitudinalModeTheory& t, double k_lambda) {
    const LongitudinalModeRates r = longitudinal_mode_rates(t, k_lambda);
    return std::max({r.heat.real(), r.sound[0].real(), r.sound[1].real()});
}

} // namespace roughgas
