// The shear mode of the homogeneous cooling state: observables/shear_mode.hpp.
#include "roughgas/observables/shear_mode.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/theory.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <variant>

namespace roughgas {

ShearModeTheory smooth_shear_mode(double alpha) {
    if (!(alpha >= 0 && alpha <= 1))
        throw std::invalid_argument("smooth_shear_mode: alpha must be in [0, 1]");
    constexpr double pi = std::numbers::pi;
    ShearModeTheory t;
    t.alpha = alpha;
    t.a2 = 16 * (1 - alpha) * (1 - 2 * alpha * alpha) / (81 - 17 * alpha + 30 * alpha * alpha * (1 - alpha));
    t.zeta_star = 5.0 / 12.0 * (1 - alpha * alpha) * (1 + 3 * t.a2 / 16);
    const double nu_eta = (3 - alpha) * (1 + alpha) / 4 * (1 - t.a2 / 32);
    t.eta_star = 1 / (nu_eta - t.zeta_star / 2);
    // zeta/(2 nu_c) with zeta = zeta* nu_0 = (4/5) zeta* nu_M; eta k^2/(n m nu_M) = (5 pi/32) eta* (k lambda)^2.
    const double per_collision = 1 / (1 - t.a2 / 16);
    t.growth = 0.4 * t.zeta_star * per_collision;
    t.damping = 5 * pi / 32 * t.eta_star * per_collision;
    t.critical_length = t.zeta_star > 0 ? 2 * pi / std::sqrt(t.growth / t.damping)
                                        : std::numeric_limits<double>::infinity();
    return t;
}

ShearModeTheory rough_shear_mode(double alpha, double beta, double q) {
    if (beta == -1)
        return smooth_shear_mode(alpha);
    if (!(alpha >= 0 && alpha <= 1 && beta > -1 && beta <= 1 && q > 0))
        throw std::invalid_argument("rough_shear_mode: needs 0 <= alpha <= 1, -1 <= beta <= 1, q > 0");
    constexpr double pi = std::numbers::pi;
    ShearModeTheory t;
    t.alpha = alpha;
    t.beta = beta;
    t.theta = theta_fixed_point(alpha, beta, q);
    const double at = (1 + alpha) / 2, bt = q * (1 + beta) / (2 * (1 + q));
    t.zeta_star = 5.0 / 12.0 * (1 - alpha * alpha + 4 * bt * (1 - bt) - 4 * bt * bt * t.theta / q);
    if (std::abs(t.zeta_star) < 1e-14) // elastic perfectly rough grains: no cooling (round-off aside)
        t.zeta_star = 0;
    const double nu_eta = (at + bt) * (2 - at - bt) + bt * bt * t.theta / (6 * q);
    t.eta_star = 1 / (nu_eta - t.zeta_star / 2);
    t.growth = 0.4 * t.zeta_star;
    t.damping = 5 * pi / 32 * t.eta_star;
    t.critical_length = t.zeta_star > 0 ? 2 * pi / std::sqrt(t.growth / t.damping)
                                        : std::numeric_limits<double>::infinity();
    return t;
}

ShearModeTheory enskog_shear_mode(double alpha, double phi, double chi) {
    if (!(alpha >= 0 && alpha <= 1 && phi >= 0 && phi < 1 && chi > 0 && std::isfinite(chi)))
        throw std::invalid_argument("enskog_shear_mode: needs 0 <= alpha <= 1, 0 <= phi < 1, chi > 0");
    constexpr double pi = std::numbers::pi;
    // a2 of the dilute gas: the cooling state's scaled distribution does not depend on chi.
    ShearModeTheory t = smooth_shear_mode(alpha);
    t.phi = phi;
    t.chi = chi;
    t.zeta_star *= chi;
    // Garzo & Dufty (1999): the kinetic flux's relaxation rate, its source (the kinetic part's
    // collisional-transfer share), then the collisional transfer of momentum and the bulk viscosity.
    const double nu_eta = chi * (3 - alpha) * (1 + alpha) / 4 * (1 - t.a2 / 32);
    const double eta_k = (1 - 0.4 * (1 + alpha) * (1 - 3 * alpha) * phi * chi) / (nu_eta - t.zeta_star / 2);
    const double kappa = 128 / (5 * pi) * phi * phi * chi * (1 + alpha) * (1 - t.a2 / 16);
    t.eta_star = eta_k * (1 + 0.8 * phi * chi * (1 + alpha)) + 0.6 * kappa;
    // Per collision: nu_c = chi nu_M (1 - a2/16); the wave number still in dilute mean free paths.
    const double per_collision = 1 / (chi * (1 - t.a2 / 16));
    t.growth = 0.4 * t.zeta_star * per_collision;
    t.damping = 5 * pi / 32 * t.eta_star * per_collision;
    t.critical_length = t.zeta_star > 0 ? 2 * pi / std::sqrt(t.growth / t.damping)
                                        : std::numeric_limits<double>::infinity();
    return t;
}

double shear_mode_rate(const ShearModeTheory& t, double k_lambda) {
    return t.growth - t.damping * k_lambda * k_lambda;
}

std::optional<ShearModeTheory> shear_mode_theory(const RunSpec& spec) {
    if (!spec.domain || spec.shear || spec.domain->has_walls() || spec.domain->has_gravity())
        return std::nullopt;
    const auto* c = spec.pairs.size() == 1 ? std::get_if<ConstantRestitution>(&spec.pairs[0]) : nullptr;
    if (spec.species.size() != 1 || c == nullptr)
        return std::nullopt;
    if (spec.enskog) {
        if (c->beta != -1) // no Enskog viscosity of rough grains here (shear_mode.hpp)
            return std::nullopt;
        return enskog_shear_mode(c->alpha, solid_fraction(spec.density, spec.species), pair_correlations(spec)[0]);
    }
    return rough_shear_mode(c->alpha, c->beta, spec.species[0].inertia);
}

} // namespace roughgas
