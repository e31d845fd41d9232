// Histograms of c*, w*, c*.w* (observables/histograms.hpp): exact references and sampled laws.
#include "roughgas/observables/histograms.hpp"

#include "roughgas/core/rng.hpp"

#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/random/normal_distribution.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace roughgas {
namespace {

Vec3Column col(const std::vector<Vec3>& v) {
    return column_of(v.data(), 0);
}

double integrate(double (*f)(double), double lo, double hi) {
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(f, lo, hi, 20, 1e-14);
}

TEST(Histograms, ProductDensityIsNormalisedWithTheMaxwellianVariance) {
    // <(c*.w*)^2> = 3 <c_k^2><w_k^2> = 3/4 for c*_k, w*_k ~ N(0, 1/2); <(c*.w*)^4> = 45/16.
    const auto f = [](double z) { return maxwell_product_density(z); };
    const auto z2 = [](double z) { return z * z * maxwell_product_density(z); };
    const auto z4 = [](double z) { return z * z * z * z * maxwell_product_density(z); };
    EXPECT_NEAR(2 * integrate(+f, 0, 60), 1.0, 1e-12);
    EXPECT_NEAR(2 * integrate(+z2, 0, 60), 0.75, 1e-12);
    EXPECT_NEAR(2 * integrate(+z4, 0, 60), 45.0 / 16.0, 1e-11);
}

TEST(Histograms, MaxwellBinsAreTheBinAveragesOfTheDensity) {
    const HistogramGrid g{40, 4.0};
    const std::vector<double> fs = maxwell_speed_bins(g), fp = maxwell_product_bins(g);
    const std::vector<double> xs = speed_bin_centres(g), xp = product_bin_centres(g);
    double ss = 0, sp = 0;
    for (std::size_t k = 0; k < fs.size(); ++k) {
        ss += fs[k] * 0.1;
        sp += fp[k] * 0.2;
        // Midpoint rule: the bin average differs from the centre value by O(width^2 f'').
        const double x = xs[k];
        EXPECT_NEAR(fs[k], 4 / std::sqrt(std::numbers::pi) * x * x * std::exp(-x * x), 0.01);
        EXPECT_NEAR(fp[k], maxwell_product_density(xp[k]), 0.02);
        EXPECT_NEAR(fp[k], fp[fp.size() - 1 - k], 1e-13); // even density
    }
    EXPECT_NEAR(ss, maxwell_speed_cdf(4.0), 1e-13);
    EXPECT_NEAR(sp, 2 * integrate(+[](double z) { return maxwell_product_density(z); }, 0, 4), 1e-12);
}

TEST(Histograms, AllGrainsAtOneSpeedFillOneBin) {
    // +-e_x, +-e_y, +-e_z with omega = 2c: <c^2> = 1, so T_tr = m/3 and |c*|^2 = m c^2/(2 T_tr) = 3/2
    // for every grain (likewise |w*|^2): all land in the bin of sqrt(3/2) = 1.2247, c*.w* = 3/2.
    std::vector<Vec3> v, w;
    const Vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& d : e)
        for (double s : {1.0, -1.0}) {
            v.push_back(s * d);
            w.push_back(s * 2.0 * d);
        }
    const SpeciesSlice sp{0, v.size(), 1.0, 0.1};
    const Moments m = compute_moments(col(v), col(w), {&sp, 1});
    const HistogramGrid g{10, 5.0};
    const auto h = compute_histograms(col(v), col(w), {&sp, 1}, m, g);
    ASSERT_EQ(h.size(), 1u);
    for (int k = 0; k < 10; ++k) {
        const auto K = static_cast<std::size_t>(k);
        EXPECT_EQ(h[0].c[K], k == 2 ? 1.0 / 0.5 : 0.0); // bin [1, 1.5), density 1/width
        EXPECT_EQ(h[0].w[K], k == 2 ? 1.0 / 0.5 : 0.0);
        EXPECT_EQ(h[0].cw[K], k == 6 ? 1.0 / 1.0 : 0.0); // c*.w* = 1.5 in [1, 2)
    }
}

TEST(Histograms, SampledMaxwellianMixturePassesChiSquare) {
    // Two species (m = 1, 8; J = 0.1, 3.2) at different temperatures, each Maxwellian: in the
    // species' own reduced variables every histogram follows the Maxwellian bins. Pearson's chi^2
    // over the bins (expected counts N p_k >= 5 kept) below its 1 - 1e-4 quantile.
    Rng rng = make_stream(41, Stream::test, 0, 0);
    boost::random::normal_distribution<double> normal;
    const std::size_t n = 40000;
    const double m[2] = {1.0, 8.0}, J[2] = {0.1, 3.2}, T[2] = {2.0, 0.5}, Tr[2] = {0.3, 4.0};
    std::vector<Vec3> v, w;
    for (int s = 0; s < 2; ++s)
        for (std::size_t i = 0; i < n; ++i) {
            const double sv = std::sqrt(T[s] / m[s]), sw = std::sqrt(Tr[s] / J[s]);
            v.push_back({sv * normal(rng), sv * normal(rng), sv * normal(rng)});
            w.push_back({sw * normal(rng), sw * normal(rng), sw * normal(rng)});
        }
    const SpeciesSlice sp[2] = {{0, n, m[0], J[0]}, {n, n, m[1], J[1]}};
    const Moments mo = compute_moments(col(v), col(w), sp);
    const HistogramGrid g{40, 4.0};
    const auto h = compute_histograms(col(v), col(w), sp, mo, g);
    const std::vector<double> fs = maxwell_speed_bins(g), fp = maxwell_product_bins(g);
    const auto chi2 = [&](const std::vector<double>& f, const std::vector<double>& ref, double width) {
        double x2 = 0;
        int dof = -1;
        for (std::size_t k = 0; k < f.size(); ++k) {
            const double expected = ref[k] * width * static_cast<double>(n);
            if (expected < 5)
                continue;
            const double observed = f[k] * width * static_cast<double>(n);
            x2 += (observed - expected) * (observed - expected) / expected;
            ++dof;
        }
        return boost::math::cdf(boost::math::chi_squared(dof), x2);
    };
    for (const SpeciesHistograms& s : h) {
        EXPECT_LT(chi2(s.c, fs, 0.1), 1 - 1e-4);
        EXPECT_LT(chi2(s.w, fs, 0.1), 1 - 1e-4);
        EXPECT_LT(chi2(s.cw, fp, 0.2), 1 - 1e-4);
    }
    // ... and a wrong reference is rejected: the speed histogram is not the product law.
    EXPECT_GT(chi2(h[0].c, fp, 0.1), 1 - 1e-4);
}

} // namespace
} // namespace roughgas
