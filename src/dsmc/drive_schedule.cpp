// DriveSchedule (dsmc/run_spec.hpp): a thermostat's strength or bath temperature over time,
// piecewise constant, and the integrals the kicks of a step need (exact for such a function).
#include "roughgas/dsmc/run_spec.hpp"

#include <algorithm>
#include <cmath>

namespace roughgas {

double DriveSchedule::at(double time) const {
    // The last piece starting at or before `time` (the first one before t[0] = 0).
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    return value[it == t.begin() ? 0 : static_cast<std::size_t>(it - t.begin()) - 1];
}

double DriveSchedule::integral(double t0, double t1) const {
    return decaying_integral(t0, t1, 0.0);
}

double DriveSchedule::decaying_integral(double t0, double t1, double r) const {
    if (!(t1 > t0))
        return 0.0;
    // Piece k covers [t[k], t[k+1]) (the first from -infinity, the last to +infinity); over its
    // overlap [a, b] with [t0, t1], int value exp(-r (t1 - s)) ds = value (e^{-r (t1 - b)} - e^{-r (t1 - a)})/r,
    // written with expm1 so that small r (and r = 0: value (b - a)) lose no digits.
    double sum = 0;
    for (std::size_t k = 0; k < value.size(); ++k) {
        const double lo = k == 0 ? t0 : std::max(t0, t[k]);
        const double hi = k + 1 < t.size() ? std::min(t1, t[k + 1]) : t1;
        if (!(hi > lo))
            continue;
        if (r == 0) {
            sum += value[k] * (hi - lo);
        } else {
            // e^{-r (t1 - hi)} - e^{-r (t1 - lo)} = e^{-r (t1 - hi)} (1 - e^{-r (hi - lo)})
            sum += value[k] * std::exp(-r * (t1 - hi)) * -std::expm1(-r * (hi - lo)) / r;
        }
    }
    return sum;
}

} // namespace roughgas
