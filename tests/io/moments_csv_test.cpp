// The rows of moments.csv (io/moments_csv.hpp): columns, replica statistics, theory, and the
// no-silent-NaN rule.
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/observables/driven_steady_state.hpp"

#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/observables/driven_theory.hpp"
#include "roughgas/observables/enskog_usf_theory.hpp"
#include "roughgas/observables/sonine_cooling_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughgas {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

RunSpec one_species(int replicas, PairRestitution r = ConstantRestitution{0.9, 0.0}) {
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {r};
    s.replicas = replicas;
    return s;
}

// A row of dsmc_columns for one species: t, coll_per_particle, T_tr, T_rot, theta, a20, a02, a11,
// A_cw, coll_rate, E_diss_rate.
std::vector<double> row(double t, double c, double T, double Tr) {
    return {t, c, T, Tr, Tr / T, 0.01, 0.02, 0.03, 0.04, c > 0 ? 5.0 : nan, c > 0 ? 0.1 : nan};
}

TEST(MomentsTable, ColumnsWithErrorsAndTheory) {
    const MomentsTable one(one_species(1));
    EXPECT_EQ(one.names().size(), 11u + 1u + 4u + 5u);
    EXPECT_EQ(one.names()[11], "zeta_star");
    EXPECT_EQ(one.names()[12], "T_tr_theory");
    EXPECT_EQ(one.units()[12], "energy");
    EXPECT_EQ(one.names()[15], "zeta_star_theory");
    EXPECT_EQ(one.names()[16], "theta_sonine");
    EXPECT_EQ(one.names().back(), "a11_sonine");
    EXPECT_TRUE(one.has_sonine());
    const MomentsTable three(one_species(3));
    ASSERT_EQ(three.names().size(), 22u + 2u + 4u + 5u);
    EXPECT_EQ(three.names()[2], "coll_per_particle");
    EXPECT_EQ(three.names()[3], "coll_per_particle_err");
    EXPECT_EQ(three.units()[5], "energy"); // T_tr_err
    EXPECT_EQ(three.names()[23], "zeta_star_err");
    const MomentsTable coulomb(one_species(1, CoulombRestitution{0.9, 0.5, 0.2}));
    EXPECT_FALSE(coulomb.has_theory());
    EXPECT_EQ(coulomb.names().size(), 11u + 1u);
    RunSpec shear = one_species(1); // heated: no cooling rate, no theory
    shear.shear = ShearSpec{};
    const std::vector<std::string> names = MomentsTable(shear).names();
    EXPECT_EQ(std::count(names.begin(), names.end(), "zeta_star"), 0);
}

// Shear runs of one species of smooth grains with constant alpha < 1: Grad's steady state, the same in
// every row, last: the Boltzmann equation's (phi = 0) or the Enskog equation's at the run's phi and chi.
// Rough grains, and elastic ones (no steady state), have none.
TEST(MomentsTable, GradColumnsOfASmoothShearedGas) {
    const std::vector<std::string> grad = {"a_star_grad",    "eta_star_grad", "P_xx_star_grad", "P_yy_star_grad",
                                           "P_zz_star_grad", "N1_star_grad",  "N2_star_grad"};
    for (const bool enskog : {false, true}) {
        RunSpec s = one_species(1, ConstantRestitution{0.7, -1.0});
        s.shear = ShearSpec{};
        s.density = 0.4775;
        if (enskog)
            s.enskog = EnskogSpec{};
        MomentsTable table(s);
        const std::vector<std::string> names = table.names();
        ASSERT_GE(names.size(), grad.size());
        EXPECT_TRUE(std::equal(grad.begin(), grad.end(), names.end() - 7));
        const std::vector<double> r(table.solver_columns().size(), 1.0);
        std::vector<std::span<const double>> rows{r};
        const std::vector<double> out = table.combine(rows);
        const double phi = solid_fraction(s.density, s.species);
        const EnskogUsfState g =
            enskog ? enskog_usf_grad(0.7, phi, carnahan_starling_chi(phi)) : enskog_usf_grad(0.7, 0.0, 1.0);
        const double expected[] = {g.a_star, g.eta_star, g.total.xx, g.total.yy, g.total.zz, g.N1, g.N2};
        for (std::size_t k = 0; k < 7; ++k)
            EXPECT_EQ(out[out.size() - 7 + k], expected[k]) << grad[k];
    }
    RunSpec rough = one_species(1);
    rough.shear = ShearSpec{};
    RunSpec elastic = one_species(1, ConstantRestitution{1.0, -1.0});
    elastic.shear = ShearSpec{};
    for (const RunSpec& s : {rough, elastic}) {
        const std::vector<std::string> names = MomentsTable(s).names();
        EXPECT_EQ(std::count(names.begin(), names.end(), "a_star_grad"), 0);
    }
}

