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
//
// The Enskog equation (smooth grains, constant alpha, solid fraction phi = (pi/6) n sigma^3, pair
// correlation at contact chi): the Navier-Stokes coefficients of Garzo & Dufty (1999), first Sonine
// approximation with a2. The homogeneous cooling state's collision operator is chi times the
// Boltzmann one, so chi cancels from its scaled distribution: a2 is the dilute one above at every
// phi (exactly, not only at this order), and zeta is chi times the dilute cooling rate. With nu_0 and
// eta_0 still the DILUTE gas's,
//   zeta*   = chi (5/12)(1 - alpha^2)(1 + 3 a2/16),
//   nu_eta* = chi (3 - alpha)(1 + alpha)/4 (1 - a2/32),
//   eta_k*  = [1 - (2/5)(1 + alpha)(1 - 3 alpha) phi chi]/(nu_eta* - zeta*/2)       (kinetic flux),
//   kappa*  = (128/(5 pi)) phi^2 chi (1 + alpha)(1 - a2/16)                        (bulk viscosity),
//   eta*    = eta_k* [1 + (4/5) phi chi (1 + alpha)] + (3/5) kappa*,
// where eta_k*'s phi term is what the collisional transfer feeds into the kinetic flux (the same
// factor 1 + (2/5)(1 + alpha)(3 alpha - 1) phi chi as in Lun, Savage, Jeffrey & Chepurniy 1984) and
// eta*'s phi chi and kappa* terms are the collisional transfer of momentum across contact. Only eta enters the transverse wave (the bulk
// viscosity and the first-order cooling rate act on compressions). A grain collides chi times as
// often as in the dilute gas, nu_c = chi nu_M (1 - a2/16), so per collision per particle
//   gamma(k) = [(2/5) zeta* - (5 pi/32) eta* (k lambda)^2]/(chi (1 - a2/16)),
// lambda the DILUTE mean free path 1/(sqrt(2) pi n sigma^2) as above (the Enskog gas's own is lambda/chi):
// the growth at k -> 0 is the dilute one at every phi, and L_c = (5 pi^(3/2)/4) sqrt(eta*/zeta*) lambda.
// Limits: phi = 0 with chi = 1 is smooth_shear_mode(alpha) exactly; alpha = 1 gives Enskog's
// first-Sonine elastic viscosity eta* = (1 + (8/5) phi chi)^2/chi + (768/(25 pi)) phi^2 chi (the
// alpha -> 1 limit of observables/enskog_usf_theory.hpp). At alpha = 0.9, phi = 0.2 (Carnahan &
// Starling chi = 1.758): eta* = 1.978 (the dilute 1.043) and zeta* = chi times the dilute one, so
// L_c = 26.28 lambda against 25.30 (46.2 of the Enskog gas's own mean free paths lambda/chi); at
// phi = 0.4 (chi = 3.704) 36.8 lambda. At alpha = 0.5, phi = 0.3 it is 13.24 lambda, below the
// dilute 14.05 (L_c^2 goes as (eta*/chi)/(zeta*/chi), and eta*/chi = 1.142 is there below the
// dilute eta* = 1.285).
// Rough grains at finite phi have no Enskog viscosity here in the scheme of Kremer, Santos & Garzo:
// enskog_shear_mode is for smooth grains only (elastic perfectly rough grains have theirs in
// observables/rough_enskog_viscosity.hpp).
#include "roughgas/dsmc/run_spec.hpp"

#include <optional>

namespace roughgas {

struct ShearModeTheory {
    double alpha = 1, beta = -1;
    double phi = 0, chi = 1; // solid fraction and pair correlation at contact (Enskog; 0 and 1: Boltzmann)
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

// The Enskog theory above for smooth grains, 0 <= alpha <= 1, 0 <= phi < 1, chi > 0 (phi = 0 with
// chi = 1: smooth_shear_mode(alpha)). eta_star and zeta_star are over the dilute eta_0 and nu_0.
ShearModeTheory enskog_shear_mode(double alpha, double phi, double chi);

// gamma(k) per collision per particle, for k lambda = `k_lambda`.
double shear_mode_rate(const ShearModeTheory& t, double k_lambda);

// The theory of a run's cooling state when it applies: a freely cooling periodic box (no shear, walls
// or gravity) of grains of one species with constant alpha and beta; nullopt otherwise. For the
// Enskog equation (spec.enskog) enskog_shear_mode at the run's phi and chi, for smooth grains only
// (nullopt for rough ones).
std::optional<ShearModeTheory> shear_mode_theory(const RunSpec& spec);

} // namespace roughgas
