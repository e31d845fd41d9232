#include "roughgas/observables/steady_state.hpp"

#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace roughgas {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// "zeta_star from 0.0626 to 0.0217": the means of the window's halves.
std::string fmt_drift(const std::string& name, double first, double second) {
    char text[160];
    std::snprintf(text, sizeof text, "%s from %.3g to %.3g", name.c_str(), first, second);
    return text;
}

// The means of B consecutive batches of equal length of x (1 <= B <= x.size()), the first
// x.size() % B values left out so that every batch has the same weight.
std::vector<double> batch_means(std::span<const double> x, std::size_t B) {
    const std::size_t len = x.size() / B, skip = x.size() - len * B;
    std::vector<double> m(B, 0.0);
    for (std::size_t b = 0; b < B; ++b) {
        for (std::size_t k = 0; k < len; ++k)
            m[b] += x[skip + b * len + k];
        m[b] /= static_cast<double>(len);
    }
    return m;
}

std::size_t index_of(const std::vector<std::string>& names, const std::string& n) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin());
}

// Least squares of ln(rows[k][of]) against rows[k][against], k in [from, to): the straight line's
// slope and the sum of squared (centred) abscissae, and the residual sum of squares about a
// parabola (a rate that drifts bends the line; the parabola keeps the bend out of the noise
// estimate). NaN slope when a value is not finite or not positive, or the abscissae coincide.
struct LogLine {
    double slope = nan, sxx = nan, rss_parabola = nan;
    std::size_t points = 0;
};
LogLine fit_log_line(const std::vector<std::vector<double>>& rows, std::size_t of, std::size_t against,
                     std::size_t from, std::size_t to) {
    LogLine l;
    l.points = to - from;
    std::vector<double> u, y;
    for (std::size_t k = from; k < to; ++k) {
        const double x = rows[k][against], v = rows[k][of];
        if (!std::isfinite(x) || !(v > 0) || !std::isfinite(v))
            return l;
        u.push_back(x);
        y.push_back(std::log(v));
    }
    const auto mean = [](const std::vector<double>& z) {
        double m = 0;
        for (double w : z)
            m += w;
        return m / static_cast<double>(z.size());
    };
    const double mu = mean(u), my = mean(y);
    double scale = 0;
    for (double& w : u) {
        w -= mu;
        scale = std::max(scale, std::abs(w));
    }
    if (!(scale > 0))
        return l;
    for (double& w : u)
        w /= scale; // in [-1, 1]: the parabola's basis stays well conditioned
    // Orthogonal basis 1, u, p2 = u^2 - m2 - (S3/S2) u (Gram-Schmidt), so the fitted parts add up.
    double s2 = 0, s3 = 0, m2 = 0, syy = 0, suy = 0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        s2 += u[k] * u[k];
        s3 += u[k] * u[k] * u[k];
        syy += (y[k] - my) * (y[k] - my);
        suy += u[k] * (y[k] - my);
    }
    m2 = s2 / static_cast<double>(u.size());
    double spp = 0, spy = 0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        const double p2 = u[k] * u[k] - m2 - s3 / s2 * u[k];
        spp += p2 * p2;
        spy += p2 * (y[k] - my);
    }
    l.slope = suy / s2 / scale;
    l.sxx = s2 * scale * scale;
    l.rss_parabola = std::max(0.0, syy - suy * suy / s2 - (spp > 0 ? spy * spy / spp : 0.0));
    return l;
}

// ln(of)'s noise variance per row from the halves' residuals about their parabolas: pooled, unless
// the halves' variances differ beyond what their degrees of freedom allow (the two-sided 1 % range of
// Fisher's F): then the quieter half's. A rate that drifts more than a parabola can follow inflates
// its half's residuals; taken alone, that half's estimate would hide the drift it comes from.
double noise_variance(const LogLine& a, const LogLine& b) {
    const double da = static_cast<double>(a.points) - 3, db = static_cast<double>(b.points) - 3;
    const double va = a.rss_parabola / da, vb = b.rss_parabola / db;
    const double pooled = (a.rss_parabola + b.rss_parabola) / (da + db);
    if (!(va > 0) || !(vb > 0))
        return pooled;
    const boost::math::fisher_f_distribution<double> f(da, db);
    const double ratio = va / vb;
    if (ratio > boost::math::quantile(boost::math::complement(f, 0.005)) || ratio < boost::math::quantile(f, 0.005))
        return std::min(va, vb);
    return pooled;
}

} // namespace

