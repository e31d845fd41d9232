#pragma once
// Species of a run as blocks of the particle store, and the species pairs ("pair types") the
// collision sampling runs one candidate process for.
#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/moments.hpp"

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
};
std::vector<PairType> make_pair_types(const std::vector<SpeciesBlock>& species);

// The mean free path of hard spheres of diameter sigma at number density n, 1/(sqrt(2) pi n sigma^2)
// (Maxwellian, equal masses): the length collision cells must resolve (with the largest diameter
// of a mixture: its shortest).
inline double mean_free_path(double density, double sigma) {
    return 1.0 / (std::sqrt(2.0) * std::numbers::pi * density * sigma * sigma);
}

// The Maxwellian collision frequency per grain at the species' temperatures (T_over_m[s] = T_tr,s/m_s):
// nu = (2/N) sum_ab P_ab pi sigma_ab^2 <g_ab>/V, <g_ab> = sqrt((8/pi)(T_a/m_a + T_b/m_b)). The engine's
// step length and the shear time step are set in units of 1/nu.
inline double maxwellian_collision_frequency(const std::vector<PairType>& types, std::span<const double> T_over_m,
                                             double volume, double particles) {
    double nu = 0;
    for (const PairType& t : types) {
        const double mean_g = std::sqrt(8.0 / std::numbers::pi * (T_over_m[t.a] + T_over_m[t.b]));
        nu += 2.0 * t.pairs * t.pc.cross_section * mean_g / volume / particles;
    }
    return nu;
}

} // namespace roughgas
