#include "roughgas/observables/pressure.hpp"

#include <cmath>
#include <numbers>

namespace roughgas {

PressureTensor pressure_tensor(Vec3Column v, std::span<const SpeciesSlice> species, double volume,
                               const Vec3& u) {
    PressureTensor P;
    for (const SpeciesSlice& sp : species) {
        PressureTensor s;
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i)
            s.add_dyad(v[i] - u);
        P.add_scaled(sp.mass / volume, s);
    }
    return P;
}

Vec3 mean_spin(Vec3Column omega, std::span<const SpeciesSlice> species) {
    return weighted_mean(omega, species, &SpeciesSlice::moment_of_inertia);
}

double usf_nu(std::span<const UsfSpecies> species, double density, double T) {
    double nu_c = 0;
    for (const UsfSpecies& a : species) {
        for (const UsfSpecies& b : species) {
            const double sigma = a.radius + b.radius;
            const double m_ab = a.mass * b.mass / (a.mass + b.mass);
            nu_c += a.fraction * b.fraction * density * sigma * sigma *
                    std::sqrt(8.0 * std::numbers::pi * T / m_ab);
        }
    }
    return 0.8 * nu_c; // (4/5) nu_c = (16/5) n sigma^2 sqrt(pi T/m) for equal spheres
}

UsfReduced usf_reduced(const PressureTensor& P, double rate, double nu, double density, double T) {
    UsfReduced r;
    const double p = density * T;
    r.a_star = rate / nu;
    r.P_star = {P.xx / p, P.yy / p, P.zz / p, P.xy / p, P.xz / p, P.yz / p};
    r.eta_star = -r.P_star.xy / r.a_star;
    r.N1_star = r.P_star.xx - r.P_star.yy;
    r.N2_star = r.P_star.yy - r.P_star.zz;
    return r;
}

} // namespace roughgas
