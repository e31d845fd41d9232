#pragma once
// Random streams keyed by what they are for, never by thread.
//
// Boost.Random 1.74 has no counter-based engine, so each stream is a small engine, xoshiro256++
// (Blackman & Vigna 2019: 256-bit state, period 2^256 - 1, passes BigCrush), whose state is
// filled by splitmix64 from a hash of the key (seed, purpose, replica, step, unit). Two keys give
// unrelated streams; the same key gives the same stream on any machine and any thread count.
// The engine is a UniformRandomBitGenerator (usable with Boost.Random and <random> distributions)
// and streams its state with << and >> (what a bit-identical checkpoint needs).
//
// The collision loop draws about 20 words per collision, one at a time, and the scalar
// generator's update is a fifth of that loop's time (measured: a throw-away LCG in its place ran
// 16 % faster for rough and 27 % for smooth grains). Its streams are therefore
// Xoshiro256ppX8: eight xoshiro256++ generators updated in lock-step (one SIMD instruction per
// operation for all eight) whose outputs are buffered, so that a draw is a load and an increment.
#include <array>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>

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
    initial_position = 6, // dsmc/spatial_engine.hpp: uniform positions in the box, one stream per species
    cell_collisions = 7,  // dsmc/spatial_engine.hpp: a step's collisions, one stream per (step, unit of cells)
    wall_emission = 8,    // dsmc/spatial_engine.hpp: diffuse walls' emission, one stream per (step, chunk of grains)
    thermostat = 9,       // dsmc/thermostat.hpp: a step's kicks, one stream per (step, species, chunk of grains)
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

// The draws below take any generator of 64-bit words (Rng, CollisionRng).
template <class G>
concept Generator64 = requires(G& g) {
    { g() } -> std::same_as<std::uint64_t>;
};

// Eight xoshiro256++ generators in lock-step, their outputs buffered: the collision loop's streams.
// Lane l is seeded with the words 4l .. 4l + 3 of the splitmix64 sequence from `seed` (Vigna's
// recommended seeding; the eight lanes are unrelated streams of period 2^256 - 1), and a refill
// advances every lane `rounds` times, writing output k of lane l to buffer[k lanes + l]. So the
// words come out in the order lane 0, 1, .., 7 of the first round, then of the second, ...; each
// lane's outputs are exactly those of an Xoshiro256pp with the same state (tests/dsmc/sampling_test.cpp).
class Xoshiro256ppX8 {
  public:
    using result_type = std::uint64_t;
    static constexpr int lanes = 8;
    static constexpr int rounds = 16;
    static constexpr int buffer_size = lanes * rounds;
    // state(): the lanes' words (lane-major), the buffer, and the read position.
    static constexpr std::size_t state_words = 4 * lanes + buffer_size + 1;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return ~result_type{0}; }

    Xoshiro256ppX8() : Xoshiro256ppX8(0) {}
    explicit Xoshiro256ppX8(std::uint64_t seed) {
        for (int l = 0; l < lanes; ++l)
            for (int w = 0; w < 4; ++w)
                s_[w][l] = splitmix64(seed);
    }

    [[gnu::always_inline]] result_type operator()() {
        if (pos_ == buffer_size) [[unlikely]]
            refill();
        return buf_[pos_++];
    }

    std::array<std::uint64_t, state_words> state() const {
        std::array<std::uint64_t, state_words> a{};
        std::size_t k = 0;
        for (int l = 0; l < lanes; ++l)
            for (int w = 0; w < 4; ++w)
                a[k++] = s_[w][l];
        for (std::uint64_t x : buf_)
            a[k++] = x;
        a[k] = pos_;
        return a;
    }
    // Throws std::runtime_error for a read position past the buffer (a malformed checkpoint).
    void set_state(const std::array<std::uint64_t, state_words>& a) {
        if (a[state_words - 1] > static_cast<std::uint64_t>(buffer_size))
            throw std::runtime_error("random stream: read position past the buffer");
        std::size_t k = 0;
        for (int l = 0; l < lanes; ++l)
            for (int w = 0; w < 4; ++w)
                s_[w][l] = a[k++];
        for (std::uint64_t& x : buf_)
            x = a[k++];
        pos_ = static_cast<unsigned>(a[k]);
    }
    friend bool operator==(const Xoshiro256ppX8& a, const Xoshiro256ppX8& b) { return a.state() == b.state(); }

  private:
    // Rare (once per buffer_size draws) and out of line, so that the loop calling operator() keeps
    // its registers.
    [[gnu::noinline]] void refill() {
        // The xoshiro256++ step on all lanes at once (GCC/Clang vector extension: one AVX-512
        // register, or two AVX2 / four SSE2 ones elsewhere); the plain lane loop was not vectorised.
        using V = std::uint64_t __attribute__((vector_size(8 * lanes)));
        V s0, s1, s2, s3;
        std::memcpy(&s0, s_[0], sizeof(V));
        std::memcpy(&s1, s_[1], sizeof(V));
        std::memcpy(&s2, s_[2], sizeof(V));
        std::memcpy(&s3, s_[3], sizeof(V));
        for (int r = 0; r < rounds; ++r) {
            const V x = s0 + s3;
            const V out = ((x << 23) | (x >> 41)) + s0;
            std::memcpy(buf_ + r * lanes, &out, sizeof(V));
            const V t = s1 << 17;
            s2 ^= s0;
            s3 ^= s1;
            s1 ^= s2;
            s0 ^= s3;
            s2 ^= t;
            s3 = (s3 << 45) | (s3 >> 19);
        }
        std::memcpy(s_[0], &s0, sizeof(V));
        std::memcpy(s_[1], &s1, sizeof(V));
        std::memcpy(s_[2], &s2, sizeof(V));
        std::memcpy(s_[3], &s3, sizeof(V));
        pos_ = 0;
    }

    alignas(64) std::uint64_t s_[4][lanes];
    alignas(64) std::uint64_t buf_[buffer_size]{};
    unsigned pos_ = buffer_size; // the first draw refills
};

using CollisionRng = Xoshiro256ppX8;

inline CollisionRng make_collision_stream(const StreamKey& k) {
    return CollisionRng(stream_hash(k));
}

// Uniform double in [0, 1): the top 53 bits.
template <Generator64 G> inline double uniform01(G& r) {
    return static_cast<double>(r() >> 11) * 0x1p-53;
}
// Uniform double in (0, 1]: never zero, so its logarithm is finite.
template <Generator64 G> inline double uniform01_open0(G& r) {
    return static_cast<double>((r() >> 11) + 1) * 0x1p-53;
}
// Uniform double in (-1, 1): -1 + (k + 1/2) 2^-51 with k the top 52 bits (exact, symmetric, never +-1).
template <Generator64 G> inline double uniform_pm1(G& r) {
    return (static_cast<double>(r() >> 12) + 0.5) * 0x1p-51 - 1.0;
}

namespace detail {
// The rare branch of uniform_index (probability < n / 2^64), kept out of line.
template <Generator64 G>
[[gnu::noinline, gnu::cold]] std::uint64_t uniform_index_reject(G& r, std::uint64_t n,
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
template <Generator64 G> [[gnu::always_inline]] inline std::uint64_t uniform_index(G& r, std::uint64_t n) {
    const __uint128_t m = static_cast<__uint128_t>(r()) * n;
    if (static_cast<std::uint64_t>(m) < n) [[unlikely]]
        return detail::uniform_index_reject(r, n, m);
    return static_cast<std::uint64_t>(m >> 64);
}

} // namespace roughgas
