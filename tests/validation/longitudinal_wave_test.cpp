// The longitudinal modes of the cooling state against Navier-Stokes hydrodynamics
// (observables/longitudinal_modes.hpp): a density wave of smooth or rough grains, A n sin(2 pi x/L), followed
// in modes.csv's amplitudes of the wave number along x (density delta n/n, temperature delta T/T and
// the flow u_x over the thermal speed sqrt(T/m)), projected on the left eigenvectors of the
// linearised equations' matrix M: each projection is one mode, exp(lambda s) in collisions per
// particle s, whatever the others do. The heat mode's rate is the slope of ln|p|, the sound mode's
// damping and frequency the slopes of ln|p| and of its phase.
// CPU: about 80 s (Release; three boxes, 8 replicas of 1e5 grains to 60 or 40 collisions per particle).
#include "../dsmc/test_stats.hpp"
#include "../dsmc/run_test_support.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/observables/longitudinal_modes.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace roughgas {
namespace {

constexpr double n = 0.02, sigma = 1.0;
const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n * sigma * sigma);

// Grains of restitution alpha and beta (-1: smooth; uniform spheres, q = 2/5) in a box L long,
// 2 lambda across (cells of lambda/4 along x), a density wave of amplitude 0.2, rows every half
// collision per particle to `end`.
RunSpec wave_run(double alpha, double L, double end, double beta = -1) {
    RunSpec spec;
    spec.species = {SpeciesSpec{}};
    spec.species[0].radius = sigma / 2;
    spec.pairs = {ConstantRestitution{alpha, beta}};
    spec.particles = 100000;
    spec.density = n;
    spec.seed = 9;
    for (int k = 1; k <= 2 * end; ++k)
        spec.output_times.push_back(0.5 * k);
    spec.end = end;
    spec.threads = 2;
    DomainSpec d;
    d.size = {L, 2 * lambda, 2 * lambda};
    d.cells = {static_cast<int>(std::lround(4 * L / lambda)), 4, 4};
    d.initial = {Perturbation::density, 0.2, {1, 0, 0}};
    d.spectra = SpectraSpec{1};
    spec.domain = d;
    return spec;
}

struct Sample {
    double s;
    Eigen::Vector3cd y; // (delta n/n, delta T/T, u_x/sqrt(T/m)) of the mode n = 1 along x
};

std::vector<Sample> trajectory(const RunSpec& spec, int replica) {
    const std::size_t js = test::column(spec, "coll_per_particle"), jT = test::column(spec, "T_tr");
    std::vector<std::size_t> j;
    for (const char* f : {"n_re", "n_im", "T_re", "T_im", "u_x_re", "u_x_im"})
        j.push_back(test::row_column(spec, std::string("mode1.1.") + f));
    std::vector<Sample> out;
    run_replica(spec, replica, [&](std::span<const double> row) {
        const std::complex<double> u(row[j[4]], row[j[5]]);
        // T about the local flow: T_tr about the box's mean velocity holds the wave's (m/6) |u|^2.
        const double T = row[jT] - std::norm(u) / 6;
        out.push_back({row[js], Eigen::Vector3cd(std::complex<double>(row[j[0]], row[j[1]]),
                                                 std::complex<double>(row[j[2]], row[j[3]]), u / std::sqrt(T))});
    });
    return out;
}

// The projection of y on the eigenvector of M whose eigenvalue is nearest `target`: (V^-1 y)_j.
std::vector<std::complex<double>> projection(const std::vector<Sample>& tr, const Eigen::Matrix3cd& M,
                                             std::complex<double> target) {
    const Eigen::ComplexEigenSolver<Eigen::Matrix3cd> es(M);
    int j = 0;
    for (int c = 1; c < 3; ++c)
        if (std::abs(es.eigenvalues()(c) - target) < std::abs(es.eigenvalues()(j) - target))
            j = c;
    const Eigen::Matrix3cd left = es.eigenvectors().inverse();
    std::vector<std::complex<double>> p;
    for (const Sample& x : tr)
        p.push_back((left.row(j) * x.y)(0));
    return p;
}

// Least-squares slope of y(s) over from <= s <= to.
double slope(const std::vector<Sample>& tr, const std::vector<double>& y, double from, double to) {
    double K = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < tr.size(); ++i) {
        const double s = tr[i].s;
        if (s < from || s > to)
            continue;
        K += 1;
        sx += s;
        sy += y[i];
        sxx += s * s;
        sxy += s * y[i];
    }
    return (K * sxy - sx * sy) / (K * sxx - sx * sx);
}

