// The steady-state detector and batch means (observables/steady_state.hpp) on synthetic series
// with known statistics: a relaxation plus noise, stationary noise, and a drift.
#include "roughgas/core/rng.hpp"
#include "roughgas/observables/steady_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace roughgas {
namespace {

double gauss(Rng& r) { // Box-Muller
    return std::sqrt(-2.0 * std::log(uniform01_open0(r))) * std::cos(2.0 * std::numbers::pi * uniform01(r));
}

// rows: t, coll_per_particle, X, with X = level + jump exp(-k/tau) + slope k + noise sigma.
std::vector<std::vector<double>> series(std::uint64_t seed, std::size_t n, double jump, double tau,
                                        double slope, double sigma) {
    Rng r = make_stream(seed, Stream::test, 0, 0);
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 0; k < n; ++k) {
        const double x = 1.0 + jump * std::exp(-static_cast<double>(k) / tau) +
                         slope * static_cast<double>(k) + sigma * gauss(r);
        rows.push_back({static_cast<double>(k), static_cast<double>(k), x});
    }
    return rows;
}

const std::vector<std::string> names = {"t", "coll_per_particle", "T_tr"};

SteadyOptions options() {
    SteadyOptions o;
    o.monitored = {"T_tr"};
    return o;
}

// Batch means of iid N(0, 1): the error is 1/sqrt(n) up to the scatter of a 10-batch estimate
// (relative sd ~ 1/sqrt(2 x 9) = 24%); over 20 seeds the mean ratio is within 15% of 1, and the
// means scatter as the errors say (|mean| < 4 err for each).
TEST(BatchMean, ErrorOfIidData) {
    double ratio = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Rng r = make_stream(seed, Stream::test, 1, 0);
        std::vector<double> x(1000);
        for (double& y : x)
            y = gauss(r);
        const SteadyValue v = batch_mean(x, 10);
        EXPECT_LT(std::abs(v.mean), 4 * v.err);
        ratio += v.err * std::sqrt(1000.0) / 20.0;
    }
    EXPECT_NEAR(ratio, 1.0, 0.15);
}

// Fewer values than batches: one value per batch, so the mean and error of 1, 2, 3 are exact
// (2 and sd / sqrt(3) = 1 / sqrt(3)); one value has a mean but no error, none has neither.
TEST(BatchMean, ShortSeriesUseOneValuePerBatch) {
    const std::vector<double> x = {1.0, 2.0, 3.0};
    const SteadyValue v = batch_mean(x, 10);
    EXPECT_DOUBLE_EQ(v.mean, 2.0);
    EXPECT_DOUBLE_EQ(v.err, 1.0 / std::sqrt(3.0));
    const SteadyValue one = batch_mean(std::vector<double>{4.0}, 10);
    EXPECT_EQ(one.mean, 4.0);
    EXPECT_TRUE(std::isnan(one.err));
    EXPECT_TRUE(std::isnan(batch_mean(std::vector<double>{}, 10).mean));
}

// A relaxation from 1 + 5 (time constant 10 rows) with noise 0.01: the transient is resolved
// until 5 exp(-k/10) is well below the noise of a half-window mean (~0.01/sqrt(200) x 3), i.e.
// k > 10 ln(5/0.002) ~ 80; the steady window starts there, not at 0, and not after half the run.
TEST(SteadyState, FindsTheEndOfARelaxation) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const SteadyResult r = find_steady_state(names, series(seed, 600, 5.0, 10.0, 0.0, 0.01), options());
        EXPECT_TRUE(r.reached);
        EXPECT_GT(r.first_row, 40u);
        EXPECT_LT(r.first_row, 120u);
        ASSERT_EQ(r.values.size(), 2u); // coll_per_particle and T_tr (t skipped)
        EXPECT_NEAR(r.values[1].mean, 1.0, 5 * r.values[1].err + 1e-4);
    }
}

TEST(SteadyState, StationaryFromTheStart) {
    int early = 0;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const SteadyResult r = find_steady_state(names, series(seed, 300, 0.0, 1.0, 0.0, 0.1), options());
        EXPECT_TRUE(r.reached);
        early += r.first_row <= 10;
    }
    EXPECT_GE(early, 8); // a 3-sigma criterion with 4-dof errors rejects a stationary window rarely
}

// A drift of 0.2 over the run against noise 0.01 is always resolved: never steady.
TEST(SteadyState, DriftIsNotSteady) {
    const SteadyResult r = find_steady_state(names, series(3, 400, 0.0, 1.0, 0.0005, 0.01), options());
    EXPECT_FALSE(r.reached);
    EXPECT_EQ(r.first_row, 200u);
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// What the scaled-state detector of a cooling run watches: with spins that change (rough grains)
// theta and the rotational cumulants too; with smooth grains, whose T_rot stays the same in every
// row up to the round-off of summing the spins in another order (a box's sort), only the
// translational ones.
TEST(SteadyMonitored, SmoothGrainsLeaveOutTheRotationalRatios) {
    const std::vector<std::string> names = {"t", "coll_per_particle", "T_tr", "T_rot", "theta", "a20", "a02", "a11"};
    const std::vector<std::vector<double>> smooth = {{0, 0, 1, 0.3, 0.3, 0, 0, 0},
                                                     {1, 1, 0.9, 0.3 * (1 + 2e-16), 0.33, 0.01, 0, 0},
                                                     {2, 2, 0.8, 0.3 * (1 - 3e-16), 0.37, 0.01, 0, 0}};
    std::vector<std::vector<double>> rough = smooth;
    rough[2][3] = 0.29;
    EXPECT_EQ(steady_monitored(names, false, &smooth), std::vector<std::string>{"a20"});
    const std::vector<std::string> all = steady_monitored(names, false, &rough);
    EXPECT_NE(std::find(all.begin(), all.end(), "theta"), all.end());
    EXPECT_NE(std::find(all.begin(), all.end(), "a02"), all.end());
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// What the steady-state detector of a shear run watches: the temperatures, the reduced stresses,
// theta and a20, and a mixture's species' theta and measured temperature ratios (not their errors,
// not the theory's ratios, not the other per-species columns).
TEST(SteadyMonitored, ShearWatchesThetaA20AndTheSpecies) {
    const std::vector<std::string> names = {"t",          "coll_per_particle", "T_tr",           "T_tr_err",
                                            "T_rot",      "theta",             "a20",            "a02",
                                            "P_xx_star",  "P_yy_star",         "P_zz_star",      "P_xy_star",
                                            "theta.a",    "theta.a_err",       "a20.a",          "T_tr.a/T_tr.b",
                                            "T_rot.a/T_rot.b", "T_tr.a/T_tr.b_theory"};
    const std::vector<std::string> expected = {"T_tr",      "T_rot", "P_xx_star", "P_yy_star",     "P_zz_star",
                                               "P_xy_star", "theta", "a20",       "theta.a",       "T_tr.a/T_tr.b",
                                               "T_rot.a/T_rot.b"};
    EXPECT_EQ(steady_monitored(names, true), expected);
}

} // namespace
} // namespace roughgas
