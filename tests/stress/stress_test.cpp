// Stress suite (`ctest -L stress`): the solver at the extremes of its parameters.
// Every test asserts finite, physically admissible output: 0 <= eps^N <= 1, beta in [-1, 1] after the
// policy, T > 0, theta >= 0, and no NaN or infinity in any row unless undefined by definition
// (MomentsTable::check, the rule the CSV writer enforces).
#include "../dsmc/run_test_support.hpp"
#include "../io/io_test_support.hpp"

#include "roughgas/contact/contact_integrator.hpp"
#include "roughgas/contact/quasistatic.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/tables.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/observables/steady_state.hpp"
#include "roughgas/observables/theory.hpp"
#include "roughgas/restitution/normal_table.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace roughgas {
namespace {

using Rows = std::vector<std::vector<double>>;

Rows run(const RunSpec& spec, int replica = 0, ReplicaSummary* summary = nullptr) {
    const auto tables = RestitutionTables::build(spec);
    MomentsTable table(spec);
    Rows rows;
    run_replica(
        spec, *tables, replica,
        [&](std::span<const double> r) {
            table.check(r); // throws NonFiniteValue on a NaN or infinity not undefined by definition
            rows.emplace_back(r.begin(), r.end());
        },
        {}, summary);
    return rows;
}

using test::column;

// T_tr > 0, T_rot >= 0, theta >= 0 in every row (and per species for mixtures).
void expect_admissible(const RunSpec& s, const Rows& rows) {
    std::vector<std::string> suffixes = {""};
    if (s.species.size() > 1)
        for (const SpeciesSpec& sp : s.species)
            suffixes.push_back("." + sp.name);
    for (const std::string& x : suffixes) {
        const std::size_t tr = column(s, "T_tr" + x), rot = column(s, "T_rot" + x), th = column(s, "theta" + x);
        for (const auto& r : rows) {
            EXPECT_GT(r[tr], 0) << "T_tr" << x << " at t = " << r[0];
            EXPECT_GE(r[rot], 0) << "T_rot" << x;
            EXPECT_GE(r[th], 0) << "theta" << x;
        }
    }
}

RunSpec one_species(PairRestitution model, std::int64_t N, double end) {
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {model};
    s.particles = N;
    s.end = end;
    for (int k = 1; k <= 10; ++k)
        s.output_times.push_back(end * k / 10.0);
    s.seed = 5;
    return s;
}

TEST(Stress, ConstantRestitutionAtItsLimits) {
    // alpha in {0, 1e-6, 1} x beta in {-1, +1, -(1 - 1e-12), 1 - 1e-12}: 30 collisions per particle,
    // N = 2000. alpha = 0 cools by a factor ~e^{-1/3} per collision per particle (smooth) and keeps
    // going: no row may hold a non-finite value or a negative temperature.
    for (double alpha : {0.0, 1e-6, 1.0})
        for (double beta : {-1.0, 1.0, -(1 - 1e-12), 1 - 1e-12}) {
            SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", beta = " + std::to_string(beta));
            const RunSpec s = one_species(ConstantRestitution{alpha, beta}, 2000, 30);
            const Rows rows = run(s);
            expect_admissible(s, rows);
            if (alpha == 1 && beta == 1 - 1e-12) { // nearly elastic and perfectly rough: theta -> 1
                EXPECT_NEAR(rows.back()[column(s, "theta")], 1.0, 0.1);
            }
        }
}

TEST(Stress, CoulombWithHugeAndTinyFriction) {
    for (double mu : {0.0, 1e-12, 1e6})
        for (double beta0 : {-1.0, 1.0}) {
            const RunSpec s = one_species(CoulombRestitution{0.5, beta0, mu}, 2000, 10);
            expect_admissible(s, run(s));
        }
}

