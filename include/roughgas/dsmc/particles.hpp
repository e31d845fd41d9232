#pragma once
// Particle stores for the collision step. The hot loop picks two random grains per candidate pair,
// so a store is laid out for one random access per grain:
//
//   RoughPacked  48 bytes per grain, {v, omega} unpadded: half the grains straddle two lines
//                (rough policies: default)
//   SmoothAoS    32 bytes per grain, {v, pad}: two grains per cache line, never straddling; omega in a
//                separate cold array that the collision step never touches (smooth policies: default)
//   RoughAoS     64 bytes per grain, {v, omega} in one aligned cache line   (measured, not used)
//   RoughSoA     v and omega in two arrays: two cache lines per grain        (measured, not used)
//   SmoothPacked 24 bytes per grain (measured, not used)
//
// Measured in tests/bench/dsmc_bench.cpp (BM_Layout_* against BM_Case_*), N = 1e6, one core,
// interleaved: RoughPacked 10-18 % faster than RoughAoS in three runs (a quarter less memory to
// stream; the second line of a straddling grain is the adjacent one, fetched with it), SmoothPacked
// 3-15 % faster in two runs and 21 % slower in a third: the defaults are StoreFor below.
//
// Storage comes from HugePageBuffer (core/huge_page_buffer.hpp): on huge pages, so that a random
// grain access costs no page walk.
//
// Particles of species s occupy the index range [offset_s, offset_s + count_s) (dsmc/species.hpp):
// no species field is stored. The grains never move: the engine sorts 4-byte indices into speed
// classes and groups (dsmc/engine.hpp), so a run needs bytes_per_particle + 4 (+ 2 of scratch
// at a step start) bytes per grain.
#include "roughgas/core/huge_page_buffer.hpp"
#include "roughgas/core/prefetch.hpp"
#include "roughgas/core/vec.hpp"

#include <cstddef>
#include <string_view>
#include <type_traits>

namespace roughgas {

// ---- rough stores: v and omega are hot ----

struct alignas(64) RoughGrain {
    static constexpr std::string_view store_name = "RoughAoS";
    Vec3 v;
    Vec3 w; // omega
};
static_assert(sizeof(RoughGrain) == 64);

struct PackedGrain {
    static constexpr std::string_view store_name = "RoughPacked";
    Vec3 v;
    Vec3 w;
};
static_assert(sizeof(PackedGrain) == 48);

// An array of grains {v, omega}: RoughGrain (one aligned cache line each) or PackedGrain (unpadded).
template <class Grain> class RoughArray {
  public:
    static constexpr std::string_view name = Grain::store_name;
    static constexpr bool rotation_hot = true;
    static constexpr std::size_t bytes_per_particle = sizeof(Grain);
    explicit RoughArray(std::size_t n = 0) : g_(n) {}
    std::size_t size() const { return g_.size(); }
    Vec3& v(std::size_t i) { return g_[i].v; }
    Vec3& w(std::size_t i) { return g_[i].w; }
    const Vec3& v(std::size_t i) const { return g_[i].v; }
    const Vec3& w(std::size_t i) const { return g_[i].w; }
    void prefetch(std::size_t i, bool for_write = false) const {
        const char* p = reinterpret_cast<const char*>(&g_[i]);
        prefetch_line(p, for_write);
        if constexpr (alignof(Grain) < 64 || sizeof(Grain) % 64 != 0)
            prefetch_line(p + sizeof(Grain) - 1, for_write); // an unaligned grain may straddle two lines
    }
    Vec3Column velocities() const { return column_of(g_.data(), offsetof(Grain, v)); }
    Vec3Column angular_velocities() const { return column_of(g_.data(), offsetof(Grain, w)); }

  private:
    HugePageBuffer<Grain> g_;
};

using RoughAoS = RoughArray<RoughGrain>;
using RoughPacked = RoughArray<PackedGrain>;

class RoughSoA {
  public:
    static constexpr std::string_view name = "RoughSoA";
    static constexpr bool rotation_hot = true;
    static constexpr std::size_t bytes_per_particle = 2 * sizeof(Vec3);
    explicit RoughSoA(std::size_t n = 0) : v_(n), w_(n) {}
    std::size_t size() const { return v_.size(); }
    Vec3& v(std::size_t i) { return v_[i]; }
    Vec3& w(std::size_t i) { return w_[i]; }
    const Vec3& v(std::size_t i) const { return v_[i]; }
    const Vec3& w(std::size_t i) const { return w_[i]; }
    void prefetch(std::size_t i, bool for_write = false) const {
        prefetch_line(&v_[i], for_write);
        prefetch_line(reinterpret_cast<const char*>(&v_[i]) + sizeof(Vec3) - 1, for_write);
        prefetch_line(&w_[i], for_write);
        prefetch_line(reinterpret_cast<const char*>(&w_[i]) + sizeof(Vec3) - 1, for_write);
    }
    Vec3Column velocities() const { return column_of(v_.data(), 0); }
    Vec3Column angular_velocities() const { return column_of(w_.data(), 0); }

