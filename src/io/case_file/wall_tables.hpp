#pragma once
// [wall_lower], [wall_upper] and each axis's own [wall_lower_x] ... [wall_upper_z]: the flat walls
// of the axes whose domain.boundary is "walls" (io/case_config.hpp's wall_tables() lists them).
// Their checks: every walled axis has a wall at 0 and at L, a diffuse wall its temperature, and a
// wall moves along itself only.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <toml++/toml.h>

namespace roughgas::case_file {

void build_walls(const toml::table& root, CaseConfig& c);
// With [domain] (built first).
void check_walls(BuildContext& ctx, const CaseConfig& c);
// Wall tables of no walled axis, and keys their kind does not read: warnings (CaseConfig::unused).
void note_unused_walls(const toml::table& root, CaseConfig& c);
void emit_walls(Emitter& e, const CaseConfig& c);

} // namespace roughgas::case_file
