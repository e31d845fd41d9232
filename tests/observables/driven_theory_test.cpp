// The driven two-temperature equations (observables/driven_theory.hpp) and their trajectory
// (HcsTrajectory with a thermostat): the Maxwell kernel's exact linear solution, the schedule's pieces,
// an idle thermostat.
#include "roughgas/observables/driven_theory.hpp"
#include "roughgas/observables/theory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace roughgas {
namespace {

HcsTheory one_species(double alpha, double beta, double q = 0.4, double m = 1.0, double R = 0.5, double n = 1.0) {
    return HcsTheory({{m, R, q, 1.0}}, {{alpha, beta}}, n);
}

// The exact solution T(t) = T* + exp(M t)(T0 - T*), T* = -M^{-1} b, of dT/dt = M T + b for a symmetric
// 2 x 2 M (by its eigenvectors).
std::vector<double> linear_solution(double m11, double m12, double m22, double b1, double b2, double x1, double x2,
                                    double t) {
    const double det = m11 * m22 - m12 * m12;
    const double s1 = -(m22 * b1 - m12 * b2) / det, s2 = -(-m12 * b1 + m11 * b2) / det;
    const double mean = 0.5 * (m11 + m22), half = 0.5 * (m11 - m22), r = std::hypot(half, m12);
    double y1 = x1 - s1, y2 = x2 - s2, out1 = s1, out2 = s2;
    for (double sign : {1.0, -1.0}) {
        const double lambda = mean + sign * r;
        // eigenvector (m12, lambda - m11), or (lambda - m22, m12): the better conditioned one
        double v1 = m12, v2 = lambda - m11;
        if (std::hypot(v1, v2) < 1e-300 || std::abs(lambda - m22) > std::abs(lambda - m11)) {
            v1 = lambda - m22;
            v2 = m12;
        }
        const double norm = std::hypot(v1, v2);
        v1 /= norm;
        v2 /= norm;
        const double c = (v1 * y1 + v2 * y2) * std::exp(lambda * t);
        out1 += c * v1;
        out2 += c * v2;
    }
    return {out1, out2};
}

// The same through a white-noise schedule (strength m xi^2 = value, eps = 0): piece by piece.
std::vector<double> chained_linear_solution(double m11, double m12, double m22, const DriveSchedule& drive, double x1,
                                            double x2, double t) {
    std::vector<double> x{x1, x2};
    double from = 0;
    for (std::size_t p = 0; p < drive.t.size() && (p == 0 || drive.t[p] < t); ++p) {
        const double to = p + 1 < drive.t.size() ? std::min(t, drive.t[p + 1]) : t;
        x = linear_solution(m11, m12, m22, drive.value[p], 0.0, x[0], x[1], to - from);
        from = to;
    }
    return x;
}

TEST(DrivenTheory, MaxwellKernelFollowsItsLinearSolution) {
    // Equal spheres with the Maxwell kernel at T0: nu = 4 n sigma^2 sqrt(pi T0/m) and, per collision,
    // <dE_tr> = -A' T_tr + 2B T_rot, <dE_rot> = 2B T_tr - 2C T_rot (A' = (1 - alpha^2)/4 + 2 eta (1 - eta);
    // theory.hpp's Maxwell averages with s = 2T/m), so dT/dt = M T + b with
    // M = (2 nu/3) [[-A', 2B], [2B, -2C]] less 2 diag(gamma, gamma_rot) for a bath.
    const double alpha = 0.8, beta = 0.3, q = 0.4, m = 1.3, R = 0.6, n = 0.9, T0 = 1.7, Tr0 = 0.2;
    const HcsTheory th({{m, R, q, 1.0}}, {{alpha, beta}}, n, {T0});
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, m, 2 * R, n);
    const double nu = 4 * n * 4 * R * R * std::sqrt(std::numbers::pi * T0 / m);
    const double A1 = (1 - alpha * alpha) / 4 + 2 * c.eta * (1 - c.eta);
    const double k = 2 * nu / 3;
    const double xi2 = 0.8, eps = 0.3, Tb = 2.5, g = 0.35, gr = 0.15;
    HcsTrajectory white(th, {{T0}, {Tr0}}, white_noise_thermostat(1, constant_drive(xi2), eps));
    HcsTrajectory bath(th, {{T0}, {Tr0}}, langevin_thermostat(1, constant_drive(Tb), g, gr));
    for (double t : {0.01, 0.3, 1.0, 4.0, 30.0}) {
        const std::vector<double> w =
            linear_solution(-k * A1, 2 * k * c.B, -2 * k * c.C, (1 - eps) * m * xi2, eps * m * xi2, T0, Tr0, t);
        const HcsTemperatures Tw = white.at(t);
        EXPECT_NEAR(Tw.T_tr[0] / w[0], 1.0, 1e-9) << t;
        EXPECT_NEAR(Tw.T_rot[0] / w[1], 1.0, 1e-9) << t;
        const std::vector<double> l =
            linear_solution(-k * A1 - 2 * g, 2 * k * c.B, -2 * k * c.C - 2 * gr, 2 * g * Tb, 2 * gr * Tb, T0, Tr0, t);
        const HcsTemperatures Tl = bath.at(t);
        EXPECT_NEAR(Tl.T_tr[0] / l[0], 1.0, 1e-9) << t;
        EXPECT_NEAR(Tl.T_rot[0] / l[1], 1.0, 1e-9) << t;
    }
}

