#pragma once
// The pair correlation at contact chi of hard spheres: the factor by which a moderately dense gas's
// collision rates exceed the dilute gas's in the Enskog equation (Enskog 1922; docs/model.md, "The
// Enskog equation"). In a spatially uniform state the Enskog collision operator is chi times the
// Boltzmann one, pair of species by pair of species.
#include "roughgas/dsmc/run_spec.hpp"

#include <cstddef>
#include <numbers>
#include <vector>

namespace roughgas {

// The densest packing of equal spheres, pi/sqrt(18) (Kepler's conjecture, proved by Hales 2005): no
// gas of hard spheres reaches it.
inline constexpr double close_packing = 0.74048048969306104;
// The solid fraction at which the hard-sphere fluid starts to freeze (Hoover & Ree 1968): above it
// the uniform fluid that the Enskog equation describes is metastable, and Carnahan & Starling's chi,
// fitted to the fluid, is an extrapolation.
inline constexpr double hard_sphere_freezing = 0.494;

// Carnahan & Starling (1969): chi = (1 - phi/2)/(1 - phi)^3 at the solid fraction phi, within 1 %
// of the hard-sphere fluid's measured contact value up to freezing.
inline double carnahan_starling_chi(double phi) { return (1 - phi / 2) / ((1 - phi) * (1 - phi) * (1 - phi)); }

// The mixture's form (Boublik 1970; Mansoori, Carnahan, Starling & Leland 1971): with
// xi_k = (pi/6) sum_s n_s sigma_s^k and mu = sigma_a sigma_b/(sigma_a + sigma_b),
//   chi_ab = 1/(1 - xi_3) + 3 xi_2 mu/(1 - xi_3)^2 + 2 xi_2^2 mu^2/(1 - xi_3)^3,
// which for one species (xi_2 = phi/sigma, mu = sigma/2) is Carnahan & Starling's exactly. `n[s]` is
// the number density of species s, `sigma[s]` its diameter, S species.
inline double bmcsl_chi_of(const double* n, const double* sigma, std::size_t S, std::size_t a, std::size_t b) {
    double xi2 = 0, xi3 = 0;
    for (std::size_t s = 0; s < S; ++s) {
        xi2 += std::numbers::pi / 6 * n[s] * sigma[s] * sigma[s];
        xi3 += std::numbers::pi / 6 * n[s] * sigma[s] * sigma[s] * sigma[s];
    }
    const double mu = sigma[a] * sigma[b] / (sigma[a] + sigma[b]), h = 1 / (1 - xi3);
    return h + 3 * xi2 * mu * h * h + 2 * xi2 * xi2 * mu * mu * h * h * h;
}

// The same for a run's species: `density` is n of all the grains, species s holding the number
// fraction x_s (n_s = x_s n, fractions normalised) with diameter sigma_s = 2 R_s.
template <class Species>
double bmcsl_chi(double density, const std::vector<Species>& species, std::size_t a, std::size_t b) {
    double total = 0;
    for (const Species& s : species)
        total += s.fraction;
    std::vector<double> n, sigma;
    for (const Species& s : species) {
        n.push_back(total > 0 ? density * s.fraction / total : 0.0);
        sigma.push_back(2 * s.radius);
    }
    return bmcsl_chi_of(n.data(), sigma.data(), species.size(), a, b);
}

// chi of every species pair (a, b), a <= b, at pair_index(a, b, S) (run_spec.hpp): all 1 without
// `enskog` (the Boltzmann equation), `enskog->chi` for a constant, else the mixture form above (for
// one species Carnahan & Starling's).
template <class Species>
std::vector<double> pair_correlations(double density, const std::vector<Species>& species,
                                      const std::optional<EnskogSpec>& enskog) {
    const std::size_t S = species.size();
    std::vector<double> chi(S * (S + 1) / 2, 1.0);
    if (!enskog)
        return chi;
    for (std::size_t a = 0; a < S; ++a)
        for (std::size_t b = a; b < S; ++b)
            chi[pair_index(a, b, S)] = enskog->model == PairCorrelationModel::constant
                                           ? enskog->chi
                                           : bmcsl_chi(density, species, a, b);
    return chi;
}
inline std::vector<double> pair_correlations(const RunSpec& spec) {
    return pair_correlations(spec.density, spec.species, spec.enskog);
}

} // namespace roughgas
