// The shear mode of an elastic gas in equilibrium: the thermal fluctuations of the transverse current
// at wave number k decay as exp(-nu k^2 t), nu = eta/(n m) the kinematic viscosity (linearised
// Navier-Stokes; the hard-sphere Boltzmann gas's eta = 1.016034 eta_0, Chapman-Enskog converged,
// eta_0 = (5/(16 sigma^2)) sqrt(m T/pi)). Per collision per particle s (ds/dt = 4 n sigma^2
// sqrt(pi T/m)) the rate is Gamma = (5 pi/32) (eta/eta_0) (k lambda)^2, here with the DSMC's own
// viscosity: eta raised by its cell-size and step laws (docs/validation.md).
// CPU: about 40 s (Release; 8 replicas of 2500 grains to 5000 collisions per particle).
#include "../dsmc/run_test_support.hpp"
#include "../dsmc/test_stats.hpp"
#include "roughgas/dsmc/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace roughgas {
namespace {

constexpr double n = 0.02, sigma = 1.0;
const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n * sigma * sigma);
constexpr double box_over_lambda = 31.4, cells_per_lambda = 4, every = 2, end = 5000;

// Elastic smooth hard spheres in a box 31.4 lambda long (k lambda = 0.2 for its longest wave along x)
// and 1 lambda across, cells of lambda/4 along x holding 20 grains, rows every 2 collisions per
// particle, the longest waves' amplitudes in the modes.
RunSpec equilibrium_run() {
    RunSpec spec;
    spec.species = {SpeciesSpec{}};
    spec.species[0].radius = sigma / 2;
    spec.pairs = {ConstantRestitution{1.0, -1.0}};
    const int cells = static_cast<int>(std::lround(box_over_lambda * cells_per_lambda));
    spec.particles = 20 * cells;
    spec.density = n;
    spec.seed = 11;
    for (double s = every; s <= end; s += every)
        spec.output_times.push_back(s);
    spec.end = end;
    spec.threads = 1;
    DomainSpec d;
    d.size = {box_over_lambda * lambda, lambda, lambda};
    d.cells = {cells, 1, 1};
    d.spectra = SpectraSpec{1};
    spec.domain = d;
    return spec;
}

// One replica's decay rate per collision per particle: the autocorrelation C(tau) of the four real
// series of the transverse flow amplitudes (u_y and u_z of the mode n = 1 along x, real and
// imaginary parts: independent in equilibrium) pooled, and the least-squares slope of -ln C over
// the lags from 10 to 60 collisions per particle (0.2 to 1.2 decay times: past the free flights, and
// C well above its noise).
double decay_rate(const RunSpec& spec, int replica) {
    std::vector<std::size_t> cols;
    for (const char* f : {"u_y_re", "u_y_im", "u_z_re", "u_z_im"})
        cols.push_back(test::row_column(spec, std::string("mode1.1.") + f));
    std::vector<std::vector<double>> series(cols.size());
    run_replica(spec, replica, [&](std::span<const double> row) {
        for (std::size_t j = 0; j < cols.size(); ++j)
            series[j].push_back(row[cols[j]]);
    });
    const std::size_t first = static_cast<std::size_t>(10 / every), last = static_cast<std::size_t>(60 / every);
    const std::size_t rows = series[0].size();
    double c0 = 0;
    for (const auto& a : series)
        for (double x : a)
            c0 += x * x / static_cast<double>(rows);
    double K = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t lag = first; lag <= last; ++lag) {
        double c = 0;
        for (const auto& a : series)
            for (std::size_t t = 0; t + lag < rows; ++t)
                c += a[t] * a[t + lag] / static_cast<double>(rows - lag);
        const double x = static_cast<double>(lag) * every, y = -std::log(c / c0);
        K += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (K * sxy - sx * sy) / (K * sxx - sx * sx);
}

// The rate against the Navier-Stokes one with the DSMC's viscosity, 1.016034 (1 + 16/(45 pi) (1/4)^2 +
// 16/(75 pi) (0.2 sqrt(pi)/2)^2) eta_0 = 1.0259 eta_0, within 4 standard errors of the replicas' mean
// plus 1.5 % for the order beyond Navier-Stokes at k lambda = 0.2 (the cooling gas's transverse waves
// show (1.6 +- 1.1) % less damping than Navier-Stokes at k lambda = 0.31, ShearModeGrowth; a (k lambda)^2
// correction scales that to 0.7 % here). The replicas resolve the rate to about 2.5 %, so the
// tolerance is about 11.5 % (at most 13.5 % with the error bound of 3 % below): a viscosity off by 15 %
// fails (the first Sonine 1.6 % is not resolved, nor is 10 %), and so does a rate per unit time
// mistaken for one per collision.
TEST(TransverseCurrent, ElasticGasFluctuationsDecayAtTheKinematicViscosity) {
    const RunSpec spec = equilibrium_run();
    std::vector<double> rates;
    for (int r = 0; r < 8; ++r)
        rates.push_back(decay_rate(spec, r));
    const test::MeanErr g = test::mean_err(rates);
    const double dx = 1 / cells_per_lambda, step = 0.2 * std::sqrt(std::numbers::pi) / 2;
    const double laws = 16 / (45 * std::numbers::pi) * dx * dx + 16 / (75 * std::numbers::pi) * step * step;
    const double k_lambda = 2 * std::numbers::pi / box_over_lambda;
    const double expected = 5 * std::numbers::pi / 32 * 1.016034 * (1 + laws) * k_lambda * k_lambda;
    std::printf("[ TRANSVERSE CURRENT ] k lambda = %.3f: decay %.5f +- %.5f per collision, Navier-Stokes %.5f\n",
                k_lambda, g.mean, g.err, expected);
    EXPECT_NEAR(g.mean, expected, 4 * g.err + 0.015 * expected);
    EXPECT_LT(g.err, 0.03 * expected) << "the replicas must resolve the rate to 3 %";
}

} // namespace
} // namespace roughgas
