// Couette flow of an elastic hard-sphere gas between diffuse walls moving at -U and +U along x
// (walls normal to y), against transport theory and momentum conservation:
//   - the momentum flux is the same everywhere in the steady state: the kinetic plus collisional
//     P_xy of the bulk profile bins (profiles.csv's fields) equals what the walls receive
//     (walls.csv's P_xy);
//   - the viscosity eta = -P_xy / (du_x/dy), with du_x/dy fitted in the bulk (two mean free paths
//     from each wall: outside the Knudsen layers), is the Chapman-Enskog one, 1.016034 eta_0 with
//     eta_0 = (5/(16 sigma^2)) sqrt(m T/pi) at the bulk temperature, raised by the DSMC's cell-size
//     error 16/(45 pi) (dy/lambda)^2 (Alexander, Garcia & Alder 1998) and its time-step error
//     16/(75 pi) (c_0 dt/lambda)^2, c_0 = sqrt(2 T/m) (Hadjiconstantinou 2000).
// Tolerances: 4 standard errors from batch means over the steady rows.
// CPU: about 15 s (Release; 40000 grains to 1000 collisions per particle).
#include "roughgas/dsmc/run.hpp"
#include "roughgas/observables/profiles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace roughgas {
namespace {

double mean(const std::vector<double>& x) {
    double s = 0;
    for (double v : x)
        s += v;
    return s / static_cast<double>(x.size());
}
double standard_error(const std::vector<double>& x) {
    const double m = mean(x);
    double ss = 0;
    for (double v : x)
        ss += (v - m) * (v - m);
    const double K = static_cast<double>(x.size());
    return std::sqrt(ss / (K * (K - 1)));
}

// Box: 10 mean free paths between the walls, 1 across (periodic); 40 cells of 0.25 lambda along y;
// U = 0.5 sqrt(T_w/m); steps of 0.2 mean free times. Rows every 10 collisions per particle; the
// first 100 (some 5 relaxation times of the slowest shear mode) dropped; the 90 others in 9 batches.
TEST(Couette, WallAndBulkMomentumFluxesAgreeAndGiveTheChapmanEnskogViscosity) {
    const double n = 0.02, sigma = 1.0, T_w = 1.0, U = 0.5;
    const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n * sigma * sigma);
    RunSpec spec;
    spec.species = {SpeciesSpec{}};
    spec.species[0].radius = sigma / 2;
    spec.pairs = {ConstantRestitution{1.0, -1.0}};
    spec.particles = 40000;
    spec.density = n;
    spec.seed = 17;
    for (int k = 1; k <= 100; ++k)
        spec.output_times.push_back(10.0 * k);
    spec.end = spec.output_times.back();
    spec.threads = 2;
    DomainSpec d;
    d.size = {lambda, 10 * lambda, lambda};
    d.cells = {1, 40, 1};
    d.boundary = {Boundary::periodic, Boundary::walls, Boundary::periodic};
    d.wall_lower = {WallKind::diffuse, T_w, {-U, 0, 0}, 1, -1};
    d.wall_upper = {WallKind::diffuse, T_w, {U, 0, 0}, 1, -1};
    d.profile_axis = 1;
    spec.domain = d;
    const std::vector<Column> cols = replica_row_columns(spec);
    const auto col = [&](const std::string& name) {
        for (std::size_t j = 0; j < cols.size(); ++j)
            if (cols[j].name == name)
                return j;
        ADD_FAILURE() << name;
        return std::size_t{0};
    };
    std::vector<std::vector<double>> rows;
    run_replica(spec, 0, [&](std::span<const double> row) { rows.emplace_back(row.begin(), row.end()); });
    ASSERT_EQ(rows.size(), 101u);

    const int bins = d.cells[1];
    const double dy = d.size[1] / bins;
    std::vector<int> bulk; // bins whose centre is at least 2 lambda from both walls
    for (int b = 0; b < bins; ++b)
        if ((b + 0.5) * dy >= 2 * lambda && (b + 0.5) * dy <= d.size[1] - 2 * lambda)
            bulk.push_back(b);
    const auto field = [&](const std::vector<double>& row, int b, const char* f) {
        return row[col("bin" + std::to_string(b) + "." + f)];
    };
    const int batches = 9, per_batch = 10;
    std::vector<double> eta_ratio, flux_difference;
    for (int k = 0; k < batches; ++k) {
        double wall = 0, bulk_flux = 0, T = 0;
        std::vector<double> u(static_cast<std::size_t>(bins), 0.0);
        for (int r = 0; r < per_batch; ++r) {
            const std::vector<double>& row = rows[static_cast<std::size_t>(11 + k * per_batch + r)];
            wall += 0.5 * (row[col("y_lower.P_xy")] + row[col("y_upper.P_xy")]) / per_batch;
            for (int b : bulk) {
                bulk_flux += (field(row, b, "P_xy") + field(row, b, "Pc_xy")) / (per_batch * bulk.size());
                T += field(row, b, "T_tr") / (per_batch * bulk.size());
            }
            for (int b = 0; b < bins; ++b)
                u[static_cast<std::size_t>(b)] += field(row, b, "u_x") / per_batch;
        }
        // Least-squares slope of u_x(y) over the bulk bins.
        double sy = 0, su = 0, syy = 0, syu = 0;
        for (int b : bulk) {
            const double y = (b + 0.5) * dy, ub = u[static_cast<std::size_t>(b)];
            sy += y;
            su += ub;
            syy += y * y;
            syu += y * ub;
        }
        const double K = static_cast<double>(bulk.size());
        const double slope = (K * syu - sy * su) / (K * syy - sy * sy);
        const double eta0 = 5.0 / (16.0 * sigma * sigma) * std::sqrt(T / std::numbers::pi);
        const double c0 = std::sqrt(2 * T), tau = lambda / std::sqrt(8 * T / std::numbers::pi);
        const double predicted = 1.016034 * eta0 *
                                 (1 + 16.0 / (45 * std::numbers::pi) * (dy / lambda) * (dy / lambda) +
                                  16.0 / (75 * std::numbers::pi) * std::pow(c0 * d.time_step * tau / lambda, 2));
        eta_ratio.push_back(-wall / slope / predicted);
        flux_difference.push_back((bulk_flux - wall) / std::abs(wall));
    }
    const double ratio = mean(eta_ratio), ratio_err = standard_error(eta_ratio);
    const double diff = mean(flux_difference), diff_err = standard_error(flux_difference);
    std::printf("eta / eta_DSMC = %.4f +- %.4f; (bulk - wall) P_xy / |P_xy| = %.4f +- %.4f\n", ratio, ratio_err,
                diff, diff_err);
    EXPECT_LT(ratio_err, 0.02) << "the statistics resolve the viscosity to 2 %";
    EXPECT_NEAR(ratio, 1.0, 4 * ratio_err);
    EXPECT_NEAR(diff, 0.0, 4 * diff_err);
}

} // namespace
} // namespace roughgas
