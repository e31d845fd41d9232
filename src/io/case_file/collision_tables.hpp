#pragma once
// [collision] and [[pair]]: the collision rule of every species pair, a [[pair]] being [collision]
// with the pair's own keys on top. Their checks: the keys each model requires, the pairs' species
// known and each pair set once; they also record which models need [material] (BuildContext).
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"
#include "toml_access.hpp"

#include <toml++/toml.h>

#include <vector>

namespace roughgas::case_file {

CollisionConfig build_collision(const Reader& r);
// `collision`: the [collision] table the pair's keys fall back to (nullptr: none).
PairConfig build_pair(const toml::table& pair, const toml::table* collision);

// [collision], then each [[pair]].
void check_collisions(BuildContext& ctx, const CaseConfig& c);

// Keys a collision model does not read: kept in the case (a --set may switch the model), reported
// as warnings (CaseConfig::unused).
void note_unused_collision_keys(const toml::table& root, CaseConfig& c);

void emit_collision(Emitter& e, const CollisionConfig& collision);
void emit_pairs(Emitter& e, const std::vector<PairConfig>& pairs);

} // namespace roughgas::case_file