SteadyValue batch_mean(std::span<const double> x, int batches) {
    SteadyValue v;
    // Fewer values than batches: one value per batch (a short window still has a mean and an error).
    const std::size_t B = std::min(static_cast<std::size_t>(std::max(batches, 1)), x.size());
    const std::size_t len = B > 0 ? x.size() / B : 0;
    if (len == 0) {
        v.mean = v.err = nan;
        return v;
    }
    const std::vector<double> m = batch_means(x, B);
    double mean = 0;
    for (double y : m)
        mean += y;
    mean /= static_cast<double>(B);
    double ss = 0;
    for (double y : m)
        ss += (y - mean) * (y - mean);
    v.mean = mean;
    v.err = B > 1 ? std::sqrt(ss / (static_cast<double>(B) * static_cast<double>(B - 1))) : nan;
    return v;
}

double trend_in_errors(std::span<const double> x, int batches) {
    const std::size_t B = std::min(static_cast<std::size_t>(std::max(batches, 1)), x.size());
    if (B < 3)
        return nan;
    const std::vector<double> m = batch_means(x, B);
    // Least squares against the batch index b - (B - 1)/2 (centred: slope and mean independent).
    const double centre = 0.5 * static_cast<double>(B - 1);
    double mean = 0, sxx = 0, sxy = 0;
    for (double y : m)
        mean += y;
    mean /= static_cast<double>(B);
    for (std::size_t b = 0; b < B; ++b) {
        const double u = static_cast<double>(b) - centre;
        sxx += u * u;
        sxy += u * (m[b] - mean);
    }
    const double slope = sxy / sxx;
    double rss = 0;
    for (std::size_t b = 0; b < B; ++b) {
        const double r = m[b] - mean - slope * (static_cast<double>(b) - centre);
        rss += r * r;
    }
    // A constant series (T_rot of smooth grains) has no trend, whatever round-off leaves in rss.
    if (!(std::abs(slope) * static_cast<double>(B) > 1e-12 * std::abs(mean)))
        return 0.0;
    const double se = std::sqrt(rss / static_cast<double>(B - 2) / sxx);
    return se > 0 ? slope / se : std::copysign(std::numeric_limits<double>::infinity(), slope);
}

