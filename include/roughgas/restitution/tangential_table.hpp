#pragma once
// eps^T(g_N, g_T) of one species pair (docs/model.md §7), tabulated so that it is never interpolated
// across the onset of asperity breaking (Brilliantov et al. (1996) Fig. 2) nor across any other jump.
//
// Below the onset, g_T < g_T,cr(g_N), no asperity breaks and the tangential motion is linear in g_T:
// eps^T = eps_unbroken(g_N), a function of g_N alone. The onset g_T,cr = c(g_N) g_N, where
// c = critical_ratio (tangential_integrator.hpp), is a table of c over x = pseudo_log2(g_N) with a
// relative error bound.
// Above it, eps^T is a 2-D table over x and y = g_T,cr/g_T in (0, 1] (y -> 0: g_T -> inf, eps^T -> 1);
// the onset line is the edge y = 1 of that table, so no cell straddles it. All three are
// adaptive tables (adaptive_table.hpp) refined until they match the direct integrator at their
// check points; where a further jump of eps^T remains (the spring stops the sliding exactly as an
// asperity breaks), the cells at the maximum depth are `direct` and the look-up integrates the
// contact there. Also direct: a relative band of `onset_band` around the onset (the table of c
// carries a relative error below it) and g_N outside [g_min, g_max].
#include "roughgas/contact/contact_integrator.hpp"
#include "roughgas/contact/contact_pair.hpp"
#include "roughgas/restitution/adaptive_table.hpp"
#include "roughgas/restitution/pseudo_log.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace roughgas {

struct TangentialTableOptions {
    double g_min = 1e-6; // range of g_N covered by the table [m/s]
    double g_max = 1e2;
    AdaptiveOptions critical{2, 1, 10, 1e-8, true}; // c, relative error; root cells per binade
    AdaptiveOptions unbroken{2, 1, 10, 2.5e-5};   // eps^T below the onset, per binade of g_N
    AdaptiveOptions breaking{1, 8, 5, 2.5e-5};    // eps^T above the onset; root_cells_x per binade
    double onset_band = 1e-6;                      // |g_T/g_T,cr - 1| below this: direct
    Tolerance tol{1e-10, 1e-12};                   // of the contact integrations behind the table
};

struct TangentialTableStats {
    AdaptiveStats critical, unbroken, breaking;
    double build_seconds = 0;
};

// The direct (uncached) eps^T with the table's interface.
struct DirectTangential {
    ContactPair pair;
    Tolerance tol{};
    double eps_t(double g_n, double g_t) const {
        return integrate_tangential(tangential_parameters(pair, g_n), std::abs(g_t) / g_n, tol).eps_t;
    }
};

class TangentialTable {
public:
    static TangentialTable build(const ContactPair& pair, TangentialTableOptions opt = {});

    // g_n > 0, any g_t (eps^T is even in g_t). Inlined into the collision loop, as are the look-ups
    // below it (a call would spill the loop's live registers around every collision); the rare
    // fallbacks, the tree walks and the direct integration, are kept out of it (cold, not inlined).
    [[gnu::always_inline]] double eps_t(double g_n, double g_t) const {
        const double v = lookup(g_n, std::abs(g_t));
        if (std::isnan(v)) [[unlikely]]
            return direct(g_n, g_t);
        return v;
    }
    // NaN where the look-up would fall back to the direct integrator.
    // The collision loop waits for this result (its latency is the loop's), so the
    // division g_N/g_T runs beside the critical look-up instead of after it: y = g_T,cr/g_T is
    // c (g_N/g_T), and the band tests compare y (g_T < g_T,cr (1 - band) <=> y > 1/(1 - band)).
    // The 1-D tables read their cell off the bits of g_N (AdaptiveTable1D::at_speed): the critical
    // look-up starts as soon as g_N is known; x is only converted for the 2-D table, beside it.
    [[gnu::always_inline]] double lookup(double g_n, double g_t) const {
        const double x = pseudo_log2(g_n);
        const double r = g_n / g_t; // +inf for g_t = 0: below the onset
        const double c = critical_.at_speed(g_n);
        // Read before the branch on c (which the predictor often misses): its loads then overlap the
        // critical look-up's instead of following them. The empty asm keeps the compiler from sinking
        // it back into the branch.
        double unbroken = unbroken_.at_speed(g_n);
        asm("" : "+x"(unbroken));
        if (std::isnan(c)) return c;
        const double y = c * r;
        if (y > y_unbroken_) return unbroken;
        if (y >= y_direct_) return std::numeric_limits<double>::quiet_NaN();
        return breaking_(x, y);
    }
    // g_T,cr(g_N): the onset of asperity breaking.
    double critical_speed(double g_n) const {
        const double c = critical_.at_speed(g_n);
        return (std::isnan(c) ? critical_ratio(tangential_parameters(pair(), g_n), opt_.tol) : c) * g_n;
    }

    const ContactPair& pair() const { return direct_.pair; }
    const TangentialTableOptions& options() const { return opt_; }
    const TangentialTableStats& stats() const { return stats_; }

    static std::string key_for(const ContactPair& pair, const TangentialTableOptions& opt);
    std::string cache_key() const { return key_for(direct_.pair, opt_); }
    std::vector<double> serialize() const;
    static TangentialTable deserialize(const ContactPair& pair, TangentialTableOptions opt, const std::vector<double>& data);

private:
    [[gnu::noinline, gnu::cold]] double direct(double g_n, double g_t) const { return direct_.eps_t(g_n, g_t); }
    TangentialTableOptions opt_{};
    DirectTangential direct_{};
    AdaptiveTable1D critical_, unbroken_;
    AdaptiveTable2D breaking_;
    TangentialTableStats stats_{};
    // The onset band in y: above y_unbroken_ no asperity breaks, in [y_direct_, y_unbroken_] direct.
    double y_unbroken_ = 0, y_direct_ = 0;
    void set_band() {
        y_unbroken_ = 1.0 / (1.0 - opt_.onset_band);
        y_direct_ = 1.0 / (1.0 + opt_.onset_band);
    }
};

} // namespace roughgas
