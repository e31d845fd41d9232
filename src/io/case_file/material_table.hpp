#pragma once
// [material]: the grains' material, which the contact models (viscoelastic, brilliantov) and
// `roughgas restitution` integrate. Its checks: the dissipation given or from both viscosities,
// and the table present, with friction and asperity, where a model or the command needs it.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"
#include "toml_access.hpp"

namespace roughgas::case_file {

MaterialConfig build_material(BuildContext& ctx, const Reader& r);
// After check_collisions, which records the models that need the table.
void check_material(BuildContext& ctx, const CaseConfig& c);
// [material] that no model of a run reads: a warning (CaseConfig::unused).
void note_unused_material(const BuildContext& ctx, CaseConfig& c);
void emit_material(Emitter& e, const MaterialConfig& m);

} // namespace roughgas::case_file
