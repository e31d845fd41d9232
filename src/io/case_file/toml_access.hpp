#pragma once
// Typed access to the parsed TOML: numbers as the schema types them (an integer may be written
// 1e5), the node at a key's display path (for message positions), and Reader, which reads one
// validated table with the schema's defaults for the keys it leaves out.
#include "roughgas/io/case_schema.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas::case_file {

std::optional<double> as_real(const toml::node& n); // an integer reads as a real
// Integers may be written as integral floats (particles = 1e5).
std::optional<std::int64_t> as_integer(const toml::node& n);
bool is_string_pair(const toml::node& n);
bool is_index(std::string_view s); // an array index of a display path ("species.1.name")

// The node at a display path ("species.1.name"), for message positions; nullptr where there is none.
const toml::node* locate(const toml::table& root, std::string_view path);

// Reads keys of one table that the schema pass accepted (every present value has the right type),
// with the schema's defaults for missing ones. A null table reads as all defaults.
class Reader {
  public:
    Reader(const toml::table* t, std::string schema_table) : t_(t), table_(std::move(schema_table)) {}

    bool has(std::string_view k) const { return node(k) != nullptr; }
    double real(std::string_view k) const;
    std::optional<double> opt_real(std::string_view k) const;
    std::int64_t integer(std::string_view k) const;
    bool boolean(std::string_view k) const;
    std::string string(std::string_view k) const;
    std::array<double, 3> real3(std::string_view k) const;
    std::array<std::int64_t, 3> integer3(std::string_view k) const;
    std::array<std::string, 3> string3(std::string_view k) const;
    std::vector<std::string> strings(std::string_view k) const;
    std::vector<std::array<double, 2>> real_pairs(std::string_view k) const; // empty when missing
    // The enumerator whose name (`names`, in enumerator order) the key holds.
    template <class E, std::size_t N>
    E choice(std::string_view k, const std::array<std::string_view, N>& names) const {
        const std::string s = string(k);
        return static_cast<E>(std::find(names.begin(), names.end(), s) - names.begin());
    }

  private:
    const toml::node* node(std::string_view k) const { return t_ ? t_->get(k) : nullptr; }
    const KeySpec& spec(std::string_view k) const;

    const toml::table* t_;
    std::string table_;
};

} // namespace roughgas::case_file
