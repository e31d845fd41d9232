// The Enskog collisions of the box (dsmc/spatial_engine.hpp, "Enskog collisions"; dsmc/enskog_cells.hpp):
// the cells' neighbourhood sums and maxima against a direct count, the blocks that collide at once
// never within reach of each other, conservation to round-off, independence of the threads, and
// the collision rate and the pressure of an elastic gas against the Enskog equation's exact values.
#include "roughgas/dsmc/enskog_cells.hpp"
#include "roughgas/dsmc/spatial_engine.hpp"
#include "spatial_test_support.hpp"

#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/dsmc/pair_correlation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace roughgas {
namespace {

struct CountCollisions {
    std::int64_t n = 0;
    void operator()(const CollisionRecord&, std::size_t) { ++n; }
    CountCollisions fork() const { return {}; }
    void merge(const CountCollisions& o) { n += o.n; }
};

// The cell index along each axis of cell c.
std::array<int, 3> coordinates(const CellGrid& g, std::size_t c) {
    return {static_cast<int>(c % static_cast<std::size_t>(g.n[0])),
            static_cast<int>((c / static_cast<std::size_t>(g.n[0])) % static_cast<std::size_t>(g.n[1])),
            static_cast<int>(c / (static_cast<std::size_t>(g.n[0]) * static_cast<std::size_t>(g.n[1])))};
}

// The cells within `reach` of cell c, each once (wrapped on periodic axes, none beyond walls). With
// Lees-Edwards boundaries shifted by `shift` cells and a fraction (shift >= 0): across y, the columns
// x - shift - reach[0] - 1 .. x - shift + reach[0] of the rows reached (the images are offset along x).
std::vector<std::size_t> neighbourhood(const CellGrid& g, std::size_t c, const std::array<int, 3>& reach,
                                       int shift = -1) {
    const std::array<int, 3> i = coordinates(g, c);
    const auto wrap = [](int q, int n) { return ((q % n) + n) % n; };
    std::vector<std::size_t> cells;
    for (int dz = -reach[2]; dz <= reach[2]; ++dz)
        for (int dy = -reach[1]; dy <= reach[1]; ++dy) {
            int y = i[1] + dy, z = i[2] + dz;
            const bool across = y < 0 || y >= g.n[1];
            if ((!g.periodic[1] && across) || (!g.periodic[2] && (z < 0 || z >= g.n[2])))
                continue;
            y = wrap(y, g.n[1]);
            z = wrap(z, g.n[2]);
            const int lo = across && shift >= 0 ? i[0] - shift - reach[0] - 1 : i[0] - reach[0];
            const int hi = across && shift >= 0 ? i[0] - shift + reach[0] : i[0] + reach[0];
            for (int x = lo; x <= hi; ++x) {
                if (!g.periodic[0] && (x < 0 || x >= g.n[0]))
                    continue;
                const auto q = static_cast<std::size_t>(wrap(x, g.n[0]) + g.n[0] * (y + g.n[1] * z));
                if (std::find(cells.begin(), cells.end(), q) == cells.end())
                    cells.push_back(q);
            }
        }
    return cells;
}

// Sums and maxima of two fields over every cell's neighbourhood, periodic and walled axes, windows
// shorter and longer than an axis: equal to the direct sums (to round-off) and maxima (exactly).
TEST(EnskogCells, NeighbourhoodSumsAndMaximaAreTheDirectOnes) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> value(-1, 1);
    for (const std::array<bool, 3> periodic : {std::array<bool, 3>{true, true, true}, std::array<bool, 3>{true, false, true},
                                               std::array<bool, 3>{false, true, false}})
        for (const std::array<int, 3> reach : {std::array<int, 3>{1, 1, 1}, std::array<int, 3>{2, 0, 3}}) {
            CellGrid g;
            g.n = {7, 4, 3};
            g.periodic = periodic;
            const std::size_t C = g.cells(), F = 2;
            std::vector<double> in(C * F);
            for (double& x : in)
                x = value(random);
            std::vector<double> sums = in, maxima = in, scratch;
            reduce_neighbourhood<false>(g, reach, sums, F, scratch);
            reduce_neighbourhood<true>(g, reach, maxima, F, scratch);
            for (std::size_t c = 0; c < C; ++c)
                for (std::size_t f = 0; f < F; ++f) {
                    double s = 0, m = -std::numeric_limits<double>::infinity();
                    for (std::size_t q : neighbourhood(g, c, reach)) {
                        s += in[q * F + f];
                        m = std::max(m, in[q * F + f]);
                    }
                    ASSERT_NEAR(sums[c * F + f], s, 1e-12) << c;
                    ASSERT_EQ(maxima[c * F + f], m) << c;
                }
        }
}

