#pragma once
// The direct (uncached) path in physical units: one call integrates one contact.
#include "roughgas/contact/contact_pair.hpp"
#include "roughgas/contact/contact_result.hpp"
#include "roughgas/contact/normal_integrator.hpp"
#include "roughgas/contact/tangential_integrator.hpp"
#include "roughgas/contact/tolerance.hpp"

namespace roughgas {

// Tangential parameters of pair `pc` at impact speed g_n > 0.
inline TangentialParameters tangential_parameters(const ContactPair& pc, double g_n) {
    return {pc.u(g_n), pc.mu / pc.kappa, pc.zeta0 / (g_n * pc.hertz_time(g_n)), pc.model};
}

// Normal part only (eps_t = 1, beta = -1, breaks = 0): g_n > 0 in m/s.
inline ContactResult integrate_normal_contact(const ContactPair& pc, double g_n, Tolerance tol = {}) {
    const NormalResult nr = integrate_normal(pc.u(g_n), pc.model, tol);
    const double T = pc.hertz_time(g_n);
    ContactResult r;
    r.eps_n = nr.eps_n;
    r.duration = nr.duration * T;
    r.max_compression = nr.max_compression * g_n * T;
    return r;
}

// Normal and tangential: g_n > 0, g_t >= 0 in m/s.
inline ContactResult integrate_contact(const ContactPair& pc, double g_n, double g_t, Tolerance tol = {}) {
    const TangentialResult tr = integrate_tangential(tangential_parameters(pc, g_n), g_t / g_n, tol);
    const double T = pc.hertz_time(g_n);
    ContactResult r;
    r.eps_n = tr.normal.eps_n;
    r.eps_t = tr.eps_t;
    r.beta = -tr.eps_t;
    r.duration = tr.normal.duration * T;
    r.max_compression = tr.normal.max_compression * g_n * T;
    r.breaks = tr.breaks;
    return r;
}

} // namespace roughgas
