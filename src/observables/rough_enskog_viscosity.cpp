#include "roughgas/observables/rough_enskog_viscosity.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace roughgas {

RoughEnskogViscosity rough_enskog_viscosity(double q, double phi, double chi) {
    if (!(std::isfinite(q) && q > 0 && q <= 2.0 / 3.0))
        throw std::invalid_argument("rough_enskog_viscosity: q must be in (0, 2/3]");
    if (!(std::isfinite(phi) && phi >= 0 && phi < 1))
        throw std::invalid_argument("rough_enskog_viscosity: phi must be in [0, 1)");
    if (!(std::isfinite(chi) && chi > 0))
        throw std::invalid_argument("rough_enskog_viscosity: chi must be positive");
    const double kappa = q / (1 + q);
    const double eta_p = 6 * (1 + q) * (1 + q) / (6 + 13 * q);
    const double A = 1.6 * (1 + 1.5 * kappa);
    const double bulk = 768 / (25 * std::numbers::pi) * (1 + 0.75 * kappa) * phi * phi * chi;
    RoughEnskogViscosity r;
    r.kinetic = eta_p * (1 + A * phi * chi) / chi;
    r.collisional = eta_p * A * phi * (1 + A * phi * chi) + bulk;
    r.total = r.kinetic + r.collisional;
    return r;
}

} // namespace roughgas
