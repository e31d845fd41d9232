#pragma once
// Constants of one species pair (a, b), precomputed once per run: everything the
// collision rule and the collision sampling read, so the rule never sees a species.
#include <cmath>
#include <numbers>

namespace roughgas {

struct GrainProperties {
    double mass = 1;      // m
    double radius = 0.5;  // R
    double inertia = 0.4; // q = J/(m R^2), docs/model.md §1
};

struct PairConstants {
    double m_eff = 0;         // m_a m_b/(m_a + m_b)
    double kappa = 0;         // 1/kappa = 1 + m_eff (1/(q_a m_a) + 1/(q_b m_b)), docs/model.md §1
    double sigma = 0;         // R_a + R_b: the collision diameter
    double cross_section = 0; // pi sigma^2
    double R_i = 0, R_j = 0;  // radii of the first (i, species a) and second (j, species b) grain
    double m_eff_over_m_i = 0, m_eff_over_m_j = 0; // P/m = (m_eff/m) p, p = P/m_eff
    // omega' = omega -/+ (n x P)/(q m R): with n x P = -kappa m_eff (1 + beta) (n x g), the factor
    // kappa m_eff/(q m R) per grain.
    double spin_i = 0, spin_j = 0;
};

inline PairConstants make_pair_constants(const GrainProperties& a, const GrainProperties& b) {
    PairConstants p;
    p.m_eff = a.mass * b.mass / (a.mass + b.mass);
    p.kappa = 1.0 / (1.0 + p.m_eff * (1.0 / (a.inertia * a.mass) + 1.0 / (b.inertia * b.mass)));
    p.sigma = a.radius + b.radius;
    p.cross_section = std::numbers::pi * p.sigma * p.sigma;
    p.R_i = a.radius;
    p.R_j = b.radius;
    p.m_eff_over_m_i = b.mass / (a.mass + b.mass);
    p.m_eff_over_m_j = a.mass / (a.mass + b.mass);
    p.spin_i = p.kappa * p.m_eff / (a.inertia * a.mass * a.radius);
    p.spin_j = p.kappa * p.m_eff / (b.inertia * b.mass * b.radius);
    return p;
}

} // namespace roughgas
