#pragma once
// [spectra]: Fourier spectra of a box's fields, which need a periodic [domain] that is not sheared.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <toml++/toml.h>

#include <optional>

namespace roughgas::case_file {

std::optional<SpectraConfig> build_spectra(const toml::table& root); // unset without [spectra]
void check_spectra(BuildContext& ctx, const CaseConfig& c);
void emit_spectra(Emitter& e, const SpectraConfig& s);

} // namespace roughgas::case_file
