#pragma once
// [restitution]: the grid of impact speeds that `roughgas restitution` tabulates; each range must
// not be reversed.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"
#include "toml_access.hpp"

namespace roughgas::case_file {

RestitutionGridConfig build_restitution_grid(const Reader& r);
void check_restitution_grid(BuildContext& ctx, const RestitutionGridConfig& g);
void emit_restitution_grid(Emitter& e, const RestitutionGridConfig& g);

} // namespace roughgas::case_file