// zeta_star: each replica's -ln(T_tr/T_tr')/(c - c') since its own previous row, then the mean and
// error over the replicas like every other column; NaN in the first row. The theory's value is
// (1 - alpha^2)/3 for smooth spheres.
TEST(MomentsTable, ReducedCoolingRatePerReplicaSinceItsPreviousRow) {
    MomentsTable table(one_species(2, ConstantRestitution{0.6, -1.0}));
    const std::vector<std::string> names = table.names();
    const auto at = [&](const std::string& n) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin());
    };
    const std::vector<double> a0 = row(0, 0, 1.0, 1.0), b0 = row(0, 0, 2.0, 1.0);
    std::vector<std::span<const double>> rows{a0, b0};
    std::vector<double> out = table.combine(rows);
    EXPECT_TRUE(std::isnan(out[at("zeta_star")]));
    EXPECT_NEAR(out[at("zeta_star_theory")], (1 - 0.36) / 3, 1e-14);
    // Replica a: T_tr 1 -> e^-0.5 over 2 collisions per particle (0.25); b: 2 -> 2 e^-0.3 over 1 (0.3).
    const std::vector<double> a1 = row(1, 2, std::exp(-0.5), 1.0), b1 = row(1, 1, 2 * std::exp(-0.3), 1.0);
    rows = {a1, b1};
    out = table.combine(rows);
    EXPECT_NEAR(out[at("zeta_star")], 0.275, 1e-14);
    EXPECT_NEAR(out[at("zeta_star_err")], 0.025, 1e-14);
    // Then a: e^-0.5 -> e^-0.9 over 1 (0.4); b: 2 e^-0.3 -> the same (0).
    const std::vector<double> a2 = row(2, 3, std::exp(-0.9), 1.0), b2 = row(2, 4, 2 * std::exp(-0.3), 1.0);
    rows = {a2, b2};
    out = table.combine(rows);
    EXPECT_NEAR(out[at("zeta_star")], 0.2, 1e-14);
    EXPECT_NEAR(out[at("zeta_star_theory")], (1 - 0.36) / 3, 1e-14);
}

TEST(MomentsTable, MeanAndStandardErrorOverReplicas) {
    MomentsTable table(one_species(3));
    const std::vector<double> a = row(0, 0, 1.0, 1.0), b = row(0, 0, 1.0, 1.0), c = row(0, 0, 1.0, 1.0);
    std::vector<std::span<const double>> rows{a, b, c};
    std::vector<double> out = table.combine(rows);
    EXPECT_EQ(out[0], 0.0);
    EXPECT_EQ(out[1], 0.0);
    EXPECT_EQ(out[out.size() - 9], 1.0); // theory at t = 0 (T_tr_theory): the initial temperatures
    const std::vector<double> d = row(0.1, 1, 0.8, 1.0), e = row(0.2, 1, 0.9, 1.0), f = row(0.3, 1, 1.3, 1.0);
    rows = {d, e, f};
    out = table.combine(rows);
    EXPECT_NEAR(out[0], 0.2, 1e-15);                                 // t: mean
    EXPECT_NEAR(out[1], std::sqrt(0.02 / 6.0), 1e-15);               // t_err: sqrt(sum (x - m)^2/(K (K - 1)))
    EXPECT_NEAR(out[4], 1.0, 1e-15);                                 // T_tr
    EXPECT_NEAR(out[5], std::sqrt((0.04 + 0.01 + 0.09) / 6), 1e-15); // T_tr_err
    HcsTrajectory th(HcsTheory({{1, 0.5, 0.4, 1}}, {{0.9, 0.0}}, 1.0), {{1.0}, {1.0}});
    EXPECT_NEAR(out[out.size() - 9], th.at(0.2).T_tr[0], 1e-12); // theory at the mean t
}

