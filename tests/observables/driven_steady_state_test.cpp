// The steady states of the driven two-temperature equations (observables/driven_steady_state.hpp):
// the closed forms of equal spheres against the general solver, their limits (an elastic gas in a
// bath, theta independent of alpha under white noise), the energy balance, mixtures and the Maxwell kernel.
#include "roughgas/observables/driven_steady_state.hpp"
#include "roughgas/observables/driven_theory.hpp"
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace roughgas {
namespace {

HcsTheory one_species(double alpha, double beta, double q = 0.4, double m = 1.0, double R = 0.5, double n = 1.0) {
    return HcsTheory({{m, R, q, 1.0}}, {{alpha, beta}}, n);
}

// A binary mixture with unequal masses, radii and q, and a different (alpha, beta) per pair.
HcsTheory mixture(double alpha = 0.8, double beta = 0.3) {
    return HcsTheory({{1.0, 0.5, 0.4, 0.3}, {3.5, 0.8, 0.25, 0.7}},
                     {{alpha, beta}, {0.5 * (1 + alpha), beta * 0.5}, {alpha, -beta}}, 2.0);
}

// The collisional rates (no thermostat) at T.
HcsTemperatures collision_rates(const HcsTheory& th, const HcsTemperatures& T) {
    HcsTemperatures d{std::vector<double>(th.species_count()), std::vector<double>(th.species_count())};
    th.rates(T.T_tr, T.T_rot, d.T_tr, d.T_rot);
    return d;
}

TEST(DrivenSteadyState, ElasticLangevinBathSetsBothTemperatures) {
    // An elastic gas in a bath is in equilibrium at T_b: the closed form, the general solver and the
    // trajectory from far away all give T_tr = T_rot = T_b (perfectly rough, and smooth with a
    // rotational friction, whose spins only the bath reaches).
    const double Tb = 2.3;
    for (double beta : {1.0, -1.0}) {
        const EqualSphereSteadyState c = langevin_steady_state(1.0, beta, 0.4, 1.7, 1.0, 0.8, Tb, 0.3, 0.7);
        EXPECT_NEAR(c.T_tr / Tb, 1.0, 1e-14) << beta;
        EXPECT_NEAR(c.T_rot / Tb, 1.0, 1e-14) << beta;
        const ThermostatSpec th = langevin_thermostat(1, constant_drive(Tb), 0.3, 0.7);
        const std::optional<DrivenSteadyState> s = driven_steady_state(one_species(1.0, beta, 0.4, 1.7, 0.5, 0.8), th);
        ASSERT_TRUE(s) << beta;
        EXPECT_NEAR(s->T.T_tr[0] / Tb, 1.0, 1e-12) << beta;
        EXPECT_NEAR(s->T.T_rot[0] / Tb, 1.0, 1e-12) << beta;
        EXPECT_NEAR(s->T_tr_over_bath[0], 1.0, 1e-12);
        HcsTrajectory tr(one_species(1.0, beta, 0.4, 1.7, 0.5, 0.8), {{9.0}, {0.1}}, th);
        const HcsTemperatures T = tr.at(40.0); // e^{-2 gamma t} = e^{-24}: within 4e-11 of T_b
        EXPECT_NEAR(T.T_tr[0] / Tb, 1.0, 1e-9) << beta;
        EXPECT_NEAR(T.T_rot[0] / Tb, 1.0, 1e-9) << beta;
    }
    // An elastic perfectly rough mixture of unequal grains: equipartition at T_b for every species.
    HcsTheory elastic({{1.0, 0.5, 0.4, 0.3}, {3.5, 0.8, 0.25, 0.7}}, {{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}}, 2.0);
    const std::optional<DrivenSteadyState> s =
        driven_steady_state(elastic, langevin_thermostat(2, constant_drive(Tb), 0.2, 0.0));
    ASSERT_TRUE(s);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(s->T.T_tr[k] / Tb, 1.0, 1e-12);
        EXPECT_NEAR(s->T.T_rot[k] / Tb, 1.0, 1e-12); // no rotational friction: the collisions bring T_rot up
        EXPECT_NEAR(s->T_tr_ratio[k], 1.0, 1e-12);
    }
}

TEST(DrivenSteadyState, InelasticLangevinBathCoolsBelowIt) {
    // The closed form (a root in T_tr) against the general solver, and the balance of each equation.
    for (double alpha : {0.5, 0.9})
        for (double beta : {-0.5, 0.4, 1.0}) {
            const double Tb = 1.5, g = 0.4, gr = 0.1;
            const EqualSphereSteadyState c = langevin_steady_state(alpha, beta, 0.4, 1.0, 1.0, 1.0, Tb, g, gr);
            EXPECT_LT(c.T_tr, Tb);
            EXPECT_LT(c.T_rot, Tb);
            const HcsTheory th = one_species(alpha, beta);
            const HcsTemperatures d = collision_rates(th, {{c.T_tr}, {c.T_rot}});
            EXPECT_NEAR(d.T_tr[0] + 2 * g * (Tb - c.T_tr), 0.0, 1e-13) << alpha << " " << beta;
            EXPECT_NEAR(d.T_rot[0] + 2 * gr * (Tb - c.T_rot), 0.0, 1e-13) << alpha << " " << beta;
            const std::optional<DrivenSteadyState> s =
                driven_steady_state(th, langevin_thermostat(1, constant_drive(Tb), g, gr));
            ASSERT_TRUE(s);
            EXPECT_NEAR(s->T.T_tr[0] / c.T_tr, 1.0, 1e-11) << alpha << " " << beta;
            EXPECT_NEAR(s->T.T_rot[0] / c.T_rot, 1.0, 1e-11) << alpha << " " << beta;
        }
    // scripts/driven_theory_reference.py (scipy's DOP853 to t = 400, no closed form): alpha = 0.9,
    // beta = 0.4, T_b = 1.5, gamma = 0.4, gamma_rot = 0.1.
    const EqualSphereSteadyState ref = langevin_steady_state(0.9, 0.4, 0.4, 1.0, 1.0, 1.0, 1.5, 0.4, 0.1);
    EXPECT_NEAR(ref.T_tr, 0.627948742105, 1e-11);
    EXPECT_NEAR(ref.T_rot, 0.371679411193, 1e-11);
    // Only the spins in the bath (gamma = 0): the collisions heat the translation from them.
    const EqualSphereSteadyState spins = langevin_steady_state(0.9, 0.2, 0.4, 1.0, 1.0, 1.0, 1.5, 0.0, 0.4);
    EXPECT_GT(spins.T_tr, 0.1);
    EXPECT_LT(spins.T_tr, spins.T_rot);
    const std::optional<DrivenSteadyState> s =
        driven_steady_state(one_species(0.9, 0.2), langevin_thermostat(1, constant_drive(1.5), 0.0, 0.4));
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->T.T_tr[0] / spins.T_tr, 1.0, 1e-11);
    EXPECT_NEAR(s->T.T_rot[0] / spins.T_rot, 1.0, 1e-11);
    // Smooth grains whose spins feel no bath: T_rot is whatever it was (NaN), T_tr that of smooth spheres.
    const EqualSphereSteadyState smooth = langevin_steady_state(0.8, -1.0, 0.4, 1.0, 1.0, 1.0, 1.5, 0.3, 0.0);
    EXPECT_TRUE(std::isnan(smooth.T_rot));
    const std::optional<DrivenSteadyState> ss =
        driven_steady_state(one_species(0.8, -1.0), langevin_thermostat(1, constant_drive(1.5), 0.3, 0.0));
    ASSERT_TRUE(ss);
    EXPECT_NEAR(ss->T.T_tr[0] / smooth.T_tr, 1.0, 1e-11);
    EXPECT_TRUE(std::isnan(ss->T.T_rot[0]));
    const EqualSphereCoefficients c = equal_sphere_coefficients(0.8, -1.0, 0.4, 1.0, 1.0, 1.0);
    EXPECT_NEAR(-c.G * c.A * std::pow(smooth.T_tr, 1.5) + 0.6 * (1.5 - smooth.T_tr), 0.0, 1e-13);
}