  private:
    HugePageBuffer<Vec3> v_, w_;
};

// ---- smooth stores: only v is hot; omega is kept (the moments report T_rot) but never touched ----

struct alignas(32) SmoothGrain {
    Vec3 v;
};
static_assert(sizeof(SmoothGrain) == 32);

class SmoothAoS {
  public:
    static constexpr std::string_view name = "SmoothAoS";
    static constexpr bool rotation_hot = false;
    static constexpr std::size_t bytes_per_particle = sizeof(SmoothGrain) + sizeof(Vec3);
    explicit SmoothAoS(std::size_t n = 0) : g_(n), w_(n) {}
    std::size_t size() const { return g_.size(); }
    Vec3& v(std::size_t i) { return g_[i].v; }
    const Vec3& v(std::size_t i) const { return g_[i].v; }
    // Cold: initialisation and observers only.
    Vec3& w(std::size_t i) { return w_[i]; }
    const Vec3& w(std::size_t i) const { return w_[i]; }
    void prefetch(std::size_t i, bool for_write = false) const { prefetch_line(&g_[i], for_write); }
    Vec3Column velocities() const { return column_of(g_.data(), offsetof(SmoothGrain, v)); }
    Vec3Column angular_velocities() const { return column_of(w_.data(), 0); }

  private:
    HugePageBuffer<SmoothGrain> g_;
    HugePageBuffer<Vec3> w_;
};

class SmoothPacked {
  public:
    static constexpr std::string_view name = "SmoothPacked";
    static constexpr bool rotation_hot = false;
    static constexpr std::size_t bytes_per_particle = 2 * sizeof(Vec3);
    explicit SmoothPacked(std::size_t n = 0) : v_(n), w_(n) {}
    std::size_t size() const { return v_.size(); }
    Vec3& v(std::size_t i) { return v_[i]; }
    const Vec3& v(std::size_t i) const { return v_[i]; }
    Vec3& w(std::size_t i) { return w_[i]; }
    const Vec3& w(std::size_t i) const { return w_[i]; }
    void prefetch(std::size_t i, bool for_write = false) const {
        prefetch_line(&v_[i], for_write);
        prefetch_line(reinterpret_cast<const char*>(&v_[i]) + sizeof(Vec3) - 1, for_write);
    }
    Vec3Column velocities() const { return column_of(v_.data(), 0); }
    Vec3Column angular_velocities() const { return column_of(w_.data(), 0); }

  private:
    HugePageBuffer<Vec3> v_, w_;
};

// The store a run uses for a restitution policy (see the table at the top): omega only where the
// policy reads it.
template <class Policy> using StoreFor = std::conditional_t<Policy::needs_rotation, RoughPacked, SmoothAoS>;

} // namespace roughgas
