// The spectra of the spatially resolved engine's gas in equilibrium (observables/spectra.hpp): the
// DSMC keeps the ideal gas's product of uniform positions and Maxwellian velocities, so at every
// wave vector S = S_T = 1 and E_perp = E_par = T, and the velocities stay Maxwellian, for cells
// smaller and larger than the mean free path alike.
#include "no_observer.hpp"
#include "roughgas/dsmc/spatial_engine.hpp"

#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/observables/spectra.hpp"
#include "roughgas/dsmc/species.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace roughgas {
namespace {

using test::NoObserver;

// 70 % grains of mass 1 and diameter 1, 30 % of mass 3 and diameter 1.6 at temperature T_heavy.
std::vector<SpeciesBlock> mixture(std::int64_t n, double T_heavy) {
    SpeciesSpec a, b;
    a.fraction = 0.7;
    b.mass = 3;
    b.radius = 0.8;
    b.fraction = 0.3;
    b.temperature = T_heavy;
    return make_species_blocks({a, b}, n);
}

// An elastic binary mixture of smooth spheres (masses 1 and 3, diameters 1 and 1.6) at T = 1 in a
// periodic cube of 24^3 cells, 2e5 grains (14 per cell), cells of 0.4 and of 2.5 mean free paths.
// Each of 21 samples (the start, then every 4 steps of 0.25 mean free times) averages a field over
// every shell's wave vectors (about 6400, half of them independent: k and -k are one mode of a
// real field), T from the sample's own kinetic energy for the currents; the samples' mean is held
// to 1 within 5 standard errors of the mean from the samples' scatter (0.4 % each). Each shell on
// its own too, so that an error that depends on k cannot hide in the mean: a mode's |field_k|^2 of
// an ideal gas scatters by its own mean (exponentially), a shell of M wave vectors averages M/2
// independent ones, and its mean over the samples is held to 1 within 5 / sqrt(M/2), the scatter of
// one sample (the samples of the slow long waves are not independent of each other). And each
// species stays Maxwellian: at every sample its a20 = (4/15) <c*^4> - 1 (c* = c / sqrt(2 T/m)), 0 for
// a Maxwellian with the sampling scatter sqrt(3.2 / N_s) (var c*^4 = 945/16 - (15/4)^2 = 45), is held
// to 0 within 5 of those.
TEST(SpatialSpectra, EquilibriumGasHasUnitSpectraForAnyCellSize) {
    const double n = 0.01, sigma = 1.6;
    const double lambda = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n * sigma * sigma);
    for (const double cell : {0.4, 2.5}) {
        SCOPED_TRACE(::testing::Message() << "cells of " << cell << " mean free paths");
        DomainSpec d;
        const int G = 24;
        d.size = {G * cell * lambda, G * cell * lambda, G * cell * lambda};
        d.cells = {G, G, G};
        const std::vector<SpeciesBlock> blocks = mixture(200000, 1.0);
        SpatialEngine<SmoothConstant> e(d, blocks, std::vector<SmoothConstant>(3, make_smooth_constant(1.0)), n, 5, 0,
                                        2);
        SpectraGeometry g;
        g.grid = d.cells;
        g.box = d.size;
        Spectra spectra(g);
        const std::vector<SpectrumBin> bins = spectrum_bins(g);
        NoObserver none;
        std::vector<std::array<double, 4>> samples;
        std::vector<std::array<double, 4>> shells; // per shell: the sum over the samples
        std::size_t shell_count = 0;
        while (shell_count < bins.size() && bins[shell_count].axis == 0)
            ++shell_count;
        shells.assign(shell_count, std::array<double, 4>{});
        for (int k = 0; k <= 80; ++k) {
            if (k % 4 == 0) {
                double E = 0, N = 0;
                for (const SpeciesBlock& s : blocks)
                    for (std::size_t i = s.offset; i < s.offset + s.count; ++i) {
                        E += 0.5 * s.grain.mass * norm2(e.velocities()[i]);
                        N += 1;
                    }
                const double T = 2 * E / (3 * N);
                for (const SpeciesBlock& s : blocks) {
                    double c2 = 0, c4 = 0;
                    for (std::size_t i = s.offset; i < s.offset + s.count; ++i)
                        c2 += norm2(e.velocities()[i]);
                    const double two_T_over_m = 2.0 * c2 / (3.0 * static_cast<double>(s.count));
                    for (std::size_t i = s.offset; i < s.offset + s.count; ++i) {
                        const double x = norm2(e.velocities()[i]) / two_T_over_m;
                        c4 += x * x;
                    }
                    const double a20 = 4.0 / 15.0 * c4 / static_cast<double>(s.count) - 1.0;
                    EXPECT_NEAR(a20, 0.0, 5 * std::sqrt(3.2 / static_cast<double>(s.count)))
                        << "species of mass " << s.grain.mass << ", step " << k;
                }
                const std::vector<double> out = spectra.compute(e.positions(), e.velocities(), e.angular_velocities(), blocks, e.team());
                std::array<double, 4> mean{};
                double modes = 0;
                for (std::size_t r = 0; r < shell_count; ++r) {
                    for (std::size_t f = 0; f < 4; ++f) {
                        mean[f] += bins[r].modes * out[r * spectrum_field_count + f];
                        shells[r][f] += out[r * spectrum_field_count + f] / (f == 1 || f == 2 ? T : 1.0);
                    }
                    modes += bins[r].modes;
                }
                for (std::size_t f = 0; f < 4; ++f)
                    mean[f] /= modes * (f == 1 || f == 2 ? T : 1.0);
                samples.push_back(mean);
            }
            if (k < 80)
                e.step(0.25 / e.collision_frequency(), none);
        }
        ASSERT_GT(e.collisions(), 200000 * 4); // the gas has collided: at least 8 per grain
        for (std::size_t f = 0; f < 4; ++f) {
            double m = 0, m2 = 0;
            for (const auto& s : samples) {
                m += s[f];
                m2 += s[f] * s[f];
            }
            const double K = static_cast<double>(samples.size());
            m /= K;
            const double se = std::sqrt((m2 / K - m * m) / (K - 1));
            EXPECT_NEAR(m, 1.0, 5 * se) << spectrum_fields[f] << " (standard error " << se << ")";
            EXPECT_LT(se, 0.01) << spectrum_fields[f];
        }
        double worst = 0; // the largest deviation in units of its bound, to see the margin
        for (std::size_t r = 0; r < shell_count; ++r)
            for (std::size_t f = 0; f < 4; ++f) {
                const double m = shells[r][f] / static_cast<double>(samples.size());
                const double bound = 5.0 / std::sqrt(std::max(1.0, 0.5 * bins[r].modes));
                worst = std::max(worst, std::abs(m - 1.0) / bound);
                EXPECT_NEAR(m, 1.0, bound) << spectrum_fields[f] << " shell " << r << " (" << bins[r].modes
                                           << " wave vectors)";
            }
        std::printf("  cells of %g mean free paths: the largest shell deviation is %.2f of its bound\n", cell,
                    worst);
    }
}

