// The driven two-temperature equations: the sources of observables/driven_theory.hpp.
#include "roughgas/observables/driven_theory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace roughgas {
namespace {

void require(bool ok, const std::string& what) {
    if (!ok)
        throw std::invalid_argument("thermostat theory: " + what);
}

bool finite_non_negative(double x) {
    return std::isfinite(x) && x >= 0;
}

} // namespace

void check_thermostat(const ThermostatSpec& thermostat, std::size_t species) {
    require(thermostat.species.size() == species, "one thermostat entry per species needed");
    for (const SpeciesThermostat& s : thermostat.species) {
        const DriveSchedule& d = s.drive;
        require(!d.t.empty() && d.t.size() == d.value.size() && d.t[0] == 0,
                "a drive schedule needs t[0] = 0 and one value per time");
        for (std::size_t k = 0; k < d.t.size(); ++k) {
            require(k == 0 || (std::isfinite(d.t[k]) && d.t[k] > d.t[k - 1]), "drive times must increase");
            require(finite_non_negative(d.value[k]), "drive values must be finite and >= 0");
        }
        require(s.rotational_share >= 0 && s.rotational_share <= 1, "the rotational share must be in [0, 1]");
        require(finite_non_negative(s.friction) && finite_non_negative(s.rotational_friction),
                "frictions must be finite and >= 0");
    }
}

void add_thermostat_sources(const ThermostatSpec& thermostat, std::span<const HcsSpecies> species, double t,
                            std::span<const double> T_tr, std::span<const double> T_rot, std::span<double> dT_tr,
                            std::span<double> dT_rot) {
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesThermostat& th = thermostat.species[s];
        const double drive = th.drive.at(t);
        if (thermostat.kind == ThermostatKind::white_noise) {
            const double power = species[s].mass * drive; // m xi^2: dT/dt of the kicks (run_spec.hpp)
            dT_tr[s] += (1 - th.rotational_share) * power;
            dT_rot[s] += th.rotational_share * power;
        } else {
            dT_tr[s] += 2 * th.friction * (drive - T_tr[s]);
            dT_rot[s] += 2 * th.rotational_friction * (drive - T_rot[s]);
        }
    }
}

void driven_rates(const HcsTheory& theory, const ThermostatSpec& thermostat, double t, std::span<const double> T_tr,
                  std::span<const double> T_rot, std::span<double> dT_tr, std::span<double> dT_rot) {
    theory.rates(T_tr, T_rot, dT_tr, dT_rot);
    add_thermostat_sources(thermostat, theory.species(), t, T_tr, T_rot, dT_tr, dT_rot);
}

std::vector<double> drive_switch_times(const ThermostatSpec& thermostat) {
    std::vector<double> t;
    for (const SpeciesThermostat& s : thermostat.species)
        for (std::size_t k = 1; k < s.drive.t.size(); ++k)
            t.push_back(s.drive.t[k]);
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    return t;
}

ThermostatSpec final_drive(ThermostatSpec thermostat) {
    for (SpeciesThermostat& s : thermostat.species)
        s.drive = constant_drive(s.drive.value.back());
    return thermostat;
}

ThermostatSpec white_noise_thermostat(std::size_t species, DriveSchedule strength, double rotational_share) {
    ThermostatSpec th;
    th.kind = ThermostatKind::white_noise;
    th.species.assign(species, SpeciesThermostat{std::move(strength), rotational_share, 0.0, 0.0});
    return th;
}

ThermostatSpec langevin_thermostat(std::size_t species, DriveSchedule bath, double friction,
                                   double rotational_friction) {
    ThermostatSpec th;
    th.kind = ThermostatKind::langevin;
    th.species.assign(species, SpeciesThermostat{std::move(bath), 0.0, friction, rotational_friction});
    return th;
}

} // namespace roughgas
