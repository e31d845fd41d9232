#pragma once
// What one collision reports: the observers sum these; the rule never measures.
#include <cstdint>

namespace roughgas {

// What a restitution policy (restitution_policy.hpp) decides for one impact.
struct Coefficients {
    double alpha = 1;
    double beta = -1;
    bool beta_clamped = false; // the model's beta left [-1, 1] and was clamped to it
};

struct CollisionRecord {
    double dE_tr = 0;  // change of the pair's translational kinetic energy (<= 0 on average)
    double dE_rot = 0; // change of its rotational kinetic energy (0 exactly when omega is not touched)
    double g_n = 0;    // |g . n| before the collision (docs/model.md §1), > 0
    double g_t = 0;    // |g^T| before the collision; NaN when the rule never reads omega (smooth)
    double alpha = 1;  // the coefficients applied: (g^N)' = -alpha g^N, (g^T)' = -beta g^T
    double beta = -1;
    bool beta_clamped =
        false; // the model's beta was outside [-1, 1] and was clamped (restitution_policy.hpp)
};

} // namespace roughgas
