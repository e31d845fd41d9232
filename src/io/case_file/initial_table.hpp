#pragma once
// [initial]: how a spatially resolved run starts: a wave on the uniform gas, or a saved state.
// Its checks: both need [domain], a saved state a kernel that takes its temperatures from the grains,
// a wave a wave number other than 0 and a wavelength of at least two cells.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <toml++/toml.h>

#include <optional>

namespace roughgas::case_file {

std::optional<InitialConfig> build_initial(const toml::table& root); // unset without [initial]
void check_initial(BuildContext& ctx, const CaseConfig& c);
// With [domain]: each wavelength spans two cells or more.
void check_wave_resolution(BuildContext& ctx, const CaseConfig& c);
void emit_initial(Emitter& e, const InitialConfig& w);

} // namespace roughgas::case_file
