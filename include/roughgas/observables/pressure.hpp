#pragma once
// The kinetic pressure tensor, the mean spin and the reduced quantities of uniform shear flow
// in the convention of the USF literature (e.g. Montanero & Garzó, Granular Matter 4,
// 17 (2002); Santos, Garzó & Dufty, PRE 69, 061303 (2004)):
//
//   P_ij = (1/V) sum_k m_k V_k,i V_k,j            kinetic pressure tensor (dilute gas: no collisional part)
//   Omega = sum_k J_k omega_k / sum_k J_k          mean spin (angular-momentum weighted)
//   nu = p/eta_0 = (16/5) n sigma^2 sqrt(pi T/m)   equal spheres; eta_0 = (5/(16 sigma^2)) sqrt(m T/pi),
//                                                  the first-Sonine elastic hard-sphere shear viscosity
//   a* = a/nu,  P*_ij = P_ij/(n T),  eta* = -P*_xy/a*,  N1* = P*_xx - P*_yy,  N2* = P*_yy - P*_zz
//
// with T = T_tr (docs/model.md §5), p = n T. For equal spheres nu = (4/5) nu_c, nu_c = 4 n sigma^2
// sqrt(pi T/m) the Maxwellian collision frequency. Mixtures: nu = (4/5) nu_c with nu_c the
// Maxwellian collision frequency per grain, averaged over the species, all at the mixture's T:
//   nu_c = sum_ab x_a x_b n sigma_ab^2 sqrt(8 pi T/m_ab),  m_ab = m_a m_b/(m_a + m_b),
// which is the equal-sphere value when the species are equal (a choice: there is no single eta_0).
#include "roughgas/core/vec.hpp"
#include "roughgas/observables/moments.hpp"

#include <array>
#include <span>

namespace roughgas {

struct PressureTensor {
    double xx = 0, yy = 0, zz = 0, xy = 0, xz = 0, yz = 0;
    // += c c^T (one grain's peculiar velocity c)
    void add_dyad(const Vec3& c) {
        xx += c.x * c.x;
        yy += c.y * c.y;
        zz += c.z * c.z;
        xy += c.x * c.y;
        xz += c.x * c.z;
        yz += c.y * c.z;
    }
    double trace() const { return xx + yy + zz; }
    // += f o
    void add_scaled(double f, const PressureTensor& o) {
        xx += f * o.xx;
        yy += f * o.yy;
        zz += f * o.zz;
        xy += f * o.xy;
        xz += f * o.xz;
        yz += f * o.yz;
    }
};

// P_ij over all grains about the velocity u (their mass-weighted mean: Moments::mean_velocity),
// per unit `volume`.
PressureTensor pressure_tensor(Vec3Column v, std::span<const SpeciesSlice> species, double volume,
                               const Vec3& u);

// Omega (zero when no grain has a moment of inertia).
Vec3 mean_spin(Vec3Column omega, std::span<const SpeciesSlice> species);

// One species of the gas for nu: its number fraction x, mass m and radius R.
struct UsfSpecies {
    double fraction = 1, mass = 1, radius = 0.5;
};

// nu = p/eta_0 above, at number density n and temperature T.
double usf_nu(std::span<const UsfSpecies> species, double density, double T);

// The reduced quantities of one state.
struct UsfReduced {
    double a_star = 0, eta_star = 0;
    PressureTensor P_star;
    double N1_star = 0, N2_star = 0;
};
UsfReduced usf_reduced(const PressureTensor& P, double rate, double nu, double density, double T);

} // namespace roughgas
