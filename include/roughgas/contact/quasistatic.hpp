#pragma once
// Validity of the quasistatic contact (Brilliantov et al. (1996), appendix B): the viscoelastic
// force of eqs. 24-25 holds when
//   (B11)  (g_N / c_t)^2 << 1,   c_t^2 = Y/(2 (1 + nu) rho_m)   (transverse speed of sound),
//   (B12)  tau_vis / t_c << 1,   tau_vis ~ A (the material's viscous relaxation time),
// with t_c the duration of the collision. We take t_c as Hertz's, 3.218 rho^{-2/5} g_N^{-1/5}
// (docs/model.md §6; the dissipative contact is shorter, by at most a factor ~2 where B12 holds).
// Thresholds: g_N/c_t > 0.1 fails B11 plainly (a tenth of the speed of sound). A stands in for
// tau_vis only up to factors of order one (A = tau_vis times a function of nu, the paper's eq. 23), and any
// clearly inelastic collision has A/t_c ~ u/4.8 = 0.1 .. 1 (e.g. ice, eps^N = 0.5 at a few m/s, the
// regime the paper fits), so B12 is called failed only where the contact is shorter than A itself
// (A/t_c > 1, eps^N ~< 0.1). Outside, the model still integrates (and the tool says so once), but its
// numbers are no longer physics.
#include "roughgas/contact/contact_pair.hpp"
#include "roughgas/contact/material.hpp"

#include <cmath>
#include <numbers>

namespace roughgas {

inline constexpr double quasistatic_speed_limit = 0.1; // g_N/c_t
inline constexpr double quasistatic_time_limit = 1.0;   // A/t_c
inline constexpr double hertz_duration_factor = 3.21806546; // t_c = 3.218... rho^{-2/5} g^{-1/5}

struct QuasistaticRatios {
    double speed = 0; // g_N / c_t (B11)
    double time = 0;  // A / t_c   (B12)
    bool holds() const { return speed <= quasistatic_speed_limit && time <= quasistatic_time_limit; }
};

// Transverse speed of sound of the material, density rho_m (mass per volume).
inline double transverse_sound_speed(const Material& mat, double rho_m) {
    return std::sqrt(mat.young_modulus / (2.0 * (1.0 + mat.poisson_ratio) * rho_m));
}

// Density of a uniform sphere of mass m and radius R.
inline double sphere_density(double m, double R) {
    return m / (4.0 / 3.0 * std::numbers::pi * R * R * R);
}

inline QuasistaticRatios quasistatic_ratios(const ContactPair& pc, double c_t, double g_n) {
    QuasistaticRatios q;
    q.speed = g_n / c_t;
    q.time = pc.A / (hertz_duration_factor * pc.hertz_time(g_n));
    return q;
}

} // namespace roughgas
