#pragma once
// A grain's collision with a flat wall (docs/model.md §8), as pure functions of the grain's state,
// the wall's unit normal n (pointing from the wall into the gas) and the wall's velocity U
// (tangential: the walls do not move along n). The wall is the partner j of the collision rule of
// collision/rule.hpp with infinite mass and no spin: m_eff = m, 1/kappa_w = 1 + 1/q, the contact
// velocity g = v - U - R omega x n, the impulse P = -m (1 + alpha) g^N - kappa_w m (1 + beta) g^T on
// the grain alone.
#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/collision/rule.hpp"
#include "roughgas/core/rng.hpp"
#include "roughgas/core/vec.hpp"

#include <cmath>
#include <numbers>

namespace roughgas {

// The pair constants of a grain with the wall: the partner's share of the impulse and its radius
// are 0 (its contact point is on its surface), so collide() leaves the partner's state unchanged.
inline PairConstants wall_pair_constants(const GrainProperties& g) {
    PairConstants p;
    p.m_eff = g.mass;
    p.kappa = g.inertia / (1.0 + g.inertia); // 1/kappa_w = 1 + m/(q m)
    p.sigma = g.radius;
    p.cross_section = 0;
    p.R_i = g.radius;
    p.R_j = 0;
    p.m_eff_over_m_i = 1;
    p.m_eff_over_m_j = 0;
    p.spin_i = p.kappa / (g.inertia * g.radius); // kappa m_eff/(q m R)
    p.spin_j = 0;
    return p;
}

// The rough wall (constant alpha, beta) with a rough grain: v and omega updated.
inline void collide_with_wall(const PairConstants& pc, const RoughConstant& wall, Vec3& v, Vec3& w, const Vec3& U,
                              const Vec3& n) {
    Vec3 v_rel = v - U, v_wall{}, w_wall{};
    collide(pc, wall, v_rel, w, v_wall, w_wall, n);
    v = v_rel + U;
}

// The same wall (beta = -1) with a smooth grain: only the normal velocity changes, to -alpha times it.
inline void collide_with_wall(const PairConstants& pc, const SmoothConstant& wall, Vec3& v, const Vec3& n) {
    Vec3 v_wall{};
    collide_normal_part(pc, wall, v, v_wall, dot(v, n) * n);
}

// Two independent standard normal deviates (Box-Muller).
template <Generator64 G> inline std::pair<double, double> normal_pair(G& r) {
    const double radius = std::sqrt(-2.0 * std::log(uniform01_open0(r)));
    const double angle = 2.0 * std::numbers::pi * uniform01(r);
    return {radius * std::cos(angle), radius * std::sin(angle)};
}

// The diffuse wall: v re-drawn from the distribution of grains leaving a wall at rest in a gas at
// (T, U), f ~ (v - U).n exp(-m |v - U|^2/(2T)) for (v - U).n > 0: the normal speed from the
// flux-weighted density s exp(-m s^2/(2T)) (s = sqrt(-2 (T/m) ln u)), each tangential component
// Gaussian about U's; omega (when `rough`) from the Maxwellian at T, each component N(0, T/J).
template <bool Rough, Generator64 G>
inline void emit_from_diffuse_wall(G& r, double T, double m, double J, const Vec3& U, int axis, double sign,
                                   Vec3& v, Vec3& w) {
    const double c = std::sqrt(T / m);
    const auto [t1, t2] = normal_pair(r);
    const double s = c * std::sqrt(-2.0 * std::log(uniform01_open0(r)));
    double out[3] = {U.x, U.y, U.z};
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    out[axis] = sign * s;
    out[a1] += c * t1;
    out[a2] += c * t2;
    v = {out[0], out[1], out[2]};
    if constexpr (Rough) {
        const double cw = std::sqrt(T / J);
        const auto [w1, w2] = normal_pair(r);
        const auto [w3, unused] = normal_pair(r);
        (void)unused;
        w = {cw * w1, cw * w2, cw * w3};
    }
}

} // namespace roughgas
