// The flat cells of the adaptive tables (adaptive_table.hpp) against the tree walk they replace on
// the collision loop: the same interpolant everywhere, NaN exactly where the tree has a direct leaf,
// and the tree itself where a leaf is deeper than the flat grid. The functions have jumps, so the
// tables hold leaves at every depth, direct leaves, and leaves deeper than flat_bits.
#include "roughgas/restitution/adaptive_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace roughgas {
namespace {

// Smooth with a jump at x = 0.3: refined down to max_depth there, direct at the jump itself.
double f1(double x) { return std::sin(3 * x) + (x > 0.3 ? 0.5 : 0.0); }
// Smooth but for a jump across the line y = 0.4 + 0.2 x.
double f2(double x, double y) { return std::cos(x + 2 * y) * 0.6 + (y > 0.4 + 0.2 * x ? 0.4 : 0.0); }

AdaptiveTable1D table1(double lo, double hi, int root_cells, int depth) {
    return AdaptiveTable1D::build(lo, hi, AdaptiveOptions{root_cells, 1, depth, 1e-9, false},
                                  [](std::span<const double> xs, std::span<const double>, std::span<double> out) {
                                      for (std::size_t i = 0; i < xs.size(); ++i) out[i] = f1(xs[i]);
                                  });
}

TEST(AdaptiveTable, FlatCellsOfOneVariableAreTheTreesInterpolant) {
    const AdaptiveTable1D t = table1(-1.0, 2.0, 4, 8); // depth 8 > flat_bits: deeper leaves exist
    ASSERT_GT(t.stats().direct_leaves, 0u);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.2, 2.2);
    int deep = 0, direct = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = i % 4 ? u(rng) : 0.3 + 1e-3 * (u(rng) - 0.5); // a quarter near the jump
        const double a = t(x), b = t.tree(x);
        if (std::isnan(b)) {
            EXPECT_TRUE(std::isnan(a)) << x;
            ++direct;
            continue;
        }
        ASSERT_FALSE(std::isnan(a)) << x;
        EXPECT_NEAR(a, b, 1e-13) << x;
        deep += std::abs(x - 0.3) < 3.0 / 64; // within a flat cell of the jump: leaves deeper than it
    }
    EXPECT_GT(direct, 0);
    EXPECT_GT(deep, 1000);
}

TEST(AdaptiveTable, LookUpFromTheBitsOfTheSpeedIsTheLookUpAtItsPseudoLogarithm) {
    // Whole binades (x = pseudo_log2 g from -6 to 3), 4 root cells each: 2^6 flat cells per binade.
    const AdaptiveTable1D t = table1(-6.0, 3.0, 4, 8);
    ASSERT_EQ(t.binade_bits(), -1) << "4 root cells over 9 binades are not a power of two per binade";
    const AdaptiveTable1D b = table1(-6.0, 3.0, 36, 8);
    ASSERT_EQ(b.binade_bits(), 6);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-6.5, 3.5);
    for (int i = 0; i < 200000; ++i) {
        const double g = std::exp2(u(rng));
        const double x = pseudo_log2(g);
        const double a = b.at_speed(g), ref = b.tree(x);
        if (std::isnan(ref)) {
            EXPECT_TRUE(std::isnan(a)) << g;
            continue;
        }
        ASSERT_FALSE(std::isnan(a)) << g;
        // The bits give the cell coordinate exactly; pseudo_log2 rounds x to 53 bits first.
        EXPECT_NEAR(a, ref, 1e-12) << g;
        const double c = t.at_speed(g), cref = t.tree(x); // the converting path of a table off the binades
        if (std::isnan(cref))
            EXPECT_TRUE(std::isnan(c)) << g;
        else
            EXPECT_NEAR(c, cref, 1e-12) << g;
    }
    EXPECT_TRUE(std::isnan(b.at_speed(std::exp2(-6.0) * (1 - 1e-16)))) << "below the table";
    EXPECT_FALSE(std::isnan(b.at_speed(std::exp2(-6.0)))) << "its first point";
    EXPECT_TRUE(std::isnan(b.at_speed(8.0))) << "at its end";
    EXPECT_TRUE(std::isnan(b.at_speed(std::numeric_limits<double>::infinity())));
}

TEST(AdaptiveTable, FlatCellsOfTwoVariablesAreTheTreesInterpolantInSinglePrecision) {
    const AdaptiveTable2D t = AdaptiveTable2D::build(
        0.0, 2.0, 0.0, 1.0, AdaptiveOptions{2, 2, 7, 2e-4, false},
        [](std::span<const double> xs, std::span<const double> ys, std::span<double> out) {
            for (std::size_t i = 0; i < xs.size(); ++i) out[i] = f2(xs[i], ys[i]);
        });
    ASSERT_GT(t.stats().direct_leaves, 0u);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> ux(-0.1, 2.1), uy(-0.1, 1.1), d(-0.01, 0.01);
    int interpolated = 0, direct = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = ux(rng);
        const double y = i % 2 ? uy(rng) : 0.4 + 0.2 * x + d(rng); // half along the jump: deep and direct leaves
        const double a = t(x, y), b = t.tree(x, y);
        if (std::isnan(b)) {
            EXPECT_TRUE(std::isnan(a)) << x << " " << y;
            ++direct;
            continue;
        }
        ASSERT_FALSE(std::isnan(a)) << x << " " << y;
        // The leaf's bilinear re-expressed on the flat cell: the same to round-off (|f| <= 1).
        EXPECT_NEAR(a, b, 1e-13) << x << " " << y;
        ++interpolated;
    }
    EXPECT_GT(direct, 0);
    EXPECT_GT(interpolated, 100000);
    // The top edge y = 1 belongs to the table; just above it does not.
    ASSERT_FALSE(std::isnan(t.tree(0.5, 1.0)));
    EXPECT_NEAR(t(0.5, 1.0), t.tree(0.5, 1.0), 1e-13);
    EXPECT_TRUE(std::isnan(t(0.5, std::nextafter(1.0, 2.0))));
}

} // namespace
} // namespace roughgas
