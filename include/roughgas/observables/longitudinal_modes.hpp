#pragma once
// The longitudinal (heat and sound) modes of the homogeneous cooling state of smooth inelastic hard
// spheres in Navier-Stokes hydrodynamics: dilute gas, constant normal restitution alpha, the
// transport coefficients of the first Sonine approximation with the fourth cumulant a2, as for the
// shear mode (observables/shear_mode.hpp). The linear stability analysis of the cooling state is
// that of Brey, Dufty, Kim & Santos 1998 and the dilute limit of Garzo 2005; the heat flux
// coefficients are those of Brey et al. 1998 and Garzo & Dufty 1999; a2 of van Noije & Ernst 1998.
//
// Hydrodynamics (d = 3, p = n T; the bulk viscosity vanishes in the Boltzmann limit):
//   dn/dt + div(n u) = 0,
//   m n (du/dt + u.grad u) = -grad p + div[eta (grad u + grad u^T - (2/3) div u I)],
//   (3/2) n (dT/dt + u.grad T) = -P:grad u - div q - (3/2) zeta n T,   q = -kappa grad T - mu grad n,
// with zeta proportional to n sqrt(T). Linearised about the cooling state (n, u = 0, T(t) with
// dT/dt = -zeta T) for a mode exp(i k x) with the flow along k, in the fields
// y = (rho, theta, w) = (delta n/n, delta T/T, u_x/sqrt(T/m)), scaled by the cooling state's own T(t)
// so that the coefficients are constant, and per collision per particle s (ds/dt = nu_c):
//   dy/ds = M y,
//           | 0                    0                    -i c            |
//   M = f * | -2 z - P mu* x^2     -z - P kappa* x^2    -(2/3) i c      |
//           | -i c                 -i c                 z - E eta* x^2  |
// x = k lambda, c = sqrt(pi/8) x = k sqrt(T/m)/nu_M, z = (2/5) zeta* = zeta/(2 nu_M),
// f = nu_M/nu_c = 1/(1 - a2/16), P = 25 pi/64 (2 kappa_0 k^2/(3 n nu_M) = P x^2),
// E = 5 pi/24 (4 eta_0 k^2/(3 m n nu_M) = E x^2); lambda, nu_M, nu_c, eta_0, zeta*, eta* as in
// shear_mode.hpp. The cooling enters three times: the loss zeta n T ~ n^2 T^(3/2) per volume puts
// -zeta (rho + (3/2) theta) into dtheta/dt, the division by the decaying T adds +zeta theta, and
// the division by the decaying thermal speed adds +zeta w/2.
// The heat flux (first Sonine; kappa_0 = (15/4) eta_0/m = (75/(64 sigma^2)) sqrt(T/(pi m)) is the
// elastic first Sonine conductivity, 2.5 % below the converged 1.025218 kappa_0):
//   nu_kappa* = (1 + alpha)/3 [1 + 33 (1 - alpha)/16 + (19 - 3 alpha) a2/512],
//   kappa* = kappa/kappa_0 = (2/3)(1 + 2 a2)/(nu_kappa* - 2 zeta*),
//   mu* = n mu/(T kappa_0) = [zeta* kappa* + (2/3) a2]/(nu_kappa* - (3/2) zeta*).
// kappa T and mu n both scale as T^(3/2), so the cooling at fixed gradients gives -(3/2) zeta*;
// grad ln T itself decays at d zeta/d ln T = zeta/2 (the further -zeta*/2 of kappa*), and the
// density dependence of the cooling, d zeta/d ln n = zeta, feeds kappa* into mu*; a2 enters
// through the fourth moment of the cooling state's distribution (Brey et al. 1998; Garzo & Dufty
// 1999 with their c = 2 a2).
//
// The eigenvalues. At k = 0, M is triangular: 0 (theta = -2 rho, the perturbation that leaves
// n sqrt(T), hence zeta, unchanged: it only shifts the clock of the cooling), -zeta/(2 nu_c) (a
// temperature perturbation: the hotter gas cools faster) and +zeta/(2 nu_c) (a uniform flow keeps
// its momentum while the thermal speed decays). The first two merge into the sound pair, complex
// for k lambda above about 0.3 zeta* at weak dissipation (0.023 at alpha = 0.9); the third, real, is the heat
// mode: it starts as the flow and crosses zero where det M = f^3 c^2 [z - P (kappa* - mu*) x^2] vanishes,
//   (k_par lambda)^2 = (128/(125 pi)) zeta*/(kappa* - mu*),
//   L_par = 2 pi/k_par = L_c sqrt(5 (kappa* - mu*)/(2 eta*))          (L_c of shear_mode.hpp):
// a periodic box longer than L_par forms clusters (the longitudinal, density instability), one
// longer than L_c vortices. For alpha > 0.3747, kappa* - mu* > 2 eta*/5 and L_par > L_c: the shear
// mode goes unstable first, in the shorter box (alpha = 0.9: L_c = 25.30 lambda, L_par = 38.23
// lambda). Below alpha = 0.3747 this theory reverses the order, and below alpha = 0.1878 its mu*
// exceeds kappa* and the heat mode grows at every k (critical_length = 0): at such strong
// dissipation the first Sonine heat flux coefficients disagree with simulations (Garzo, Santos &
// Montanero 2007).
// Checks: elastic grains (a2 = zeta* = mu* = 0, kappa* = eta* = 1): the heat mode is
// -D_T k^2/nu_M = -(15 pi/64) x^2 (D_T = 2 kappa_0/(5 n)), the sound modes +-i sqrt(5/3) c - Gamma x^2:
// the adiabatic speed sqrt(5 T/(3 m)) and Gamma x^2 = [(4/3) eta_0/(m n) + (2/3) D_T] k^2/(2 nu_M),
// Gamma = 35 pi/192; as alpha -> 1, L_par -> sqrt(5/2) L_c ~ 17.05 lambda/sqrt(1 - alpha^2).
//
// Rough grains (constant alpha and beta > -1, moment of inertia q m R^2): the scheme of Kremer,
// Santos & Garzo (2014), Chapman-Enskog to first order about the cooling state in the
// two-temperature Maxwellian approximation (theta = T_rot/T_tr at its fixed point, no cumulants),
// each transport coefficient in the first Sonine approximation; zeta*, theta, eta* as in
// rough_shear_mode. The temperature is T = (T_tr + T_rot)/2 (energy density 3 n T), p = n T_tr =
// 2 n T/(1 + theta); all rates over nu_0 = n T_tr/eta_0 at T_tr, at = (1 + alpha)/2,
// bt = q (1 + beta)/(2 (1 + q)), A = (1 - alpha^2)/4 + bt (1 - bt), B = bt^2/q, C = (bt/q)(1 - bt/q).
// The gas cools at zeta = zeta^(0) + zeta_U div u and the pressure tensor has the bulk part
// -eta_b div u (eta_b = eta_b* eta_0):
//   compression heats the translational degrees first, so T_tr/T_rot lags its fixed point. The scalar
//   part of the first-order distribution is the two-temperature Maxwellian's shift
//   delta T_tr = -delta T_rot = -eta_b* T_tr div u/nu_0, whose collisional relaxation has the rates
//   d_t = (d/dT_tr - d/dT_rot)(dT_tr/dt)/nu_0 = (5/6)[B (theta - 2) - 3 A],
//   d_r = (d/dT_tr - d/dT_rot)(dT_rot/dt)/nu_0 = (5/6)[3 B + C (2 - theta)];
//   with the source -(2/3) theta/(1 + theta) T_tr div u of the pressure work and the cooling state's
//   own decay of the shift (-zeta/2):
//   eta_b* = (2/3) theta/[d_r - theta d_t - (1 + theta) zeta*/2],
//   zeta_U = (d_t + d_r) eta_b*/(1 + theta)   (the change of the cooling with the split: at q = 2/5
//   negative for alpha <= 0.9, a compressed gas cooling faster, but positive at alpha = 1, beta < 1).
// The heat flux q = q_tr + q_rot = -kappa grad T - mu grad n, trial functions V (m V^2/(2 T_tr) - 5/2)
// and V (I w^2/(2 T_rot) - 3/2) times the Maxwellian; the two fluxes relax as
// d(q_tr, q_rot)/dt = -nu_0 N (q_tr, q_rot) with
//   N_tt = [41 (at + bt) - 33 (at^2 + bt^2) - 16 at bt - 7 bt^2 theta/q]/12,   N_tr = -(25/18) bt^2/q,
//   N_rt = -(5/12)(bt/q)[bt theta/q + 3 bt - theta],
//   N_rr = (5/18)[3 (at + bt) - (bt/q)(4 at + 6 bt - 7) - 3 bt^2/q^2],
// and, as for smooth grains (the same -2 zeta and -(3/2) zeta),
//   kappa* = kappa/kappa_0 = (8/(15 (1 + theta))) (1, 1).(N - 2 zeta* I)^-1 (5/2, (3/2) theta),
//   mu* = n mu/(T kappa_0) = zeta* (1, 1).(N - (3/2) zeta* I)^-1 k,
//   k = (8/(15 (1 + theta))) (N - 2 zeta* I)^-1 (5/2, (3/2) theta)   (kappa* = k_tr + k_rot),
// kappa_0 = (15/4) eta_0/m at T_tr. The fields are now y = (delta n/n, delta T/T, u_x/sqrt(T_tr/m)),
// s counts collisions per particle at T_tr (nu_M = nu_c: no a2), c = sqrt(pi/8) x, z = (2/5) zeta*:
//       | 0                        0                        -i c                          |
//   M = | -2 z - (P/2) mu* x^2     -z - (P/2) kappa* x^2    -i [2/(3 (1 + theta)) + zeta_U] c |
//       | -i c                     -i c                     z - (E eta* + (5 pi/32) eta_b*) x^2 |
// (the energy density 3 n T halves the conduction term and carries the work p div u/(3 n T); the
// bulk viscosity adds to (4/3) eta; zeta_U div u is the first-order cooling). At k = 0 the
// eigenvalues are again 0 and -+zeta/(2 nu_c); det M = c^2 [z - (P/2)(kappa* - mu*) x^2] puts the
// heat mode's zero at
//   (k_par lambda)^2 = (256/(125 pi)) zeta*/(kappa* - mu*),   L_par = L_c sqrt(5 (kappa* - mu*)/(4 eta*)),
// independent of eta_b and zeta_U. At alpha = 0.9, q = 2/5: L_par = 22.8, 19.0, 20.7, 48.8 lambda for
// beta = -0.5, 0, 0.5, 1 (L_c = 17.1, 15.3, 16.7, 36.7 lambda): the shear mode still goes unstable first.
// Checks: the elastic perfectly rough gas (alpha = beta = 1, theta = 1) does not cool (zeta_U = mu* = 0)
// and has the first approximations of Pidduck's gas (Chapman & Cowling 1970):
//   kappa* = 12 (1 + q)^2 (37 + 151 q + 50 q^2)/(25 (12 + 75 q + 101 q^2 + 102 q^3)),
//   eta_b* = (1 + q)^2/(10 q);
// its sound travels at the adiabatic speed of six degrees of freedom, sqrt(4 T/(3 m)) (gamma = 4/3),
// damped at {[(4/3) eta + eta_b]/(m n) + (1/3) kappa/(4 n)} k^2/2, and its heat mode decays at
// kappa k^2/(4 n). For bt = 0 (beta = -1) N_tr = N_rt = 0 and N_tt is the smooth nu_kappa* with a2 = 0;
// beta = -1 itself is the smooth theory above (the rough formulas do not tend to it, as for the shear mode).
#include "roughgas/observables/shear_mode.hpp"

