// The Maxwell kernel (run.kernel = "maxwell", dsmc/run_spec.hpp): the DSMC against the closed linear
// ODEs of its temperatures (observables/theory.hpp), which are exact for this kernel (no Maxwellian
// assumption), so any deviation beyond the sampling error is a bug of the kernel or the ODEs.
#include "run_test_support.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/observables/theory.hpp"

#include "test_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace roughgas {
namespace {

using test::column;

using test::MeanErr;
using test::mean_err;

// Replicas of `spec`; for each output row k and each named column, the ratio DSMC/ODE at the row's t
// (each replica's own t) over the replicas.
std::vector<std::vector<MeanErr>> ratios(const RunSpec& spec, int replicas, const std::vector<std::string>& cols) {
    const auto tables = RestitutionTables::build(spec);
    const std::size_t rows = spec.output_times.size();
    std::vector<std::vector<std::vector<double>>> r(rows, std::vector<std::vector<double>>(cols.size()));
    for (int rep = 0; rep < replicas; ++rep) {
        HcsTrajectory ode(*hcs_theory(spec), initial_temperatures(spec), 1e-11);
        std::size_t k = 0;
        run_replica(spec, *tables, rep, [&](std::span<const double> row) {
            if (row[0] == 0)
                return; // the row at t = 0
            const HcsTemperatures T = ode.at(row[0]);
            const HcsTheory& th = ode.theory();
            for (std::size_t c = 0; c < cols.size(); ++c) {
                const std::string& name = cols[c];
                const double theory = name == "T_tr"    ? th.mixture_T_tr(T)
                                      : name == "T_rot" ? th.mixture_T_rot(T)
                                      : name == "T_tr.a" ? T.T_tr[0]
                                      : name == "T_tr.b" ? T.T_tr[1]
                                      : name == "T_rot.a" ? T.T_rot[0]
                                                          : T.T_rot[1];
                r[k][c].push_back(row[column(spec, name)] / theory);
            }
            ++k;
        });
    }
    std::vector<std::vector<MeanErr>> out(rows);
    for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t c = 0; c < cols.size(); ++c)
            out[k].push_back(mean_err(r[k][c]));
    return out;
}

// `s` in a periodic cube of 3 hard-sphere mean free paths (unit diameters, n = 0.02) in cells of half
// of one. The Maxwell kernel's rate stays that of the start while the gas cools, so its own mean
// free path shrinks as sqrt(T): at T_tr = 0.2 the cells are about one of them and the box about
// seven, still below the instability length, and the gas stays uniform and follows the ODEs.
RunSpec in_a_small_box(RunSpec s) {
    s.density = 0.02;
    const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * s.density);
    DomainSpec d;
    d.size = {3 * lambda, 3 * lambda, 3 * lambda};
    d.cells = {6, 6, 6};
    s.domain = d;
    return s;
}

TEST(Maxwell, RoughGasFollowsTheExactTemperatureOdes) {
    // One species, alpha = 0.8, beta = 0.4, started far from the cooling state (T_rot = 0.1 T_tr):
    // T_tr and T_rot at 1, 2, 4, 8 collisions per particle (T_tr falls to ~0.2, theta rises from 0.1
    // to ~0.5). N = 2e4, 8 replicas, 4 groups: each ratio DSMC/ODE within 4 standard errors of 1
    // (errors ~0.1-0.3%), and within 1% (the O(1/N) pair correlations of the finite gas are far below).
    // The same gas in a small box too: the cells' Maxwell kernel (every pair of a cell at the
    // constant rate, the cell for the volume) gives each grain the homogeneous rate, so the same ODEs
    // hold, within the same tolerances.
    RunSpec s;
    SpeciesSpec a;
    a.rotational_temperature = 0.1;
    s.species = {a};
    s.pairs = {ConstantRestitution{0.8, 0.4}};
    s.particles = 20000;
    s.output_times = {1, 2, 4, 8};
    s.end = 8;
    s.seed = 3;
    s.groups = 4; // the homogeneous gas's; a box's work units are its cells
    s.kernel = CollisionKernel::maxwell;
    for (const bool box : {false, true}) {
        const auto r = ratios(box ? in_a_small_box(s) : s, 8, {"T_tr", "T_rot"});
        for (std::size_t k = 0; k < r.size(); ++k) {
            std::printf("  %s%g collisions per particle: T_tr/ODE = %.5f +- %.5f, T_rot/ODE = %.5f +- %.5f\n",
                        box ? "box, " : "", s.output_times[k], r[k][0].mean, r[k][0].err, r[k][1].mean,
                        r[k][1].err);
            for (const MeanErr& m : r[k]) {
                EXPECT_NEAR(m.mean, 1.0, 4 * m.err) << "row " << k << " box " << box;
                EXPECT_NEAR(m.mean, 1.0, 0.01) << "row " << k << " box " << box;
            }
        }
    }
}