TEST(DrivenSteadyState, WhiteNoiseThetaDoesNotDependOnAlpha) {
    // eps = 0: dT_rot/dt = G T_tr^{1/2}(B T_tr - C T_rot) = 0 alone, theta = B/C = q(1 + beta)/(1 + 2q - beta)
    // (driven_steady_state.hpp), whatever alpha; 1 for perfectly rough spheres, whatever q.
    for (double q : {0.25, 0.4, 2.0 / 3.0})
        for (double beta : {-0.6, 0.0, 0.5, 1.0}) {
            const double closed = q * (1 + beta) / (1 + 2 * q - beta);
            for (double alpha : {0.2, 0.6, 0.9, 1.0}) {
                const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, 1, 1, 1);
                EXPECT_NEAR(white_noise_steady_theta(alpha, beta, q), closed, 1e-15);
                EXPECT_NEAR(c.B / c.C, closed, 1e-14);
                if (alpha == 1 && beta == 1)
                    continue; // elastic: no steady state
                const std::optional<DrivenSteadyState> s =
                    driven_steady_state(one_species(alpha, beta, q), white_noise_thermostat(1, constant_drive(0.7)));
                ASSERT_TRUE(s) << alpha << " " << beta << " " << q;
                EXPECT_NEAR(s->theta, closed, 1e-12) << alpha << " " << beta << " " << q;
            }
            EXPECT_NEAR(white_noise_steady_theta(0.5, 1.0, q), 1.0, 1e-15);
        }
    // The printed value for uniform spheres (q = 2/5) at beta = 0: 0.4/1.8.
    EXPECT_NEAR(white_noise_steady_theta(0.9, 0.0, 0.4), 2.0 / 9.0, 1e-15);
}

