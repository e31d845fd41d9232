#include "roughgas/observables/thermal_temperature.hpp"

#include <limits>
#include <stdexcept>

namespace roughgas {

double thermal_temperature(std::span<const double> cell_sums, std::size_t fields, std::span<const double> masses) {
    const std::size_t S = masses.size();
    if (fields < 5 || S == 0 || cell_sums.size() % (fields * S) != 0)
        throw std::invalid_argument("thermal_temperature: cell sums of another layout");
    const std::size_t cells = cell_sums.size() / (fields * S);
    double energy = 0, dof = 0; // sum_c sum_j m_j |v_j - U_c|^2 and sum_c (N_c - 1)
    for (std::size_t c = 0; c < cells; ++c) {
        double N = 0, M = 0, px = 0, py = 0, pz = 0, K = 0;
        for (std::size_t s = 0; s < S; ++s) {
            const double* f = cell_sums.data() + (c * S + s) * fields;
            const double m = masses[s];
            N += f[0];
            M += m * f[0];
            px += m * f[1];
            py += m * f[2];
            pz += m * f[3];
            K += m * f[4];
        }
        if (N < 2)
            continue; // one grain is its own flow: no thermal motion to measure
        energy += K - (px * px + py * py + pz * pz) / M;
        dof += N - 1;
    }
    return dof > 0 ? energy / (3 * dof) : std::numeric_limits<double>::quiet_NaN();
}

} // namespace roughgas
