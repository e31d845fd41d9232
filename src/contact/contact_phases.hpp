#pragma once
// Where the compression clock vs = sqrt(X) of contact_ode.hpp may be used: dS/dvs = 2 vs / V is
// harmless only while |V| stays well away from 0. Both switch points below come from energy bounds
// (d(V^2)/dX = 2 X''), so they hold for every u without integrating anything.
#include "roughgas/contact/contact_model.hpp"

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace roughgas::detail {

// (u + X)^{5/2} - u^{5/2}, without cancellation when X << u.
inline double rise_of_power_2_5(double u, double X) {
    if (X < u) {
        return std::pow(u, 2.5) * std::expm1(2.5 * std::log1p(X / u));
    }
    return std::pow(X + u, 2.5) - std::pow(u, 2.5);
}

// Loading (V > 0): the repulsive force is at most X^{1/2}(X + u) (eq. 24) or (X + u)^{3/2}
// (eq. 25) since V <= 1, so V^2 >= 1 - loss(X) with the loss below. Returns vs_1 = sqrt(X_1) with
// loss(X_1) = 3/4, i.e. V >= 1/2 on the whole loading piece (for u = 0: V = 1/2 exactly).
inline double loading_end_root(NormalForm form, double u) {
    const auto excess = [form, u](double X) {
        const double loss = form == NormalForm::eq24
                                ? 0.8 * std::pow(X, 2.5) + (4.0 / 3.0) * u * std::pow(X, 1.5)
                                : 0.8 * rise_of_power_2_5(u, X);
        return loss - 0.75;
    };
    // Both losses exceed 0.8 X^{5/2}, which is 3/4 at X = (15/16)^{2/5}: a bracket for any u.
    const double hi = std::pow(15.0 / 16.0, 0.4);
    std::uintmax_t iterations = 100;
    // Relative: X_1 ~ u^{-3/2} is tiny at large u. Only a switch point, so 1e-6 is plenty; the
    // lower end of the bracket has loss <= 3/4, which keeps the guarantee V >= 1/2.
    const auto tol = [](double a, double b) { return std::abs(b - a) <= 1e-6 * std::max(a, b); };
    const auto r =
        boost::math::tools::toms748_solve(excess, 0.0, hi, excess(0.0), excess(hi), tol, iterations);
    return std::sqrt(r.first > 0 ? r.first : 0.5 * r.second);
}

// Unloading (V < 0) from (X, V) down to X = 0: may we switch to the compression clock here?
// Repulsion (force > 0) is at most X^{3/2} for both forms (X + uV <= X), so it adds at most
// W_r = 2 (2/5) X^{5/2} to V^2. Attraction (separation end only; docs/model.md §6) is at most
// X^{1/2} u|V| (eq. 24) or (u|V|)^{3/2} (eq. 25), with |V| <= 1.25 |V_now| while V^2 <= 1.25 V_now^2;
// integrated over [0, X] it removes at most W_a from V^2. Requiring V^2 >= 4 (W_r + W_a) keeps
// V^2 in [3/4, 5/4] V_now^2 until X = 0: |V| stays away from 0 and no capture can occur.
inline bool unloading_is_safe(NormalForm form, ContactEnd end, double u, double X, double V) {
    if (!(V < 0)) {
        return false;
    }
    const double w_repulsive = 0.8 * X * X * std::sqrt(X);
    double w_attractive = 0.0;
    if (end == ContactEnd::separation) {
        const double uv = 1.25 * u * std::abs(V);
        w_attractive = form == NormalForm::eq24 ? 2.0 * (2.0 / 3.0) * uv * X * std::sqrt(X)
                                                : 2.0 * X * uv * std::sqrt(uv);
    }
    return V * V >= 4.0 * (w_repulsive + w_attractive);
}

} // namespace roughgas::detail
