// The instability of the cooling state against Navier-Stokes hydrodynamics: in a cooling gas of
// smooth grains (alpha = 0.9, critical length L_c = 25.3 mean free paths, observables/shear_mode.hpp)
// a transverse wave u_y = A sqrt(T/m) sin(2 pi x/L) decays against the thermal speed in a box shorter
// than L_c and grows in a longer one, at gamma = growth - damping (k lambda)^2 per collision per
// particle.
// CPU: about 75 s (Release; eight boxes, 8 replicas of 1e5 grains to 40, 20 or 12 collisions per particle).
#include "../dsmc/test_stats.hpp"
#include "../dsmc/run_test_support.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/observables/shear_mode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

namespace roughgas {
namespace {

constexpr double n = 0.02, sigma = 1.0, alpha = 0.9;
const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n * sigma * sigma);

// Grains (smooth: beta = -1; restitution a, beta) in a box L long (cells of lambda/4 along x) and 2 lambda across, the
// wave's amplitude 0.2 of the thermal speed, rows every collision per particle to `end`; rough grains
// start at the cooling state's theta.
RunSpec wave_run(double L, double beta = -1, double end = 40, double a = alpha) {
    RunSpec spec;
    spec.species = {SpeciesSpec{}};
    spec.species[0].radius = sigma / 2;
    if (beta > -1)
        spec.species[0].rotational_temperature = rough_shear_mode(a, beta, 0.4).theta;
    spec.pairs = {ConstantRestitution{a, beta}};
    spec.particles = 100000;
    spec.density = n;
    spec.seed = 5;
    for (int k = 1; k <= end; ++k)
        spec.output_times.push_back(k);
    spec.end = end;
    spec.threads = 2;
    DomainSpec d;
    d.size = {L, 2 * lambda, 2 * lambda};
    d.cells = {static_cast<int>(std::lround(4 * L / lambda)), 4, 4};
    d.initial = {Perturbation::transverse, 0.2, {1, 0, 0}};
    spec.domain = d;
    return spec;
}

// The DSMC's viscosity over the gas's: its cell-size and time-step laws for cells of lambda/4 along
// the wave and steps of 0.2 mean free times, 16/(45 pi) (1/4)^2 + 16/(75 pi) (0.2 sqrt(pi)/2)^2.
const double laws = 16.0 / (45.0 * std::numbers::pi) / 16 +
                    16.0 / (75.0 * std::numbers::pi) * std::pow(0.2 * std::sqrt(std::numbers::pi) / 2, 2);

// Each replica's gamma: the least-squares slope of ln(u_wave / sqrt(T/m)) over coll_per_particle
// from 5 to 40 (after the transient of the Maxwellian start, while the wave stays well above the
// sampling noise and below half the thermal speed). T is the temperature about the flow:
// T_tr about the box's mean velocity holds the wave's (m/6) u_wave^2.
std::vector<double> growth_rates(const RunSpec& spec, int replicas) {
    const auto col = [&](const char* name) { return test::column(spec, name); };
    const std::size_t js = col("coll_per_particle"), ju = col("u_wave"), jT = col("T_tr");
    std::vector<double> rates;
    for (int r = 0; r < replicas; ++r) {
        double K = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        run_replica(spec, r, [&](std::span<const double> row) {
            const double s = row[js], u = row[ju], T = row[jT] - u * u / 6;
            if (s < 5)
                return;
            const double y = std::log(u / std::sqrt(T));
            K += 1;
            sx += s;
            sy += y;
            sxx += s * s;
            sxy += s * y;
        });
        rates.push_back((K * sxy - sx * sy) / (K * sxx - sx * sx));
    }
    return rates;
}

// The prediction for the DSMC's gas: the viscosity raised by its cell-size and time-step laws,
// 16/(45 pi) (dx/lambda)^2 + 16/(75 pi) (0.2 sqrt(pi)/2)^2 = 0.9 % (docs/validation.md). Allowed
// beyond 4 standard errors of the replicas' mean: 3 % of the damping term (the first Sonine
// viscosity is 1.6 % below the converged one at alpha = 1; the order beyond Navier-Stokes at
// k lambda = 0.31 is not resolved by these runs, 1.6 +- 1.1 % less damping) and 1 % of the growth
// term (the first Sonine cooling rate). Measured: -0.0174 +- 0.0006 against -0.0182 in the box of
// 0.8 L_c, +0.0190 +- 0.0002 against +0.0191 in the box of 1.6 L_c. A gas that did not cool, a
// viscosity off by 15 % or a cooling rate off by 10 % fails the checks.
TEST(ShearModeGrowth, TransverseWaveDecaysBelowAndGrowsAboveTheCriticalLength) {
    const ShearModeTheory t = smooth_shear_mode(alpha);
    // The replicas resolve the rate to (standard error at most) 2.4 % of the damping at 0.8 L_c and
    // 2.6 % of the rate at 1.6 L_c: about twice the errors reached.
    for (const auto& [factor, resolution] : {std::pair{0.8, 0.0012}, std::pair{1.6, 0.0005}}) {
        const double L = factor * t.critical_length * lambda, k_lambda = 2 * std::numbers::pi * lambda / L;
        const double damping = t.damping * (1 + laws) * k_lambda * k_lambda, expected = t.growth - damping;
        const test::MeanErr g = test::mean_err(growth_rates(wave_run(L), 8));
        std::printf("[ SHEAR MODE ] L = %.2f L_c (k lambda = %.3f): gamma = %+.5f +- %.5f per collision, "
                    "Navier-Stokes %+.5f\n",
                    factor, k_lambda, g.mean, g.err, expected);
        EXPECT_EQ(g.mean > 0, factor > 1) << "the wave must decay below L_c and grow above it";
        EXPECT_NEAR(g.mean, expected, 4 * g.err + 0.03 * damping + 0.01 * t.growth) << factor << " L_c";
        EXPECT_LT(g.err, resolution);
    }
}

// The three kinds of rough grains in a box of `factor` L_c: each point's rate over 8 replicas, held
// to Navier-Stokes within 4 standard errors + 3 % of the damping + 3 % of the growth term, and its
// standard error below `resolution`; `sign` (+1, -1) the sign the rate must have.
void rough_grains_in_a_box(double factor, double resolution, int sign) {
    struct Point {
        double alpha, beta, end;
    };
    for (const Point p : {Point{0.9, 0.0, 20}, Point{0.9, 1.0, 40}, Point{0.8, -0.5, 12}}) {
        const ShearModeTheory t = rough_shear_mode(p.alpha, p.beta, 0.4);
        const double L = factor * t.critical_length * lambda, k_lambda = 2 * std::numbers::pi * lambda / L;
        const double damping = t.damping * (1 + laws) * k_lambda * k_lambda, expected = t.growth - damping;
        const test::MeanErr g = test::mean_err(growth_rates(wave_run(L, p.beta, p.end, p.alpha), 8));
        std::printf("[ SHEAR MODE ] rough, alpha = %.2f, beta = %+.2f, L = %.1f L_c (k lambda = %.3f): gamma = %+.5f "
                    "+- %.5f per collision, Navier-Stokes %+.5f\n",
                    p.alpha, p.beta, factor, k_lambda, g.mean, g.err, expected);
        EXPECT_GT(sign * g.mean, 0) << "the wave must decay below L_c and grow above it: " << p.alpha << ", "
                                    << p.beta << ", " << factor << " L_c";
        EXPECT_NEAR(g.mean, expected, 4 * g.err + 0.03 * damping + 0.03 * t.growth) << p.alpha << ", " << p.beta;
        EXPECT_LT(g.err, resolution);
    }
}

// Rough grains (q = 2/5) at medium roughness, alpha = 0.9, beta = 0 (L_c = 15.3 mean free paths, more
// unstable than smooth grains), at perfect roughness, alpha = 0.9, beta = 1 (L_c = 36.7: less
// unstable), and at weak roughness with stronger dissipation, alpha = 0.8, beta = -0.5 (L_c = 15.4),
// each started at the cooling state's theta of the Maxwellian approximation, in a box of 1.6 L_c;
// fitted from 5 collisions per particle until the wave nears half the thermal speed (20, 40 and 12).
// Allowed beyond 4 standard errors: the smooth test's 3 % of the damping, and 3 % of the growth
// term for the Maxwellian cooling state (at alpha = 0.9, beta = 0 the DSMC's theta settles 5 % below
// it, and its cooling rate per collision within 0.3 % of it). Measured: docs/validation.md.
TEST(ShearModeGrowth, RoughGrainsGrowAtTheirRateAboveTheCriticalLength) { rough_grains_in_a_box(1.6, 0.002, +1); }

// The same three kinds of rough grains in a box of 0.8 L_c: the wave decays (the sign is the check
// that cannot drift), and its rate stays within the growth test's allowance of Navier-Stokes
// (measured at beta = 0: -0.0451 +- 0.0012 against -0.0541, 7 standard errors but inside the 3 %
// allowances by 0.003; the damping at k lambda = 0.51 falls below Navier-Stokes's, as for smooth
// grains: docs/validation.md).
TEST(ShearModeGrowth, RoughGrainsDecayBelowTheCriticalLength) { rough_grains_in_a_box(0.8, 0.003, -1); }

} // namespace
} // namespace roughgas
