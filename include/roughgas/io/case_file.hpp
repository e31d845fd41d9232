#pragma once
// Case files: TOML text -> validated CaseConfig (toml++ stays inside src/io/case_file.cpp and src/io/case_file/).
//
// Order of work: parse the TOML, apply `--set KEY=VALUE` overrides, validate everything against
// io/case_schema.hpp and the cross-key rules, and only then return; any problem throws
// InputError listing every issue found (file:line:column: key = value: what is allowed).
#include "roughgas/io/case_config.hpp"
#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/input_error.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace roughgas {

// What the case must be complete for. `run` is what `roughgas check` validates.
enum class CaseUse {
    run,        // a simulation: the collision model decides what [material] must hold
    restitution // `roughgas restitution`: also needs [material] with friction and asperity
};

// `overrides` are "KEY=VALUE" strings as given to --set: KEY is a dotted path ("collision.alpha",
// "species.0.radius" for the first [[species]]), VALUE a TOML value; a bare word is a string
// ("collision.model=brilliantov"). Array tables may grow by one: "species.1.name=b" adds a second
// [[species]] when there was one.
// `file` names the source in messages; it is not read.
CaseConfig parse_case(std::string_view toml_text, const std::string& file,
                      const std::vector<std::string>& overrides = {}, CaseUse use = CaseUse::run);

// Reads `file` (the path as the user wrote it, kept for messages) and parses it.
CaseConfig load_case(const std::string& file, const std::vector<std::string>& overrides = {},
                     CaseUse use = CaseUse::run);

// The resolved case (every default filled in) as TOML: parse_case(emit_case(c), ...) == c.
std::string emit_case(const CaseConfig& cfg);

// The schema entry (io/case_schema.hpp) of a key as --set names it ("species.1.mass": array indices
// left out); nullptr for a key the schema does not have.
const KeySpec* find_key_of(const std::string& key);

} // namespace roughgas
