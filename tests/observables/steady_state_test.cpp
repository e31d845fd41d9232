// The steady-state detector and batch means (observables/steady_state.hpp) on synthetic series
// with known statistics: a relaxation plus noise, stationary noise, and drifts.
#include "roughgas/core/rng.hpp"
#include "roughgas/observables/steady_state.hpp"
#include "roughgas/observables/uniformity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
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

namespace roughgas {
namespace {

// The trend statistic on exact series: no trend in a constant, an enormous one on a line,
// and for a line plus a known alternating perturbation its closed form. Ten batches of one value
// each: x_b = 0.1 b + 0.01 (-1)^b; the fit's slope is 0.1 + 0.01 sum u_b (-1)^b / sum u_b^2 and its
// residuals' scatter gives the error.
TEST(TrendInErrors, ExactSeries) {
    EXPECT_EQ(trend_in_errors(std::vector<double>(10, 2.5), 10), 0.0);
    std::vector<double> line(10), wiggle(10);
    for (std::size_t b = 0; b < 10; ++b) {
        line[b] = 1 + 0.1 * static_cast<double>(b);
        wiggle[b] = line[b] + 0.01 * (b % 2 == 0 ? 1.0 : -1.0);
    }
    EXPECT_GT(trend_in_errors(line, 10), 1e9); // only round-off about the line
    double sxx = 0, sxe = 0;
    for (std::size_t b = 0; b < 10; ++b) {
        const double u = static_cast<double>(b) - 4.5, e = b % 2 == 0 ? 0.01 : -0.01;
        sxx += u * u;
        sxe += u * e;
    }
    const double slope = 0.1 + sxe / sxx;
    double rss = 0;
    // Residuals about the fitted line (mean of wiggle = 1.45: the perturbations cancel).
    for (std::size_t b = 0; b < 10; ++b) {
        const double u = static_cast<double>(b) - 4.5;
        const double r = wiggle[b] - 1.45 - slope * u;
        rss += r * r;
    }
    EXPECT_NEAR(trend_in_errors(wiggle, 10), slope / std::sqrt(rss / 8 / sxx), 1e-9);
    EXPECT_TRUE(std::isnan(trend_in_errors(std::vector<double>{1.0, 2.0}, 10)));
}

// A cooling box that starts to cluster: its reduced cooling rate flat for the first half of the
// rows, then falling steadily to a third of it (22 rows, noise 0.0003, as the clustering slab of
// cases/box_cooling_slab.toml shows). The falling half's batch means spread widely, so the halves'
// test, dividing by their scatter, finds no drift; the trend test resolves it in every seed.
TEST(SteadyState, ADriftThroughTheWindowIsNotSteady) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        Rng r = make_stream(seed, Stream::test, 2, 0);
        std::vector<std::vector<double>> rows;
        for (std::size_t k = 0; k < 23; ++k) {
            const double fall = k < 12 ? 0.0 : 0.04 * static_cast<double>(k - 12) / 10.0;
            rows.push_back({static_cast<double>(k), 10.0 * static_cast<double>(k), 0.0625 - fall + 0.0003 * gauss(r)});
        }
        SteadyOptions o = options();
        o.min_rows = 10;
        o.max_start = 1.0;
        o.trend_threshold = std::numeric_limits<double>::infinity(); // the halves' test alone
        EXPECT_TRUE(find_steady_state(names, rows, o).reached) << seed;
        o.trend_threshold = SteadyOptions{}.trend_threshold;
        const SteadyResult s = find_steady_state(names, rows, o);
        EXPECT_FALSE(s.reached) << seed;
        EXPECT_EQ(s.drift.rfind("T_tr from ", 0), 0u) << s.drift;
    }
}

} // namespace
} // namespace roughgas


