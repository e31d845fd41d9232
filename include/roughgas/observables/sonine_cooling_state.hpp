#pragma once
// The homogeneous cooling state of equal rough spheres (constant alpha, beta; reduced moment of
// inertia q) in the first Sonine approximation (Santos, Kremer & dos Santos, Phys. Fluids 23,
// 030604 (2011)), with the reduced rates of observables/sonine_rates.hpp.
//
// In the scaled cooling state theta and the cumulants are constant: both temperatures decay at
// one rate and the fourth moments in the variables scaled by the decaying thermal speeds stay put,
//   R_c2 = R_w2,                                               (theta)
//   R_c4 = 5 R_c2 (1 + a20),  R_w4 = 5 R_w2 (1 + a02),  R_c2w2 = (3/2)(R_c2 + R_w2)(1 + a11)
// (<c^4> = (15/4)(1 + a20), <c^2> = 3/2, so d<c^4>/dt = 2 <c^4> d ln T_tr/dt, etc.). Linearised in
// the cumulants: the products of two cumulants in the last three equations are dropped (the
// rates are already linear in them), so at fixed theta the cumulants solve a 3 x 3 linear system
// M a = v. theta itself is not expanded about the Maxwellian value: it is the root of R_c2 - R_w2 (at the
// cumulants of the linear system) on the branch continued from the Maxwellian theta*
// (observables/theory.hpp theta_fixed_point): the root nearest to it in ln theta with no pole of
// the linear system (det M = 0) in between. Then
//   zeta* = (2/3) R_c2 / (1 - a20/16),
// the decay of T_tr per collision per particle (moments.csv's zeta_star: the collision frequency of
// the Sonine distribution is nu_M (1 - a20/16)).
//
// Smooth spheres (beta = -1) have no scaled theta (T_rot stays while T_tr decays): the state is that
// of van Noije & Ernst (1998), a20 = 16(1 - alpha)(1 - 2 alpha^2)/(81 - 17 alpha + 30 alpha^2 (1 - alpha))
// (the a20 equation alone), theta = +infinity (NaN at alpha = 1, as theta_fixed_point), a02 and a11
// NaN (the spins keep their initial distribution). beta -> -1 is a singular limit (Santos, Kremer &
// dos Santos 2011): theta grows like 1/(1 + beta)^2, and a20 tends to a value other than van Noije
// & Ernst's.
//
// Where the approximation fails: near the smooth limit the linear system's determinant crosses zero
// near the root (at alpha = 0.9, q = 0.4: no root on the branch at beta = -0.9; at beta = -0.8 a root
// with a02 = -5.8) and strong inelasticity with little roughness gives large cumulants (alpha = 0.5,
// beta = -0.5: a02 = 19.9, theta 61 % below the Maxwellian): a first Sonine approximation describes
// small cumulants only.
#include <optional>

namespace roughgas {

struct SonineCoolingState {
    double theta = 0; // T_rot/T_tr
    double a20 = 0, a02 = 0, a11 = 0;
    double zeta_star = 0; // -d ln T_tr per collision per particle
};

// nullopt where the branch has no root, and where the root's a20 or a02 is below -2/5, which no
// distribution has (<x^2> >= <x>^2 for x = c^2: (15/4)(1 + a20) >= 9/4). Throws
// std::invalid_argument for alpha outside [0, 1], beta outside [-1, 1] or q <= 0.
std::optional<SonineCoolingState> sonine_cooling_state(double alpha, double beta, double q);

} // namespace roughgas
