#pragma once
// [shear]: the uniform shear flow of run.kind = "shear", which requires its rate.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <toml++/toml.h>

#include <optional>

namespace roughgas::case_file {

// Unset without [shear] or without shear.rate (which check_shear then asks for).
std::optional<ShearConfig> build_shear(const toml::table& root);
void check_shear(BuildContext& ctx, const CaseConfig& c);
// [shear] with another run.kind: a warning (CaseConfig::unused).
void note_unused_shear(const toml::table& root, CaseConfig& c);
void emit_shear(Emitter& e, const ShearConfig& s);

} // namespace roughgas::case_file
