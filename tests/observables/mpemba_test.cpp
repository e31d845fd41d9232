// The Mpemba crossing of the driven two-temperature equations (observables/mpemba.hpp).
#include "roughgas/observables/mpemba.hpp"

#include "roughgas/observables/driven_steady_state.hpp"
#include "roughgas/observables/driven_theory.hpp"
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace roughgas {
namespace {

HcsTheory one_species(double alpha, double beta, double q = 0.4, double m = 1.0, double R = 0.5, double n = 1.0) {
    return HcsTheory({{m, R, q, 1.0}}, {{alpha, beta}}, n);
}

// Rough spheres (alpha = 0.9, beta = -0.3, q = 2/5) under white noise (eps = 0) with the steady state
// at T_tr = 1 (n = 1, sigma = 1, m = 1): xi^2 = G (A - B theta). The hotter sample A starts with
// theta = 0.1, the colder B with theta = 4.
struct MpembaCase {
    HcsTheory theory = one_species(0.9, -0.3);
    ThermostatSpec thermostat;
    HcsTemperatures A{{2.0}, {0.2}}, B{{1.5}, {6.0}};
    MpembaCase() {
        const EqualSphereCoefficients c = equal_sphere_coefficients(0.9, -0.3, 0.4, 1, 1, 1);
        thermostat = white_noise_thermostat(1, constant_drive(c.G * (c.A - c.B * white_noise_steady_theta(0.9, -0.3, 0.4))));
    }
};

TEST(Mpemba, HotterSampleWithLowThetaOvertakesTheColderOne) {
    const MpembaCase mc;
    EXPECT_NEAR(white_noise_steady_state(0.9, -0.3, 0.4, 1, 1, 1, mc.thermostat.species[0].drive.value[0]).T_tr, 1.0,
                1e-14);
    const std::optional<double> t = mpemba_crossing_time(mc.theory, mc.thermostat, mc.A, mc.B, 3.0);
    ASSERT_TRUE(t);
    // scripts/driven_theory_reference.py (scipy's DOP853, rtol 1e-13, and brentq on the same equations):
    // t_c = 0.282396774451, 2.0021 collision times at the steady state's 4 sqrt(pi) collisions per unit time.
    EXPECT_NEAR(*t, 0.282396774451, 1e-8);
    const std::optional<double> again = mpemba_crossing_time(mc.theory, mc.thermostat, mc.A, mc.B, 3.0);
    ASSERT_TRUE(again);
    EXPECT_EQ(*again, *t); // reproducible to the bit
    // The crossing happens: A is hotter just before it and colder after, by 0.148 at its widest
    // (5.25 collision times).
    HcsTrajectory a(mc.theory, mc.A, mc.thermostat), b(mc.theory, mc.B, mc.thermostat);
    EXPECT_GT(a.at(0.99 * *t).T_tr[0], b.at(0.99 * *t).T_tr[0]);
    EXPECT_LT(a.at(1.01 * *t).T_tr[0], b.at(1.01 * *t).T_tr[0]);
    const double late = 5.25 / (4 * std::sqrt(std::numbers::pi));
    EXPECT_NEAR(b.at(late).T_tr[0] - a.at(late).T_tr[0], 0.148, 0.001);
    // Not before t_max, and not at all with the thetas swapped (the hotter sample keeps its lead).
    EXPECT_FALSE(mpemba_crossing_time(mc.theory, mc.thermostat, mc.A, mc.B, 0.9 * *t));
    const HcsTemperatures A2{{2.0}, {6.0}}, B2{{1.5}, {0.2}};
    EXPECT_FALSE(mpemba_crossing_time(mc.theory, mc.thermostat, A2, B2, 10.0));
    EXPECT_THROW(mpemba_crossing_time(mc.theory, mc.thermostat, mc.A, mc.A, 1.0), std::invalid_argument);
}

} // namespace
} // namespace roughgas