// Two blocks of one colour: no cell within reach of the one is within reach of the other (so
// their collisions, which change grains and read bounds within reach, may run at once). Grids with
// even and odd numbers of cells, periodic and walled, reaches of 1 to 3 cells, and with
// Lees-Edwards boundaries at every offset (one block or several along y).
TEST(EnskogCells, BlocksOfOneColourAreNeverWithinReachOfEachOther) {
    for (const std::array<int, 3> n : {std::array<int, 3>{12, 9, 5}, std::array<int, 3>{17, 8, 30}})
        for (const int kind : {0, 1, 2})
            for (const int r : {1, 2, 3}) {
                const bool periodic = kind != 1, lees_edwards = kind == 2;
                if (lees_edwards && n[2] > 5)
                    continue; // every offset of the small grid is enough, and quick
                CellGrid g;
                g.n = n;
                g.periodic = {periodic, true, !periodic || lees_edwards};
                const std::array<int, 3> reach{r, lees_edwards ? r : 1, r};
                const CellBlocks b = make_cell_blocks(g, reach, lees_edwards);
                std::size_t blocks = 0;
                for (const std::vector<std::size_t>& colour : b.by_colour)
                    blocks += colour.size();
                EXPECT_EQ(blocks, b.count());
                if (!lees_edwards || b.edges[1].size() > 2) // else one block along y, so one along x
                    EXPECT_GT(b.count(), 1u);               // the grids are long enough for several blocks
                for (int shift = lees_edwards ? 0 : -1; shift < (lees_edwards ? n[0] : 0); ++shift) {
                    // The cells each block reaches: its own and those within reach of them.
                    std::vector<std::vector<char>> reached(b.count(), std::vector<char>(g.cells(), 0));
                    for (std::size_t c = 0; c < g.cells(); ++c) {
                        const std::array<int, 3> i = coordinates(g, c);
                        std::size_t block = 0, scale = 1;
                        for (std::size_t a = 0; a < 3; ++a) {
                            const auto k = static_cast<std::size_t>(
                                std::upper_bound(b.edges[a].begin(), b.edges[a].end(), i[a]) - b.edges[a].begin() - 1);
                            block += k * scale;
                            scale *= b.edges[a].size() - 1;
                        }
                        for (std::size_t q : neighbourhood(g, c, reach, shift))
                            reached[block][q] = 1;
                    }
                    for (const std::vector<std::size_t>& colour : b.by_colour)
                        for (std::size_t u = 0; u < colour.size(); ++u)
                            for (std::size_t v = u + 1; v < colour.size(); ++v)
                                for (std::size_t c = 0; c < g.cells(); ++c)
                                    ASSERT_FALSE(reached[colour[u]][c] && reached[colour[v]][c])
                                        << "blocks " << colour[u] << ", " << colour[v] << " share cell " << c
                                        << " (grid " << n[0] << "x" << n[1] << "x" << n[2] << ", kind " << kind
                                        << ", reach " << r << ", shift " << shift << ")";
                }
            }
}

using test::two_species;

using test::energy;
using test::momentum;

// A dense mixture of elastic, perfectly rough grains (BMCSL chi of the local densities) in a
// periodic box with cells smaller than a grain: momentum conserved and energy constant to round-off
// over 20 steps; every pair collides chi_ab times more often than in the Boltzmann box, so the
// collisions are many (about 3 per grain).
TEST(SpatialEnskog, ConservesMomentumAndEnergy) {
    DomainSpec d;
    d.size = {9.0, 9.0, 9.0};
    d.cells = {15, 15, 15};
    std::vector<SpeciesBlock> blocks = two_species(8000);
    const std::vector<PairType> types = make_pair_types(blocks);
    std::vector<AnyRoughPolicy> policies;
    for (std::size_t k = 0; k < types.size(); ++k)
        policies.push_back(to_any_rough(AnyPolicy(make_rough_constant(1.0, 1.0))));
    const double density = 0.3;
    SpatialEngine<AnyRoughPolicy> e(d, blocks, policies, density, 7, 0, 2);
    std::vector<SpeciesSpec> species(2);
    species[0].fraction = 0.7;
    species[0].radius = 0.5;
    species[1].fraction = 0.3;
    species[1].radius = 0.8;
    std::vector<double> chi;
    for (std::size_t a = 0; a < 2; ++a)
        for (std::size_t b = a; b < 2; ++b)
            chi.push_back(bmcsl_chi(density, species, a, b));
    e.set_enskog(chi, 0.0, 5);
    const Vec3 p0 = momentum(e);
    const double E0 = energy(e);
    CountCollisions count;
    for (int k = 0; k < 20; ++k)
        e.step(0.5 / e.collision_frequency(), count);
    EXPECT_GT(count.n, 10000);
    EXPECT_LT(std::sqrt(norm2(momentum(e) - p0)), 1e-12 * std::sqrt(2 * E0 * 8000));
    EXPECT_NEAR(energy(e) / E0, 1.0, 1e-12);
}

