// The normal contact (Brilliantov et al. (1996) eqs. 24-26; docs/model.md §6) in Hertz units: the contact
// ODE of contact_ode.hpp without the tangential pair, integrated by contact_driver.hpp.
#include "roughgas/contact/normal_integrator.hpp"

#include "contact_driver.hpp"

namespace roughgas {

NormalResult integrate_normal(double u, ContactModel model, Tolerance tol) {
    detail::check_contact_arguments("roughgas::integrate_normal", u, tol);
    detail::DriverSetup setup;
    setup.coefficients = detail::OdeCoefficients{model.form, u, 0.0, 0.0};
    setup.end = detail::resolved_end(model.end, u);
    setup.tol = tol;
    return detail::integrate_contact_ode<2>(setup).normal;
}

} // namespace roughgas
