#pragma once
// Smooth spheres (beta = -1) heated by white noise (eps = 0) in the first Sonine approximation:
// van Noije & Ernst, Granular Matter 1, 57 (1998); compared with the DSMC by Montanero & Santos,
// Granular Matter 2, 53 (2000).
//
// f(c) = f_M(c) [1 + a2 S2(c^2)], c = v/sqrt(2T/m), S2 of observables/sonine_rates.hpp. The kicks act as
// (xi^2/2) times the Laplacian in v, so d<|v|^2>/dt = d xi^2 and d<|v|^4>/dt = 2(d + 2) xi^2 <|v|^2> from the
// kicks alone; in the steady state the collisions take exactly that away, and their ratio is
//   (d<|v|^4>/dt)_coll = (2(d + 2)/d) <|v|^2> (d<|v|^2>/dt)_coll,   i.e. R_c4 = 5 R_c2 in d = 3
// (rates of observables/sonine_rates.hpp). In the cooling state the same ratio carries a factor
// (1 + a2) (both moments decay with T: R_c4 = 5 R_c2 (1 + a2)); here it does not, because the kicks
// feed the fourth moment in proportion to the second. With the rates linear in a2 (the a2^2 terms of the
// collision integral dropped) the equation is linear in a2. At d = 3, with the smooth rates
// R_c2 = 2a + (3/8) a a2, R_c4 = 11a - 8a^2 + [(237a + 32 at - 120a^2)/16] a2 (a = (1 - alpha^2)/4,
// at = (1 + alpha)/2; sonine_rates.hpp at beta = -1) it gives
//   a2 = 16 a (1 - 2 alpha^2)/(207a + 16(1 + alpha) - 120 a^2)
//      = 16 (1 - alpha)(1 - 2 alpha^2)/(241 - 177 alpha + 30 alpha^2 (1 - alpha)),
// van Noije & Ernst's
//   a2 = 16 (1 - alpha)(1 - 2 alpha^2)/(73 + 56 d - 24 d alpha - 105 alpha + 30 (1 - alpha) alpha^2)
// at d = 3. In d dimensions van Noije & Ernst's collisional moments mu_p = -int c^p J[f, f], linear in a2,
// have the ratios
//   mu_2 ~ 1 + 3 a2/16,   mu_4 ~ (d + 3/2 + alpha^2) + K a2,   K = (3/32)(10d + 39 + 10 alpha^2) + (d - 1)/(1 - alpha)
// (at d = 3 these are R_c2 and R_c4 above: R_c4^0/R_c2^0 = (9 + 2 alpha^2)/2, R_c4^20/R_c2^0 = K), and the
// steady state mu_4 = (d + 2) mu_2 (the kicks' ratio with <c^2> = d/2) gives
//   a2 = (1/2 - alpha^2)/(K - 3(d + 2)/16),
// which is the formula above; the cooling state's mu_4 = (d + 2)(1 + a2) mu_2 gives from the same K their
//   a2 = 16 (1 - alpha)(1 - 2 alpha^2)/(9 + 24d - (41 - 8d) alpha + 30 alpha^2 (1 - alpha))
// (observables/sonine_cooling_state.hpp at d = 3); tests/observables/white_noise_sonine_test.cpp checks
// all three. At alpha = 0.9, d = 3: a2 = -0.0118 (the cooling state's a2 is -0.0146: the noise keeps
// the distribution closer to the Maxwellian). a2 = 0 at alpha = 1/sqrt(2).
//
// The cooling rate of this f is the Maxwellian one times (1 + 3 a2/16) (in any d; R_c2 above):
//   zeta(T) = G A sqrt(T) (1 + 3 a2/16),   A = (1 - alpha^2)/4,  G = (16/3) n sigma^2 sqrt(pi/m),
// and the steady state m xi^2 = zeta(T) T gives T = [m xi^2/(G A (1 + 3 a2/16))]^{2/3}: the Maxwellian
// steady temperature times (1 + 3 a2/16)^{-2/3}. Per collision (frequency nu_M (1 - a2/16), nu_M = 4 n
// sigma^2 sqrt(pi T/m)): zeta* = ((1 - alpha^2)/3)(1 + 3 a2/16)/(1 - a2/16).
//
// Only this linear ansatz is implemented. Keeping the a2^2 terms of the collision integral (the
// "nonlinear" first Sonine approximation) makes the equation quadratic in a2, a correction of
// relative order a2 (|a2| < 0.03 for alpha >= 0.5); it is not implemented.
namespace roughgas {

// van Noije & Ernst's steady a2 in `dimension` dimensions (2 or 3), alpha in [0, 1].
double white_noise_a2(double alpha, int dimension = 3);

struct WhiteNoiseSonineState {
    double a2 = 0;
    double T_tr = 0;      // the steady temperature with the Sonine cooling rate
    double zeta_star = 0; // zeta per collision of the Sonine distribution
};
// d = 3, smooth spheres of mass m, diameter sigma at density n, white noise of strength xi^2 (eps = 0).
WhiteNoiseSonineState white_noise_sonine_state(double alpha, double mass, double sigma, double density,
                                               double strength);

} // namespace roughgas
