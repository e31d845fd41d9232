#pragma once
// The wording the case-file messages share: how a value, a key's expectation, a table and a list
// are written, so that the schema pass and the cross-key checks describe keys the same way.
#include "roughgas/io/case_schema.hpp"

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas::case_file {

// A TOML basic string, escaped: as the "allowed" lists print strings and as emit_case writes them.
std::string quote(std::string_view s);

// A value as the user wrote it ("1e10", "\"eq26\"", "[ 0, 1 ]").
std::string value_text(const toml::node& n);

std::string unit_suffix(const KeySpec& s); // " (Pa)", or "" for a dimensionless key
std::string type_phrase(KeyType t);        // "a real number", "an array of three integers", ...

// "a real number > 0 (Pa)", "one of \"eq24\", \"eq25\"": what a key accepts, for messages.
std::string expectation(const KeySpec& s);

std::vector<std::string> key_names(std::string_view table); // the schema's keys of a table, in order
std::string table_header(const TableSpec& t);               // "[run]", "[[species]]"
std::string join(const std::vector<std::string>& v);        // "a, b, c"

// A key of this name in another table: the user put a right key in the wrong place.
std::optional<std::string> misplaced(std::string_view name, std::string_view table);

} // namespace roughgas::case_file
