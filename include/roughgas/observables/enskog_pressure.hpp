#pragma once
// The pressure of a uniform gas in the Enskog equation (Enskog 1922; Garzo & Dufty 1999 for inelastic
// grains): p = p_kin + p_coll, p_kin = sum_s n_s T_tr,s and the collisional transfer
//   p_coll = (pi/3) sum_a sum_b n_a n_b chi_ab sigma_ab^3 m_ab (1 + alpha_ab) (T_tr,a/m_a + T_tr,b/m_b),
// m_ab = m_a m_b/(m_a + m_b), the sums over ordered species pairs. Derivation: a collision moves the
// normal impulse m_ab (1 + alpha) g_n (docs/model.md §3; the tangential one is normal to sigma n and
// adds nothing to the trace) across sigma_ab n; collisions of an a grain with b grains at the relative
// velocity g and direction n happen at the rate density n_a n_b chi_ab sigma_ab^2 (g.n) over the
// approaching hemisphere, whose integral of (g.n)^2 is (2 pi/3) g^2, and <g^2> = 3 (T_a/m_a + T_b/m_b)
// for any uncorrelated velocities of zero mean: p_coll is exact for every distribution, given the
// temperatures (one species: p = n T [1 + 2 (1 + alpha) phi chi], phi = (pi/6) n sigma^3; elastic:
// Carnahan & Starling's p/(nT) = (1 + phi + phi^2 - phi^3)/(1 - phi)^3). beta does not enter.
#include "roughgas/observables/theory.hpp"

namespace roughgas {

// The kinetic part sum_s x_s n T_tr,s at the temperatures T.
double enskog_kinetic_pressure(const HcsTheory& theory, const HcsTemperatures& T);
// The collisional part above.
double enskog_collisional_pressure(const HcsTheory& theory, const HcsTemperatures& T);

// Carnahan & Starling's equation of state of elastic hard spheres, p/(n T) at the solid fraction phi.
inline double carnahan_starling_compressibility(double phi) {
    return (1 + phi + phi * phi - phi * phi * phi) / ((1 - phi) * (1 - phi) * (1 - phi));
}

} // namespace roughgas