TEST(Stress, NormalContactOverTwentyDecadesOfImpactSpeed) {
    // w = g_N rho^2 tau^5 from 1e-15 to 1e5 (u = w^{1/5} from 1e-3 to 10) integrated directly, and
    // the table from 1e-40 to 1e40 (series below, power tail above its grid): eps^N in [0, 1],
    // non-increasing in w, the duration finite and positive.
    for (NormalForm form : {NormalForm::eq24, NormalForm::eq25})
        for (ContactEnd end : {ContactEnd::force, ContactEnd::separation}) {
            const ContactModel model{form, end};
            double previous = 1;
            for (double lw = -15; lw <= 5; lw += 0.25) {
                const double w = std::pow(10.0, lw);
                const NormalResult r = integrate_normal(std::pow(w, 0.2), model);
                EXPECT_GE(r.eps_n, 0) << "w = " << w;
                EXPECT_LE(r.eps_n, 1) << "w = " << w;
                EXPECT_LE(r.eps_n, previous * (1 + 1e-9)) << "w = " << w;
                EXPECT_TRUE(std::isfinite(r.duration) && r.duration > 0) << "w = " << w;
                previous = r.eps_n;
            }
            const NormalTable table = NormalTable::build(model);
            previous = 1;
            for (double lw = -40; lw <= 40; lw += 0.1) {
                const double e = table.eps_n(std::pow(10.0, lw));
                EXPECT_GE(e, 0) << "w = 1e" << lw;
                EXPECT_LE(e, previous) << "w = 1e" << lw;
                previous = e;
            }
        }
}

TEST(Stress, OutsideTheQuasistaticRangeTheToolWarnsOnceAndWorks) {
    // `roughgas restitution` of the ice case on a grid from 1e-10 to 1e5 m/s (w over 15 decades, up
    // to 1e4 at 1e5 m/s): exit 0, every eps^N in [0, 1], and exactly one warning naming the range
    // where Brilliantov et al. (1996), appendix B, fails (g_N > 0.1 c_t = 196 m/s here, or
    // A/t_c > 1). The shipped grid (1e-4 .. 10 m/s) gives none.
    const test::ScratchDir dir;
    const std::string ice = std::string(ROUGHGAS_SOURCE_DIR) + "/cases/ice.toml";
    const std::string common = " --set restitution.g_t_points=2 --set contact.cache=false --force";
    const test::CommandResult wide =
        run_roughgas("restitution '" + ice + "' --out '" + (dir / "wide").string() + "'" + common +
                         " --set restitution.g_n_min=1e-10 --set restitution.g_n_max=1e5 --set restitution.g_n_points=31",
                     dir);
    EXPECT_EQ(wide.status, 0) << wide.err;
    std::size_t warnings = 0;
    for (std::size_t at = wide.err.find("warning"); at != std::string::npos; at = wide.err.find("warning", at + 1))
        ++warnings;
    EXPECT_EQ(warnings, 1u) << wide.err;
    EXPECT_NE(wide.err.find("outside the quasistatic range"), std::string::npos) << wide.err;
    const std::string normal = test::read_file(dir / "wide" / "normal.csv");
    std::istringstream in(normal);
    int rows = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line[0] == 'g')
            continue;
        const double eps = std::stod(line.substr(line.find(',', line.find(',') + 1) + 1));
        EXPECT_GE(eps, 0) << line;
        EXPECT_LE(eps, 1) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 31);
    const test::CommandResult shipped = run_roughgas(
        "restitution '" + ice + "' --out '" + (dir / "shipped").string() + "'" + common + " --set restitution.g_n_points=5",
        dir);
    EXPECT_EQ(shipped.status, 0);
    EXPECT_EQ(shipped.err.find("warning"), std::string::npos) << shipped.err;
}

TEST(Stress, QuasistaticRatiosOfIce) {
    // c_t = sqrt(Y/(2 (1 + nu) rho_m)) = 1961 m/s for Y = 1e10 Pa, nu = 0.3, 1000 kg/m^3; A/t_c grows
    // as g^{1/5} (t_c ~ g^{-1/5}).
    Material ice;
    ice.young_modulus = 1e10;
    ice.poisson_ratio = 0.3;
    ice.dissipation = 5.300775e-5;
    const double m = 4.188790204786391e-3, R = 0.01;
    EXPECT_NEAR(sphere_density(m, R), 1000.0, 1e-9);
    const double c_t = transverse_sound_speed(ice, 1000.0);
    EXPECT_NEAR(c_t, std::sqrt(1e10 / 2600.0), 1e-9);
    const ContactPair pc = make_contact_pair(ice, {}, m, R, 0.4, m, R, 0.4);
    const QuasistaticRatios a = quasistatic_ratios(pc, c_t, 1.0), b = quasistatic_ratios(pc, c_t, 32.0);
    EXPECT_NEAR(b.time / a.time, 2.0, 1e-12);
    EXPECT_NEAR(b.speed / a.speed, 32.0, 1e-12);
    EXPECT_TRUE(a.holds());
    EXPECT_FALSE(quasistatic_ratios(pc, c_t, 1000.0).holds());
}

