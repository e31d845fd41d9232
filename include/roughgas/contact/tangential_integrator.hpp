#pragma once
// Tangential contact with the asperity model (Brilliantov et al. (1996) eq. 37 made well-defined,
// docs/model.md §7), driven by the normal solution and integrated together with it, break to break.
//
// Hertz units as for the normal problem, plus e = eta/zeta_0 (asperity strain) and p = zeta'/g_N:
//   p' = (mu/kappa) X''(S) e,   e' = p / z,   z = zeta_0/(g_N T)
//   p(0) = g_T/g_N,  e(0) = 0;  |e| = 1 breaks the asperity: e -> 0.
// eps^T = p(S_c)/p(0) (the paper's eq. 38 with zeta' for zeta).
// Only a compressive normal force (X'' < 0) loads the asperities: X'' is replaced by min(X'', 0),
// which matters only in the attractive phase of a `separation` contact (src/contact/contact_ode.hpp,
// `compressive`). Note that |eps^T| <= 1 is NOT guaranteed by this model: the asperity spring
// stiffens with F_N while strained and can gain energy (tests/contact/tangential_integrator_test.cpp,
// StiffeningAsperitySpringCanExceedPerfectReversal: eps^T = -1.24 for u = 0, (mu/kappa)/z = 1.54).
#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/contact_result.hpp"
#include "roughgas/contact/tolerance.hpp"

namespace roughgas {

struct TangentialParameters {
    double u = 0;             // normal dissipation parameter w^{1/5}
    double mu_over_kappa = 0; // mu/kappa
    double z = 1;             // zeta_0 / (g_N T): asperity scale in units of the compression scale
    ContactModel model{};
};

struct TangentialResult {
    NormalResult normal;
    double eps_t = 1; // the paper's convention; in [0, 1] while sliding (turning_points == 0), can leave
                      // [-1, 1] otherwise (see the top of this file)
    int breaks = 0;
    // Sign changes of p during the contact. Between breaks e' = p/z, so every turning point is a
    // local maximum of |e|: eps_t jumps (as a function of g_T/g_N or of any parameter) where a new
    // break first appears at such an interior maximum, because e then drops from 1 to 0 mid-contact.
    // A new break appearing at the end of the contact changes nothing. A table builder therefore
    // brackets jumps by changes of `breaks` (and of `turning_points`) between neighbouring nodes.
    int turning_points = 0;
};

// ratio = g_T/g_N >= 0. ratio = 0 returns the limit ratio -> 0 (no break, linear response).
// A negative ratio is accepted and gives the eps_t of |ratio| (the model is odd in g_T).
TangentialResult integrate_tangential(const TangentialParameters& p, double ratio, Tolerance tol = {});

// Smallest g_T/g_N at which an asperity breaks during the contact: without breaks the tangential
// motion is linear in g_T, so this is 1/max_S|e(S)| of the unbroken solution with p(0) = 1.
double critical_ratio(const TangentialParameters& p, Tolerance tol = {});

} // namespace roughgas