// A driven run (spec.thermostat) writes the driven theory in the same columns: the trajectory with
// the thermostat's sources through its schedule (observables/driven_theory.hpp), zeta_star_theory the
// collisions' part alone; no _sonine columns (they describe the cooling state).
TEST(MomentsTable, DrivenRunsCarryTheDrivenTheory) {
    RunSpec spec = one_species(1, ConstantRestitution{0.8, 0.2});
    spec.thermostat = white_noise_thermostat(1, DriveSchedule{{0.0, 1.0}, {2.0, 0.5}}, 0.1);
    MomentsTable table(spec);
    EXPECT_TRUE(table.has_theory());
    EXPECT_FALSE(table.has_sonine());
    const std::vector<std::string> names = table.names();
    ASSERT_EQ(names.back(), "theta_steady_theory"); // after the trajectory's columns, the steady state's
    ASSERT_EQ(names[names.size() - 4], "zeta_star_theory");
    const HcsTheory theory({{1, 0.5, 0.4, 1}}, {{0.8, 0.2}}, 1.0);
    HcsTrajectory driven(theory, {{1.0}, {1.0}}, *spec.thermostat);
    HcsTrajectory cooling(theory, {{1.0}, {1.0}});
    for (double t : {0.0, 0.5, 2.0}) {
        const std::vector<double> r = row(t, t, 1.0, 1.0);
        const std::vector<std::span<const double>> rows{r};
        const std::vector<double> out = table.combine(rows);
        const HcsTemperatures T = driven.at(t);
        EXPECT_NEAR(out[out.size() - 7] / T.T_tr[0], 1.0, 1e-12) << t; // T_tr_theory
        EXPECT_NEAR(out[out.size() - 6] / T.T_rot[0], 1.0, 1e-12) << t;
        EXPECT_NEAR(out[out.size() - 4], reduced_cooling_rate(theory, T), 1e-12) << t;
        // The steady state under the final drive, the same in every row.
        const std::optional<DrivenSteadyState> st = driven_steady_state(theory, *spec.thermostat);
        ASSERT_TRUE(st);
        EXPECT_EQ(out[out.size() - 3], st->T_tr) << t;
        EXPECT_EQ(out[out.size() - 2], st->T_rot) << t;
        EXPECT_EQ(out.back(), st->theta) << t;
        if (t > 0) { // heated: above the cooling gas
            EXPECT_GT(T.T_tr[0], 1.5 * cooling.at(t).T_tr[0]) << t;
        }
    }
}