TEST(Maxwell, MixtureFollowsTheExactTemperatureOdes) {
    // Binary mixture, unequal masses, radii, q and temperatures, a different (alpha, beta) per pair:
    // per-species T_tr and T_rot at 1, 3 collisions per particle. N = 2e4, 8 replicas; within 4
    // standard errors of 1.
    RunSpec s;
    SpeciesSpec a, b;
    a.name = "a";
    a.fraction = 0.4;
    a.rotational_temperature = 0.2;
    b.name = "b";
    b.mass = 3;
    b.radius = 0.8;
    b.inertia = 0.3;
    b.fraction = 0.6;
    b.temperature = 2;
    s.species = {a, b};
    s.pairs = {ConstantRestitution{0.9, 0.5}, ConstantRestitution{0.7, 0.0}, ConstantRestitution{0.8, -0.5}};
    s.particles = 20000;
    s.output_times = {1, 3};
    s.end = 3;
    s.seed = 5;
    s.kernel = CollisionKernel::maxwell;
    const std::vector<std::string> cols = {"T_tr.a", "T_tr.b", "T_rot.a", "T_rot.b"};
    // The homogeneous gas, and the same in a small box (the pairs' rates thinned from the largest).
    for (const bool box : {false, true}) {
        const auto r = ratios(box ? in_a_small_box(s) : s, 8, cols);
        for (std::size_t k = 0; k < r.size(); ++k)
            for (std::size_t c = 0; c < cols.size(); ++c) {
                std::printf("  %s%g collisions per particle: %s/ODE = %.5f +- %.5f\n", box ? "box, " : "",
                            s.output_times[k], cols[c].c_str(), r[k][c].mean, r[k][c].err);
                EXPECT_NEAR(r[k][c].mean, 1.0, 4 * r[k][c].err) << cols[c] << " row " << k << " box " << box;
            }
    }
}

TEST(Maxwell, CollisionRateDoesNotDependOnTheTemperature) {
    // coll_rate (collisions per particle per unit time over each interval) stays at the initial
    // hard-sphere frequency 4 n sigma^2 sqrt(pi T0/m) while T_tr falls by half (alpha = 0.5, smooth): each
    // interval of 1 collision per particle (N = 2e4: 1e4 collisions, Poisson error 1%) within 4%.
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {ConstantRestitution{0.5, -1.0}};
    s.particles = 20000;
    s.output_times = {1, 2, 3, 4, 5, 6};
    s.end = 6;
    s.kernel = CollisionKernel::maxwell;
    const auto tables = RestitutionTables::build(s);
    const double nu = 4.0 * std::sqrt(std::numbers::pi);
    double T_first = 0, T_last = 0;
    run_replica(s, *tables, 0, [&](std::span<const double> row) {
        if (row[0] == 0) {
            T_first = row[column(s, "T_tr")];
            return;
        }
        T_last = row[column(s, "T_tr")];
        EXPECT_NEAR(row[column(s, "coll_rate")] / nu, 1.0, 0.04) << "t = " << row[0];
    });
    EXPECT_LT(T_last, 0.6 * T_first) << "the gas must have cooled (to exp(-0.75) = 0.47)";
}

} // namespace
} // namespace roughgas
