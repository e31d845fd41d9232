#pragma once
// 3-vectors of the hot loop: a plain aggregate of three doubles (24 bytes, trivially copyable).
//
// Measured against Eigen::Vector3d: the collision rule (collision/rule.hpp) on grains in L1 costs
// 12 ns per collision with either (-O3 -march=native, same code generated up to noise). The plain
// struct is kept: no alignment or expression-template surprises, a known size inside the 64-byte
// grain of the particle store, named fields.
#include <cmath>
#include <cstddef>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace roughgas {

struct Vec3 {
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Vec3&, const Vec3&) = default;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator-(const Vec3& a) {
    return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(double s, const Vec3& a) {
    return {s * a.x, s * a.y, s * a.z};
}
inline Vec3 operator*(const Vec3& a, double s) {
    return {s * a.x, s * a.y, s * a.z};
}
inline Vec3& operator+=(Vec3& a, const Vec3& b) {
    a.x += b.x;
    a.y += b.y;
    a.z += b.z;
    return a;
}
inline Vec3& operator-=(Vec3& a, const Vec3& b) {
    a.x -= b.x;
    a.y -= b.y;
    a.z -= b.z;
    return a;
}
inline Vec3& operator*=(Vec3& a, double s) {
    a.x *= s;
    a.y *= s;
    a.z *= s;
    return a;
}

// sqrt of x >= 0 as one instruction. std::sqrt must set errno for x < 0, and GCC (without
// -fno-math-errno) then emits a library call on paths it deems cold, such as the accepted branch
// of the collision loop (measured: 4% of the loop in sqrt@plt).
inline double sqrt_nonneg(double x) {
#if defined(__SSE2__)
    return _mm_cvtsd_f64(_mm_sqrt_sd(_mm_set_sd(x), _mm_set_sd(x)));
#else
    return std::sqrt(x);
#endif
}

inline double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline double norm2(const Vec3& a) {
    return dot(a, a);
}
inline double norm(const Vec3& a) {
    return sqrt_nonneg(norm2(a));
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// A read-only column of Vec3 with a byte stride: how observers read v or omega of any particle
// store layout (dsmc/particles.hpp) without knowing it.
struct Vec3Column {
    const std::byte* base = nullptr;
    std::size_t stride = sizeof(Vec3);
    const Vec3& operator[](std::size_t i) const { return *reinterpret_cast<const Vec3*>(base + i * stride); }
};

template <class T> Vec3Column column_of(const T* first, std::size_t member_offset) {
    return {reinterpret_cast<const std::byte*>(first) + member_offset, sizeof(T)};
}

} // namespace roughgas
