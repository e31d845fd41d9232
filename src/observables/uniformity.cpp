#include "roughgas/observables/uniformity.hpp"

#include <boost/math/special_functions/gamma.hpp>

#include <cmath>

namespace roughgas {

double uniform_structure_factor_bound(double independent_modes, double p) {
    // S = (1/a) sum of a unit exponentials: gamma of shape a, scale 1/a; Q(a, a S) = p.
    const double a = independent_modes;
    return boost::math::gamma_q_inv(a, p) / a;
}

std::optional<NonUniformity> first_non_uniform_row(const std::vector<double>& S, const std::vector<double>& modes,
                                                   int replicas) {
    constexpr double p = 1e-6;
    for (std::size_t k = 0; k < S.size(); ++k) {
        if (!std::isfinite(S[k]) || !(modes[k] >= 2))
            continue;
        const double bound = uniform_structure_factor_bound(0.5 * replicas * modes[k], p);
        if (S[k] > bound)
            return NonUniformity{k, S[k], bound};
    }
    return std::nullopt;
}

} // namespace roughgas
