#pragma once
// Sampling of the impact direction (docs/model.md §4): given a colliding pair with relative velocity
// g_c = v_i - v_j, the unit normal n (from j to i) lies on the approaching hemisphere g_c . n < 0
// with density proportional to |g_c^ . n|.
#include "roughgas/core/rng.hpp"
#include "roughgas/core/vec.hpp"

#include <cmath>

namespace roughgas {

// Uniform on the unit sphere (Marsaglia 1972): (x, y) uniform in the unit disc by rejection
// (acceptance pi/4), then (2x sqrt(1-s), 2y sqrt(1-s), 1 - 2s) with s = x^2 + y^2. No trigonometry.
template <Generator64 G> [[gnu::always_inline]] inline Vec3 uniform_direction(G& rng) {
    double x, y, s;
    do {
        x = uniform_pm1(rng);
        y = uniform_pm1(rng);
        s = x * x + y * y;
    } while (s >= 1.0);
    const double f = 2.0 * sqrt_nonneg(1.0 - s);
    return {x * f, y * f, 1.0 - 2.0 * s};
}

// n = -(g^ + u)/|g^ + u| with u uniform on the unit sphere. Exact: the point g^ + u is uniform on the
// unit sphere centred at g^, which passes through the origin; seen from the origin, the ray at
// angle theta to g^ meets it at distance r = 2 cos(theta) and at incidence angle theta to its
// normal, so the solid-angle density is r^2/cos(theta) = 4 cos(theta): proportional to cos(theta)
// on the hemisphere around g^ (tests/dsmc/sampling_test.cpp checks the law of g_n = |g_c . n|).
// `g_abs` = |g_c| > 0. The degenerate u = -g^ (probability 0) is redrawn.
template <Generator64 G>
[[gnu::always_inline]] inline Vec3 sample_impact_normal(G& rng, const Vec3& g_c, double g_abs) {
    for (;;) {
        const Vec3 d = g_c + g_abs * uniform_direction(rng); // |g_c| (g^ + u)
        const double d2 = norm2(d);
        if (d2 > 0)
            return (-1.0 / sqrt_nonneg(d2)) * d;
    }
}

// The normal part g^N = (g_c . n) n of the relative velocity (docs/model.md §1) at an impact drawn as
// in sample_impact_normal, without forming n: with n = -(g^ + u)/|g^ + u|, g_c . n = -|g_c| |g^ + u|/2,
// so g^N = (g_c + |g_c| u)/2. No square root and no division: what a smooth collision needs (it
// acts along g^N only, rule.hpp), drawn from the same numbers as the normal (the test checks both).
template <Generator64 G>
[[gnu::always_inline]] inline Vec3 sample_impact_normal_part(G& rng, const Vec3& g_c, double g_abs) {
    return 0.5 * (g_c + g_abs * uniform_direction(rng));
}

} // namespace roughgas
