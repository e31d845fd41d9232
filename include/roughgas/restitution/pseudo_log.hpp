#pragma once
// A logarithm read off the IEEE-754 bits: for g = m 2^e (1 <= m < 2), pseudo_log2(g) = e + (m - 1).
// Continuous, strictly increasing and exact at powers of two; costs a few integer operations, so
// tables over many decades can be indexed without calling std::log in the hot loop.
#include <bit>
#include <cmath>
#include <cstdint>

namespace roughgas {

inline double pseudo_log2(double g) { // g > 0, finite, normal
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(g);
    const int e = static_cast<int>(bits >> 52) - 1023;
    const double frac = static_cast<double>(bits & ((std::uint64_t{1} << 52) - 1)) * 0x1p-52;
    return e + frac;
}

inline double pseudo_exp2(double x) { // inverse of pseudo_log2
    const double e = std::floor(x);
    return std::ldexp(1.0 + (x - e), static_cast<int>(e));
}

} // namespace roughgas
