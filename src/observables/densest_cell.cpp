// The densest cell's density, a lower bound of it: observables/densest_cell.hpp.
#include "roughgas/observables/densest_cell.hpp"

#include <algorithm>
#include <cmath>

namespace roughgas {

double densest_cell_density(const std::vector<double>& sums, std::size_t fields, std::size_t species,
                            std::size_t cells, double density) {
    double most = 0, all = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        double n = 0;
        for (std::size_t s = 0; s < species; ++s)
            n += sums[(c * species + s) * fields];
        most = std::max(most, n);
        all += n;
    }
    const double mean = all / static_cast<double>(cells);
    if (!(mean > 0))
        return density;
    return density * std::max(1.0, (most - 8.0 * std::sqrt(mean) - 8.0) / mean);
}

} // namespace roughgas
