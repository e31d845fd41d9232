#pragma once
// Everything the contact of one species pair depends on, precomputed once. Equation numbers:
// Brilliantov et al. (1996).
#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/material.hpp"

#include <cmath>

namespace roughgas {

struct ContactPair {
    double m_eff = 0;  // m_i m_j/(m_i + m_j), eq. 5 [kg]
    double R_eff = 0;  // R_i R_j/(R_i + R_j), eq. 6 [m]
    double kappa = 0;  // docs/model.md §1 (eq. 8): 2/7 for equal uniform spheres
    double rho = 0;    // 2 Y sqrt(R_eff)/(3 m_eff (1 - nu^2)), docs/model.md §6 [m^{-1/2} s^{-2}]
    double A = 0;      // dissipative constant [s]
    double mu = 0;     // friction coefficient
    double zeta0 = 0;  // asperity scale [m]
    ContactModel model{};

    // docs/model.md §6: tau = (3/2) A for eq. 24, tau = A for eq. 25.
    double tau() const { return model.form == NormalForm::eq24 ? 1.5 * A : A; }
    // The single number eps^N depends on: w = g_N rho^2 tau^5 (docs/model.md §6).
    double w_per_speed() const { const double t = tau(); return rho * rho * t * t * t * t * t; }
    double w(double g_n) const { return g_n * w_per_speed(); }
    // Hertz time scale T = rho^{-2/5} g_N^{-1/5}: the elastic contact lasts 3.218... T.
    double hertz_time(double g_n) const { return std::pow(rho * rho * g_n, -0.2); }
    // Dissipation parameter of the Hertz-scaled equation, u = w^{1/5} = (tau/T).
    double u(double g_n) const { return tau() / hertz_time(g_n); }
    friend bool operator==(const ContactPair&, const ContactPair&) = default;
};

// Pair constants for grains (m, R, q = J/(m R^2)) of one material.
inline ContactPair make_contact_pair(const Material& mat, ContactModel model, double m_i, double R_i,
                                     double q_i, double m_j, double R_j, double q_j) {
    ContactPair p;
    p.m_eff = m_i * m_j / (m_i + m_j);
    p.R_eff = R_i * R_j / (R_i + R_j);
    p.kappa = 1.0 / (1.0 + p.m_eff * (1.0 / (q_i * m_i) + 1.0 / (q_j * m_j)));
    const double nu = mat.poisson_ratio;
    p.rho = 2.0 * mat.young_modulus * std::sqrt(p.R_eff) / (3.0 * p.m_eff * (1.0 - nu * nu));
    p.A = mat.dissipation;
    p.mu = mat.friction;
    p.zeta0 = mat.asperity;
    p.model = model;
    return p;
}

} // namespace roughgas