SteadyResult find_steady_state(const std::vector<std::string>& names,
                               const std::vector<std::vector<double>>& rows, const SteadyOptions& o,
                               const std::vector<std::string>& skip) {
    SteadyResult r;
    const std::size_t n = rows.size();
    const auto series = [&](std::size_t col, std::size_t from, std::size_t to) {
        std::vector<double> x;
        for (std::size_t k = from; k < to; ++k)
            x.push_back(rows[k][col]);
        return x;
    };
    std::vector<std::size_t> mon;
    for (const std::string& m : o.monitored)
        if (const std::size_t j = index_of(names, m); j < names.size())
            mon.push_back(j);
    // For each monitored column, the columns of the decay it is the rate of (none: names.size()).
    std::vector<std::pair<std::size_t, std::size_t>> rate_of(mon.size(), {names.size(), names.size()});
    for (std::size_t i = 0; i < mon.size(); ++i)
        for (const SteadyOptions::DecayRate& d : o.decay_rates)
            if (names[mon[i]] == d.column && index_of(names, d.of) < names.size() &&
                index_of(names, d.against) < names.size())
                rate_of[i] = {index_of(names, d.of), index_of(names, d.against)};
    const int half_batches = std::max(2, o.batches / 2);
    // The row-by-row test's bound: the normal tail of `threshold` at the t quantile of the X_err's
    // replicas - 1 degrees of freedom.
    double row_threshold = o.threshold;
    if (o.replicas > 1) {
        const double tail = boost::math::cdf(boost::math::complement(boost::math::normal_distribution<double>(), o.threshold));
        row_threshold = boost::math::quantile(
            boost::math::complement(boost::math::students_t_distribution<double>(o.replicas - 1), tail));
    }
    // Row 0 is the initial state (its rates are undefined): never part of the window.
    std::size_t k0 = std::min<std::size_t>(1, n);
    // Of the window tried last: the monitored column that failed and its halves' means.
    struct Failed {
        std::size_t column;
        double first, second;
    };
    std::optional<Failed> failed;
    const std::size_t stride = std::max<std::size_t>(1, n / 100);
    const auto last_start = static_cast<std::size_t>(o.max_start * static_cast<double>(n));
    for (; k0 + std::max<std::size_t>(o.min_rows, 4) <= n && k0 <= last_start; k0 += stride) {
        const std::size_t mid = k0 + (n - k0) / 2;
        bool steady = true;
        for (std::size_t i = 0; i < mon.size() && steady; ++i) {
            const std::size_t j = mon[i];
            const std::vector<double> a = series(j, k0, mid), b = series(j, mid, n);
            const SteadyValue A = batch_mean(a, half_batches), B = batch_mean(b, half_batches);
            if (!std::isfinite(A.mean) && !std::isfinite(B.mean))
                continue; // undefined throughout (e.g. T_rot of smooth grains started without spin)
            failed = Failed{j, A.mean, B.mean}; // the column under test: named if the window fails
            // A drift through the whole window (it inflates B.err, which the halves' test divides by).
            if (const double t = trend_in_errors(series(j, k0, n), o.batches); std::abs(t) > o.trend_threshold) {
                steady = false;
                break;
            }
            if (rate_of[i].first < names.size()) {
                // A decay rate: the halves' and the head's slopes of ln(of), their errors from
                // ln(of)'s noise (row k's rate spans rows k - 1 and k, so the first half's line
                // starts at row k0 - 1; k0 >= 1).
                const auto [of, against] = rate_of[i];
                const LogLine la = fit_log_line(rows, of, against, k0 - 1, mid);
                const LogLine lb = fit_log_line(rows, of, against, mid, n);
                const LogLine lh = fit_log_line(rows, of, against, k0 - 1, std::min(k0 + o.head_rows, mid));
                if (std::isfinite(la.slope) && std::isfinite(lb.slope) && la.points > 3 && lb.points > 3) {
                    failed = Failed{j, -la.slope, -lb.slope};
                    const double s2 = noise_variance(la, lb);
                    const double slack = 1e-12 * std::max(std::abs(la.slope), std::abs(lb.slope));
                    if (!(std::abs(lb.slope - la.slope) <= o.threshold * std::sqrt(s2 * (1 / la.sxx + 1 / lb.sxx)) + slack)) {
                        steady = false;
                        break;
                    }
                    if (o.head_rows > 0 && std::isfinite(lh.slope) &&
                        !(std::abs(lb.slope - lh.slope) <= o.threshold * std::sqrt(s2 * (1 / lh.sxx + 1 / lb.sxx)) + slack)) {
                        steady = false;
                        break;
                    }
                    // No row-by-row test against the replicas' X_err: the second half's slope is far
                    // more precise than any one row, so a row's error from a few replicas (itself
                    // uncertain by a factor 1/sqrt(2 (R - 1))) would decide alone and refuse by
                    // chance; the head's slope above holds the same information.
                    continue;
                }
            }
            // The error of both means from the second half's batches (a transient inside the first
            // half would inflate its own batch error and hide itself); the 1e-12 relative slack:
            // a constant column, e.g. T_rot of smooth grains, has err = 0.
            const double se =
                B.err * std::sqrt(1.0 + static_cast<double>(b.size()) / static_cast<double>(a.size()));
            const double slack = 1e-12 * std::max(std::abs(A.mean), std::abs(B.mean));
            if (!(std::abs(B.mean - A.mean) <= o.threshold * se + slack)) {
                steady = false;
                break;
            }
            if (o.head_rows > 0) {
                const std::vector<double> head = series(j, k0, std::min(k0 + o.head_rows, mid));
                const double mean_h = batch_mean(head, 1).mean;
                const double se_h =
                    B.err * std::sqrt(1.0 + static_cast<double>(b.size()) / static_cast<double>(head.size()));
                if (std::isfinite(mean_h) && !(std::abs(B.mean - mean_h) <= o.threshold * se_h + slack)) {
                    steady = false;
                    break;
                }
                // With replicas, each of those rows against the late mean within its own error.
                if (const std::size_t e = index_of(names, names[j] + "_err"); o.head_each_row && e < names.size()) {
                    for (std::size_t k = k0; k < std::min(k0 + o.head_rows, mid) && steady; ++k) {
                        const double x = rows[k][j], ex = rows[k][e];
                        if (std::isfinite(x) && std::isfinite(ex) &&
                            !(std::abs(x - B.mean) <= row_threshold * std::sqrt(ex * ex + B.err * B.err) + slack))
                            steady = false;
                    }
                    if (!steady)
                        break;
                }
            }
        }
        if (steady) {
            r.reached = true;
            break;
        }
    }
    if (!r.reached && failed)
        r.drift = fmt_drift(names[failed->column], failed->first, failed->second);
    if (!r.reached)
        k0 = std::min(k0, n > 0 ? n / 2 : 0);
    r.first_row = k0;
    r.rows = n - k0;
    for (std::size_t j = 0; j < names.size(); ++j) {
        if (names[j].ends_with("_err") || std::find(skip.begin(), skip.end(), names[j]) != skip.end())
            continue;
        SteadyValue v = batch_mean(series(j, k0, n), o.batches);
        v.name = names[j];
        r.values.push_back(v);
    }
    return r;
}

