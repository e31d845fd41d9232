#pragma once
// [fields]: the fields of every collision cell written at output rows, which need [domain] and can
// come from at most the run's replicas.
#include "build_context.hpp"
#include "emitter.hpp"
#include "roughgas/io/case_config.hpp"

#include <toml++/toml.h>

#include <optional>

namespace roughgas::case_file {

std::optional<FieldsConfig> build_fields(const toml::table& root); // unset without [fields]
void check_fields(BuildContext& ctx, const CaseConfig& c);
void emit_fields(Emitter& e, const FieldsConfig& f);

} // namespace roughgas::case_file