// The first-Sonine scaled state: its five values in every row, after the Maxwellian theory; written
// for one species with the hard-sphere kernel only; smooth grains have no theta, a02, a11 (NaN).
TEST(MomentsTable, SonineColumnsAreTheScaledStateInEveryRow) {
    MomentsTable table(one_species(1, ConstantRestitution{0.9, 0.5}));
    const std::optional<SonineCoolingState> s = sonine_cooling_state(0.9, 0.5, 0.4);
    ASSERT_TRUE(s);
    const std::vector<double> want = {s->theta, s->zeta_star, s->a20, s->a02, s->a11};
    for (double t : {0.0, 1.0, 7.0}) {
        const std::vector<double> r = row(t, t, std::exp(-t), 1.0);
        const std::vector<std::span<const double>> rows{r};
        const std::vector<double> out = table.combine(rows);
        EXPECT_EQ(std::vector<double>(out.end() - 5, out.end()), want) << t;
    }
    MomentsTable smooth(one_species(1, ConstantRestitution{0.6, -1.0}));
    const std::vector<double> r = row(0, 0, 1.0, 1.0);
    const std::vector<std::span<const double>> rows{r};
    const std::vector<double> out = smooth.combine(rows);
    const double a2 = 16 * 0.4 * (1 - 2 * 0.36) / (81 - 17 * 0.6 + 30 * 0.36 * 0.4);
    EXPECT_TRUE(std::isnan(out[out.size() - 5])); // theta_sonine
    EXPECT_NEAR(out[out.size() - 3], a2, 1e-14);    // a20_sonine: van Noije & Ernst
    EXPECT_TRUE(std::isnan(out[out.size() - 2]) && std::isnan(out[out.size() - 1]));
    RunSpec maxwell = one_species(1);
    maxwell.kernel = CollisionKernel::maxwell;
    RunSpec mix = one_species(1);
    mix.species.resize(2);
    mix.species[1].name = "b";
    mix.pairs.assign(3, ConstantRestitution{0.9, 0.0});
    for (const RunSpec& spec : {maxwell, mix, one_species(1, CoulombRestitution{0.9, 0.5, 0.2})}) {
        const MomentsTable t(spec);
        EXPECT_FALSE(t.has_sonine());
        const std::vector<std::string> names = t.names();
        EXPECT_EQ(std::count(names.begin(), names.end(), "theta_sonine"), 0);
    }
}

TEST(MomentsTable, NoSilentNaN) {
    const MomentsTable table(one_species(1));
    EXPECT_NO_THROW(table.check(row(0, 0, 1, 1))); // rates undefined at t = 0
    EXPECT_NO_THROW(table.check(row(1, 1, 1, 1)));
    std::vector<double> r = row(1, 1, 1, 1);
    r[9] = nan; // coll_rate after t = 0
    try {
        table.check(r);
        FAIL() << "no exception";
    } catch (const NonFiniteValue& e) {
        EXPECT_EQ(e.column(), "coll_rate");
        EXPECT_EQ(e.t(), 1.0);
        EXPECT_NE(std::string(e.what()).find("column coll_rate is nan at t = 1"), std::string::npos)
            << e.what();
    }
    r = row(1, 1, 1, 1);
    r[5] = std::numeric_limits<double>::infinity(); // a20
    EXPECT_THROW(table.check(r), NonFiniteValue);
    // No rotation at all (smooth grains started without spin): a02, a11, A_cw are undefined.
    r = row(1, 1, 1, 0);
    r[6] = r[7] = r[8] = nan;
    EXPECT_NO_THROW(table.check(r));
    r[3] = 0.5; // ... but not when T_rot > 0
    EXPECT_THROW(table.check(r), NonFiniteValue);
}

TEST(MomentsTable, EveryColumnHasAMeaningAndTheGeneratedTableListsIt) {
    RunSpec mix;
    for (const char* name : {"x", "y", "z"}) { // (GCC 12 warns, wrongly, on name = "x": -Wrestrict)
        mix.species.emplace_back();
        mix.species.back().name = std::string(name);
    }
    mix.pairs.assign(6, ConstantRestitution{0.9, 0.1});
    mix.pairs[4] = BrilliantovRestitution{};
    mix.replicas = 2;
    const std::string md = moments_columns_markdown();
    for (const RunSpec& s : {one_species(1), one_species(3), mix}) {
        const MomentsTable table(s);
        for (const Column& c : table.columns()) {
            EXPECT_FALSE(moments_column_meaning(c.name).empty()) << c.name;
        }
    }
    for (const char* c :
         {"| `t` | time |", "| `X_err` |", "| `T_tr.NAME` | energy |", "| `T_tr.A/T_tr.B` | - |",
          "| `beta_clamped` |", "| `theta_theory` | - |", "| `T_tr_theory.NAME` | energy |", "| `zeta_star` | - |",
          "| `zeta_star_theory` | - |", "| `theta_sonine` | - |", "| `a11_sonine` | - |"})
        EXPECT_NE(md.find(c), std::string::npos) << c << "\n" << md;
    EXPECT_EQ(md.find("| `T_tr.B` |"), std::string::npos) << md; // B only in the ratios
}

} // namespace
} // namespace roughgas