TEST(Stress, DissipationFromZeroToHuge) {
    // A from 1e-30 s (elastic: eps^N = 1 to the integration tolerance) to 1e3 s (u ~ 1e3 at 1 m/s)
    // for SI ice spheres of 1 cm at impact speeds from 1e-10 to 1e3 m/s.
    Material ice;
    ice.young_modulus = 1e10;
    ice.poisson_ratio = 0.3;
    const double m = 4.18879e-3, R = 0.01;
    const auto table = NormalTable::build({});
    for (double A : {1e-30, 1e-10, 5.3e-5, 1.0, 1e3}) {
        ice.dissipation = A;
        const ContactPair pc = make_contact_pair(ice, {}, m, R, 0.4, m, R, 0.4);
        for (double lg = -10; lg <= 3; lg += 0.5) {
            const double g = std::pow(10.0, lg);
            const double e = table.eps_n(pc.w(g));
            EXPECT_GE(e, 0);
            EXPECT_LE(e, 1);
            if (A == 1e-30) {
                EXPECT_NEAR(e, 1.0, 1e-9) << "g = " << g;
            }
            if (pc.u(g) <= 10) { // the direct integrator's range
                const ContactResult r = integrate_normal_contact(pc, g);
                EXPECT_NEAR(r.eps_n, e, 1e-7) << "A = " << A << ", g = " << g;
            }
        }
    }
}

TEST(Stress, TinyAsperitiesAndHugeFrictionTakeBoundedTime) {
    // z = zeta_0/(g_N T) down to 1e-5 (up to ~3e6 asperity breaks in one contact) and mu/kappa up to
    // 1e3 (a stiff asperity spring: up to ~1e4 oscillations): every contact finishes, eps^T is finite,
    // and the break count follows the sliding distance (breaks ~ 1/z). Time per contact, measured on
    // the development machine (docs/reliability.md): about 1.2 us per break plus, for an unbroken stiff
    // spring, about 5e-5 s x sqrt(mu/(kappa z)); the step budget (src/contact/contact_driver.hpp)
    // bounds it.
    int previous_breaks = 0;
    for (double z : {1e-2, 1e-3, 1e-4, 1e-5}) {
        const TangentialParameters p{0.3, 0.05, z, {}};
        const auto t0 = std::chrono::steady_clock::now();
        const TangentialResult r = integrate_tangential(p, 1.0);
        const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("  z = %g: eps_T = %.6f, %d breaks, %.3f s\n", z, r.eps_t, r.breaks, sec);
        EXPECT_TRUE(std::isfinite(r.eps_t));
        EXPECT_GT(r.eps_t, 0.9); // sliding throughout: eps^T -> 1 - mu (1 + eps^N) g_N/(2 kappa g_T) as z -> 0
        if (previous_breaks > 0) {
            EXPECT_NEAR(r.breaks / static_cast<double>(previous_breaks), 10.0, 0.5);
        }
        previous_breaks = r.breaks;
    }
    for (double mk : {1e2, 1e3})
        for (double z : {1e-3, 1e-5})
            for (double ratio : {0.1, 10.0}) {
                const TangentialResult r = integrate_tangential({0.3, mk, z, {}}, ratio);
                EXPECT_TRUE(std::isfinite(r.eps_t)) << mk << " " << z << " " << ratio;
                EXPECT_LE(std::abs(r.eps_t), 1.5);
            }
}

RunSpec viscoelastic_cooling(double A, std::int64_t N, double end) {
    ContactPair pc; // reduced units: m = 1, R = 0.5 for both grains, rho = 1
    pc.m_eff = 0.5;
    pc.R_eff = 0.25;
    pc.kappa = 2.0 / 7.0;
    pc.rho = 1;
    pc.A = A;
    RunSpec s = one_species(ViscoelasticRestitution{pc, 0.5, false}, N, end);
    s.output_times.clear();
    for (double t = 1; t < end; t *= 1.5)
        s.output_times.push_back(t);
    s.output_times.push_back(end);
    return s;
}

