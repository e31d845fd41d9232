#pragma once
// The collisional production rates of the second- and fourth-degree moments of equal rough spheres
// (constant alpha, beta; reduced moment of inertia q) in the first Sonine approximation (Santos,
// Kremer & dos Santos, Phys. Fluids 23, 030604 (2011)):
//
//   f = f_M(c) f_M(w) [1 + a20 S2(c^2) + a02 S2(w^2) + a11 S1(c^2) S1(w^2)],
//   c = v/sqrt(2 T_tr/m),  w = omega/sqrt(2 T_rot/I),  S1(x) = 3/2 - x,  S2(x) = 15/8 - 5x/2 + x^2/2,
//
// a20, a02, a11 the cumulants of docs/model.md §5 (this f has exactly those fourth moments).
// For a one-particle function psi(c, w) the reduced production rate is
//   R_psi = -(d<psi>/dt)_coll / nu_M,   nu_M = 4 n sigma^2 sqrt(pi T_tr/m),
// at fixed T_tr and T_rot, to first order in the cumulants (the Boltzmann collision integral is
// bilinear in f; the products of two cumulants are dropped):
//   R_psi = R_psi^0 + R_psi^20 a20 + R_psi^02 a02 + R_psi^11 a11.
// The collision frequency of f is nu_M (1 - a20/16): the spins do not enter the hard-sphere rate.
//
// Closed forms. With at = (1 + alpha)/2, bt = q (1 + beta)/(2 (1 + q)) (the prefactors of the
// collision rule of docs/model.md §3 for equal spheres), br = bt/q and theta = T_rot/T_tr, let
//   a = at (1 - at) = (1 - alpha^2)/4,  b = bt (1 - bt),  c = br (1 - br),
//   X = bt^2 theta/q,  Y = bt^2/(q theta),  d = bt br = bt^2/q.
// Then (derived by Gaussian moments of the collision integrals, with n along z; the coefficients
// reproduce scripts/rough_sonine_reference.py's sympy forms identically and its quadrature to
// round-off, tests/observables/sonine_theory_test.cpp):
//   R_c2^0    = 2(a + b) - 2X                  R_c2^20 = (3/8)(a + b) + X/8
//   R_c2^02   = 0                              R_c2^11 = -X/2
//   R_w2^0    = 2c - 2Y                        R_w2^20 = -c/8 - (3/8) Y
//   R_w2^02   = 0                              R_w2^11 = c/2
//   R_c4^0    = 11(a + b) - 8(a^2 + ab + b^2) - X (11 - 8a - 16b) - 8X^2
//   R_c4^20   = [237(a + b) + 32(at + bt) - 64 at bt - 120(a^2 + ab + b^2)]/16
//               - X (41 - 24a - 48b)/16 + X^2/2
//   R_c4^02   = -4X^2                          R_c4^11 = -(3/4) X (11 - 8a - 16b) - 4X^2
//   R_w4^0    = 2c (5 - 4c) - 2Y (5 - 8c) - 8Y^2
//   R_w4^20   = -c (5 - 4c)/8 - (3/8) Y (5 - 8c) - (15/2) Y^2
//   R_w4^02   = 9c + br - 4c^2                 R_w4^11 = c (5 - 4c) - (3/2) Y (5 - 8c)
//   R_c2w2^0  = (6a + 6b + 7c + 4d - 8ac - 16bc - 16d^2)/2 - Y (9 - 8a - 16b)/2 - 4X (1 - 2c)
//   R_c2w2^20 = (18a + 18b + 29c + 12d - 24ac - 48bc - 48d^2)/32 - (3/32) Y (53 - 40a - 80b)
//               + X (1 - 2c)/4
//   R_c2w2^02 = -X (5 - 8c)/2
//   R_c2w2^11 = (18a + 18b + 21c + 12 at + 12 bt + 16 br - 12d - 24ac - 48bc - 48d^2 - 16 at br)/8
//               - 2X (1 - 2c)
// Checks: <c^2> = 3/2, so R_c2 = -(3/2)(d ln T_tr/dt)_coll/nu_M, and the Maxwellian parts are the
// cooling equations of Huthmann & Zippelius (1997) (A, B, C of observables/theory.hpp:
// R_c2^0 = 2(A - B theta), R_w2^0 = 2(C - B/theta)); at beta = -1 (bt = 0) the translational rates
// are those of smooth spheres, whose linearised a20 equation gives van Noije & Ernst's (1998) a2;
// at alpha = beta = 1 and theta = 1 every R^0 of the cooling-state equations vanishes.
namespace roughgas {

// One reduced rate, linear in the cumulants.
struct SonineRate {
    double one = 0, a20 = 0, a02 = 0, a11 = 0; // R^0, R^20, R^02, R^11
    double at(double c20, double c02, double c11) const { return one + a20 * c20 + a02 * c02 + a11 * c11; }
};

// The rates of psi = c^2, w^2, c^4, w^4 and c^2 w^2.
struct SonineRates {
    SonineRate c2, w2, c4, w4, c2w2;
};

// The closed forms above at (alpha, beta, q, theta); theta > 0, q > 0.
SonineRates sonine_rates(double alpha, double beta, double q, double theta);

} // namespace roughgas
