// Case files with toml++: parse, apply --set, check against the schema (pass 1), then build the
// config and check the rules that involve several keys (pass 2). Each step is in case_file/; each
// pass reports every issue it finds, and the next one runs only on a case the previous one accepted.
#include "roughgas/io/case_file.hpp"

#include "case_file/case_builder.hpp"
#include "case_file/diagnostics.hpp"
#include "case_file/overrides.hpp"
#include "case_file/schema_check.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace roughgas {

CaseConfig parse_case(std::string_view toml_text, const std::string& file,
                      const std::vector<std::string>& overrides, CaseUse use) {
    toml::table root;
    try {
        root = toml::parse(toml_text, std::string_view(file));
    } catch (const toml::parse_error& e) {
        const toml::source_position p = e.source().begin;
        throw InputError(
            file, "", "TOML syntax error: " + std::string(e.description()),
            p ? std::optional(SourcePosition{static_cast<int>(p.line), static_cast<int>(p.column)})
              : std::nullopt);
    }
    case_file::Diagnostics d(file);
    for (const std::string& arg : overrides) {
        case_file::apply_override(root, arg, d);
    }
    case_file::switch_clock(root, overrides);
    d.throw_if_any();
    case_file::check_schema(root, d);
    d.throw_if_any(); // the builder relies on every present value having the right type
    CaseConfig cfg = case_file::build_case(root, use, d);
    d.throw_if_any();
    return cfg;
}

CaseConfig load_case(const std::string& file, const std::vector<std::string>& overrides, CaseUse use) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw InputError(file, "", fmt::format("cannot read the case file ({})", std::strerror(errno)));
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_case(text.str(), file, overrides, use);
}

const KeySpec* find_key_of(const std::string& key) {
    return find_key(case_file::schema_path(case_file::split_path(key)));
}

} // namespace roughgas
