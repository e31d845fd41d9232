#pragma once
// The shear (transverse) mode of the homogeneous cooling state of smooth inelastic hard spheres in
// Navier-Stokes hydrodynamics: dilute gas, constant normal restitution alpha, the transport
// coefficients of the first Sonine approximation with the fourth cumulant a2 (Brey, Dufty, Kim &
// Santos 1998; Garzo & Dufty 1999; a2 of van Noije & Ernst 1998).
//
// A transverse wave u_y = u_k sin(k x), u_k much smaller than the thermal speed, decouples from the
// density and temperature: du_k/dt = -eta k^2 u_k/(n m) while the gas cools as dT/dt = -zeta T. Per
// collision per particle s (ds/dt = nu_c, the true collision frequency per grain), the wave's
// amplitude against the thermal speed changes at the rate
//   gamma(k) = d ln(u_k / sqrt(T/m)) / ds = [zeta/2 - eta k^2/(n m)] / nu_c
//            = [(2/5) zeta* - (5 pi/32) eta* (k lambda)^2] / (1 - a2/16),
// independent of T: it grows (the gas leaves the homogeneous state by shear vortices) when k is
// below k_c, (k_c lambda)^2 = (64/(25 pi)) zeta*/eta*, i.e. in a periodic box longer than
// L_c = 2 pi/k_c = (5 pi^(3/2)/4) sqrt(eta*/zeta*) lambda. Here lambda = 1/(sqrt(2) pi n sigma^2),
// nu_M = 4 n sigma^2 sqrt(pi T/m), nu_c = nu_M (1 - a2/16), and
//   a2    = 16 (1 - alpha)(1 - 2 alpha^2) / (81 - 17 alpha + 30 alpha^2 (1 - alpha)),
//   zeta* = zeta/nu_0 = (5/12)(1 - alpha^2)(1 + 3 a2/16),          nu_0 = n T/eta_0 = (4/5) nu_M,
//   eta*  = eta/eta_0 = 1/(nu_eta* - zeta*/2),  nu_eta* = (3 - alpha)(1 + alpha)/4 (1 - a2/32),
// eta_0 = (5/(16 sigma^2)) sqrt(m T/pi). At alpha = 1: a2 = zeta* = 0, eta* = 1 (the first Sonine
// elastic viscosity, 1.6 % below the converged Chapman-Enskog 1.016034), and no finite L_c; as
// alpha -> 1, L_c ~ 10.78 lambda / sqrt(1 - alpha^2).
//
// Rough grains (constant alpha and beta > -1, moment of inertia q m R^2): the cooling state in the
// two-temperature Maxwellian approximation (Huthmann & Zippelius 1997; Luding, Huthmann, McNamara &
// Zippelius 1998), theta = T_rot/T_tr at its fixed point, and the shear viscosity in the first
// Sonine approximation with the trial function c_x c_y, the scheme of Kremer, Santos & Garzo (2014).
// With at = (1 + alpha)/2, bt = q (1 + beta)/(2 (1 + q)), all rates over nu_0 at T_tr:
//   zeta*   = (5/12)[1 - alpha^2 + 4 bt (1 - bt) - 4 bt^2 theta/q]   (T_tr, T_rot, T all decay at it),
//   nu_eta* = (at + bt)(2 - at - bt) + bt^2 theta/(6 q),   eta* = 1/(nu_eta* - zeta*/2),
//   gamma(k) = (2/5) zeta* - (5 pi/32) eta* (k lambda)^2 per collision per particle (no a2 here).
// The spins do not enter the shear mode at Navier-Stokes order: in the Boltzmann limit the momentum
// flux is the kinetic one. Checks: beta = -1 exactly is the smooth case above (the rough formulas
// do not tend to it: as beta -> -1 the slow exchange with the spins makes zeta* -> 0 and L_c grow
// without bound); elastic perfectly rough grains (alpha = beta = 1) do not cool and have Pidduck's
// viscosity 6 (1 + q)^2/(6 + 13 q) eta_0. Medium roughness makes the gas more unstable than smooth
// grains (L_c = 15.3 lambda at alpha = 0.9, beta = 0, q = 2/5), nearly perfect roughness less (36.7
// lambda at beta = 1): the "dual role" of roughness (Garzo, Santos & Kremer 2018).
#include "roughgas/dsmc/run_spec.hpp"

#include <optional>

namespace roughgas {

struct ShearModeTheory {
    double alpha = 1, beta = -1;
    double theta = 0;     // T_rot/T_tr of the cooling state (rough grains; 0 for smooth ones)
    double a2 = 0;        // fourth cumulant of the cooling state
    double zeta_star = 0; // cooling rate over nu_0
    double eta_star = 1;  // shear viscosity over eta_0
    // gamma(k) = growth - damping (k lambda)^2, per collision per particle.
    double growth = 0, damping = 0;
    double critical_length = 0; // L_c / lambda (infinite at alpha = 1)
};

// The theory above for 0 <= alpha <= 1.
ShearModeTheory smooth_shear_mode(double alpha);

// The theory for rough grains, -1 <= beta <= 1 (beta = -1: smooth_shear_mode(alpha)), q the reduced
// moment of inertia (2/5: uniform spheres); a2 = 0.
ShearModeTheory rough_shear_mode(double alpha, double beta, double q);

// gamma(k) per collision per particle, for k lambda = `k_lambda`.
double shear_mode_rate(const ShearModeTheory& t, double k_lambda);

// The theory of a run's cooling state when it applies: a freely cooling periodic box (no shear, walls
// or gravity) of grains of one species with constant alpha and beta; nullopt otherwise.
std::optional<ShearModeTheory> shear_mode_theory(const RunSpec& spec);

} // namespace roughgas