TEST(DrivenTheory, ScheduleIsIntegratedPieceByPiece) {
    // Maxwell kernel, white noise switched 2 -> 0 (free cooling) -> 0.5 at t = 0.7 and 1.9: the exact
    // solution chained across the switches.
    const double alpha = 0.7, beta = 0.0, q = 0.4, T0 = 1.0, Tr0 = 0.5;
    const HcsTheory th({{1.0, 0.5, q, 1.0}}, {{alpha, beta}}, 1.0, {T0});
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, 1.0, 1.0, 1.0);
    const double k = 2 * 4 * std::sqrt(std::numbers::pi * T0) / 3;
    const double m11 = -k * ((1 - alpha * alpha) / 4 + 2 * c.eta * (1 - c.eta)), m12 = 2 * k * c.B,
                 m22 = -2 * k * c.C;
    const DriveSchedule drive{{0.0, 0.7, 1.9}, {2.0, 0.0, 0.5}};
    HcsTrajectory tr(th, {{T0}, {Tr0}}, white_noise_thermostat(1, drive));
    EXPECT_EQ(drive_switch_times(white_noise_thermostat(1, drive)), (std::vector<double>{0.7, 1.9}));
    const auto exact = [&](double t) { return chained_linear_solution(m11, m12, m22, drive, T0, Tr0, t); };
    for (double t : {0.5, 0.7, 1.2, 1.9, 2.0, 5.0}) { // on and across both switches
        const std::vector<double> x = exact(t);
        const HcsTemperatures T = tr.at(t);
        EXPECT_NEAR(T.T_tr[0] / x[0], 1.0, 1e-9) << t;
        EXPECT_NEAR(T.T_rot[0] / x[1], 1.0, 1e-9) << t;
    }
    // One call across both switches gives the same as the calls above.
    HcsTrajectory once(th, {{T0}, {Tr0}}, white_noise_thermostat(1, drive));
    EXPECT_NEAR(once.at(5.0).T_tr[0] / exact(5.0)[0], 1.0, 1e-9);
    // A pulse much shorter than the steps the free cooling around it allows: an integration that did
    // not stop at the switches would step over it, or part of it, unseen (the error control catches
    // an ordinary jump, not one no stage lands in); it adds 5e-3 to T_tr (m = 1).
    const DriveSchedule pulse{{0.0, 1.0, 1.001}, {0.0, 5.0, 0.0}};
    HcsTrajectory kicked(th, {{T0}, {Tr0}}, white_noise_thermostat(1, pulse));
    const std::vector<double> after = chained_linear_solution(m11, m12, m22, pulse, T0, Tr0, 3.0);
    EXPECT_NEAR(kicked.at(3.0).T_tr[0] / after[0], 1.0, 1e-9);
    // Hard spheres: the scheduled trajectory equals one restarted at the switch from its state there.
    const HcsTheory hs = one_species(alpha, beta);
    const DriveSchedule bath{{0.0, 0.4}, {3.0, 0.5}};
    HcsTrajectory a(hs, {{1.0}, {0.2}}, langevin_thermostat(1, bath, 0.5, 0.2));
    HcsTrajectory first(hs, {{1.0}, {0.2}}, langevin_thermostat(1, constant_drive(3.0), 0.5, 0.2));
    const HcsTemperatures mid = first.at(0.4);
    HcsTrajectory second(hs, mid, langevin_thermostat(1, constant_drive(0.5), 0.5, 0.2));
    for (double t : {0.4, 0.9, 3.0}) {
        const HcsTemperatures x = a.at(t), y = second.at(t - 0.4);
        EXPECT_NEAR(x.T_tr[0] / y.T_tr[0], 1.0, 1e-9) << t;
        EXPECT_NEAR(x.T_rot[0] / y.T_rot[0], 1.0, 1e-9) << t;
    }
}

TEST(DrivenTheory, CoolingIsUnchangedByAnIdleThermostat) {
    // A thermostat of strength 0 (or a bath without friction) leaves the cooling trajectory.
    // A mixture of unequal grains, a different (alpha, beta) per pair.
    const HcsTheory th({{1.0, 0.5, 0.4, 0.4}, {2.5, 0.7, 0.3, 0.6}}, {{0.8, 0.3}, {0.9, 0.1}, {0.7, -0.2}}, 1.5);
    const HcsTemperatures T0{{1.0, 2.0}, {0.5, 0.1}};
    HcsTrajectory cool(th, T0), idle(th, T0, white_noise_thermostat(2, constant_drive(0.0)));
    for (double t : {0.1, 3.0, 1e3}) {
        const HcsTemperatures a = cool.at(t), b = idle.at(t);
        for (std::size_t s = 0; s < 2; ++s) {
            EXPECT_NEAR(b.T_tr[s] / a.T_tr[s], 1.0, 1e-8) << t;
            EXPECT_NEAR(b.T_rot[s] / a.T_rot[s], 1.0, 1e-8) << t;
        }
    }
}

} // namespace
} // namespace roughgas
