#pragma once
// Integrates the normal contact (Brilliantov et al. (1996) eqs. 24-26) in Hertz units with Boost.Odeint
// (adaptive Dormand-Prince 5(4) with dense output) and locates the end of the contact as an event.
#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/contact_result.hpp"
#include "roughgas/contact/tolerance.hpp"

namespace roughgas {

// u = w^{1/5} >= 0 (u = 0: Hertz's elastic contact). Error ~0.5 tol.rel on eps_n for u <= 10
// (w <= 1e5; tests/contact/normal_integrator_test.cpp); it still works up to u ~ 1e2 - 1e3, beyond
// which the damping makes the ODE stiff for the explicit stepper and the bounded step count
// throws std::runtime_error. Throws std::invalid_argument for u < 0, non-finite u or tol <= 0.
NormalResult integrate_normal(double u, ContactModel model, Tolerance tol = {});

} // namespace roughgas