// One thread or two, periodic, walled or sheared by Lees-Edwards boundaries: the same collisions
// in the same order (the blocks and their streams do not depend on the threads), so the same
// velocities bit for bit.
TEST(SpatialEnskog, ThreadCountDoesNotChangeTheResults) {
    for (const int kind : {0, 1, 2}) {
        const bool walls = kind == 1;
        DomainSpec d;
        d.size = {12.0, 10.0, 8.0};
        d.cells = {16, 14, 10};
        if (kind == 2)
            d.shear_rate = 0.3;
        if (walls) {
            d.boundary[1] = Boundary::walls;
            d.wall_lower.kind = d.wall_upper.kind = WallKind::diffuse;
            d.wall_lower.velocity = {-0.5, 0, 0};
            d.wall_upper.velocity = {0.5, 0, 0};
        }
        std::vector<std::vector<Vec3>> v;
        for (int threads : {1, 2}) {
            SpatialEngine<RoughConstant, true> e(d, two_species(10000), {make_rough_constant(0.8, 0.3),
                                                                     make_rough_constant(0.9, 0.0),
                                                                     make_rough_constant(0.7, -0.2)},
                                                  0.25, 5, 1, threads);
            e.set_enskog({1.9, 2.1, 2.4}, 0.0, 3);
            CountCollisions count;
            for (int k = 0; k < 8; ++k)
                e.step(0.3 / e.collision_frequency(), count);
            EXPECT_GT(count.n, 5000);
            v.push_back(e.velocities());
        }
        ASSERT_EQ(v[0].size(), v[1].size());
        for (std::size_t i = 0; i < v[0].size(); ++i)
            ASSERT_TRUE(v[0][i].x == v[1][i].x && v[0][i].y == v[1][i].y && v[0][i].z == v[1][i].z) << i;
    }
}

// Elastic smooth spheres in a periodic box, chi of Carnahan & Starling at the local density: the
// collision frequency per grain is chi 4 n sigma^2 sqrt(pi T/m) and the pressure p = n T (1 + 4 phi
// chi) (the Enskog equation's exact equilibrium values), at phi = 0.01 (the Boltzmann limit) and
// phi = 0.25. Cells of sigma holding 64 grains each: the partners' cells hold enough grains that a pair which has just collided (and now recedes)
// is rarely drawn again (docs/validation.md: the frequency comes out 0.5 % low at 2.5 grains per
// cell, 0.17 % at 20). Over 6 collisions per grain of 64000 grains: standard errors 0.16 % of the
// frequency and about 0.2 % of the collisional pressure (its impulses vary); tolerances of 5 of them.
TEST(SpatialEnskog, ElasticCollisionRateAndPressureAreEnskogs) {
    for (const double phi : {0.01, 0.25}) {
        const double sigma = 1.0, n = 6 * phi / (std::numbers::pi * sigma * sigma * sigma);
        const double chi = carnahan_starling_chi(phi);
        // 64000 grains in 10^3 cells of sigma (64 each): a partner a diameter away is one or two
        // cells from its grain.
        DomainSpec d;
        d.size = {10.0, 10.0, 10.0};
        d.cells = {10, 10, 10};
        const std::int64_t N = 64000;
        SpatialEngine<SmoothConstant> e(d, make_species_blocks({SpeciesSpec{}}, N), {make_smooth_constant(1.0)}, n, 11,
                                        0, 2);
        e.set_enskog({chi}, 0.0, 3);
        CountCollisions count;
        const double nu0 = chi * 4 * n * sigma * sigma * std::sqrt(std::numbers::pi);
        for (int k = 0; k < 24; ++k)
            e.step(0.25 / nu0, count);
        double E = 0;
        for (const Vec3& v : e.velocities())
            E += 0.5 * norm2(v);
        const double T = 2 * E / (3 * static_cast<double>(N));
        const double rate = 2.0 * static_cast<double>(count.n) / (static_cast<double>(N) * e.time());
        EXPECT_NEAR(rate / (nu0 * std::sqrt(T)), 1.0, 5.0 / std::sqrt(static_cast<double>(count.n))) << phi;
        double trace = 0;
        for (const Virial& b : e.take_virial())
            trace += b[0] + b[1] + b[2];
        const double p_coll = trace / (3 * e.volume() * e.time()); // the volume N/n of the simulated grains
        const double expected = 4 * phi * chi * n * T;
        EXPECT_NEAR(p_coll / expected, 1.0, 5.0 * 1.3 / std::sqrt(static_cast<double>(count.n))) << phi;
    }
}

} // namespace
} // namespace roughgas
