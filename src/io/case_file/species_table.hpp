#pragma once
// [[species]]: one table per species of grains. Its checks: names unique, fractions summing to 1,
// and at least one simulated particle of each species.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"
#include "toml_access.hpp"

#include <vector>

namespace roughgas::case_file {

SpeciesConfig build_species(BuildContext& ctx, const Reader& r);
void check_species(BuildContext& ctx, const CaseConfig& c);
void emit_species(Emitter& e, const std::vector<SpeciesConfig>& species);

} // namespace roughgas::case_file
