#include "roughgas/observables/histograms.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/bessel.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace roughgas {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

void check(const HistogramGrid& g) {
    if (g.bins < 1 || !(g.max > 0) || !std::isfinite(g.max))
        throw std::invalid_argument("HistogramGrid: bins >= 1 and a finite max > 0 needed");
}

// Adds x to the histogram [lo, lo + bins width) (counts; scaled to densities at the end).
void add(std::vector<double>& h, double x, double lo, double inv_width) {
    const double k = std::floor((x - lo) * inv_width);
    if (k >= 0 && k < static_cast<double>(h.size()))
        h[static_cast<std::size_t>(k)] += 1.0;
}

void to_density(std::vector<double>& h, double n, double width) {
    for (double& x : h)
        x = n > 0 ? x / (n * width) : nan;
}

} // namespace

std::vector<double> speed_bin_centres(const HistogramGrid& g) {
    check(g);
    const double w = g.max / g.bins;
    std::vector<double> x(static_cast<std::size_t>(g.bins));
    for (int k = 0; k < g.bins; ++k)
        x[static_cast<std::size_t>(k)] = (k + 0.5) * w;
    return x;
}

std::vector<double> product_bin_centres(const HistogramGrid& g) {
    check(g);
    const double w = 2.0 * g.max / g.bins;
    std::vector<double> x(static_cast<std::size_t>(g.bins));
    for (int k = 0; k < g.bins; ++k)
        x[static_cast<std::size_t>(k)] = -g.max + (k + 0.5) * w;
    return x;
}

std::vector<SpeciesHistograms> compute_histograms(Vec3Column v, Vec3Column omega,
                                                  std::span<const SpeciesSlice> species, const Moments& m,
                                                  const HistogramGrid& g) {
    check(g);
    if (m.species.size() != species.size())
        throw std::invalid_argument("compute_histograms: moments of another species list");
    const auto B = static_cast<std::size_t>(g.bins);
    const double ws = g.max / g.bins, wp = 2.0 * g.max / g.bins;
    std::vector<SpeciesHistograms> out(species.size());
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSlice& sp = species[s];
        const GroupMoments& gm = m.species[s];
        SpeciesHistograms& h = out[s];
        h.c.assign(B, 0.0);
        const bool rot = gm.T_rot > 0;
        h.w.assign(B, rot ? 0.0 : nan);
        h.cw.assign(B, rot ? 0.0 : nan);
        const double sc = gm.T_tr > 0 ? std::sqrt(sp.mass / (2.0 * gm.T_tr)) : 0.0;
        const double sw = rot ? std::sqrt(sp.moment_of_inertia / (2.0 * gm.T_rot)) : 0.0;
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            const Vec3 c = sc * (v[i] - m.mean_velocity);
            add(h.c, norm(c), 0.0, 1.0 / ws);
            if (rot) {
                const Vec3 w = sw * omega[i];
                add(h.w, norm(w), 0.0, 1.0 / ws);
                add(h.cw, dot(c, w), -g.max, 1.0 / wp);
            }
        }
        const double n = static_cast<double>(sp.count);
        to_density(h.c, gm.T_tr > 0 ? n : 0.0, ws);
        if (rot) {
            to_density(h.w, n, ws);
            to_density(h.cw, n, wp);
        }
    }
    return out;
}

double maxwell_speed_cdf(double x) {
    if (!(x > 0))
        return 0.0;
    return std::erf(x) - 2.0 / std::sqrt(std::numbers::pi) * x * std::exp(-x * x);
}

double maxwell_product_density(double z) {
    const double a = std::abs(2.0 * z);
    if (a == 0)
        return 2.0 / std::numbers::pi; // x K_1(x) -> 1 as x -> 0
    if (a > 1400)
        return 0.0; // K_1 underflows
    return (2.0 / std::numbers::pi) * a * boost::math::cyl_bessel_k(1, a);
}

std::vector<double> maxwell_speed_bins(const HistogramGrid& g) {
    check(g);
    const double w = g.max / g.bins;
    std::vector<double> f(static_cast<std::size_t>(g.bins));
    for (int k = 0; k < g.bins; ++k)
        f[static_cast<std::size_t>(k)] = (maxwell_speed_cdf((k + 1) * w) - maxwell_speed_cdf(k * w)) / w;
    return f;
}

std::vector<double> maxwell_product_bins(const HistogramGrid& g) {
    check(g);
    const double w = 2.0 * g.max / g.bins;
    std::vector<double> f(static_cast<std::size_t>(g.bins));
    for (int k = 0; k < g.bins; ++k) {
        const double a = -g.max + k * w;
        // The density is smooth except for a z^2 log|z| term at 0, a bin edge or inside one bin:
        // split there so that each piece is integrated to round-off.
        const auto integrate = [](double lo, double hi) {
            return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(maxwell_product_density, lo,
                                                                                 hi, 8, 1e-13);
        };
        const double b = a + w;
        const double sum = a < 0 && b > 0 ? integrate(a, 0.0) + integrate(0.0, b) : integrate(a, b);
        f[static_cast<std::size_t>(k)] = sum / w;
    }
    return f;
}

} // namespace roughgas
