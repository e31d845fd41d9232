#pragma once
// [thermostat] and [[species_thermostat]]: the drive of a homogeneous gas, white noise or a Langevin
// bath, constant or over time (a schedule), with one species' values in place of [thermostat]'s.
// Each kind reads its own keys; the other kind's are refused.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <toml++/toml.h>

#include <optional>
#include <vector>

namespace roughgas::case_file {

std::optional<ThermostatConfig> build_thermostat(const toml::table& root); // unset without [thermostat]
std::vector<SpeciesThermostatConfig> build_species_thermostats(const toml::table& root);
void check_thermostat(BuildContext& ctx, const CaseConfig& c);
// Whether the thermostat of `c` (required) can feed the gas energy: a Langevin bath always exchanges
// it; white noise of strength 0 for every species at all times leaves the gas cooling freely.
bool thermostat_heats(const CaseConfig& c);
void emit_thermostat(Emitter& e, const ThermostatConfig& t);
void emit_species_thermostats(Emitter& e, const std::vector<SpeciesThermostatConfig>& s);

} // namespace roughgas::case_file
