#pragma once
// The steady part of a time series of output rows, and its averages with batch-means errors, so
// that a run can start anywhere and report when it has reached the steady state.
//
// Criterion (drift). For a candidate start row k0, the window [k0, n) is cut into two halves.
// The second half's mean of every monitored quantity X gets a batch-means standard error se_2
// (the half cut into `batches/2` consecutive batches); the first half's mean is taken to have the
// same variance per row (a transient in it would inflate its own batch error and hide itself).
// The window is steady when, for every monitored X,
//     |mean_2(X) - mean_1(X)| <= threshold se_2 sqrt(1 + n_2/n_1),
// i.e. no drift of X is resolved by the data (with `head_rows` > 0, the same test for the mean of
// the window's first `head_rows` rows against the second half's). A drift that goes on through the
// window spreads the second half's batch means and so inflates se_2, the error it is compared with:
// the window is also cut into `batches` batches, a straight line fitted to their means, and the
// window is steady only if, for every X, the line's slope lies within `trend_threshold` of its
// standard error (from the batch means' scatter about the line: a trend does not inflate it). The
// steady start is the first such k0 (scanned upwards, over the first `max_start` of the rows, with
// at least `min_rows` rows in the window).
// A monitored decay rate (zeta_star = -d ln T_tr/d coll_per_particle between consecutive rows) is
// tested through the quantity it differentiates instead: straight lines fitted to ln T_tr against
// coll_per_particle over each half (and over the head rows with the row before them), their slopes
// compared within `threshold` of the error from the lines' residuals. A rate's rows are as noisy
// as 1/(the rows' spacing): with log-spaced rows the late ones are a hundred times quieter than the
// early ones, so an error from the second half's rows would refuse any window with early rows,
// while ln T_tr's noise is the same in every row.
// Monitored (steady_monitored): T_tr, T_rot, P*_xx, P*_yy, P*_zz, P*_xy, theta, a20 (and a
// mixture's species' theta and temperature ratios) for shear runs; the scale-free ratios for
// cooling runs, whose steady state is the scaled (homogeneous cooling) state.
//
// Averages. Every other quantity is averaged over the steady window with the batch-means error:
// the window cut into `batches` consecutive batches of equal length, se = sd(batch means)/sqrt(B).
// Batches longer than the correlation time (rows are about one collision per particle apart; the
// stresses relax within a few) make the batch means independent; the rows being replica means,
// the error includes the spread of the replicas.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace roughgas {

struct SteadyOptions {
    std::vector<std::string> monitored;
    int batches = 10;
    double threshold = 3;
    std::size_t min_rows = 20;
    // The window's first row among the first `max_start` of the rows (a fraction).
    double max_start = 0.5;
    // The trend test's bound on |slope|/se(slope): with 10 batches the ratio of a stationary series
    // follows Student's t with 8 degrees of freedom, beyond 4 with probability 0.4 %.
    double trend_threshold = 4;
    // > 0: also the mean of the window's first `head_rows` rows against the second half's, so that
    // a transient of a few rows at the window's start, diluted in the first half's mean, is seen.
    std::size_t head_rows = 0;
    // With head_rows > 0 and X_err columns (replicas): also each of those rows against the second
    // half's mean within 3 of its own X_err combined with the half's error.
    bool head_each_row = true;
    // The replicas behind the X_err columns (0: unknown). An X_err from R replicas has R - 1 degrees
    // of freedom, so the row-by-row test's bound is Student's t quantile of R - 1 degrees at the
    // normal tail of `threshold` (9.2 for 4 replicas, 235 for 2, against 3): three rows of four
    // columns tested at 3 against errors from 4 replicas refuse a steady window one time in two.
    int replicas = 0;
    // Monitored columns that are decay rates: column = -d ln(of)/d(against) between consecutive rows.
    struct DecayRate {
        std::string column, of, against;
    };
    std::vector<DecayRate> decay_rates;
};

struct SteadyValue {
    std::string name;
    double mean = 0, err = 0;
};

struct SteadyResult {
    bool reached = false;
    // Not reached: the monitored quantity that drifted over the last window tried, and by how much
    // ("zeta_star from 0.0626 to 0.0217"); empty when reached.
    std::string drift;
    std::size_t first_row = 0;       // the window's first row (reached or not: the last candidate tried)
    std::size_t rows = 0;            // rows in the window
    std::vector<SteadyValue> values; // every column but the skipped ones, in column order
    std::vector<std::string> monitored; // what the criterion watched
};

// Mean and batch-means standard error of x (B batches of equal length; the first len % B values
// are left out, so every batch has the same weight; fewer than B values: one per batch). err is NaN
// with fewer than 2 values, mean too with none.
SteadyValue batch_mean(std::span<const double> x, int batches);

// The slope of x against its index, in units of its standard error: a straight line fitted to the
// means of B consecutive batches of equal length (the first len % B values left out, as batch_mean
// does), the error from their scatter about the line. NaN with fewer than 3 batches; 0 when x is
// constant; +-inf when the means lie on the line exactly (round-off aside).
double trend_in_errors(std::span<const double> x, int batches);

// `names`: the columns of `rows`; columns named in `skip` (and every X_err column) are not averaged.
SteadyResult find_steady_state(const std::vector<std::string>& names,
                               const std::vector<std::vector<double>>& rows, const SteadyOptions& options,
                               const std::vector<std::string>& skip = {"t"});

// The monitored quantities above for a run of the given kind, among `names`. Shear: T_tr, T_rot,
// the reduced stresses, theta, a20, each species' theta and the species' temperature ratios. Cooling (the scaled homogeneous cooling state, whose temperatures keep
// falling): the scale-free ratios theta, a20, a02, a11, the reduced cooling rate zeta_star, each
// species' theta and the species' temperature ratios. With `rows`, rotational columns (theta, a02, a11, T_rot ratios) are left out
// of a cooling run whose T_rot never changes: smooth grains keep their spins bit for bit, so theta
// grows as T_tr falls and has no scaled value.
std::vector<std::string> steady_monitored(const std::vector<std::string>& names, bool shear,
                                          const std::vector<std::vector<double>>* rows = nullptr);

} // namespace roughgas
