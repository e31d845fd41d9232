#pragma once
// The density of a box's densest cell, as the resolution warnings read it (cell_over_lambda_cells of
// moments.csv): a cluster's cells can hold many times the mean while the slabs of profiles.csv
// average it away. A cell's count is noisy, though: in a uniform gas of about m grains per cell the
// fullest of C cells holds about m + sqrt(2 m ln C) (sqrt(2 ln C) = 4.7 standard deviations at
// C = 50 000), which read as a density would warn of clusters that are not there. So the count is
// taken 8 Poisson standard deviations of the mean and 8 grains more low (the grains for sparse
// cells, whose tails are longer than a normal one's: at m = 0.5 the fullest of 2 million cells
// holds about 7), and never below the mean: N_c - 8 sqrt(m) - 8 grains, at least m. A uniform gas
// then reads as its mean density, a cluster of many times the mean as nearly its own.
#include <cstddef>
#include <vector>

namespace roughgas {

// `sums`: per (cell, species), `fields` numbers, the count first (SpatialEngine::cell_sums);
// `density`: the box's mean number density. Returns that lower bound of the densest cell's density.
double densest_cell_density(const std::vector<double>& sums, std::size_t fields, std::size_t species,
                            std::size_t cells, double density);

} // namespace roughgas