#include <Eigen/Dense>

#include <array>
#include <complex>
#include <optional>

namespace roughgas {

struct LongitudinalModeTheory {
    ShearModeTheory shear;          // alpha, beta, theta, a2, zeta*, eta*, L_c (shear_mode.hpp)
    double kappa_star = 1;          // thermal conductivity over kappa_0
    double mu_star = 0;             // coefficient of grad n in the heat flux over T kappa_0/n
    double bulk_viscosity_star = 0; // eta_b/eta_0 (rough grains; 0 for smooth ones)
    double zeta_u = 0;          // first-order cooling zeta_U: zeta = zeta^(0) + zeta_U div u (rough grains)
    double critical_length = 0; // L_par / lambda (infinite at alpha = 1, 0 where mu* >= kappa*)
};

// The theory above for 0 <= alpha <= 1.
LongitudinalModeTheory smooth_longitudinal_modes(double alpha);

// The theory for rough grains, -1 <= beta <= 1 (beta = -1: smooth_longitudinal_modes(alpha)), q the
// reduced moment of inertia; theta is shear.theta.
LongitudinalModeTheory rough_longitudinal_modes(double alpha, double beta, double q);

// The theory of a run's cooling state where it applies (as shear_mode_theory: a freely cooling
// periodic box of grains of one species with constant alpha and beta, of the Boltzmann equation:
// the Enskog gas's heat and sound modes are not given here); nullopt otherwise.
std::optional<LongitudinalModeTheory> longitudinal_mode_theory(const RunSpec& spec);

// M at k lambda = `k_lambda`: d(delta n/n, delta T/T, u_x/sqrt(T_tr/m))/ds = M (...), s in collisions
// per particle (for rough grains T = (T_tr + T_rot)/2 and s at T_tr, as above).
Eigen::Matrix3cd longitudinal_mode_matrix(const LongitudinalModeTheory& t, double k_lambda);

// The eigenvalues of M, per collision per particle. The heat mode is the real eigenvalue that
// continues +zeta/(2 nu_c) of k = 0: the largest of three real ones, or the real one beside a
// complex pair. sound[0] and sound[1] are the other two: a conjugate pair with Im sound[0] > 0,
// or two real ones, sound[0] > sound[1]. The labels follow the branches through the hydrodynamic
// range; where the sound pair turns real again (overdamped, k lambda of order 1 and beyond
// Navier-Stokes: 1.35 at alpha = 0.9), the largest of the three real eigenvalues is called heat
// even where it continues the sound pair.
// Computed from D^-1 M D with D = diag(1, 1, i), a real matrix (the flow is a quarter period out
// of phase with density and temperature), so that the real eigenvalues come out exactly real.
struct LongitudinalModeRates {
    std::complex<double> heat;
    std::array<std::complex<double>, 2> sound;
};
LongitudinalModeRates longitudinal_mode_rates(const LongitudinalModeTheory& t, double k_lambda);

// The largest real part of the three eigenvalues: positive (the mode grows) for k lambda below
// 2 pi/critical_length, negative above.
double longitudinal_max_rate(const LongitudinalModeTheory& t, double k_lambda);

} // namespace roughgas
