// The Strang step length of uniform shear flow (dsmc/shear.hpp).
#include "roughgas/dsmc/shear.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace roughgas {

double streamed_temperature_ratio(const PressureTensor& P, double a, double s) {
    const double xx = P.xx - 2 * a * s * P.xy + a * a * s * s * P.yy;
    return std::max(0.0, xx + P.yy + P.zz) / P.trace();
}

double strang_step_length(double tau, double nu_ref, const PressureTensor& P, double a, double h_prev) {
    const double trace = P.trace();
    if (!(nu_ref > 0) || !std::isfinite(nu_ref) || !(trace > 0) || !std::isfinite(trace))
        throw std::runtime_error("uniform shear flow: no collision can happen: every grain is at rest in "
                                 "the centre-of-mass frame (translational temperature 0)");
    const double target = tau / nu_ref; // h sqrt(T'/T) = tau/nu_ref
    // g(h) = h sqrt(T'(h)/T) - target: negative at h = 0, growing without bound (T' grows as h^2 once
    // a s P_yy dominates; before that, while T' may dip for P_xy > 0, h itself grows).
    const auto g = [&](double h) {
        return h * std::sqrt(streamed_temperature_ratio(P, a, 0.5 * (h_prev + h))) - target;
    };
    double lo = 0, hi = target;
    for (int k = 0; g(hi) < 0; ++k) {
        if (k == 200) // unreachable for a finite state: T' >= (P_yy + P_zz)/tr P > 0 unless all V_y = 0, and then T' = T
            throw std::logic_error("strang_step_length: no bracket");
        hi *= 2;
    }
    // Bisection to a relative 1e-12: a few dozen evaluations of a closed form, once per step.
    while (hi - lo > 1e-12 * hi) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) < 0 ? lo : hi) = mid;
    }
    return hi;
}

} // namespace roughgas
