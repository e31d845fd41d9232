#pragma once
// CSV output (docs/reference.md "Output"): '#' lines saying where the numbers came from, one header
// line, then rows at full precision (the shortest decimal that reads back to the same double: 0.8, not
// 0.80000000000000004). Written atomically.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace roughgas {

// What the '#' lines record, so a CSV file can be reproduced from itself.
struct CsvProvenance {
    std::string case_file;              // as the user gave it
    std::vector<std::string> overrides; // the --set arguments
    std::optional<std::uint64_t> seed;
    std::string resolved_case;      // emit_case(cfg): every key with defaults filled in
    std::vector<std::string> notes; // further "# ..." lines, e.g. what the table holds
    // The unit of every column, in column order: written as the last '#' line, right above the
    // header, as "# units: u1,u2,..." (one entry per column, so a reader can zip it with the
    // header). Empty: no such line.
    std::vector<std::string> units;
};

class CsvWriter {
  public:
    CsvWriter(std::vector<std::string> columns, const CsvProvenance& provenance);

    // Throws std::invalid_argument unless there is one value per column (and one unit per column
    // when units are given: in the constructor).
    void add_row(std::span<const double> values);
    void add_row(std::initializer_list<double> values) { add_row(std::span(values.begin(), values.size())); }

    // A '#' line after the provenance notes (e.g. a warning found while the run proceeds).
    void add_note(const std::string& note);

    std::size_t rows() const { return rows_; }
    const std::vector<std::string>& columns() const { return columns_; }
    const std::string& text() const { return text_; }
    // May be called again after more rows: each call replaces the file atomically.
    void write(const std::filesystem::path& path) const;

  private:
    std::vector<std::string> columns_;
    std::string text_;
    std::size_t rows_ = 0;
    std::size_t notes_end_ = 0; // where add_note inserts
};

std::string roughgas_version();
// Compiler, optimisation and OpenMP of this build, for the '#' lines.
std::string build_info();

} // namespace roughgas
