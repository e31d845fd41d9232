#pragma once
// The universal table eps^N(w) (docs/model.md §6): one table per (form, end) serves every material
// and every species pair, since eps^N depends on w = g_N rho^2 tau^5 only.
//
// Grid: pseudo-logarithmic, read off the IEEE-754 bits of w. Each binade [2^e, 2^{e+1}) with
// e_min <= e < e_max is cut into 2^mantissa_bits equal intervals, so the interval index is a
// shift of the bit pattern and no logarithm is taken on look-up. On each interval eps^N is a
// cubic Hermite patch through the nodes, with node slopes from a 5-point (Fornberg) derivative
// in ln w, limited by Fritsch-Carlson so the interpolant is monotone (eps^N falls with w).
//
// Below the table (w < 2^e_min): the small-w expansion in u = w^{1/5},
//   1 - eps^N = u (c1 + c_{3/2} u^{1/2} + c2 u + c_{5/2} u^{3/2} + c3 u^2),
// fitted by least squares to direct solutions on u in [series_fit_lo, series_fit_hi]; c1 is the
// published C1 = 1.15344 for eq. 24 (the u^{1/2} powers appear with the `force` end, whose attraction-
// free tail differs from `separation` at O(u^{5/2})).
// Above the table (w >= 2^e_max): a power law eps^N = eps(w_max) (w/w_max)^{-p} with the table's
// logarithmic slope p at w_max: continuous, monotone, positive (eps^N -> 0 as w -> inf). The
// direct path is the reference there; the power law is documented as an extrapolation.
#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/normal_integrator.hpp"
#include "roughgas/contact/tolerance.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace roughgas {

struct NormalTableOptions {
    int e_min = -60;         // w_min = 2^-60 = 8.7e-19
    int e_max = 17;          // w_max = 2^17 = 1.3e5: 23 decades in all
    int mantissa_bits = 6;   // 64 intervals per binade: relative spacing <= 1/64
    Tolerance tol{1e-13, 1e-15};
    friend bool operator==(const NormalTableOptions&, const NormalTableOptions&) = default;
};

// Direct (uncached) eps^N(w): the reference, with the same interface as the table.
struct DirectNormal {
    ContactModel model{};
    Tolerance tol{};
    double eps_n(double w) const { return integrate_normal(std::pow(w, 0.2), model, tol).eps_n; }
};

class NormalTable {
public:
    // Builds the table (OpenMP-parallel over nodes). Throws std::runtime_error if the data are
    // not monotone (which would mean an integration failure).
    static NormalTable build(ContactModel model, NormalTableOptions opt = {});

    [[gnu::always_inline]] double eps_n(double w) const {
        if (!(w >= w_min_)) return below(w); // also w <= 0 and NaN go to the series branch
        if (w >= w_max_) return above(w);
        const std::uint64_t bits = std::bit_cast<std::uint64_t>(w);
        const int shift = 52 - opt_.mantissa_bits;
        const std::uint64_t k = (bits >> shift) - index_base_;
        const double t = static_cast<double>(bits & ((std::uint64_t{1} << shift) - 1)) * t_scale_;
        const auto& c = coef_[k];
        return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
    }

    double w_min() const { return w_min_; }
    double w_max() const { return w_max_; }
    const ContactModel& model() const { return model_; }
    const NormalTableOptions& options() const { return opt_; }
    std::size_t intervals() const { return coef_.size(); }
    int limited_intervals() const { return limited_; } // intervals the monotonicity limiter touched
    double build_seconds() const { return build_seconds_; }
    // Coefficients of the small-w series 1 - eps = u (s[0] + s[1] u^{1/2} + s[2] u + s[3] u^{3/2} + s[4] u^2).
    const std::array<double, 5>& series() const { return series_; }

    // Everything the table depends on, as text: the key of a persisted copy.
    static std::string key_for(ContactModel model, const NormalTableOptions& opt);
    std::string cache_key() const { return key_for(model_, opt_); }
    // Flat payload for persistence, and the inverse (throws std::runtime_error on a size mismatch).
    std::vector<double> serialize() const;
    static NormalTable deserialize(ContactModel model, NormalTableOptions opt, const std::vector<double>& data);

private:
    double below(double w) const;
    double above(double w) const;
    void finish_layout();

    ContactModel model_{};
    NormalTableOptions opt_{};
    std::vector<std::array<double, 4>> coef_; // cubic in local t in [0, 1) per interval
    std::array<double, 5> series_{};
    double w_min_ = 0; // 2^e_min, kept: std::ldexp is a library call, and eps_n runs once per collision
    double w_max_ = 0, eps_max_ = 0, slope_max_ = 0; // power-law tail: eps_max (w/w_max)^slope_max
    std::uint64_t index_base_ = 0;
    double t_scale_ = 0;
    int limited_ = 0;
    double build_seconds_ = 0;
};

} // namespace roughgas