// Per replica: the heat mode's rate and the sound mode's damping rate and frequency, each fitted
// over its window.
struct Rates {
    std::vector<double> heat, sound_re, sound_im;
};
Rates fitted_rates(const RunSpec& spec, const Eigen::Matrix3cd& M, const LongitudinalModeRates& theory,
                   std::array<double, 2> heat_window, std::array<double, 2> sound_window, int replicas) {
    Rates r;
    for (int k = 0; k < replicas; ++k) {
        const std::vector<Sample> tr = trajectory(spec, k);
        const auto ph = projection(tr, M, theory.heat), ps = projection(tr, M, theory.sound[0]);
        std::vector<double> lh, ls, phase;
        double unwrap = 0, last = std::arg(ps.front());
        for (std::size_t i = 0; i < tr.size(); ++i) {
            lh.push_back(std::log(std::abs(ph[i])));
            ls.push_back(std::log(std::abs(ps[i])));
            const double a = std::arg(ps[i]);
            unwrap += std::remainder(a - last, 2 * std::numbers::pi);
            last = a;
            phase.push_back(unwrap);
        }
        r.heat.push_back(slope(tr, lh, heat_window[0], heat_window[1]));
        r.sound_re.push_back(slope(tr, ls, sound_window[0], sound_window[1]));
        r.sound_im.push_back(slope(tr, phase, sound_window[0], sound_window[1]));
    }
    return r;
}

// The DSMC's transport coefficients for cells of lambda/4 along the wave and steps of 0.2 mean free
// times: the viscosity's cell-size and step laws, 16/(45 pi) (1/4)^2 + 16/(75 pi) (0.2 sqrt(pi)/2)^2
// = 0.98 %, and the thermal conductivity's cell-size law 32/(225 pi) (1/4)^2 = 0.28 % (Alexander,
// Garcia & Alder 1998) and step law 32/(225 pi) (0.2 sqrt(pi)/2)^2 = 0.14 % (Hadjiconstantinou 2000).
LongitudinalModeTheory dsmc_theory(LongitudinalModeTheory t, double eta_factor, double kappa_factor) {
    const double step = std::pow(0.2 * std::sqrt(std::numbers::pi) / 2, 2);
    t.shear.eta_star *= eta_factor * (1 + 16 / (45 * std::numbers::pi) / 16 + 16 / (75 * std::numbers::pi) * step);
    t.kappa_star *= kappa_factor * (1 + 32 / (225 * std::numbers::pi) / 16 + 32 / (225 * std::numbers::pi) * step);
    return t;
}

// Elastic grains in a box of 40 lambda (k lambda = 0.157): the density wave splits into the heat
// (entropy) mode, decaying at (15 pi/64) (kappa/kappa_0) (k lambda)^2 per collision, and the sound
// pair at the adiabatic speed sqrt(5 T/(3 m)), decaying by viscosity and conduction; with the
// Chapman-Enskog converged eta = 1.016034 eta_0 and kappa = 1.025218 kappa_0 and the DSMC's laws.
// Fitted from 1 to 50 (heat) and 60 (sound) collisions per particle. Allowed beyond 4 standard
// errors of the replicas' mean: 3 % of each rate for the order beyond Navier-Stokes. At twice the
// wave number (k lambda = 0.314, a box of 20 lambda) that order is plain: the heat mode decays 18 %
// more slowly than Navier-Stokes, the sound 9 % more slowly and at a 4.5 % higher frequency
// (measured once, docs/validation.md); at k lambda = 0.157 each agrees within 2.4 %.
TEST(LongitudinalWave, ElasticDensityWaveSplitsIntoTheHeatAndSoundModes) {
    const double L = 40 * lambda, k_lambda = 2 * std::numbers::pi * lambda / L;
    const LongitudinalModeTheory t = dsmc_theory(smooth_longitudinal_modes(1.0), 1.016034, 1.025218);
    const Eigen::Matrix3cd M = longitudinal_mode_matrix(t, k_lambda);
    const LongitudinalModeRates th = longitudinal_mode_rates(t, k_lambda);
    const Rates r = fitted_rates(wave_run(1.0, L, 60), M, th, {1, 50}, {1, 60}, 8);
    const test::MeanErr heat = test::mean_err(r.heat), re = test::mean_err(r.sound_re),
                        im = test::mean_err(r.sound_im);
    std::printf("[ LONGITUDINAL ] elastic, k lambda = %.3f: heat %+.5f +- %.5f (Navier-Stokes %+.5f), sound "
                "%+.5f +- %.5f (%+.5f) and frequency %.5f +- %.5f (%.5f) per collision\n",
                k_lambda, heat.mean, heat.err, th.heat.real(), re.mean, re.err, th.sound[0].real(), im.mean, im.err,
                th.sound[0].imag());
    EXPECT_NEAR(heat.mean, th.heat.real(), 4 * heat.err + 0.03 * std::abs(th.heat.real()));
    EXPECT_NEAR(re.mean, th.sound[0].real(), 4 * re.err + 0.03 * std::abs(th.sound[0].real()));
    EXPECT_NEAR(im.mean, th.sound[0].imag(), 4 * im.err + 0.03 * std::abs(th.sound[0].imag()));
}

