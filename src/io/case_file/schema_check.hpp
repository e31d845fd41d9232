#pragma once
// Pass 1 of a case file: every table and key against the schema (io/case_schema.hpp): unknown names
// (with the nearest known one), wrong types, values out of range, required keys missing.
#include "diagnostics.hpp"

#include <toml++/toml.h>

namespace roughgas::case_file {

void check_schema(const toml::table& root, Diagnostics& d);

} // namespace roughgas::case_file
