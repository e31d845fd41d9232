#pragma once
// The grains and thermostats of the driven-gas tests (thermostat_test.cpp, spatial_thermostat_test.cpp).
#include "roughgas/dsmc/run_spec.hpp"

#include <cstddef>

namespace roughgas::test {

inline SpeciesSpec grain(double T = 1, double T_rot = 1, double mass = 1) {
    SpeciesSpec s; // R = 0.5 (sigma = 1), q = 0.4
    s.mass = mass;
    s.temperature = T;
    s.rotational_temperature = T_rot;
    return s;
}

inline ThermostatSpec white_noise(double strength, double share, std::size_t species = 1, bool exact = false) {
    ThermostatSpec t;
    t.kind = ThermostatKind::white_noise;
    t.exact_energy = exact;
    SpeciesThermostat s;
    s.drive.value = {strength};
    s.rotational_share = share;
    t.species.assign(species, s);
    return t;
}

inline ThermostatSpec langevin(double T_b, double gamma, double gamma_rot, std::size_t species = 1) {
    ThermostatSpec t;
    t.kind = ThermostatKind::langevin;
    SpeciesThermostat s;
    s.drive.value = {T_b};
    s.friction = gamma;
    s.rotational_friction = gamma_rot;
    t.species.assign(species, s);
    return t;
}

} // namespace roughgas::test
