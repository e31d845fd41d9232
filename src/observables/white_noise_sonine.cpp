// Smooth spheres under white noise in the first Sonine approximation: observables/white_noise_sonine.hpp.
#include "roughgas/observables/white_noise_sonine.hpp"

#include "roughgas/observables/theory.hpp"

#include <cmath>
#include <stdexcept>

namespace roughgas {

double white_noise_a2(double alpha, int dimension) {
    if (!(alpha >= 0 && alpha <= 1))
        throw std::invalid_argument("white_noise_a2: alpha must be in [0, 1]");
    if (dimension != 2 && dimension != 3)
        throw std::invalid_argument("white_noise_a2: dimension must be 2 or 3");
    const double d = dimension;
    return 16 * (1 - alpha) * (1 - 2 * alpha * alpha) /
           (73 + 56 * d - 24 * d * alpha - 105 * alpha + 30 * (1 - alpha) * alpha * alpha);
}

WhiteNoiseSonineState white_noise_sonine_state(double alpha, double mass, double sigma, double density,
                                               double strength) {
    WhiteNoiseSonineState s;
    s.a2 = white_noise_a2(alpha, 3);
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, -1.0, 0.4, mass, sigma, density);
    const double factor = 1 + 3 * s.a2 / 16; // the Sonine correction of the cooling rate
    s.T_tr = c.A > 0 ? std::pow(mass * strength / (c.G * c.A * factor), 2.0 / 3.0) : HUGE_VAL;
    s.zeta_star = (1 - alpha * alpha) / 3 * factor / (1 - s.a2 / 16);
    return s;
}

} // namespace roughgas
