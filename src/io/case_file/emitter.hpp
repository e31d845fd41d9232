#pragma once
// Writes the resolved case as TOML, one "key = value" line at a time under table headers; values
// are written so that they read back as the same values (reals with toml_real, strings escaped).
// Each table's file emits its own keys with it (emit_case.cpp puts the tables in order).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas::case_file {

class Emitter {
  public:
    void header(std::string_view h); // "[run]", "[[species]]": a blank line before all but the first
    void put(std::string_view k, double x);
    void put(std::string_view k, std::int64_t x);
    void put(std::string_view k, std::uint64_t x);
    void put(std::string_view k, bool b);
    void put(std::string_view k, std::string_view s);
    void put(std::string_view k, const std::array<std::string, 2>& p);
    void put(std::string_view k, const std::array<double, 3>& x);
    void put(std::string_view k, const std::array<std::int64_t, 3>& x);
    void put(std::string_view k, const std::vector<std::string>& x);
    void put(std::string_view k, const std::array<std::string, 3>& x);
    void put(std::string_view k, const std::vector<std::array<double, 2>>& x); // [[a, b], [c, d]]
    void put(std::string_view k, const std::optional<double>& x); // nothing for an unset key
    std::string str() const { return text_; }

  private:
    void line(std::string_view k, const std::string& v);
    std::string text_;
};

} // namespace roughgas::case_file
