#pragma once
// The warnings a planned case deserves before any work, from its resolved case and the solver's
// spec: the keys it holds that the run will not read, a gas too dense for the Boltzmann equation,
// and a box's cells (against the mean free path and a grain, the grains they hold) and steps.
// `roughgas run` prints each once on stderr and in the '#' lines of its CSVs (run/provenance.hpp),
// `roughgas check` on stderr: the same list, so that check warns of what run would.
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/io/case_config.hpp"

#include <string>
#include <vector>

namespace roughgas::cli {

// The dense-gas warning's threshold on chi - 1 (chi: dsmc/pair_correlation.hpp's carnahan_starling_chi): 5 %, reached at
// the solid fraction phi = 0.0193.
inline constexpr double dense_gas_excess = 0.05;
// The grains per cell below which a box's cells hold too few grains for independent collisions:
// docs/validation.md measures the cooling state's theta and a20 against the grains per cell, whose
// bias exceeds three of that measurement's errors at 5 and below.
inline constexpr double fewest_grains_per_cell = 5.0;
// An Enskog box: the deficit of the collision frequency, one over the grains in the cells a diameter
// from a grain (setup_warnings.cpp), above which `run` warns.
inline constexpr double enskog_partner_deficit = 0.001;

// The largest cell edge of a box run over the mean free path at the mean density,
// 1/(sqrt(2) pi n sigma^2) of the largest diameter sigma (the ratio moments.csv's cell_over_lambda
// reports per slab as the run goes).
double cells_over_mean_free_path(const RunSpec& spec);

// Each warning as one line, without the "warning: " the outputs put before it.
std::vector<std::string> setup_warnings(const CaseConfig& cfg, const RunSpec& spec);

} // namespace roughgas::cli
