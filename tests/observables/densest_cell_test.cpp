// The densest cell's density for the resolution warnings (observables/densest_cell.hpp): a uniform
// gas's noisiest cell reads as the mean density, a cluster as its own less eight standard
// deviations of the mean count.
#include "roughgas/observables/densest_cell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace roughgas {
namespace {

// Per (cell, species) five numbers, the count first, as SpatialEngine::cell_sums lays them out.
std::vector<double> sums_of(const std::vector<std::vector<double>>& counts) {
    std::vector<double> out;
    for (const auto& cell : counts)
        for (double n : cell)
            out.insert(out.end(), {n, 0.0, 0.0, 0.0, 0.0});
    return out;
}

TEST(DensestCell, AUniformGasReadsAsItsMeanDensity) {
    // 50 000 cells of two species with Poisson counts of means 14 and 6: the fullest cell holds about
    // 20 + 4.7 sqrt(20), still below 20 + 8 sqrt(20).
    std::mt19937_64 rng(3);
    std::poisson_distribution<int> a(14.0), b(6.0);
    std::vector<std::vector<double>> counts(50000);
    for (auto& c : counts)
        c = {static_cast<double>(a(rng)), static_cast<double>(b(rng))};
    EXPECT_EQ(densest_cell_density(sums_of(counts), 5, 2, counts.size(), 0.02), 0.02);
    // Sparse cells, 0.5 grains each: the fullest of 200 000 holds about 6, ten times the mean.
    std::poisson_distribution<int> sparse(0.5);
    std::vector<std::vector<double>> few(200000);
    for (auto& c : few)
        c = {static_cast<double>(sparse(rng))};
    EXPECT_EQ(densest_cell_density(sums_of(few), 5, 1, few.size(), 0.02), 0.02);
}

TEST(DensestCell, AClusterReadsAsItsOwnDensityLessTheNoise) {
    std::vector<std::vector<double>> counts(1000, std::vector<double>{20.0});
    counts[417] = {2020.0}; // a cluster of a hundred times the mean
    const double mean = (999 * 20.0 + 2020.0) / 1000;
    EXPECT_DOUBLE_EQ(densest_cell_density(sums_of(counts), 5, 1, counts.size(), 0.02),
                     0.02 * (2020.0 - 8 * std::sqrt(mean) - 8) / mean);
    // An empty box reads as the mean density (no division by zero).
    EXPECT_EQ(densest_cell_density(sums_of(std::vector<std::vector<double>>(8, {0.0})), 5, 1, 8, 0.5), 0.5);
}

} // namespace
} // namespace roughgas