// Inelastic grains, alpha = 0.9, in a box of 1.6 L_par (L_par = 38.2 lambda; k lambda = 0.103): the
// heat mode grows (the density instability) while the sound pair is damped. Fitted from 5 collisions
// per particle (after the Maxwellian start's transient) to 60. Allowed beyond 4 standard errors: 5 %
// of the conduction term P (kappa* - mu*) (k lambda)^2 (the first Sonine kappa* and mu*) and 1 % of
// the growth term (the cooling rate) in the heat mode; 3 % of the sound pair's rates.
TEST(LongitudinalWave, CoolingGasDensityWaveGrowsAsTheHeatMode) {
    const LongitudinalModeTheory gas = smooth_longitudinal_modes(0.9);
    const double L = 1.6 * gas.critical_length * lambda, k_lambda = 2 * std::numbers::pi * lambda / L;
    const LongitudinalModeTheory t = dsmc_theory(gas, 1, 1);
    const Eigen::Matrix3cd M = longitudinal_mode_matrix(t, k_lambda);
    const LongitudinalModeRates th = longitudinal_mode_rates(t, k_lambda);
    const Rates r = fitted_rates(wave_run(0.9, L, 60), M, th, {5, 60}, {5, 60}, 8);
    const test::MeanErr heat = test::mean_err(r.heat), re = test::mean_err(r.sound_re),
                        im = test::mean_err(r.sound_im);
    std::printf("[ LONGITUDINAL ] alpha = 0.9, L = 1.6 L_par, k lambda = %.3f: heat %+.5f +- %.5f (Navier-Stokes "
                "%+.5f), sound %+.5f +- %.5f (%+.5f) and frequency %.5f +- %.5f (%.5f) per collision\n",
                k_lambda, heat.mean, heat.err, th.heat.real(), re.mean, re.err, th.sound[0].real(), im.mean, im.err,
                th.sound[0].imag());
    const double conduction = 25 * std::numbers::pi / 64 * (t.kappa_star - t.mu_star) * k_lambda * k_lambda /
                              (1 - t.shear.a2 / 16);
    EXPECT_GT(heat.mean, 0) << "the density wave must grow beyond L_par";
    EXPECT_NEAR(heat.mean, th.heat.real(), 4 * heat.err + 0.05 * conduction + 0.01 * t.shear.growth);
    EXPECT_NEAR(re.mean, th.sound[0].real(), 4 * re.err + 0.03 * std::abs(th.sound[0].real()));
    EXPECT_NEAR(im.mean, th.sound[0].imag(), 4 * im.err + 0.03 * std::abs(th.sound[0].imag()));
}

// Rough grains, alpha = 0.9, beta = 0 (q = 2/5), in a box of 1.6 L_par (L_par = 19.0 lambda;
// k lambda = 0.207), against the rough theory (Kremer, Santos & Garzo's scheme: first Sonine
// kappa*, mu*, bulk viscosity and first-order cooling about the two-temperature Maxwellian). The
// fields are those of M for rough grains: delta T/T is taken as delta T_tr/T_tr (equal in
// Navier-Stokes order, the spins' temperature following the translational one) and the flow over
// sqrt(T_tr/m). Fitted from 5 to 40 collisions per particle.
TEST(LongitudinalWave, RoughGasDensityWaveGrowsBeyondTheCriticalLength) {
    const LongitudinalModeTheory gas = rough_longitudinal_modes(0.9, 0.0, 0.4);
    const double L = 1.6 * gas.critical_length * lambda, k_lambda = 2 * std::numbers::pi * lambda / L;
    const LongitudinalModeTheory t = dsmc_theory(gas, 1, 1);
    const Eigen::Matrix3cd M = longitudinal_mode_matrix(t, k_lambda);
    const LongitudinalModeRates th = longitudinal_mode_rates(t, k_lambda);
    const Rates r = fitted_rates(wave_run(0.9, L, 40, 0.0), M, th, {5, 40}, {5, 40}, 8);
    const test::MeanErr heat = test::mean_err(r.heat), re = test::mean_err(r.sound_re),
                        im = test::mean_err(r.sound_im);
    std::printf("[ LONGITUDINAL ] alpha = 0.9, beta = 0, L = 1.6 L_par, k lambda = %.3f: heat %+.5f +- %.5f "
                "(Navier-Stokes %+.5f), sound %+.5f +- %.5f (%+.5f) and frequency %.5f +- %.5f (%.5f) per collision\n",
                k_lambda, heat.mean, heat.err, th.heat.real(), re.mean, re.err, th.sound[0].real(), im.mean, im.err,
                th.sound[0].imag());
    // The density wave grows in a box beyond L_par, as the theory says. Its rate is not compared
    // with Navier-Stokes here: the projection feeds delta T_tr/T_tr where the theory's delta T/T is
    // that of (T_tr + T_rot)/2 (modes.csv has no T_rot amplitude), and the growing heat mode leaks
    // into the other projections; fits of the cell fields without eigenvectors give +0.0352 +-
    // 0.0004 against Navier-Stokes +0.0422, a departure that grows as (k lambda)^2
    // (docs/validation.md, "The longitudinal modes of rough grains").
    EXPECT_GT(heat.mean, 4 * heat.err) << "the density wave must grow beyond L_par";
}

} // namespace
} // namespace roughgas
