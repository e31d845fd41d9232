#pragma once
// The steady states of the driven two-temperature equations (observables/driven_theory.hpp), in the
// Maxwellian approximation (exact for the Maxwell kernel).
//
// Equal spheres (one species; A, B, C, G of observables/theory.hpp) under white noise of strength
// xi^2 and share eps. In the steady state
//   G T_tr^{3/2} (A - B theta) = (1 - eps) m xi^2,     G T_tr^{3/2} (C theta - B) = eps m xi^2.
// eps = 0: the spins get no energy but from collisions, so dT_rot/dt = 0 alone fixes
//   theta = B/C = eta/(1 - eta/q) = q (1 + beta)/(1 + 2q - beta)
// (eta = q(1 + beta)/(2(1 + q)), so eta/q = (1 + beta)/(2(1 + q)) and 1 - eta/q = (1 + 2q - beta)/(2(1 + q))):
// independent of alpha, 1 for perfectly rough spheres (beta = 1) whatever q, 0 for smooth ones;
// then T_tr^{3/2} = m xi^2/(G (A - B theta)). eps > 0: the ratio of the two equations is linear in theta,
//   theta = [(1 - eps) B + eps A]/[(1 - eps) C + eps B],
// and their sum gives T_tr^{3/2} = m xi^2/(G [A - B + (C - B) theta]) (the injected power m xi^2 equals the
// collisional loss of T_tr + T_rot). Smooth spheres (beta = -1, B = C = 0): T_tr^{3/2} = (1 - eps) m xi^2/(G A);
// T_rot stays at its initial value (eps = 0: theta undefined, NaN) or grows without bound (eps > 0:
// theta = +infinity). (Rough spheres under this thermostat: Vega Reyes & Santos 2015, Torrente et al.
// 2019; the closed forms here follow from the equations above.)
// The steady state in reduced variables does not depend on xi: T_tr scales as (m xi^2)^{2/3}.
//
// Equal spheres in a Langevin bath at T_b (frictions gamma, gamma_rot): dT_rot/dt = 0 gives T_rot as a
// function of T_tr, T_rot = (G B T_tr^{3/2} + 2 gamma_rot T_b)/(G C T_tr^{1/2} + 2 gamma_rot), and T_tr is
// the root of
//   f(T) = G T^{1/2} (-A T + B T_rot(T)) + 2 gamma (T_b - T)
// in (0, T_b]: f > 0 as T -> 0 and f(T_b) <= 0, since A >= B (A - B = (1 - alpha^2)/4 + eta (1 - beta)/2)
// and T_rot(T_b) <= T_b (B <= C: eta <= q/(1 + q)). Elastic grains (alpha = 1, beta = +-1): T_tr = T_rot
// = T_b (with gamma_rot = 0 and beta = -1 T_rot is that of the start: NaN here).
//
// Any gas (mixtures, the Maxwell kernel, per-species drives): Newton's method in ln T (to 1e-13) from
// a guess (per species the equal-sphere closed form with its own pair's alpha, beta, or the bath's
// temperature); where it does not converge, the equations are relaxed in time (HcsTrajectory with the
// drives held at their last values) by some 20 collision or friction times and Newton's method is
// tried again, up to 200 times. Mixtures do not
// share their temperatures (non-equipartition: Barrat & Trizac 2002 for smooth grains under white
// noise), which T_tr_ratio reports.
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/theory.hpp"

#include <optional>
#include <vector>

namespace roughgas {

struct DrivenSteadyState {
    HcsTemperatures T;            // per species; a T_rot that nothing sets (see above) is NaN
    double T_tr = 0, T_rot = 0;   // the mixture's (HcsTheory::mixture_T_tr, mixture_T_rot)
    double theta = 0;             // T_rot/T_tr of the mixture
    std::vector<double> theta_s;  // T_rot,s/T_tr,s
    std::vector<double> T_tr_ratio; // T_tr,s/T_tr: 1 for every species of a gas in equipartition
    // Langevin: T_tr,s/T_b,s and T_rot,s/T_b,s (1 for an elastic gas); NaN under white noise.
    std::vector<double> T_tr_over_bath, T_rot_over_bath;
    double zeta_star = 0; // the collisions' reduced cooling rate there (reduced_cooling_rate)
};

// The steady state under the thermostat's final drives (ThermostatSpec's schedules held at their
// last values). nullopt where there is none: an elastic gas under white noise heats without bound,
// as do spins fed by white noise (eps > 0) that no collision couples to the translation; and where
// the relaxation or Newton's method does not converge. Throws std::invalid_argument for a thermostat
// check_thermostat refuses.
std::optional<DrivenSteadyState> driven_steady_state(const HcsTheory& theory, const ThermostatSpec& thermostat);

// --- equal spheres: the closed forms above ---
struct EqualSphereSteadyState {
    double T_tr = 0, T_rot = 0, theta = 0;
};
// theta under white noise of share eps (above); NaN for beta = -1, eps = 0, +infinity for beta = -1, eps > 0.
double white_noise_steady_theta(double alpha, double beta, double q, double rotational_share = 0);
EqualSphereSteadyState white_noise_steady_state(double alpha, double beta, double q, double mass, double sigma,
                                                double density, double strength, double rotational_share = 0);
EqualSphereSteadyState langevin_steady_state(double alpha, double beta, double q, double mass, double sigma,
                                             double density, double bath, double friction, double rotational_friction);

} // namespace roughgas