TEST(DrivenSteadyState, WhiteNoiseSteadyStateBalancesTheEnergy) {
    // At the closed-form state the collisions take out of T_tr and T_rot exactly what the kicks put
    // in: (1 - eps) m xi^2 and eps m xi^2; the general solver finds the same state; a trajectory
    // from far away tends to it.
    const double m = 2.0, R = 0.4, n = 0.6, xi2 = 0.9;
    for (double eps : {0.0, 0.3, 1.0})
        for (double alpha : {0.6, 0.95})
            for (double beta : {-0.4, 0.5}) {
                const EqualSphereSteadyState c =
                    white_noise_steady_state(alpha, beta, 0.4, m, 2 * R, n, xi2, eps);
                const HcsTheory th = one_species(alpha, beta, 0.4, m, R, n);
                const HcsTemperatures d = collision_rates(th, {{c.T_tr}, {c.T_rot}});
                EXPECT_NEAR(d.T_tr[0] / (m * xi2), -(1 - eps), 1e-13) << eps << " " << alpha << " " << beta;
                EXPECT_NEAR(d.T_rot[0] / (m * xi2), -eps, 1e-13) << eps << " " << alpha << " " << beta;
                const ThermostatSpec wn = white_noise_thermostat(1, constant_drive(xi2), eps);
                const std::optional<DrivenSteadyState> s = driven_steady_state(th, wn);
                ASSERT_TRUE(s);
                EXPECT_NEAR(s->T.T_tr[0] / c.T_tr, 1.0, 1e-12);
                EXPECT_NEAR(s->T.T_rot[0] / c.T_rot, 1.0, 1e-12);
                EXPECT_TRUE(std::isnan(s->T_tr_over_bath[0])); // no bath
                HcsTrajectory tr(th, {{5 * c.T_tr}, {0.0}}, wn);
                const HcsTemperatures T = tr.at(2000.0 / collision_frequency(th, {{c.T_tr}, {c.T_rot}}));
                EXPECT_NEAR(T.T_tr[0] / c.T_tr, 1.0, 1e-8) << eps << " " << alpha << " " << beta;
                EXPECT_NEAR(T.T_rot[0] / c.T_rot, 1.0, 1e-8) << eps << " " << alpha << " " << beta;
            }
    // No steady state: an elastic gas heats for ever; smooth spheres fed through their spins keep
    // a finite T_tr while T_rot grows without bound.
    EXPECT_FALSE(driven_steady_state(one_species(1.0, 1.0), white_noise_thermostat(1, constant_drive(1.0))));
    const std::optional<DrivenSteadyState> smooth =
        driven_steady_state(one_species(0.8, -1.0), white_noise_thermostat(1, constant_drive(1.0), 0.5));
    ASSERT_TRUE(smooth);
    EXPECT_NEAR(smooth->T.T_tr[0] / white_noise_steady_state(0.8, -1.0, 0.4, 1, 1, 1, 1.0, 0.5).T_tr, 1.0, 1e-12);
    EXPECT_TRUE(std::isinf(smooth->T.T_rot[0]));
}

