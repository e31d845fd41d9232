#include "roughgas/observables/steady_state.hpp"

#include <algorithm>
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
    const int half_batches = std::max(2, o.batches / 2);
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
        for (std::size_t j : mon) {
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
                            !(std::abs(x - B.mean) <= o.threshold * std::sqrt(ex * ex + B.err * B.err) + slack))
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
