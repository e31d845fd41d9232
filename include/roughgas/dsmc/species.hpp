#pragma once
// Species of a run as blocks of the particle store, and the species pairs ("pair types") the
// collision sampling runs one candidate process for.
#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/dsmc/run_spec.hpp"

#include <cstddef>
#include <cstdint>
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

// Species pair (a, b), a <= b, at index pair_index(a, b, n_species) (run_spec.hpp).
struct PairType {
    std::size_t a = 0, b = 0;
    PairConstants pc; // i from species a, j from species b
    double pairs = 0; // distinct candidate pairs: N_a N_b, or N_a (N_a - 1)/2 for a = b
};
std::vector<PairType> make_pair_types(const std::vector<SpeciesBlock>& species);

} // namespace roughgas
