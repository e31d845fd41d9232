// T_th, the translational temperature about each collision cell's flow
// (observables/thermal_temperature.hpp): its exact split of T_tr into thermal and flow parts, its
// absence of bias at two grains per cell, and moments.csv's column in a box with a wave.
#include "../dsmc/run_test_support.hpp"
#include "../dsmc/test_stats.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/observables/thermal_temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace roughgas {
namespace {

constexpr std::size_t fields = 5; // count, sum of v (3), sum of |v|^2: SpatialEngine::cell_sums()

struct Grain {
    std::size_t cell, species;
    double v[3];
};

// The cells' sums of `grains` in cell_sums()'s layout.
std::vector<double> sums_of(const std::vector<Grain>& grains, std::size_t cells, std::size_t S) {
    std::vector<double> s(cells * S * fields, 0.0);
    for (const Grain& g : grains) {
        double* f = s.data() + (g.cell * S + g.species) * fields;
        f[0] += 1;
        for (int a = 0; a < 3; ++a) {
            f[1 + a] += g.v[a];
            f[4] += g.v[a] * g.v[a];
        }
    }
    return s;
}

// A mixture (masses 1 and 4) at temperature T with a different flow in every cell, Poisson-many
// grains per cell (mean `per_cell`: empty cells and cells of one grain included).
std::vector<Grain> flowing_mixture(std::size_t cells, double per_cell, double T, const double* masses,
                                   std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::poisson_distribution<int> count(per_cell);
    std::normal_distribution<double> gauss;
    std::vector<Grain> grains;
    for (std::size_t c = 0; c < cells; ++c) {
        const double U[3] = {3 * gauss(rng), 3 * gauss(rng), 3 * gauss(rng)}; // flows ~ 3 sqrt(T/m)
        for (int j = count(rng); j > 0; --j) {
            Grain g{c, static_cast<std::size_t>(j % 2), {}};
            for (int a = 0; a < 3; ++a)
                g.v[a] = U[a] + std::sqrt(T / masses[g.species]) * gauss(rng);
            grains.push_back(g);
        }
    }
    return grains;
}

// 3 N T_tr = 3 (N - C) T_th + sum_c M_c |U_c - u|^2 (C: the cells holding a grain; u the mass-weighted
// mean velocity), to round-off, whatever the velocities.
TEST(ThermalTemperature, SplitsTheTranslationalTemperatureIntoThermalAndFlowParts) {
    const double masses[2] = {1.0, 4.0};
    const std::size_t cells = 500;
    const std::vector<Grain> grains = flowing_mixture(cells, 3.0, 0.7, masses, 11);
    const double T_th = thermal_temperature(sums_of(grains, cells, 2), fields, masses);

    double M = 0, P[3] = {0, 0, 0};
    std::vector<double> Mc(cells, 0.0), Pc(3 * cells, 0.0);
    for (const Grain& g : grains) {
        const double m = masses[g.species];
        M += m;
        Mc[g.cell] += m;
        for (int a = 0; a < 3; ++a) {
            P[a] += m * g.v[a];
            Pc[3 * g.cell + a] += m * g.v[a];
        }
    }
    double E = 0; // sum_j m_j |v_j - u|^2
    for (const Grain& g : grains)
        for (int a = 0; a < 3; ++a)
            E += masses[g.species] * (g.v[a] - P[a] / M) * (g.v[a] - P[a] / M);
    double flow = 0;
    std::size_t occupied = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        if (Mc[c] == 0)
            continue;
        ++occupied;
        for (int a = 0; a < 3; ++a)
            flow += Mc[c] * std::pow(Pc[3 * c + a] / Mc[c] - P[a] / M, 2);
    }
    const double N = static_cast<double>(grains.size());
    ASSERT_GT(flow, E / 2); // the flows carry a large share: the split is tested, not a small term
    EXPECT_NEAR(3 * (N - static_cast<double>(occupied)) * T_th + flow, E, 1e-11 * E);
}

// At two grains per cell (a third of the cells' grains counted as their flow's) T_th is the
// grains' temperature within its sampling error: sum_c (N_c - 1) ~ 10^5 degrees of freedom give a
// relative standard error sqrt(2/(3 * 10^5)) = 0.26 %, checked to 5 of them. Dividing by N_c
// instead would read (N - C)/N = 0.57 of it.
TEST(ThermalTemperature, IsUnbiasedAtTwoGrainsPerCell) {
    const double masses[2] = {1.0, 4.0};
    const std::size_t cells = 100000;
    const double T = 1.3;
    const std::vector<Grain> grains = flowing_mixture(cells, 2.0, T, masses, 12);
    const double T_th = thermal_temperature(sums_of(grains, cells, 2), fields, masses);
    EXPECT_NEAR(T_th / T, 1.0, 5 * std::sqrt(2.0 / (3.0 * 1e5)));
}

TEST(ThermalTemperature, IsNaNWithoutACellOfTwoGrains) {
    const double masses[1] = {1.0};
    const std::vector<Grain> grains = {{0, 0, {1, 0, 0}}, {2, 0, {0, 1, 0}}};
    EXPECT_TRUE(std::isnan(thermal_temperature(sums_of(grains, 3, 1), fields, masses)));
    EXPECT_THROW(thermal_temperature(std::vector<double>(7, 0.0), fields, masses), std::invalid_argument);
}

// moments.csv's T_th in a box whose gas carries a transverse wave u_y = A sqrt(T/m) sin(k x): at
// t = 0 the wave's flow share of T_tr, m u_wave^2/6, is all that separates T_tr from T_th (the
// cells, 40 per wavelength, resolve its flow energy to (k dx)^2/12 = 2e-3). Each replica
// gives T_tr - m u_wave^2/6 - T_th; their mean is 0 within 5 standard errors, and the test is
// sharp: their standard error (3e-4 T) is far below the share (A^2/6 = 0.042 T) and below the bias
// of dividing by N_c (cells/N = 0.016 T).
TEST(ThermalTemperature, IsTheTranslationalTemperatureLessTheWavesShare) {
    RunSpec spec;
    spec.species = {SpeciesSpec{}};
    spec.pairs = {ConstantRestitution{1.0, -1.0}};
    spec.particles = 20000;
    spec.density = 0.02;
    spec.output_times = {0.5};
    spec.end = 0.5;
    spec.threads = 1;
    DomainSpec d;
    const double L = std::cbrt(20000 / 0.02);
    d.size = {L, L, L};
    d.cells = {40, 2, 4}; // 62 grains per cell
    d.initial = {Perturbation::transverse, 0.5, {1, 0, 0}};
    spec.domain = d;
    const std::size_t jT = test::column(spec, "T_tr"), ju = test::column(spec, "u_wave"),
                      jth = test::column(spec, "T_th");
    std::vector<double> gap, share;
    for (int r = 0; r < 8; ++r) {
        bool first = true;
        run_replica(spec, r, [&](std::span<const double> row) {
            if (!first)
                return;
            first = false;
            const double s = row[ju] * row[ju] / 6;
            share.push_back(s);
            gap.push_back(row[jT] - s - row[jth]);
        });
    }
    const test::MeanErr g = test::mean_err(gap), s = test::mean_err(share);
    EXPECT_NEAR(s.mean, 0.25 / 6, 0.01);
    EXPECT_LT(g.err, 1e-3);
    EXPECT_LT(std::abs(g.mean), 5 * g.err) << g.mean << " +- " << g.err;
}

} // namespace
} // namespace roughgas
