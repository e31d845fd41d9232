#pragma once
// Whether a box's gas is still uniform, from its structure factor at the smallest wave numbers
// (spectra.csv): the summaries of a cooling box average a scaled homogeneous state only where the
// box holds one.
//
// In a uniform gas (positions independent, as in a dilute gas at equilibrium and in the
// homogeneous cooling state) each independent wave vector's |rho_k|^2 / N is exponentially
// distributed with mean 1, so a shell's S, the mean over its n_modes/2 independent wave vectors
// (k and -k are one mode of a real field) and over K replicas, follows a gamma distribution of
// shape a = K n_modes / 2 and mean 1. A row's S above that distribution's upper quantile at
// probability p is a density fluctuation the uniform gas does not make: clusters (Goldhirsch &
// Zanetti 1993), or a sound or heat mode grown far beyond its thermal level.
#include <cstddef>
#include <optional>
#include <vector>

namespace roughgas {

// The S that a uniform gas's shell of `independent_modes` = K n_modes / 2 exceeds with probability p.
double uniform_structure_factor_bound(double independent_modes, double p);

struct NonUniformity {
    std::size_t row = 0; // the first row where S of the smallest shell exceeds the bound
    double S = 0, bound = 0;
};

// `S[k]` and `modes[k]`: row k's structure factor of the smallest |k| shell and that shell's
// n_modes; `replicas`: K. The bound at p = 1e-6 per row keeps a uniform box of a few hundred rows
// from being called non-uniform by chance (probability below 1e-3). Rows with a NaN S (none
// yet) are skipped. None when every row is within the bound.
std::optional<NonUniformity> first_non_uniform_row(const std::vector<double>& S, const std::vector<double>& modes,
                                                   int replicas);

} // namespace roughgas
