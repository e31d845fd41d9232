#pragma once
// Histograms of the reduced speeds and of the translation-rotation product:
//
//   c* = |c| sqrt(m/(2 T_tr,s)),   w* = |omega| sqrt(J/(2 T_rot,s)),   c*.w* (the reduced vectors' dot product)
//
// per species s, with c = v - u (u the centre-of-mass velocity) and the species' own temperatures
// (observables/moments.hpp). Reduced variables make histograms at different times comparable (the
// homogeneous cooling state is a scaling solution) and give every species the same Maxwellian
// reference: for independent Maxwellian c and omega,
//
//   |c*|, |w*|:  f(x) = (4/sqrt(pi)) x^2 exp(-x^2),  F(x) = erf(x) - (2/sqrt(pi)) x exp(-x^2)
//   c*.w*:       f(z) = (4/pi) |z| K_1(2|z|)
//
// (the second: c*_k w*_k with c*_k, w*_k ~ N(0, 1/2) has the characteristic function (1 + k^2/4)^(-1/2);
// the sum of three, (1 + k^2/4)^(-3/2), transforms to (4/pi)|z| K_1(2|z|); it integrates to 1).
// A histogram holds the probability density averaged over each bin: count/(N width), grains outside
// the range counted in N (so the bins sum to the fraction inside). The Maxwellian references are
// bin averages too, so the two compare without discretisation error.
#include "roughgas/core/vec.hpp"
#include "roughgas/observables/moments.hpp"

#include <span>
#include <vector>

namespace roughgas {

struct HistogramGrid {
    int bins = 50;
    double max = 5.0; // |c*| and |w*| in [0, max), c*.w* in [-max, max)
};

struct SpeciesHistograms {
    std::vector<double> c, w, cw; // densities per bin; w, cw are NaN where T_rot,s = 0
};

// Bin centres of the speed histograms (|c*|, |w*|) and of c*.w*.
std::vector<double> speed_bin_centres(const HistogramGrid& g);
std::vector<double> product_bin_centres(const HistogramGrid& g);

// One histogram set per species; `m` must be compute_moments of the same state.
std::vector<SpeciesHistograms> compute_histograms(Vec3Column v, Vec3Column omega,
                                                  std::span<const SpeciesSlice> species, const Moments& m,
                                                  const HistogramGrid& g);

// Bin averages of the Maxwellian densities above.
std::vector<double> maxwell_speed_bins(const HistogramGrid& g);
std::vector<double> maxwell_product_bins(const HistogramGrid& g);
double maxwell_speed_cdf(double x);
double maxwell_product_density(double z);

} // namespace roughgas
