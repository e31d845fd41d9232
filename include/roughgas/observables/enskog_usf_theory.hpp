#pragma once
// The steady uniform shear flow (USF) of the Enskog equation for inelastic SMOOTH hard spheres (one
// species, mass m, diameter sigma, constant normal restitution alpha, solid fraction
// phi = (pi/6) n sigma^3, pair correlation at contact chi) in Grad's approximation.
//
// Flow u = a y x. In the frame moving with u the steady state is uniform in the peculiar velocity V.
// A pair i, j at contact has n = (r_i - r_j)/sigma; the partner's peculiar velocity seen at r_i is
// V_j - a sigma n_y x, so the relative velocity entering the collision is g = V_i - V_j + a sigma n_y x.
// Pairs collide at the rate density chi sigma^2 Theta(-g.n) |g.n| f(V_i) f(V_j) per solid angle of n
// (full sphere, ordered pairs), and i receives the impulse J = (m/2)(1 + alpha)|g.n| n.
//
// Balances (P^k_ij = n m <V_i V_j>, 3 n T = tr P^k defines T):
//   0 = -a (delta_ix P^k_yj + delta_jx P^k_yi) + Lambda_ij,   Lambda_ij = production of n m <V_i V_j>,
// i.e. xx: Lambda_xx = 2 a P^k_xy, yy: Lambda_yy = 0, zz: Lambda_zz = 0, xy: Lambda_xy = a P^k_yy.
// Their trace is the energy balance: tr Lambda = -2 a P^c_xy - 3 n T zeta (the shifted relative velocity
// makes collisions do the work -a P^c_xy; zeta ~ 1 - alpha^2 is the inelastic loss), so the viscous
// heating -a (P^k_xy + P^c_xy) of the total stress balances n T zeta.
// The collisional transfer P^c_ij (flux along i of j momentum) is the rate of sigma n_i J_j per volume
// (each unordered pair once); at a = 0 its trace over 3 is 2 (1 + alpha) phi chi n T.
//
// Grad's approximation: f = f_M [1 + (m/2T) c_ij V_i V_j], c = P^k/(nT) - I (traceless; the heat flux
// vanishes by symmetry). Lambda and P^c are kept LINEAR in c (the product f(V_i) f(V_j) loses its c c
// term, of the order of the fourth cumulants Grad's f already drops) and EXACT in the shear shift
// a sigma: averaging f_M(V_i) f_M(V_j) over the centre-of-mass velocity and the relative velocity normal
// to n leaves one Gaussian integral over w = (V_i - V_j).n, variance 2T/m, cut at g.n < 0 by the shift
// b = a sigma n_x n_y. These are closed forms in erfc(b/v0) and exp(-(b/v0)^2), v0 = 2 sqrt(T/m); the
// remaining integral over n (b depends on n) is done by Gauss-Legendre in n_z times the trapezoid rule
// in the azimuth, converged to ~1e-13 (the integrand is entire in n). The shift is not small in dense
// steady states (a sigma/sqrt(T/m) ~ 10.8 phi a*, 2.3 at phi = 0.25, alpha = 0.5): truncating the moments
// at (a sigma)^2 and c a sigma would move eta* there by -11% and a* by +7%.
//
// Limits: phi -> 0 is the Boltzmann Grad USF, Lambda = -n T nu chi [beta c + zeta* I] with
// beta = (1 + alpha)(3 - alpha)/4, zeta* = (5/12)(1 - alpha^2), whose steady state is
// a*^2 = 3 chi^2 zeta* beta^2/(2 (beta - zeta*)), eta* = (beta - zeta*)/(chi beta^2),
// P*_yy = P*_zz = 1 - zeta*/beta. alpha -> 1 (a -> 0) gives Enskog's Navier-Stokes shear viscosity in the
// first Sonine approximation, eta/eta_0 = (1 + (8/5) phi chi)^2/chi + (768/(25 pi)) phi^2 chi.
//
// Reduced variables: nu = (16/5) n sigma^2 sqrt(pi T/m) (the dilute gas's p/eta_0, no chi), a* = a/nu,
// P*_ij = P_ij/(nT), eta* = -P*_xy/a* with P = P^k + P^c, N1* = P*_xx - P*_yy, N2* = P*_yy - P*_zz.
//
// References: Lun, Savage, Jeffrey & Chepurniy (1984) (the structure: kinetic and collisional stresses
// of sheared inelastic spheres); Garzo & Dufty (1999) (Enskog transport of inelastic hard spheres);
// Montanero, Garzo, Santos & Brey (1999) and Santos, Garzo & Dufty (2004) (Enskog USF, Grad's method
// and simulations).

namespace roughgas {

// A symmetric tensor of USF's symmetry (xz = yz = 0), in units of n T.
struct UsfTensor {
    double xx = 0, yy = 0, zz = 0, xy = 0;
};

// Lambda/(n T nu) and P^c/(n T) at the reduced shear rate a* for the Grad distribution whose kinetic
// pressure tensor is `kinetic` (P^k/(nT), trace 3).
struct EnskogUsfMoments {
    UsfTensor production;
    UsfTensor collisional;
};

// Throws std::invalid_argument unless alpha in [0, 1], phi in [0, 1), chi > 0, a* >= 0 (all finite)
// and tr kinetic = 3 within 1e-9.
EnskogUsfMoments enskog_usf_collisional_moments(double alpha, double phi, double chi, double a_star,
                                                const UsfTensor& kinetic);

struct EnskogUsfState {
    double a_star = 0;   // the steady a/nu
    double eta_star = 0; // -P*_xy/a*
    UsfTensor kinetic, collisional, total;
    double N1 = 0, N2 = 0; // of the total tensor
};

// The steady state (the root a* > 0 of the energy balance, the other balances solved for c).
// Throws std::invalid_argument unless alpha in [0, 1) (elastic spheres have no steady shear state),
// phi in [0, 1), chi > 0, all finite.
EnskogUsfState enskog_usf_grad(double alpha, double phi, double chi);

} // namespace roughgas