// A run's spectra come from the engine's sums per cell (Spectra::compute_from_cell_sums): the same
// fields on the grid, transforms and rows as the sums over the grains' positions (Spectra::compute),
// to round-off. A box of 6 x 5 x 4 cells (the two paths order the cells differently), walls across
// y with gravity along them (a flow u_y), a drift along x (U != 0), two species of different masses
// and temperatures, after a few steps (the store sorted by cell, the sums those the collisions left).
TEST(SpatialSpectra, CellSumsGiveTheGrainsSpectra) {
    const std::vector<SpeciesBlock> blocks = mixture(6000, 2.0);
    DomainSpec d;
    d.size = {30, 25, 20};
    d.cells = {6, 5, 4};
    d.boundary = {Boundary::periodic, Boundary::walls, Boundary::periodic};
    d.wall_lower = {WallKind::diffuse, 1.0, {0, 0, 0}, 1, -1};
    d.wall_upper = {WallKind::specular, 1.0, {0, 0, 0}, 1, -1};
    d.gravity = {0, -0.05, 0};
    d.profile_axis = 1;
    SpatialEngine<RoughConstant, true> e(d, blocks, std::vector<RoughConstant>(3, make_rough_constant(0.8, 0.3)),
                                         0.1, 5, 0, 2);
    for (std::size_t i = 0; i < e.particles(); ++i)
        e.v(i).x += 0.7;
    NoObserver none;
    for (int k = 0; k < 5; ++k)
        e.step(0.25 / e.collision_frequency(), none);
    SpectraGeometry g;
    g.grid = d.cells;
    g.box = d.size;
    g.modes = 2;
    Spectra by_grains(g), by_cells(g);
    const std::vector<double> want = by_grains.compute(e.positions(), e.velocities(), e.angular_velocities(), blocks, e.team());
    const std::vector<double> got =
        by_cells.compute_from_cell_sums(e.cell_sums(), e.cell_sum_fields, e.cell_spin_sums(), e.velocities(), blocks,
                                        e.team());
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t r = 0; r < want.size(); ++r)
        EXPECT_NEAR(got[r], want[r], 1e-11 * (1 + std::abs(want[r]))) << "value " << r;
    for (int f = 0; f < 5; ++f) {
        double scale = 0;
        for (double q : by_grains.field(f))
            scale = std::max(scale, std::abs(q));
        ASSERT_GT(scale, 0.0) << "field " << f;
        for (std::size_t c = 0; c < by_grains.field(f).size(); ++c)
            ASSERT_NEAR(by_cells.field(f)[c], by_grains.field(f)[c], 1e-12 * scale) << "field " << f << ", cell " << c;
    }
}

} // namespace
} // namespace roughgas
