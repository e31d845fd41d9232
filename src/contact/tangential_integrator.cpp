// The tangential contact with the asperity model (Brilliantov et al. (1996) eq. 37 made well-defined,
// docs/model.md §7), integrated together with the normal motion by contact_driver.hpp.
//
// Scaling. tangential_integrator.hpp writes p' = (mu/kappa) X'' e, e' = p/z, p(0) = r = g_T/g_N,
// |e| = 1 breaks. The driver integrates p^ = p/|r| and e^ = e/s with s = min(|r|, 1):
//   e^' = k_e p^,  p^' = k_p X'' e^,  k_e = |r|/(s z),  k_p = (mu/kappa) s/|r|,
//   p^(0) = sign(r),  break at |e^| = 1/s,  eps_t = p^(S_c)/p^(0).
// Both components are O(1) for every r, so the absolute tolerance means the same thing for a
// nearly sticking r = 1e-6 as for a sliding r = 1e3. For |r| < 1 the equations do not depend on r
// at all, only the threshold 1/|r| does: r -> 0 is the unbroken linear problem (threshold infinite),
// which is what ratio = 0 returns and what critical_ratio measures.
//
// Cost. Each break costs about one Dormand-Prince step (contact_driver.hpp), measured 0.5-1 us;
// a sliding contact (p keeps its sign) breaks about |r| S_c / z times (the strain grows by 1 in
// Delta S = z/|p|). E.g. u = 0.3, mu/kappa = 1.75, r = 3: z = 1e-3 -> 6.7e3 breaks, 5.5 ms;
// z = 1e-4 -> 6.7e4 breaks, 35 ms. Sticking (p -> 0) stops the breaks. The time is linear in the
// number of breaks and bounded: the step budget allows 16 steps per break.
#include "roughgas/contact/tangential_integrator.hpp"

#include "contact_driver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace roughgas {

namespace {

void check_tangential_parameters(const char* where, const TangentialParameters& p, Tolerance tol) {
    detail::check_contact_arguments(where, p.u, tol);
    if (!(std::isfinite(p.mu_over_kappa) && p.mu_over_kappa >= 0)) {
        std::ostringstream msg;
        msg << where << ": mu/kappa = " << p.mu_over_kappa << ", need a finite value >= 0";
        throw std::invalid_argument(msg.str());
    }
    if (!(p.z > 0)) { // +inf allowed: no asperity strain at all
        std::ostringstream msg;
        msg << where << ": z = zeta0/(g_N T) = " << p.z << ", need z > 0";
        throw std::invalid_argument(msg.str());
    }
}

// The unbroken linear problem with p(0) = 1 (threshold infinite).
detail::DriverSetup linear_setup(const TangentialParameters& p, Tolerance tol) {
    detail::DriverSetup setup;
    setup.coefficients = detail::OdeCoefficients{p.model.form, p.u, 1.0 / p.z, p.mu_over_kappa};
    setup.end = detail::resolved_end(p.model.end, p.u);
    setup.p0 = 1.0;
    setup.tol = tol;
    return setup;
}

} // namespace

TangentialResult integrate_tangential(const TangentialParameters& p, double ratio, Tolerance tol) {
    check_tangential_parameters("roughgas::integrate_tangential", p, tol);
    if (!std::isfinite(ratio)) {
        std::ostringstream msg;
        msg << "roughgas::integrate_tangential: g_T/g_N = " << ratio << ", need a finite value";
        throw std::invalid_argument(msg.str());
    }
    detail::DriverSetup setup = linear_setup(p, tol);
    const double r = std::abs(ratio);
    if (r > 0) {
        const double s = std::min(r, 1.0);
        setup.coefficients.k_e = r / (s * p.z);
        setup.coefficients.k_p = p.mu_over_kappa * s / r;
        setup.threshold = 1.0 / s;
        setup.p0 = ratio > 0 ? 1.0 : -1.0;
    }
    const detail::DriverResult d = detail::integrate_contact_ode<4>(setup);
    TangentialResult result;
    result.normal = d.normal;
    result.eps_t = d.p_end / setup.p0;
    result.breaks = d.breaks;
    result.turning_points = d.turning_points;
    return result;
}

double critical_ratio(const TangentialParameters& p, Tolerance tol) {
    check_tangential_parameters("roughgas::critical_ratio", p, tol);
    const detail::DriverResult d = detail::integrate_contact_ode<4>(linear_setup(p, tol));
    return d.max_abs_e > 0 ? 1.0 / d.max_abs_e : std::numeric_limits<double>::infinity();
}

} // namespace roughgas
