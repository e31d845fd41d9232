#pragma once
// Pass 2 of a case file: CaseConfig built table by table, then the rules that involve several keys
// checked, then what the run will not read noted as warnings. Runs only on a case that passed the
// schema pass (schema_check.hpp): every present value has the right type.
#include "diagnostics.hpp"
#include "roughgas/io/case_file.hpp"

#include <toml++/toml.h>

namespace roughgas::case_file {

CaseConfig build_case(const toml::table& root, CaseUse use, Diagnostics& d);

} // namespace roughgas::case_file
