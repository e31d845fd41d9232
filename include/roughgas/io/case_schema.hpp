#pragma once
// The one list of case-file keys: type, unit, default, allowed values, description.
// The parser validates against it, docs/reference.md's key table is generated from it
// (`roughgas keys`), and tests/io/reference_test.cpp checks that the two agree.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace roughgas {

// real3, integer3, string3: an array of three (one per axis x, y, z), each element within the
// key's bounds or choices; a string default applies to every element.
// string_list: an array of distinct strings, at least one, each one of the key's choices; the
// default is the elements separated by spaces.
// real_pairs: an array of [real, real] pairs, at least one, each element within the key's bounds.
enum class KeyType {
    boolean, integer, real, string, string_pair, real3, integer3, string3, string_list, real_pairs
};

// How a missing key is resolved.
enum class Need {
    defaulted,   // takes `default_value`
    required,    // always required (within its table)
    conditional, // required or resolved depending on other keys: `note` says how (checked by the parser)
    optional     // may stay unset
};

enum class Bound { none, open, closed };

struct Limit {
    Bound bound = Bound::none;
    double value = 0;
    std::string text; // how to print `value` ("" = shortest round-trip form), e.g. "2/3"
};

using KeyDefault = std::variant<std::monostate, bool, std::int64_t, double, std::string>;

struct KeySpec {
    std::string path; // "material.young_modulus"; keys of [[species]] are "species.radius"
    KeyType type = KeyType::real;
    std::string unit; // "" for dimensionless
    Need need = Need::defaulted;
    KeyDefault default_value;
    std::string note; // Need::conditional: when the key is required, or where its value comes from
    Limit lower, upper;
    std::vector<std::string> choices; // allowed strings (empty: any)
    std::string description;
    std::string range_reason; // what the value measures and why its range, told with a value outside it

    std::string_view table() const; // "material"
    std::string_view name() const;  // "young_modulus"
    // "> 0", "in (-1, 0.5)", "one of \"eq24\", \"eq25\"" or "" (anything of the right type).
    std::string allowed() const;
    std::string default_text() const; // "1.0", "\"cooling\"", "required", the note, or "unset"
    std::vector<std::string> default_list() const; // a string_list's default: its elements
    // "real", "integer", "boolean", "string", "[string, string]", "[real, real, real]", "[[real, real], ...]", ...
    std::string type_name() const;
    bool allows(double x) const;      // within [lower, upper]
    bool allows(std::string_view s) const;
};

struct TableSpec {
    std::string name;        // "species"
    bool array = false;      // [[species]] rather than [species]
    std::string requirement; // "required", "required for ...", or "optional"
    std::string description;
};

const std::vector<TableSpec>& case_tables();
const std::vector<KeySpec>& case_schema();
const TableSpec* find_table(std::string_view name);
const KeySpec* find_key(std::string_view path); // schema path, without array indices

// Markdown table (one row per key, schema order) for the case-file keys of docs/reference.md.
// A table cell of the generated Markdown: '|' escaped, which would split the cell.
std::string markdown_cell(std::string s);

std::string case_keys_markdown();
// Markdown table of the case file's tables.
std::string case_tables_markdown();

// Shortest text that reads back as the same double and as a TOML float (1.0, not 1).
std::string toml_real(double x);

} // namespace roughgas
