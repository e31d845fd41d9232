#pragma once
// The Maxwellian two-temperature theory of a DRIVEN homogeneous gas: the cooling equations of
// observables/theory.hpp (HcsTheory::rates, hard spheres or the Maxwell kernel, one species or a
// mixture) plus the energy a thermostat (dsmc/run_spec.hpp ThermostatSpec) feeds each species s of
// mass m_s:
//
//   white noise, strength xi_s^2 = drive_s(t), rotational share eps_s:
//     dT_tr,s/dt = (collisions) + (1 - eps_s) m_s xi_s^2,    dT_rot,s/dt = (collisions) + eps_s m_s xi_s^2
//   (each velocity component kicked by a Gaussian of variance (1 - eps) xi^2 dt gives
//   (1/2) m <|dv|^2> = (3/2)(1 - eps) m xi^2 dt per grain, i.e. dT_tr = (1 - eps) m xi^2 dt with
//   T_tr = (1/3) m <c^2>; the torque kicks of omega, variance eps m xi^2 dt/I, give dT_rot likewise);
//
//   Langevin bath at T_b,s = drive_s(t), frictions gamma_s, gamma_rot,s:
//     dT_tr,s/dt = (collisions) + 2 gamma_s (T_b,s - T_tr,s),   dT_rot,s/dt = (collisions) + 2 gamma_rot,s (T_b,s - T_rot,s)
//   (dv = -gamma v dt + sqrt(2 gamma T_b/m) dW: d<v^2>/dt = -2 gamma <v^2> + 6 gamma T_b/m).
//
// The sources are those of the thermostat's own equations, exact for any velocity distribution;
// only the collision terms carry the Maxwellian approximation (for the Maxwell kernel none: the
// driven equations are then linear and exact, dT/dt = M T + b(t), with M the kernel's constant
// matrix less 2 diag(gamma) for a bath, and b the white noise's m xi^2 or the bath's 2 gamma T_b).
// In every case the thermostat's kicks are independent of the collisions, so the two add.
//
// References: van Noije & Ernst, Granular Matter 1, 57 (1998) and Montanero & Santos, Granular
// Matter 2, 53 (2000) (white noise, smooth spheres); Vega Reyes & Santos (2015) (white noise on
// rough spheres); Torrente, Lopez-Castano, Lasanta, Vega Reyes, Prados & Santos (2019) (the
// two-temperature equations of rough spheres under white noise and their Mpemba effect).
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/theory.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace roughgas {

// Throws std::invalid_argument unless `thermostat` has one entry per species and every schedule
// starts at t = 0 with increasing times, one finite value >= 0 per time; eps in [0, 1]; frictions
// finite and >= 0.
void check_thermostat(const ThermostatSpec& thermostat, std::size_t species);

// Adds the thermostat's sources at time t (above) to dT_tr and dT_rot.
void add_thermostat_sources(const ThermostatSpec& thermostat, std::span<const HcsSpecies> species, double t,
                            std::span<const double> T_tr, std::span<const double> T_rot, std::span<double> dT_tr,
                            std::span<double> dT_rot);

// The driven equations' right-hand side: HcsTheory::rates plus the sources at time t.
void driven_rates(const HcsTheory& theory, const ThermostatSpec& thermostat, double t, std::span<const double> T_tr,
                  std::span<const double> T_rot, std::span<double> dT_tr, std::span<double> dT_rot);

// The times > 0 at which some species' drive switches, increasing, each once: between two of them
// the driven equations are smooth and are integrated in one piece (HcsTrajectory).
std::vector<double> drive_switch_times(const ThermostatSpec& thermostat);

// The same thermostat with every drive held at its last value (the state the schedule ends in).
ThermostatSpec final_drive(ThermostatSpec thermostat);

// One drive for all `species`: white noise of strength xi0^2 = `strength` and share eps, or a
// Langevin bath at `bath` with frictions gamma, gamma_rot.
ThermostatSpec white_noise_thermostat(std::size_t species, DriveSchedule strength, double rotational_share = 0);
ThermostatSpec langevin_thermostat(std::size_t species, DriveSchedule bath, double friction,
                                   double rotational_friction);
inline DriveSchedule constant_drive(double value) {
    return DriveSchedule{{0.0}, {value}};
}

} // namespace roughgas
