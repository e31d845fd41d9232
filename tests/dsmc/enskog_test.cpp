// The Enskog equation of the homogeneous gas (run.equation = "enskog"; dsmc/pair_correlation.hpp):
// every pair collides chi times as often as in the Boltzmann equation, and the collisions' virial
// gives the collisional pressure p_coll (dsmc/gas_row.hpp).
//   - Same seed, same collisions: the Enskog run is the Boltzmann run with its clock chi times faster,
//     row by row (the candidates' exponential increments scale by 1/chi, nothing else changes).
//   - Elastic grains: p/(n T) from the virial against Carnahan & Starling's equation of state.
//   - Inelastic rough grains, cooling, one species and a mixture (each pair's BMCSL chi): p_coll of
//     every interval against Enskog's exact result at the interval's temperatures
//     (observables/enskog_pressure.hpp), exact for any distribution.
//   - A driven gas: the steady T_tr against the first Sonine approximation at the rate n chi.
// The statistical tests take the standard error from the spread of the rows' intervals, which are
// nearly independent (each holds 5e3 or more collisions); CPU about 1 s.
#include "run_test_support.hpp"
#include "test_stats.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/observables/enskog_pressure.hpp"
#include "roughgas/observables/white_noise_sonine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

namespace roughgas {
namespace {

using Rows = std::vector<std::vector<double>>;
using test::column;
using test::mean_err;

Rows run(const RunSpec& spec) {
    const auto tables = RestitutionTables::build(spec);
    Rows rows;
    run_replica(spec, *tables, 0, [&](std::span<const double> r) { rows.emplace_back(r.begin(), r.end()); });
    return rows;
}

// One species of unit diameter (R = 0.5, m = 1) at the solid fraction phi: n = 6 phi/pi.
RunSpec dense_gas(double phi, ConstantRestitution r, std::int64_t N, double end, double every) {
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {r};
    s.particles = N;
    s.density = 6 * phi / std::numbers::pi;
    s.end = end;
    for (double x = every; x < end * (1 + 1e-12); x += every)
        s.output_times.push_back(x);
    s.output_times.back() = end;
    s.seed = 17;
    s.enskog = EnskogSpec{};
    return s;
}

TEST(Enskog, PairCorrelationsOfOneSpeciesAndOfMixtures) {
    // Carnahan & Starling at phi = 0.3: 0.85/0.343.
    EXPECT_NEAR(carnahan_starling_chi(0.3), 0.85 / 0.343, 1e-15);
    SpeciesSpec a, b;
    b.radius = 0.25;
    a.fraction = 0.4, b.fraction = 0.6;
    // Equal diameters: the mixture form is Carnahan & Starling's at the total phi, for every pair.
    const double n = 0.5;
    SpeciesSpec a2 = a;
    a2.name = "twin";
    a2.fraction = 0.6;
    const double phi = solid_fraction(n, std::vector<SpeciesSpec>{a, a2});
    for (auto [x, y] : {std::pair{0, 0}, std::pair{0, 1}, std::pair{1, 1}})
        EXPECT_NEAR(bmcsl_chi(n, std::vector<SpeciesSpec>{a, a2}, x, y), carnahan_starling_chi(phi), 1e-14);
    // Unequal: chi_ab grows with the pair's reduced diameter mu = sigma_a sigma_b/(sigma_a + sigma_b),
    // the large pair's above the mixed one's above the small one's, each above 1/(1 - xi_3).
    const std::vector<SpeciesSpec> mix{a, b};
    const double big = bmcsl_chi(n, mix, 0, 0), mixed = bmcsl_chi(n, mix, 0, 1), small = bmcsl_chi(n, mix, 1, 1);
    const double xi3 = solid_fraction(n, mix);
    EXPECT_GT(big, mixed);
    EXPECT_GT(mixed, small);
    EXPECT_GT(small, 1 / (1 - xi3));
    EXPECT_EQ(mixed, bmcsl_chi(n, mix, 1, 0));
    // The run's list: pair_index order; a constant everywhere; 1 without the Enskog equation.
    RunSpec s;
    s.species = mix;
    s.density = n;
    EXPECT_EQ(pair_correlations(s), (std::vector<double>{1, 1, 1}));
    s.enskog = EnskogSpec{};
    EXPECT_EQ(pair_correlations(s), (std::vector<double>{big, mixed, small}));
    s.enskog = EnskogSpec{PairCorrelationModel::constant, 1.7};
    EXPECT_EQ(pair_correlations(s), (std::vector<double>{1.7, 1.7, 1.7}));
}

TEST(Enskog, TheBoltzmannRunWithAClockChiTimesFaster) {
    // Rough grains cooling, same seed: a constant chi = 2.5, and Carnahan & Starling's at phi = 0.2 and
    // at phi = 1e-4 (the Boltzmann limit, chi = 1.00025).
    RunSpec boltzmann = dense_gas(0.2, {0.8, 0.4}, 3000, 6, 0.5);
    boltzmann.enskog.reset();
    const Rows B = run(boltzmann);
    for (const auto& [enskog, chi] : {std::pair{EnskogSpec{PairCorrelationModel::constant, 2.5}, 2.5},
                                      std::pair{EnskogSpec{}, carnahan_starling_chi(0.2)}}) {
        RunSpec s = boltzmann;
        s.enskog = enskog;
        const Rows E = run(s);
        ASSERT_EQ(E.size(), B.size());
        for (std::size_t k = 1; k < B.size(); ++k) {
            EXPECT_NEAR(E[k][0] * chi / B[k][0], 1.0, 1e-12) << "row " << k; // t
            for (const char* q : {"coll_per_particle", "T_tr", "T_rot", "a20", "a02", "a11", "A_cw"}) {
                const std::size_t j = column(boltzmann, q);
                EXPECT_NEAR(E[k][j], B[k][j], 1e-12 * std::abs(B[k][j]) + 1e-15) << q << ", row " << k;
            }
            const std::size_t rate = column(boltzmann, "coll_rate");
            EXPECT_NEAR(E[k][rate] / (chi * B[k][rate]), 1.0, 1e-12);
        }
    }
    RunSpec dilute = dense_gas(1e-4, {0.8, 0.4}, 3000, 6, 0.5);
    const Rows D = run(dilute);
    dilute.enskog.reset();
    const Rows DB = run(dilute);
    EXPECT_NEAR(D.back()[0] * carnahan_starling_chi(1e-4) / DB.back()[0], 1.0, 1e-12);
}

TEST(Enskog, ElasticVirialPressureIsCarnahanStarlings) {
    // 2e4 grains, 40 intervals of half a collision per particle (5e3 collisions each).
    for (double phi : {0.1, 0.25, 0.4}) {
        const RunSpec s = dense_gas(phi, {1.0, -1.0}, 20000, 20, 0.5);
        const Rows rows = run(s);
        const std::size_t p = column(s, "p"), p_kin = column(s, "p_kin");
        std::vector<double> Z;
        for (std::size_t k = 1; k < rows.size(); ++k)
            Z.push_back(rows[k][p] / rows[k][p_kin]);
        const auto [mean, err] = mean_err(Z);
        const double cs = carnahan_starling_compressibility(phi);
        EXPECT_NEAR(mean, cs, 4 * err) << "phi = " << phi << ": " << mean << " +- " << err << " against " << cs;
        EXPECT_LT(err, 0.003 * cs);
        RecordProperty("Z_phi_" + std::to_string(phi), std::to_string(mean) + " +- " + std::to_string(err));
    }
}

// p_coll of every interval over Enskog's exact value at the interval's mean temperatures (the two
// rows' mean: the intervals are short, a quarter of a collision per particle, over which the
// temperatures' curvature moves the mean by ~1e-4).
std::vector<double> collisional_pressure_ratios(const RunSpec& s) {
    const Rows rows = run(s);
    HcsTheory th = *hcs_theory(s);
    const std::size_t S = s.species.size();
    std::vector<double> ratio;
    const auto temperatures = [&](const std::vector<double>& row) {
        HcsTemperatures T;
        for (std::size_t a = 0; a < S; ++a) {
            const std::string suffix = S > 1 ? "." + s.species[a].name : "";
            T.T_tr.push_back(row[column(s, "T_tr" + suffix)]);
            T.T_rot.push_back(row[column(s, "T_rot" + suffix)]);
        }
        return T;
    };
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const double expected =
            0.5 * (enskog_collisional_pressure(th, temperatures(rows[k - 1])) + enskog_collisional_pressure(th, temperatures(rows[k])));
        ratio.push_back(rows[k][column(s, "p_coll")] / expected);
    }
    return ratio;
}

TEST(Enskog, InelasticCollisionalPressureIsEnskogsExactResult) {
    // One species of rough grains at phi = 0.3, cooling through the transient to the cooling state.
    const auto [one, one_err] = mean_err(collisional_pressure_ratios(dense_gas(0.3, {0.8, 0.4}, 40000, 10, 0.25)));
    EXPECT_NEAR(one, 1.0, 4 * one_err) << one << " +- " << one_err;
    RecordProperty("one_species", std::to_string(one) + " +- " + std::to_string(one_err));
    EXPECT_LT(one_err, 0.004);
    // A mixture at phi = 0.25: large heavy and small light grains, every pair its own chi and alpha.
    RunSpec mix = dense_gas(0.25, {0.9, 0.2}, 40000, 10, 0.25);
    SpeciesSpec small;
    small.name = "small";
    small.radius = 0.3;
    small.mass = 0.25;
    small.fraction = 0.5;
    mix.species[0].name = "large";
    mix.species[0].fraction = 0.5;
    mix.species.push_back(small);
    mix.density = 0.25 / solid_fraction(1.0, mix.species);
    mix.pairs = {ConstantRestitution{0.9, 0.2}, ConstantRestitution{0.7, -1.0}, ConstantRestitution{0.95, 0.6}};
    const auto [two, two_err] = mean_err(collisional_pressure_ratios(mix));
    EXPECT_NEAR(two, 1.0, 4 * two_err) << two << " +- " << two_err;
    RecordProperty("mixture", std::to_string(two) + " +- " + std::to_string(two_err));
    EXPECT_LT(two_err, 0.004);
}

TEST(Enskog, DrivenSteadyStateAgainstTheSonineApproximationAtTheRateNChi) {
    // Smooth grains, alpha = 0.7, at phi = 0.25 under white noise: the steady T_tr of the first Sonine
    // approximation (van Noije & Ernst 1998) with the collision frequency of n chi. The DSMC's steps of
    // one mean free time put T_tr about 0.2 % low (tests/validation/driven_test.cpp), the Sonine
    // approximation's T_tr is within 0.2 % at alpha = 0.3: a band of 0.5 % and four standard errors.
    RunSpec s = dense_gas(0.25, {0.7, -1.0}, 20000, 60, 1.0);
    s.thermostat = ThermostatSpec{};
    s.thermostat->species.resize(1);
    s.thermostat->species[0].drive.value = {1.0};
    const Rows rows = run(s);
    std::vector<double> T;
    for (std::size_t k = 20; k < rows.size(); ++k) // after 20 collisions per particle
        T.push_back(rows[k][column(s, "T_tr")]);
    const auto [mean, err] = mean_err(T);
    const double chi = carnahan_starling_chi(0.25);
    const double sonine = white_noise_sonine_state(0.7, 1.0, 1.0, s.density * chi, 1.0).T_tr;
    EXPECT_NEAR(mean / sonine, 1.0, 0.005 + 4 * err / sonine) << mean << " +- " << err << " against " << sonine;
    RecordProperty("T_tr", std::to_string(mean) + " +- " + std::to_string(err) + " against " + std::to_string(sonine));
    // The Boltzmann gas's steady T_tr is chi^(2/3) times higher: the test tells the two apart.
    EXPECT_GT(std::pow(chi, 2.0 / 3.0) - 1, 10 * (0.005 + 4 * err / sonine));
}

TEST(Enskog, ShearedGasCarriesStressAcrossTheGrainsAndTurnsTheSpins) {
    // Rough grains (alpha = 0.9, beta = 0.5) at phi = 0.25 sheared at a = 0.5 (a* from 0.18 to 0.5):
    // the collisional stress tensor's trace is the virial's p_coll (the same collisions, two sums),
    // its shear stress is negative (momentum carried down the gradient), and the shifted collisions
    // turn the mean spin towards half the vorticity, -a/2, where the Boltzmann gas keeps it at 0.
    RunSpec s = dense_gas(0.25, {0.9, 0.5}, 10000, 20, 1.0);
    s.shear = ShearSpec{0.5, 0.2};
    const Rows E = run(s);
    const auto at = [&](const std::vector<double>& row, const char* q) { return row[column(s, q)]; };
    for (std::size_t k = 1; k < E.size(); ++k) {
        const double trace = (at(E[k], "P_coll_xx") + at(E[k], "P_coll_yy") + at(E[k], "P_coll_zz")) / 3;
        EXPECT_NEAR(trace, at(E[k], "p_coll"), 1e-12 * at(E[k], "p_coll")) << "row " << k;
        EXPECT_LT(at(E[k], "P_coll_xy"), 0.0) << "row " << k;
        EXPECT_LT(at(E[k], "P_xy"), 0.0) << "row " << k;
        // eta* is of the whole stress: kinetic and collisional.
        const double P_star_xy = (at(E[k], "P_xy") + at(E[k], "P_coll_xy")) / (s.density * at(E[k], "T_tr"));
        EXPECT_NEAR(at(E[k], "P_xy_star"), P_star_xy, 1e-12 * std::abs(P_star_xy));
    }
    const double Omega = at(E.back(), "omega_z");
    EXPECT_LT(Omega, -0.25 * 0.5 / 2) << Omega;
    EXPECT_GT(Omega, -0.5) << Omega;
    RunSpec b = s;
    b.enskog.reset();
    const Rows B = run(b);
    EXPECT_LT(std::abs(B.back()[column(b, "omega_z")]), 0.02) << B.back()[column(b, "omega_z")];
}

} // namespace
} // namespace roughgas
