// The Mpemba crossing of the driven two-temperature equations: observables/mpemba.hpp.
#include "roughgas/observables/mpemba.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace roughgas {

std::optional<double> mpemba_crossing_time(const HcsTheory& theory, const ThermostatSpec& thermostat,
                                           const HcsTemperatures& A, const HcsTemperatures& B, double t_max,
                                           double rel_tol) {
    if (!(t_max > 0))
        throw std::invalid_argument("mpemba_crossing_time: t_max must be > 0");
    const double d0 = theory.mixture_T_tr(A) - theory.mixture_T_tr(B);
    if (d0 == 0)
        throw std::invalid_argument("mpemba_crossing_time: the two samples start at the same T_tr");
    HcsTrajectory a(theory, A, thermostat, rel_tol), b(theory, B, thermostat, rel_tol);
    const auto difference = [&](const HcsTemperatures& Ta, const HcsTemperatures& Tb) {
        return theory.mixture_T_tr(Ta) - theory.mixture_T_tr(Tb);
    };
    const auto sign_changed = [&](const HcsTemperatures& Ta, const HcsTemperatures& Tb) {
        const double d = difference(Ta, Tb);
        return d == 0 || (d > 0) != (d0 > 0);
    };
    // A change of sign the integration resolves: the difference on one side of it exceeds 1e4 times
    // the tolerance, relative to T_tr. Both samples tend to one steady state, where their difference
    // decays to the integration error and may change sign by round-off alone.
    const auto resolved = [&](const HcsTemperatures& Ta, const HcsTemperatures& Tb, double d_before) {
        const double scale = 1e4 * rel_tol * std::max(theory.mixture_T_tr(Ta), theory.mixture_T_tr(Tb));
        return std::max(std::abs(d_before), std::abs(difference(Ta, Tb))) > scale;
    };
    double t = 0, d = d0;
    HcsTemperatures Ta = A, Tb = B;
    while (t < t_max) {
        const double nu = std::max(collision_frequency(theory, Ta), collision_frequency(theory, Tb));
        const double next = std::min(t_max, nu > 0 ? t + 0.05 / nu : t_max);
        // The trajectories at t, kept to probe the interval (t, next] if the sign changes in it.
        const HcsTrajectory a0 = a, b0 = b;
        Ta = a.at(next);
        Tb = b.at(next);
        if (sign_changed(Ta, Tb) && resolved(Ta, Tb, d)) {
            double lo = t, hi = next;
            while (hi - lo > 1e-12 * hi) {
                const double mid = 0.5 * (lo + hi);
                HcsTrajectory pa = a0, pb = b0;
                (sign_changed(pa.at(mid), pb.at(mid)) ? hi : lo) = mid;
            }
            return hi;
        }
        if (sign_changed(Ta, Tb)) // an unresolved change of sign: the difference is round-off from here on
            return std::nullopt;
        t = next;
        d = difference(Ta, Tb);
    }
    return std::nullopt;
}

} // namespace roughgas
