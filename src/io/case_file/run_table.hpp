#pragma once
// [run]: what to simulate and for how long. Its checks are of run.kernel and run.end against the
// species and their collision rules: the Maxwell kernel's constant restitution, and how far a
// cooling gas can go before its temperature underflows.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"
#include "toml_access.hpp"

namespace roughgas::case_file {

RunConfig build_run(const Reader& r);
void check_run(BuildContext& ctx, const CaseConfig& c);
void note_unused_enskog(const toml::table& root, CaseConfig& c);
void emit_run(Emitter& e, const RunConfig& r);

} // namespace roughgas::case_file
