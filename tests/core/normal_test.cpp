// The ziggurat normal deviates (core/normal.hpp) against the standard normal law: moments, the
// probabilities of bins of the CDF (a chi-square test) and the tail beyond the base layer.
#include "roughgas/core/normal.hpp"
#include "roughgas/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace roughgas {
namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

TEST(ZigguratNormal, MomentsAndBinsAreThoseOfTheStandardNormal) {
    // 4e6 deviates: the mean's standard error is 5e-4, the variance's 7e-4, the fourth moment's
    // (sqrt(96/n)) 4.9e-3; tolerance 5 of them. 40 bins of equal probability under the normal plus two
    // tails beyond +-R: chi-square with 41 degrees of freedom, refused above 80 (p ~ 2e-4).
    constexpr int n = 4000000;
    CollisionRng g = make_collision_stream(StreamKey{17, Stream::test, 0, 0, 0});
    const ZigguratNormal normal;
    double s1 = 0, s2 = 0, s4 = 0;
    constexpr int bins = 40;
    std::vector<double> edges;
    for (int k = 1; k < bins; ++k) { // inverse CDF by bisection: the edges of equal-probability bins
        double lo = -10, hi = 10;
        for (int it = 0; it < 200; ++it)
            (normal_cdf(0.5 * (lo + hi)) < static_cast<double>(k) / bins ? lo : hi) = 0.5 * (lo + hi);
        edges.push_back(0.5 * (lo + hi));
    }
    std::vector<double> count(bins, 0.0);
    double beyond_R = 0;
    for (int i = 0; i < n; ++i) {
        const double x = normal(g);
        s1 += x;
        s2 += x * x;
        s4 += x * x * x * x;
        std::size_t b = 0;
        while (b < edges.size() && x >= edges[b])
            ++b;
        count[b] += 1;
        beyond_R += std::abs(x) > ZigguratNormal::R;
    }
    EXPECT_NEAR(s1 / n, 0.0, 5 * std::sqrt(1.0 / n));
    EXPECT_NEAR(s2 / n, 1.0, 5 * std::sqrt(2.0 / n));
    EXPECT_NEAR(s4 / n, 3.0, 5 * std::sqrt(96.0 / n));
    double chi2 = 0;
    const double expected = static_cast<double>(n) / bins;
    for (double c : count)
        chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 80.0);
    // The tail: 2 (1 - Phi(R)) = 2.58e-4 of the deviates, ~1030 of them: 5 Poisson errors.
    const double tail = 2 * (1 - normal_cdf(ZigguratNormal::R)) * n;
    EXPECT_NEAR(beyond_R, tail, 5 * std::sqrt(tail));
}

} // namespace
} // namespace roughgas
