#pragma once
// Enskog's shear viscosity of a dense gas of elastic, perfectly rough spheres (alpha = beta = 1: a
// collision reverses the whole relative velocity of the contact points), in the first Sonine
// approximation: the trial function C_x C_y in the translational velocity alone (Pidduck 1922;
// Chapman & Cowling 1970, section 11.6, for the dilute gas; McCoy, Sandler & Dahler 1966 and
// Theodosopulu & Dahler 1974 for the dense gas's Enskog theory). One species, mass m, diameter sigma,
// moment of inertia I, q = 4 I/(m sigma^2) (2/5 for uniform spheres, 0 < q <= 2/3), solid fraction
// phi = (pi/6) n sigma^3, pair correlation at contact chi. With kappa = q/(1 + q) (the impulse on the
// grain is J = -m [(g_c.n) n + kappa g_ct], g_c the relative velocity of the contact points, g_ct its
// part tangent to the contact) and eta_0 = (5/(16 sigma^2)) sqrt(m T/pi),
//   eta/eta_0 = eta_P (1 + A phi chi)^2/chi + (768/(25 pi)) (1 + (3/4) kappa) phi^2 chi,
//   eta_P = 6 (1 + q)^2/(6 + 13 q),    A = (8/5)(1 + (3/2) kappa),
// eta_P Pidduck's dilute viscosity (the kinetic stress relaxes at chi nu_0/eta_P, nu_0 = n T/eta_0).
// Derivation (moments of the Enskog collision operator at linear order in the gradient, the
// Maxwellian in V and in the spin about the local half-vorticity, times 1 + (m/2T) c_ij V_i V_j;
// equivalent to the first Sonine approximation of the Chapman-Enskog solution): a pair a diameter
// apart meets with the relative contact velocity g_c = G + sigma E.n - (sigma/2) S x n + sigma (Omega
// - w/2) x n, G = V_i - V_j, S the sum of the spin fluctuations, E the rate of strain, w the
// vorticity and Omega the mean spin. (1) The strain part of the shift feeds the kinetic stress:
// production of n m <V_x V_y> gains -(4 pi/15) chi n^2 sigma^3 T (1 + (3/2) kappa) a (the tangential
// impulse adds the kappa term), which multiplies the kinetic flux by 1 + A phi chi. (2) The collisional
// transfer sum sigma n_i J_j of a Grad distribution carries A phi chi times its kinetic stress
// deviation (the normal impulse the 8/5, the tangential one 12 kappa/5: the same A, as Onsager's
// symmetry requires). (3) The Maxwellian's own transfer across the shifted contact gives the bulk-like
// term; the tangential impulse adds (3/4) kappa of it. The antisymmetric stress,
// -eps_ijk P_jk, is the spin production and is proportional to Omega - w/2 alone (the strain, the
// stress deviation and the collision rule are parity even): in uniform shear flow u = a y x, w = -a z,
// the mean spin relaxes, within a few collisions per grain, to Omega_z = -a/2, where the stress tensor
// is symmetric, P_xy = P_yx = -eta a with eta the above. That is the DSMC's eta* = -P*_xy/a* (the
// whole tensor, docs/model.md "Uniform shear flow") once the spin has settled; before, the flux
// along y of x-momentum exceeds eta a by the spin's share (at Omega = 0 by a third of the bulk-like
// term).
//
// Limits: phi -> 0 (chi -> 1) is Pidduck's eta_P exactly. kappa -> 0 (q -> 0, the mass at the
// centre) gives Enskog's smooth-sphere value (1 + (8/5) phi chi)^2/chi + (768/(25 pi)) phi^2 chi
// (observables/enskog_usf_theory.hpp at alpha -> 1), and eta_P -> 1; but q -> 0 is not the smooth
// gas: the tangential impulse vanishes only as kappa |g_ct| ~ sqrt(q) (the spins' speeds grow as
// 1/sqrt(q)), the spins keep exchanging energy among themselves, and their exchange with the
// translation slows as q, so the limit is a smooth gas carrying a second, separately conserved
// rotational energy (a specific heat of 3 per grain, not 3/2); the translational viscosity is the
// smooth one, the heat conduction not. Uniform spheres (q = 2/5, kappa = 2/7): eta_P = 1.05, A = 16/7,
// bulk-like coefficient (768/(25 pi)) 17/14 = 11.873 against 9.778. phi = 0.1 (Carnahan & Starling chi =
// 1.30316): eta* = 1.51196 (smooth 1.24816); phi = 0.25 (chi = 2.07407): 3.95657 (smooth 2.88158).
// Higher Sonine approximations raise the dilute smooth eta by 1.6 %. For rough spheres the trial
// function C_x C_y leaves out the spins' anisotropy J omega_x omega_y, a true tensor of the shear's
// symmetry that the tangential impulse couples to the stress: with it (a Galerkin quadrature of the
// linearized collision operator) the dilute eta is 1.065 times Pidduck's, and the DSMC's kinetic
// stress lies 5 to 7 % above eta_P (1 + A phi chi)/chi while its collisional transfer, given that
// kinetic stress, follows A phi chi times it plus the bulk-like term (docs/validation.md). In the
// dense gas the anisotropy enters only through the kinetic stress (the shifted contact neither
// produces it nor does it carry momentum across the contact, both zero within a quadrature's noise),
// so eta_P -> 1.0652 eta_P in the formula gives 1.6005 and 4.1142 at phi = 0.1 and 0.25.

namespace roughgas {

struct RoughEnskogViscosity {
    double kinetic = 0;     // eta_P (1 + A phi chi)/chi: the kinetic stress's share, over eta_0
    double collisional = 0; // the collisional transfer's share, eta_P A phi (1 + A phi chi) + bulk-like term
    double total = 0;       // eta/eta_0
};

// Throws std::invalid_argument unless q in (0, 2/3], phi in [0, 1), chi > 0 (all finite).
RoughEnskogViscosity rough_enskog_viscosity(double q, double phi, double chi);

} // namespace roughgas