std::vector<std::string> steady_monitored(const std::vector<std::string>& names, bool shear,
                                          const std::vector<std::vector<double>>* rows) {
    const auto has = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) != names.end(); };
    std::vector<std::string> out;
    if (shear) {
        // The temperatures and stresses, and theta and a20: the spins and the velocity distribution's
        // shape relax more slowly than T_tr (at alpha = 0.7, theta keeps falling for ~20 collisions
        // per particle after T_tr has nearly settled), and so do a mixture's species.
        for (const std::string w : {"T_tr", "T_rot", "P_xx_star", "P_yy_star", "P_zz_star", "P_xy_star", "theta", "a20"})
            if (has(w))
                out.push_back(w);
        for (const std::string& n : names) {
            const std::string base = n.substr(0, n.find('.'));
            const bool species = n.find('.') != std::string::npos && !n.ends_with("_err") &&
                                 !n.ends_with("_theory") && (base == "theta" || n.find('/') != std::string::npos);
            if (species)
                out.push_back(n);
        }
        return out;
    }
    // Smooth grains: T_rot the same in every row (no collision changes a spin), to round-off (a box
    // sums the spins in the order its sort by cell leaves them).
    bool spins_change = true;
    if (rows && !rows->empty() && has("T_rot")) {
        const auto k = static_cast<std::size_t>(std::find(names.begin(), names.end(), "T_rot") - names.begin());
        const double first = rows->front()[k];
        spins_change = std::any_of(rows->begin(), rows->end(), [&](const std::vector<double>& r) {
            return !(std::abs(r[k] - first) <= 1e-12 * std::abs(first));
        });
    }
    const auto rotational = [](const std::string& n) {
        return n.rfind("theta", 0) == 0 || n.rfind("a02", 0) == 0 || n.rfind("a11", 0) == 0 ||
               n.rfind("T_rot", 0) == 0;
    };
    for (const std::string& n : names) {
        if (n.size() > 4 && n.compare(n.size() - 4, 4, "_err") == 0)
            continue;
        const std::string base = n.substr(0, n.find('.'));
        const bool ratio = n.find('/') != std::string::npos && (base == "T_tr" || base == "T_rot") &&
                           !n.ends_with("_theory"); // the measured ratios, not the theory's
        const bool scale_free = n == "theta" || n == "a20" || n == "a02" || n == "a11" || n == "zeta_star" ||
                                (base == "theta" && n != "theta" && n.find("_theory") == std::string::npos &&
                                 n.find('/') == std::string::npos) ||
                                ratio;
        if (scale_free && (spins_change || !rotational(n)))
            out.push_back(n);
    }
    return out;
}

} // namespace roughgas