namespace roughgas {
namespace {

// The uniform gas's bound on S: for one independent mode S is exponential, P(S > x) = exp(-x), so
// the bound at p is -ln p; many modes bring it towards the mean 1. A uniform box's rows (S drawn
// as the mean of a unit exponentials) stay below it; a row of S = 40 (a cluster) is the first above.
TEST(Uniformity, BoundAndFirstNonUniformRow) {
    EXPECT_NEAR(uniform_structure_factor_bound(1, 1e-6), -std::log(1e-6), 1e-9);
    EXPECT_LT(uniform_structure_factor_bound(400, 1e-6), 1.4);
    Rng r = make_stream(7, Stream::test, 3, 0);
    std::vector<double> S, modes;
    for (int k = 0; k < 300; ++k) {
        double sum = 0;
        for (int i = 0; i < 4; ++i)
            sum += -std::log(uniform01_open0(r));
        S.push_back(sum / 4);
        modes.push_back(8); // 4 independent modes, one replica
    }
    EXPECT_FALSE(first_non_uniform_row(S, modes, 1).has_value());
    S[200] = 40;
    const std::optional<NonUniformity> u = first_non_uniform_row(S, modes, 1);
    ASSERT_TRUE(u.has_value());
    EXPECT_EQ(u->row, 200u);
    EXPECT_NEAR(u->bound, uniform_structure_factor_bound(4, 1e-6), 1e-12);
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// Rows of a cooling run at log-spaced collision counts c_k = 0.1 x 10^(k/10) (ten per decade, as
// the shipped cooling cases write them): ln T_tr = -zeta(c) c-integrated plus independent noise
// sigma in every row, zeta_star the rows' difference quotient -(ln T_k - ln T_(k-1))/(c_k - c_(k-1)).
// The rate zeta falls from zeta0 to zeta1 from c_drop on (a box that clusters cools more slowly).
std::vector<std::vector<double>> cooling_rows(std::uint64_t seed, double zeta0, double zeta1, double c_drop,
                                              double sigma) {
    Rng r = make_stream(seed, Stream::test, 3, 0);
    std::vector<std::vector<double>> rows;
    double ln_prev = 0, c_prev = 0;
    for (std::size_t k = 0; k <= 40; ++k) {
        const double c = 0.1 * std::pow(10.0, static_cast<double>(k) / 10.0);
        // zeta(c) = zeta0 up to c_drop, then zeta0 - (zeta0 - zeta1) log10(c/c_drop)/2: zeta1 two decades on.
        const double b = (zeta0 - zeta1) / (2 * std::log(10.0));
        const double decay = c <= c_drop ? zeta0 * c
                                         : zeta0 * c - b * (c * std::log(c / c_drop) - c + c_drop);
        const double ln_t = -decay + sigma * gauss(r);
        const double zeta = k == 0 ? std::numeric_limits<double>::quiet_NaN() : -(ln_t - ln_prev) / (c - c_prev);
        rows.push_back({c, c, std::exp(ln_t), zeta});
        ln_prev = ln_t;
        c_prev = c;
    }
    return rows;
}

SteadyOptions cooling_options(bool as_rate) {
    SteadyOptions o;
    o.monitored = {"zeta_star"};
    o.min_rows = 10;
    o.max_start = 1.0;
    o.head_rows = 3;
    if (as_rate)
        o.decay_rates = {{"zeta_star", "T_tr", "coll_per_particle"}};
    return o;
}

// A constant cooling rate with ln T_tr's noise the same in every row: zeta_star's rows are then
// 1/(spacing) noisy, a hundred times noisier at 1 collision per particle than at 100. Tested as a
// decay rate (ln T_tr's lines) the scaled state is found from the first rows in nearly every seed
// (each test at 3 standard errors refuses a stationary window rarely); tested as plain rows, whose
// error comes from the quiet late ones, the early rows' noise refuses the early windows.
TEST(SteadyState, ADecayRateIsTestedThroughTheQuantityItDifferentiates) {
    const std::vector<std::string> cols = {"t", "coll_per_particle", "T_tr", "zeta_star"};
    int early = 0, early_as_rows = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const auto rows = cooling_rows(seed, 0.063, 0.063, 1e9, 0.003);
        const SteadyResult r = find_steady_state(cols, rows, cooling_options(true));
        EXPECT_TRUE(r.reached) << seed << ": " << r.drift;
        early += r.reached && r.first_row <= 3;
        const SteadyResult p = find_steady_state(cols, rows, cooling_options(false));
        early_as_rows += p.reached && p.first_row <= 3;
    }
    EXPECT_GE(early, 18);
    EXPECT_LE(early_as_rows, 5);
}

// The rate falling from 0.063 at 10 collisions per particle to 0.040 at 1000, steadily in ln c:
// resolved by the lines of ln T_tr, so no window is steady, and the drift names zeta_star with its
// halves' rates.
TEST(SteadyState, ADecayRateThatFallsIsNotSteady) {
    const std::vector<std::string> cols = {"t", "coll_per_particle", "T_tr", "zeta_star"};
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const SteadyResult r =
            find_steady_state(cols, cooling_rows(seed, 0.063, 0.040, 10.0, 0.003), cooling_options(true));
        EXPECT_FALSE(r.reached) << seed << " from " << r.first_row;
        EXPECT_EQ(r.drift.rfind("zeta_star from 0.0", 0), 0u) << r.drift;
    }
}

} // namespace
} // namespace roughgas

namespace roughgas {
namespace {

// A head row whose replicas happened to agree: 1.5 row sds (0.0015) from the late mean with an X_err
// of 0.0002, about 5 of its combined errors (with the late mean's 0.00022). Beyond 3 for a known
// error, but an X_err from 4 replicas has 3 degrees of freedom, and Student's t of 3 degrees exceeds
// 5 with probability 1.5 % (the bound at the normal tail of 3 is 9.2). With the replicas given the
// window from row 1 passes; without them it is refused.
TEST(SteadyState, HeadRowsAgainstReplicaErrorsUseStudentsT) {
    const std::vector<std::string> cols = {"t", "coll_per_particle", "T_tr", "T_tr_err"};
    std::vector<std::vector<double>> rows;
    Rng r = make_stream(4, Stream::test, 4, 0);
    for (std::size_t k = 0; k < 40; ++k)
        rows.push_back({static_cast<double>(k), static_cast<double>(k), 1.0 + 0.001 * gauss(r), 0.001});
    rows[1][2] = 1.0015;
    rows[1][3] = 0.0002;
    SteadyOptions o = options();
    o.head_rows = 3;
    o.max_start = 0.03; // the window from row 1 (the first after the initial state) or none
    o.replicas = 4;
    const SteadyResult known = find_steady_state(cols, rows, o);
    EXPECT_TRUE(known.reached) << known.drift;
    EXPECT_EQ(known.first_row, 1u);
    o.replicas = 0;
    EXPECT_FALSE(find_steady_state(cols, rows, o).reached);
}

} // namespace
} // namespace roughgas
