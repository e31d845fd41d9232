#pragma once
// Random streams keyed by what they are for, never by thread (style.md §2.10).
//
// Boost.Random 1.74 has no counter-based engine, so each stream is a small engine, xoshiro256++
// (Blackman & Vigna 2019: 256-bit state, period 2^256 - 1, passes BigCrush), whose state is
// filled by splitmix64 from a hash of the key (seed, purpose, replica, step, unit). Two keys give
// unrelated streams; the same key gives the same stream on any machine and any thread count.
// The engine is a UniformRandomBitGenerator (usable with Boost.Random and <random> distributions)
// and streams its state with << and >> (what a bit-identical checkpoint needs).
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>

namespace roughgas {

// Every purpose that draws random numbers, listed once. Append new purposes at the end: the
// numeric value is part of the key, so renumbering changes every run's trajectory.
enum class Stream : std::uint64_t {
    initial_velocity = 1, // dsmc/init.hpp: Maxwellian v, one stream per species (unit = species)
    initial_rotation = 2, // dsmc/init.hpp: Maxwellian omega, one stream per species
    collisions = 3,       // dsmc/engine.hpp: candidate clock, pair choice, acceptance, impact direction;
                          // one stream per (step, work unit)
    partition = 4,        // reserved: per-step random partition of the particles into work units
    test = 5,             // tests only
};

// splitmix64 (Steele, Lea & Flood 2014): the output function of one step from state x.
constexpr std::uint64_t splitmix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

class Xoshiro256pp {
  public:
    using result_type = std::uint64_t;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return ~result_type{0}; }

    Xoshiro256pp() : Xoshiro256pp(0) {}
    // The four state words are successive splitmix64 outputs from `seed` (never all zero).
    explicit Xoshiro256pp(std::uint64_t seed) {
        for (auto& w : s_)
            w = splitmix64(seed);
    }

    result_type operator()() {
        const std::uint64_t result = std::rotl(s_[0] + s_[3], 23) + s_[0];
        const std::uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = std::rotl(s_[3], 45);
        return result;
    }

    // The four state words as they are, for a checkpoint's binary encoding (dsmc/engine.hpp).
    std::array<std::uint64_t, 4> state() const { return {s_[0], s_[1], s_[2], s_[3]}; }
    void set_state(const std::array<std::uint64_t, 4>& s) {
        for (int k = 0; k < 4; ++k)
            s_[k] = s[static_cast<std::size_t>(k)];
    }

    friend bool operator==(const Xoshiro256pp&, const Xoshiro256pp&) = default;
    friend std::ostream& operator<<(std::ostream& os, const Xoshiro256pp& r) {
        return os << r.s_[0] << ' ' << r.s_[1] << ' ' << r.s_[2] << ' ' << r.s_[3];
    }
    friend std::istream& operator>>(std::istream& is, Xoshiro256pp& r) {
        return is >> r.s_[0] >> r.s_[1] >> r.s_[2] >> r.s_[3];
    }

  private:
    std::uint64_t s_[4];
};

using Rng = Xoshiro256pp;

struct StreamKey {
    std::uint64_t seed = 0;
    Stream purpose = Stream::test;
    std::uint64_t replica = 0;
    std::uint64_t step = 0;
    std::uint64_t unit = 0;
};

// Hash of the key: each word is absorbed through a splitmix64 round, so every bit of every field
// reaches every bit of the result.
constexpr std::uint64_t stream_hash(const StreamKey& k) {
    std::uint64_t h = 0x726f756768676173ULL; // "roughgas"
    for (std::uint64_t w : {k.seed, static_cast<std::uint64_t>(k.purpose), k.replica, k.step, k.unit}) {
        std::uint64_t x = h ^ w;
        h = splitmix64(x);
    }
    return h;
}

inline Rng make_stream(const StreamKey& k) {
    return Rng(stream_hash(k));
}
inline Rng make_stream(std::uint64_t seed, Stream purpose, std::uint64_t step, std::uint64_t unit,
                       std::uint64_t replica = 0) {
    return make_stream(StreamKey{seed, purpose, replica, step, unit});
}

// Uniform double in [0, 1): the top 53 bits.
inline double uniform01(Rng& r) {
    return static_cast<double>(r() >> 11) * 0x1p-53;
}
// Uniform double in (0, 1]: never zero, so its logarithm is finite.
inline double uniform01_open0(Rng& r) {
    return static_cast<double>((r() >> 11) + 1) * 0x1p-53;
}
// Uniform double in (-1, 1): -1 + (k + 1/2) 2^-51 with k the top 52 bits (exact, symmetric, never +-1).
inline double uniform_pm1(Rng& r) {
    return (static_cast<double>(r() >> 12) + 0.5) * 0x1p-51 - 1.0;
}

namespace detail {
// The rare branch of uniform_index (probability < n / 2^64), kept out of line.
[[gnu::noinline, gnu::cold]] inline std::uint64_t uniform_index_reject(Rng& r, std::uint64_t n,
                                                                       __uint128_t m) {
    const std::uint64_t threshold = (0 - n) % n;
    while (static_cast<std::uint64_t>(m) < threshold)
        m = static_cast<__uint128_t>(r()) * n;
    return static_cast<std::uint64_t>(m >> 64);
}
} // namespace detail

// Uniform integer in [0, n), n >= 1, exactly (Lemire 2019: multiply-shift with rejection of the
// 2^64 mod n low values that would make some results more likely). Always inlined: the collision
// loop draws two per candidate, and a call there spills the loop's registers.
[[gnu::always_inline]] inline std::uint64_t uniform_index(Rng& r, std::uint64_t n) {
    const __uint128_t m = static_cast<__uint128_t>(r()) * n;
    if (static_cast<std::uint64_t>(m) < n) [[unlikely]]
        return detail::uniform_index_reject(r, n, m);
    return static_cast<std::uint64_t>(m >> 64);
}

} // namespace roughgas
