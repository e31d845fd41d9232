// The random building blocks of the collision sampling: the impact direction (docs/model.md §4) and
// exact uniform indices. Chi-square statistics with a threshold at p = 1e-3 (each test can fail
// by chance once in a thousand runs; the seeds are fixed, so a pass is reproducible).
#include "roughgas/collision/sampling.hpp"
#include "roughgas/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace roughgas {
namespace {

// Pearson chi-square of counts against equal expectation.
double chi_square(const std::vector<long>& counts, double samples) {
    const double e = samples / static_cast<double>(counts.size());
    double x = 0;
    for (long c : counts)
        x += (c - e) * (c - e) / e;
    return x;
}
// Upper 1e-3 quantiles of chi-square: 19 dof 43.82, 9 dof 27.88, 99 dof 148.23.
constexpr double chi2_19 = 43.82, chi2_9 = 27.88;

TEST(ImpactNormal, HasDensityProportionalToCosineOnTheApproachingHemisphere) {
    // For density 2 mu on mu = |g^ . n| in [0, 1] (the cosine law with d Omega = d mu d phi),
    // mu^2 is uniform; the azimuth phi around g^ is uniform. 1e6 samples, 20 bins each.
    Rng rng = make_stream(21, Stream::test, 0, 0);
    const Vec3 g{0.3, -1.7, 0.8};
    const double g_abs = norm(g);
    const Vec3 gh = (1.0 / g_abs) * g;
    // An orthonormal frame (gh, e1, e2) for the azimuth.
    const Vec3 e1 = (1.0 / norm(cross(gh, Vec3{1, 0, 0}))) * cross(gh, Vec3{1, 0, 0});
    const Vec3 e2 = cross(gh, e1);
    const int n = 1000000;
    std::vector<long> mu2_bins(20, 0), phi_bins(20, 0);
    for (int k = 0; k < n; ++k) {
        const Vec3 nv = sample_impact_normal(rng, g, g_abs);
        ASSERT_NEAR(norm(nv), 1.0, 1e-14);
        const double c = dot(gh, nv);
        ASSERT_LT(c, 0.0) << "n must point against g (approaching pair)";
        const double mu = -c;
        mu2_bins[std::min(19, static_cast<int>(mu * mu * 20))]++;
        const double phi = std::atan2(dot(nv, e2), dot(nv, e1)) + std::numbers::pi;
        phi_bins[std::min(19, static_cast<int>(phi / (2 * std::numbers::pi) * 20))]++;
    }
    EXPECT_LT(chi_square(mu2_bins, n), chi2_19);
    EXPECT_LT(chi_square(phi_bins, n), chi2_19);
    // A sampler uniform on the hemisphere (mu uniform) would put 1/sqrt(20) of the samples into
    // the first mu^2 bin instead of 1/20: a chi-square of order 1e5.
}

TEST(ImpactNormal, NormalPartIsThatOfTheSameDrawnNormal) {
    // sample_impact_normal_part must return (g . n) n for the n that sample_impact_normal draws from
    // the same random numbers (whose law the test above checks): two copies of one stream.
    Rng rng = make_stream(23, Stream::test, 0, 0);
    for (const Vec3 g : {Vec3{0.3, -1.7, 0.8}, Vec3{1e-9, 0, 0}, Vec3{-4e5, 2e5, 1e5}}) {
        const double g_abs = norm(g);
        for (int k = 0; k < 10000; ++k) {
            Rng a = rng, b = rng;
            const Vec3 n = sample_impact_normal(a, g, g_abs);
            const Vec3 g_N = sample_impact_normal_part(b, g, g_abs);
            ASSERT_EQ(a, b) << "both must consume the same numbers";
            const Vec3 want = dot(g, n) * n;
            ASSERT_LE(norm(g_N - want), 1e-14 * g_abs) << "k = " << k;
            rng = a;
        }
    }
}

TEST(UniformIndex, IsUniformForSmallAndAwkwardRanges) {
    Rng rng = make_stream(22, Stream::test, 0, 0);
    for (std::uint64_t m : {std::uint64_t{10}, std::uint64_t{3}}) {
        std::vector<long> bins(m, 0);
        const int n = 300000;
        for (int k = 0; k < n; ++k) {
            const std::uint64_t x = uniform_index(rng, m);
            ASSERT_LT(x, m);
            bins[x]++;
        }
        EXPECT_LT(chi_square(bins, n), m == 10 ? chi2_9 : 13.82) << "m = " << m; // 2 dof: 13.82
    }
    // A range near 2^64: the rejection branch keeps every value below it reachable and in range.
    const std::uint64_t big = (std::uint64_t{1} << 63) + 12345;
    for (int k = 0; k < 1000; ++k)
        ASSERT_LT(uniform_index(rng, big), big);
}

TEST(Streams, AreKeyedAndReproducible) {
    Rng a = make_stream(1, Stream::collisions, 5, 0, 0), b = make_stream(1, Stream::collisions, 5, 0, 0);
    EXPECT_EQ(a(), b());
    Rng c = make_stream(1, Stream::collisions, 6, 0, 0), d = make_stream(1, Stream::collisions, 5, 1, 0),
        e = make_stream(1, Stream::collisions, 5, 0, 1), f = make_stream(2, Stream::collisions, 5, 0, 0),
        g = make_stream(1, Stream::initial_velocity, 5, 0, 0);
    const auto first = make_stream(1, Stream::collisions, 5, 0, 0)();
    for (Rng* r : {&c, &d, &e, &f, &g})
        EXPECT_NE((*r)(), first);
    // State streaming: a restored engine continues identically (checkpoints).
    Rng x = make_stream(9, Stream::test, 0, 0);
    for (int k = 0; k < 10; ++k)
        x();
    std::stringstream ss;
    ss << x;
    Rng y;
    ss >> y;
    EXPECT_EQ(x, y);
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(x(), y());
    Rng z; // the raw words, as the engine's binary state holds them (dsmc/engine.hpp save_state)
    z.set_state(x.state());
    EXPECT_EQ(z, x);
    EXPECT_EQ(z(), x());
    // Uniform doubles stay in their intervals at the extremes.
    EXPECT_GT(uniform01_open0(x), 0.0);
    EXPECT_LT(uniform01(x), 1.0);
}

// The collision loop's generator (rng.hpp): each of its eight lanes is exactly xoshiro256++ from its
// four seed words, and the words come out round by round, lanes in order, across several refills.
TEST(Streams, EightLaneGeneratorIsXoshiroLaneByLane) {
    constexpr int L = CollisionRng::lanes, B = CollisionRng::buffer_size;
    const StreamKey key{3, Stream::collisions, 1, 7, 2};
    CollisionRng x8 = make_collision_stream(key);
    std::uint64_t seed = stream_hash(key);
    std::vector<Xoshiro256pp> lanes(L);
    for (auto& lane : lanes) {
        std::array<std::uint64_t, 4> s;
        for (auto& w : s)
            w = splitmix64(seed); // lane l: words 4l .. 4l + 3 of the splitmix64 sequence
        lane.set_state(s);
    }
    for (int k = 0; k < 5 * B + 3; ++k)
        ASSERT_EQ(x8(), lanes[static_cast<std::size_t>(k % L)]()) << "word " << k;
    // Its checkpoint words continue it exactly, mid-buffer; a position past the buffer is refused.
    CollisionRng copy;
    copy.set_state(x8.state());
    EXPECT_EQ(copy, x8);
    for (int k = 0; k < 2 * B; ++k)
        ASSERT_EQ(copy(), x8());
    auto bad = x8.state();
    bad.back() = B + 1;
    EXPECT_THROW(copy.set_state(bad), std::runtime_error);
    // Distinct keys, distinct streams.
    EXPECT_NE(make_collision_stream(key)(), make_collision_stream(StreamKey{3, Stream::collisions, 1, 7, 3})());
}

} // namespace
} // namespace roughgas
