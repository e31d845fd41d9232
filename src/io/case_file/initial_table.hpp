#pragma once
// [initial]: how a run starts: from a saved state (any run), and a box's wave on its start.
// Its checks: a saved state needs a kernel that takes its temperatures from the grains; a wave
// (initial.mode) needs [domain], a wave number other than 0 and a wavelength of at least two cells.
// initial.amplitude and initial.wave only shape a wave: without one (a homogeneous run) they are not
// read, and the resolved case always holds them.
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