TEST(DrivenSteadyState, MixtureUnderWhiteNoise) {
    // Two identical species are one: the mixture's steady state is the closed form of one species.
    const HcsTheory twins({{1.0, 0.5, 0.4, 0.3}, {1.0, 0.5, 0.4, 0.7}}, {{0.8, 0.2}, {0.8, 0.2}, {0.8, 0.2}}, 1.3);
    const std::optional<DrivenSteadyState> s = driven_steady_state(twins, white_noise_thermostat(2, constant_drive(0.5)));
    ASSERT_TRUE(s);
    const EqualSphereSteadyState c = white_noise_steady_state(0.8, 0.2, 0.4, 1.0, 1.0, 1.3, 0.5);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(s->T.T_tr[k] / c.T_tr, 1.0, 1e-12);
        EXPECT_NEAR(s->T.T_rot[k] / c.T_rot, 1.0, 1e-12);
    }
    // Unequal grains: no equipartition, but every species' equations balance (the heavier grain,
    // fed m xi^2, is hotter).
    const HcsTheory mix = mixture();
    const ThermostatSpec wn = white_noise_thermostat(2, constant_drive(0.5));
    const std::optional<DrivenSteadyState> u = driven_steady_state(mix, wn);
    ASSERT_TRUE(u);
    EXPECT_GT(u->T.T_tr[1] / u->T.T_tr[0], 1.5);
    std::vector<double> dT(2), dR(2);
    driven_rates(mix, wn, 0.0, u->T.T_tr, u->T.T_rot, dT, dR);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(dT[k] / (mix.species()[k].mass * 0.5), 0.0, 1e-12);
        EXPECT_NEAR(dR[k] / (mix.species()[k].mass * 0.5), 0.0, 1e-12);
    }
    EXPECT_NEAR(0.3 * u->T_tr_ratio[0] + 0.7 * u->T_tr_ratio[1], 1.0, 1e-14);
    // The same state as the end of a trajectory from elsewhere, for white noise and for a bath with
    // different frictions per species (some 10^3 collision times: relaxed to round-off).
    ThermostatSpec bath = langevin_thermostat(2, constant_drive(1.2), 0.3, 0.1);
    bath.species[1].friction = 0.05;
    bath.species[1].rotational_friction = 0.0;
    for (const ThermostatSpec& th : {wn, bath}) {
        const std::optional<DrivenSteadyState> ss = driven_steady_state(mix, th);
        ASSERT_TRUE(ss);
        HcsTrajectory tr(mix, {{3.0, 0.2}, {0.1, 4.0}}, th);
        const HcsTemperatures T = tr.at(1e3 / collision_frequency(mix, ss->T));
        for (std::size_t k = 0; k < 2; ++k) {
            EXPECT_NEAR(T.T_tr[k] / ss->T.T_tr[k], 1.0, 1e-8) << k;
            EXPECT_NEAR(T.T_rot[k] / ss->T.T_rot[k], 1.0, 1e-8) << k;
        }
    }
}

TEST(DrivenSteadyState, MaxwellKernelSteadyStateSolvesItsLinearSystem) {
    // dT/dt = M T + b with M = (2 nu/3) [[-A', 2B], [2B, -2C]] (driven_theory_test.cpp): T* = -M^{-1} b.
    const double alpha = 0.8, beta = 0.3, q = 0.4, m = 1.3, R = 0.6, n = 0.9, T0 = 1.7;
    const HcsTheory th({{m, R, q, 1.0}}, {{alpha, beta}}, n, {T0});
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, m, 2 * R, n);
    const double k = 2 * 4 * n * 4 * R * R * std::sqrt(std::numbers::pi * T0 / m) / 3;
    const double m11 = -k * ((1 - alpha * alpha) / 4 + 2 * c.eta * (1 - c.eta)), m12 = 2 * k * c.B,
                 m22 = -2 * k * c.C;
    const double xi2 = 0.8, eps = 0.3, b1 = (1 - eps) * m * xi2, b2 = eps * m * xi2;
    const double det = m11 * m22 - m12 * m12;
    const std::optional<DrivenSteadyState> s =
        driven_steady_state(th, white_noise_thermostat(1, constant_drive(xi2), eps));
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->T.T_tr[0] / (-(m22 * b1 - m12 * b2) / det), 1.0, 1e-12);
    EXPECT_NEAR(s->T.T_rot[0] / (-(m11 * b2 - m12 * b1) / det), 1.0, 1e-12);
}

} // namespace
} // namespace roughgas
