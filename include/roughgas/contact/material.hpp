#pragma once
// Material constants of the viscoelastic contact, SI units (Brilliantov et al. (1996)
// eqs. 14, 23, 32-35).

namespace roughgas {

struct Material {
    double young_modulus = 1.0e10; // Y [Pa]
    double poisson_ratio = 0.3;    // nu, in (-1, 0.5)
    double dissipation = 0.0;      // A of eq. 23 [s]
    double friction = 0.0;         // mu of eq. 35 (Coulomb bound |F^T| <= mu F^N)
    double asperity = 1.0e-6;      // zeta_0 of eq. 32 [m]
    friend bool operator==(const Material&, const Material&) = default;
};

// Eq. 23: A from the viscous constants eta_1 (shear) and eta_2 (bulk) [Pa s].
inline double dissipation_from_viscosities(double eta1, double eta2, double young_modulus,
                                           double poisson_ratio) {
    const double nu = poisson_ratio;
    const double d = 3.0 * eta2 - eta1;
    return (1.0 / 3.0) * d * d / (3.0 * eta2 + 2.0 * eta1) *
           ((1.0 - nu * nu) * (1.0 - 2.0 * nu) / (young_modulus * nu * nu));
}

} // namespace roughgas
