#pragma once
// Species of a run as blocks of the particle store, and the species pairs ("pair types") the
// collision sampling runs one candidate process for.
#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/moments.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace roughgas {

// Species s owns the store's index range [offset, offset + count).
struct SpeciesBlock {
    std::string name;
    GrainProperties grain;
    std::size_t offset = 0, count = 0;
    double temperature = 1, rotational_temperature = 1; // initial T_tr, T_rot
    double moment_of_inertia() const { return grain.inertia * grain.mass * grain.radius * grain.radius; } // J
};

// Counts from the number fractions by largest remainders (ties to the lower index), so they sum to
// `particles` exactly and each is within 1 of particles x fraction (fractions normalised).
std::vector<SpeciesBlock> make_species_blocks(const std::vector<SpeciesSpec>& species,
                                              std::int64_t particles);

// The blocks as the moments see them (observables/moments.hpp): each species' range, m and J.
inline std::vector<SpeciesSlice> species_slices(const std::vector<SpeciesBlock>& blocks) {
    std::vector<SpeciesSlice> slices;
    for (const SpeciesBlock& b : blocks)
        slices.push_back({b.offset, b.count, b.grain.mass, b.moment_of_inertia()});
    return slices;
}

// Species pair (a, b), a <= b, at index pair_index(a, b, n_species) (run_spec.hpp).
struct PairType {
    std::size_t a = 0, b = 0;
    PairConstants pc; // i from species a, j from species b
    double pairs = 0; // distinct candidate pairs: N_a N_b, or N_a (N_a - 1)/2 for a = b
    double chi = 1;   // the pair correlation at contact (dsmc/pair_correlation.hpp): 1 in a Boltzmann gas
    // chi pi sigma^2: what the pair's collision rate is proportional to (the Enskog equation of a
    // uniform gas, chi times the Boltzmann rate).
    double rate_section() const { return chi * pc.cross_section; }
};
// `chi`: the pair correlation of each pair (pair_index order); empty: 1, the Boltzmann equation.
std::vector<PairType> make_pair_types(const std::vector<SpeciesBlock>& species, const std::vector<double>& chi = {});

// The mean free path of hard spheres of diameter sigma at number density n, 1/(sqrt(2) pi n sigma^2)
// (Maxwellian, equal masses): the length collision cells must resolve (with the largest diameter
// of a mixture: its shortest).
inline double mean_free_path(double density, double sigma) {
    return 1.0 / (std::sqrt(2.0) * std::numbers::pi * density * sigma * sigma);
}

// The largest diameter 2 max R of the species (of the case or of the run): the one the cells and the
// mean free path of a mixture are measured against.
template <class Species> double largest_diameter(const std::vector<Species>& species) {
    double R = 0;
    for (const Species& s : species)
        R = std::max(R, s.radius);
    return 2 * R;
}

// The solid fraction phi = sum_s n_s (pi/6) sigma_s^3 of grains at the number density n
// (run.density: all the grains, of every species), species s holding the number fraction x_s
// (n_s = x_s n, fractions normalised) with diameter sigma_s = 2 R_s.
template <class Species> double solid_fraction(double density, const std::vector<Species>& species) {
    double total = 0, volume = 0;
    for (const Species& s : species) {
        total += s.fraction;
        volume += s.fraction * std::numbers::pi / 6.0 * 8.0 * s.radius * s.radius * s.radius;
    }
    return total > 0 ? density * volume / total : 0.0;
}

// The Maxwellian collision frequency per grain at the species' temperatures (T_over_m[s] = T_tr,s/m_s):
// nu = (2/N) sum_ab P_ab chi_ab pi sigma_ab^2 <g_ab>/V, <g_ab> = sqrt((8/pi)(T_a/m_a + T_b/m_b)). The engine's
// step length and the shear time step are set in units of 1/nu.
inline double maxwellian_collision_frequency(const std::vector<PairType>& types, std::span<const double> T_over_m,
                                             double volume, double particles) {
    double nu = 0;
    for (const PairType& t : types) {
        const double mean_g = std::sqrt(8.0 / std::numbers::pi * (T_over_m[t.a] + T_over_m[t.b]));
        nu += 2.0 * t.pairs * t.rate_section() * mean_g / volume / particles;
    }
    return nu;
}

} // namespace roughgas
