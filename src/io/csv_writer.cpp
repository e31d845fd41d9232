#include "roughgas/io/csv_writer.hpp"

#include "roughgas/io/atomic_file.hpp"

#include <fmt/format.h>

#include <iterator>
#include <stdexcept>
#include <string_view>

namespace roughgas {
namespace {

void comment(std::string& out, std::string_view line) {
    out += line.empty() ? "#\n" : fmt::format("# {}\n", line);
}

// Echoes a multi-line text (the resolved case) as '#' lines.
void comment_block(std::string& out, std::string_view text) {
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        comment(out, text.substr(0, nl));
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    }
}

} // namespace

std::string roughgas_version() {
#ifdef ROUGHGAS_VERSION
    return ROUGHGAS_VERSION;
#else
    return "unknown";
#endif
}

std::string build_info() {
    std::string s;
#if defined(__clang__)
    s = fmt::format("clang {}.{}.{}", __clang_major__, __clang_minor__, __clang_patchlevel__);
#elif defined(__GNUC__)
    s = fmt::format("GCC {}.{}.{}", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#else
    s = "unknown compiler";
#endif
#ifdef NDEBUG
    s += ", optimised (NDEBUG)";
#else
    s += ", debug (assertions on)";
#endif
#ifdef _OPENMP
    s += fmt::format(", OpenMP {}", _OPENMP);
#else
    s += ", no OpenMP";
#endif
    return s + fmt::format(", C++ {}", __cplusplus);
}

CsvWriter::CsvWriter(std::vector<std::string> columns, const CsvProvenance& p)
    : columns_(std::move(columns)) {
    comment(text_, "roughgas " + roughgas_version());
    comment(text_, "case: " + p.case_file);
    for (const std::string& o : p.overrides) {
        comment(text_, "set: " + o);
    }
    if (p.seed) {
        comment(text_, fmt::format("seed: {}", *p.seed));
    }
    comment(text_, "build: " + build_info());
    for (const std::string& n : p.notes) {
        comment(text_, n);
    }
    notes_end_ = text_.size();
    if (!p.resolved_case.empty()) {
        comment(text_, "resolved case (every default filled in):");
        comment_block(text_, p.resolved_case);
    }
    if (!p.units.empty()) {
        if (p.units.size() != columns_.size()) {
            throw std::invalid_argument(
                fmt::format("CSV header has {} units for {} columns", p.units.size(), columns_.size()));
        }
        std::string line = "units: ";
        for (std::size_t i = 0; i < p.units.size(); ++i) {
            line += (i ? "," : "") + p.units[i];
        }
        comment(text_, line);
    }
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        text_ += (i ? "," : "") + columns_[i];
    }
    text_ += '\n';
}

void CsvWriter::add_note(const std::string& note) {
    std::string line;
    comment(line, note);
    text_.insert(notes_end_, line);
    notes_end_ += line.size();
}

void CsvWriter::add_row(std::span<const double> values) {
    if (values.size() != columns_.size()) {
        throw std::invalid_argument(
            fmt::format("CSV row has {} values for {} columns", values.size(), columns_.size()));
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i)
            text_ += ',';
        fmt::format_to(std::back_inserter(text_), "{}", values[i]);
    }
    text_ += '\n';
    ++rows_;
}

void CsvWriter::write(const std::filesystem::path& path) const {
    write_file_atomically(path, text_);
}

} // namespace roughgas
