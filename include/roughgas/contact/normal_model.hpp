#pragma once
// Right-hand sides of the normal contact problem in Hertz units (docs/model.md §6).
//
// With xi = g_N T X, t = T S and T = rho^{-2/5} g_N^{-1/5}, both equations of
// Brilliantov et al. (1996) lose rho and g_N:
//   eq. 24:  X'' = -X^{1/2} (X + u X')          u = (3/2) A / T = w^{1/5}
//   eq. 25:  X'' = -sgn(y)|y|^{3/2},  y = X + u X'   u = A / T = w^{1/5}
// with X(0) = 0, X'(0) = 1. The normal force is proportional to -X''.
// For eq. 25 the force is continued oddly once y < 0 (attraction, as eq. 24 gives once X + uX' < 0):
// this only matters for the `separation` end.
#include "roughgas/contact/contact_model.hpp"

#include <cmath>

namespace roughgas {

// Acceleration X'' at compression X >= 0 and compression rate V = X'.
inline double normal_acceleration(NormalForm form, double X, double V, double u) {
    if (form == NormalForm::eq24) {
        return -std::sqrt(X) * (X + u * V);
    }
    const double y = X + u * V;
    return y >= 0 ? -y * std::sqrt(y) : -y * std::sqrt(-y);
}

// The quantity whose first zero ends a `force` contact: the normal force has the sign of this.
inline double normal_force_sign_function(NormalForm /*form*/, double X, double V, double u) {
    return X + u * V; // both forms: force > 0 (repulsive) iff X + u V > 0 (with X > 0 for eq. 24)
}

} // namespace roughgas