TEST(Stress, ViscoelasticCoolingFortyDecadesApproachesTheElasticTheta) {
    // eps^N(g_N) from the table with A = 30 (u = 1.5 A (rho^2 g)^{1/5} ~ 50 at the start: eps^N ~ 0.1),
    // constant beta = 0.5 (so the gas keeps cooling through its tangential losses when eps^N -> 1).
    // As T falls by 40 decades the typical u falls by 10^4 and eps^N -> 1, so theta approaches the
    // elastic long-time value theta*(alpha = 1, beta = 0.5) of the Maxwellian theory (0.7095 for
    // q = 0.4), from far above it (theta ~ 2 while eps^N is small). Statistics: N = 4000, theta
    // averaged over the last 5 rows; sd of one row's theta ~ sqrt(4/(3N)) = 1.8 %; the Maxwellian
    // theory is itself an approximation, off by ~2 % at moderate alpha (docs/validation.md). Tolerance 5 %.
    const RunSpec s = viscoelastic_cooling(30.0, 4000, 1000);
    ReplicaSummary summary;
    const Rows rows = run(s, 0, &summary);
    expect_admissible(s, rows);
    const double T0 = rows.front()[column(s, "T_tr")], T1 = rows.back()[column(s, "T_tr")];
    double theta = 0;
    for (std::size_t k = rows.size() - 5; k < rows.size(); ++k)
        theta += rows[k][column(s, "theta")] / 5;
    const double elastic = theta_fixed_point(1.0, 0.5, 0.4);
    std::printf("  T/T0 = %.3e after %g collisions per particle; theta = %.4f (elastic limit %.4f; %.2f s)\n",
                T1 / T0, rows.back()[1], theta, elastic, summary.seconds);
    for (std::size_t k = 0; k < rows.size(); k += 4)
        std::printf("    coll/particle %8.1f  T/T0 %.3e  theta %.4f\n", rows[k][1], rows[k][column(s, "T_tr")] / T0,
                    rows[k][column(s, "theta")]);
    EXPECT_LT(T1 / T0, 1e-40);
    EXPECT_NEAR(theta / elastic, 1.0, 0.05);
    double theta_max = 0; // the approach: from far above
    for (const auto& r : rows)
        theta_max = std::max(theta_max, r[column(s, "theta")]);
    EXPECT_GT(theta_max / elastic, 2.0);
}

TEST(Stress, ShearRatesOverEighteenDecadesReachOneSteadyState) {
    // Uniform shear flow of rough spheres (alpha = 0.9, beta = 0, constant: no scale of its own)
    // started at T = 1 with shear rates a from 1e-12 to 1e6 (a* = a/nu from 2e-13 to 2e5): the
    // gas cools by ~1e-26 before a tiny rate heats it, or heats by ~5e10 under a huge one. Every
    // row finite and admissible; no Strang step holds more than 1 collision per grain (the step
    // follows the temperature through the stream before it: without that the first step at
    // a = 1e6 held ~1e4); and every rate ends in the same steady state, whose reduced shear rate
    // a* and viscosity eta* do not depend on a: the means over the last 200 collisions per grain
    // (10 batches of 20 collisions per grain, ~10 relaxation times of the stresses each, so the
    // batch means are independent) agree with those of a = 1 by Welch's t-test. Its threshold is
    // Student's t quantile for the Welch-Satterthwaite degrees of freedom (~18) at a two-sided
    // false-alarm probability of 1.25e-4 per comparison, 1e-3 for the 8 comparisons together
    // (a fixed multiple of the errors with 5 batches, 4 degrees of freedom each, raised a false
    // alarm for a few % of the seeds).
    const auto shear = [](double a) {
        RunSpec s;
        s.species = {SpeciesSpec{}};
        s.species[0].temperature = s.species[0].rotational_temperature = 1;
        s.pairs = {ConstantRestitution{0.9, 0.0}};
        s.particles = 2000;
        s.shear = ShearSpec{a, 0.2};
        for (int k = 1; k <= 110; ++k)
            s.output_times.push_back(5.0 * k);
        s.seed = 13;
        return s;
    };
    constexpr int batches = 10;
    constexpr int comparisons = 8;
    constexpr double family_false_alarm = 1e-3;
    struct Steady {
        SteadyValue a_star, eta_star;
    };
    const auto run_rate = [&](double a) {
        SCOPED_TRACE("shear rate " + std::to_string(a));
        const RunSpec s = shear(a);
        const Rows rows = run(s);
        expect_admissible(s, rows);
        const std::size_t cpp = column(s, "coll_per_particle");
        for (std::size_t k = 1; k < rows.size(); ++k)
            EXPECT_LT(rows[k][cpp], s.output_times[k - 1] + 1.0) << "row " << k;
        std::vector<double> a_star, eta_star;
        for (const auto& r : rows)
            if (r[cpp] > 350) {
                a_star.push_back(r[column(s, "a_star")]);
                eta_star.push_back(r[column(s, "eta_star")]);
            }
        return Steady{batch_mean(a_star, batches), batch_mean(eta_star, batches)};
    };
    const Steady ref = run_rate(1.0);
    for (double a : {1e-12, 1e-6, 1e3, 1e6}) {
        const Steady st = run_rate(a);
        for (auto [x, y] : {std::pair{st.a_star, ref.a_star}, {st.eta_star, ref.eta_star}}) {
            // Welch-Satterthwaite: each error has batches - 1 degrees of freedom.
            const double vx = x.err * x.err, vy = y.err * y.err;
            const double dof = (vx + vy) * (vx + vy) / ((vx * vx + vy * vy) / (batches - 1));
            const double t = boost::math::quantile(boost::math::complement(
                boost::math::students_t(dof), 0.5 * family_false_alarm / comparisons));
            EXPECT_NEAR(x.mean, y.mean, t * std::sqrt(vx + vy)) << x.name << " at a = " << a << ", t = " << t;
        }
    }
}

