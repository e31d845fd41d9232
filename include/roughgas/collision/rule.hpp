#pragma once
// The collision rule of docs/model.md §3 as a pure function: two grain states, the unit normal n
// (pointing from j to i) and the pair's restitution policy in; the new states and a
// CollisionRecord out. Unequal species are covered by the pair constants (m_eff, kappa, radii).
//
//   g   = v_i - v_j - R_i omega_i x n - R_j omega_j x n,   g^N = (g.n) n,   g^T = g - g^N
//   P   = -m_eff (1 + alpha) g^N - kappa m_eff (1 + beta) g^T                  (impulse on i)
//   v_i' = v_i + P/m_i,   v_j' = v_j - P/m_j
//   omega_i' = omega_i - (n x P)/(q_i m_i R_i),   omega_j' = omega_j - (n x P)/(q_j m_j R_j)
//
// With p = P/m_eff = a n - b g^T, a = -(1 + alpha)(g.n), b = kappa (1 + beta), and n x P = -m_eff b (n x g)
// (n x g^N = 0). The rule conserves momentum and the angular momentum about the contact point and
// gives (g^N)' = -alpha g^N, (g^T)' = -beta g^T (tests/collision/rule_test.cpp).
#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/collision/record.hpp"
#include "roughgas/core/vec.hpp"

#include <cmath>
#include <limits>

namespace roughgas {

// Rough grains: reads and updates v and omega of both. The policy decides alpha and beta.
template <class Policy>
[[gnu::always_inline]] inline CollisionRecord collide(const PairConstants& pc, const Policy& policy,
                                                      Vec3& v_i, Vec3& w_i, Vec3& v_j, Vec3& w_j,
                                                      const Vec3& n) {
    static_assert(Policy::needs_rotation, "smooth policies use the overload without omega");
    const Vec3 g_c = v_i - v_j;
    const Vec3 g = g_c - cross(pc.R_i * w_i + pc.R_j * w_j, n);
    const double g_dot_n = dot(g, n); // = g_c . n: rotation has no normal part
    const Vec3 g_T = g - g_dot_n * n;
    const double g_n = std::abs(g_dot_n);
    const double g_t = sqrt_nonneg(norm2(g_T));
    const Coefficients c = policy(g_n, g_t);

    const double a = -(1.0 + c.alpha) * g_dot_n;
    const double b = pc.kappa * (1.0 + c.beta);
    const Vec3 p = a * n - b * g_T; // P/m_eff
    v_i += pc.m_eff_over_m_i * p;
    v_j -= pc.m_eff_over_m_j * p;
    const Vec3 n_x_g = cross(n, g_T); // = n x g
    w_i += (pc.spin_i * (1.0 + c.beta)) * n_x_g;
    w_j += (pc.spin_j * (1.0 + c.beta)) * n_x_g;

    CollisionRecord r;
    // Translational: sum of (m/2)(|v'|^2 - |v|^2) = P.g_c + |P|^2/(2 m_eff); the total is docs/model.md §3.
    r.dE_tr = pc.m_eff * (dot(p, g_c) + 0.5 * norm2(p));
    const double dE =
        0.5 * pc.m_eff *
        ((c.alpha * c.alpha - 1.0) * g_n * g_n + pc.kappa * (c.beta * c.beta - 1.0) * g_t * g_t);
    r.dE_rot = dE - r.dE_tr;
    r.g_n = g_n;
    r.g_t = g_t;
    r.alpha = c.alpha;
    r.beta = c.beta;
    r.beta_clamped = c.beta_clamped;
    return r;
}

// Smooth grains (beta = -1), given the normal part g^N = (g . n) n of the relative velocity: only the
// normal impulse P = -m_eff (1 + alpha) g^N acts (docs/model.md §3), so n itself is never needed (the
// hard-sphere kernel draws g^N directly, sampling.hpp). g_n = |g^N|; omega is neither read nor
// written, and g_t is not evaluated (NaN in the record).
template <class Policy>
[[gnu::always_inline]] inline CollisionRecord
collide_normal_part(const PairConstants& pc, const Policy& policy, Vec3& v_i, Vec3& v_j, const Vec3& g_N) {
    static_assert(!Policy::needs_rotation, "rough policies need omega");
    const double g_n2 = norm2(g_N);
    // Dropped by the compiler where neither the policy nor the observer reads it.
    const double g_n = sqrt_nonneg(g_n2);
    const Coefficients c = policy(g_n, std::numeric_limits<double>::quiet_NaN());
    const double a = 1.0 + c.alpha;
    v_i -= (pc.m_eff_over_m_i * a) * g_N;
    v_j += (pc.m_eff_over_m_j * a) * g_N;

    CollisionRecord r;
    r.dE_tr = 0.5 * pc.m_eff * (c.alpha * c.alpha - 1.0) * g_n2;
    r.dE_rot = 0;
    r.g_n = g_n;
    r.g_t = std::numeric_limits<double>::quiet_NaN();
    r.alpha = c.alpha;
    r.beta = -1.0;
    return r;
}

// Smooth grains given the unit normal n (from j to i).
template <class Policy>
inline CollisionRecord collide(const PairConstants& pc, const Policy& policy, Vec3& v_i, Vec3& v_j,
                               const Vec3& n) {
    return collide_normal_part(pc, policy, v_i, v_j, dot(v_i - v_j, n) * n);
}

} // namespace roughgas