TEST(Stress, ShearRowsDenserThanTheStrangSteps) {
    // Rows every 0.01 collisions per grain, a twentieth of a Strang step (time_step = 0.2): each
    // row ends a step shortened to its collision count (plus a few collisions), so no two rows share
    // a step (which would leave an empty interval: coll_rate 0/0) and every row is finite.
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {ConstantRestitution{0.9, 0.0}};
    s.particles = 4000;
    s.shear = ShearSpec{1.0, 0.2};
    for (int k = 1; k <= 200; ++k)
        s.output_times.push_back(0.01 * k);
    s.seed = 17;
    const Rows rows = run(s);
    ASSERT_EQ(rows.size(), s.output_times.size() + 1);
    expect_admissible(s, rows);
    const std::size_t cpp = column(s, "coll_per_particle");
    for (std::size_t k = 1; k < rows.size(); ++k) {
        EXPECT_GE(rows[k][cpp], s.output_times[k - 1] - 1e-12);
        EXPECT_LT(rows[k][cpp], s.output_times[k - 1] + 0.01) << "row " << k; // < 20 collisions past
    }
}

TEST(Stress, ExtremeMixtures) {
    // Mass ratio 1e4, size ratio 100, and a species of number fraction 1e-4 (2 grains of 20000):
    // constant restitution for every pair; every row admissible, per species too.
    const auto mixture = [](double m2, double R2, double x2) {
        RunSpec s;
        SpeciesSpec a, b;
        a.name = "a";
        b.name = "b";
        b.mass = m2;
        b.radius = R2;
        a.fraction = 1 - x2;
        b.fraction = x2;
        s.species = {a, b};
        s.pairs = {ConstantRestitution{0.9, 0.5}, ConstantRestitution{0.8, 0.0}, ConstantRestitution{0.7, -0.5}};
        s.particles = 20000;
        s.end = 5;
        s.output_times = {1, 2, 3, 4, 5};
        s.seed = 3;
        return s;
    };
    for (const RunSpec& s : {mixture(1e4, 0.5, 0.5), mixture(1e-4, 0.5, 0.5), mixture(1.0, 50.0, 0.5),
                             mixture(1.0, 0.005, 0.5), mixture(1e4, 50.0, 1e-4), mixture(1.0, 0.5, 1e-4)}) {
        SCOPED_TRACE("m2 = " + std::to_string(s.species[1].mass) + ", R2 = " + std::to_string(s.species[1].radius) +
                     ", x2 = " + std::to_string(s.species[1].fraction));
        expect_admissible(s, run(s));
    }
}

} // namespace
} // namespace roughgas
