// Collecting the case file's issues, each with its position in the file, and throwing them sorted.
#include "diagnostics.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

namespace roughgas::case_file {

void Diagnostics::add(const std::string& key, std::string message, const toml::node* node) {
    std::optional<SourcePosition> where;
    if (overridden(key)) {
        message += " (set with --set)";
    } else if (node != nullptr && node->source().begin) {
        const toml::source_position p = node->source().begin;
        where = SourcePosition{static_cast<int>(p.line), static_cast<int>(p.column)};
    }
    issues_.push_back({file_, key, std::move(message), where});
}

void Diagnostics::throw_if_any() {
    if (issues_.empty())
        return;
    std::stable_sort(issues_.begin(), issues_.end(), [](const InputIssue& a, const InputIssue& b) {
        const auto rank = [](const InputIssue& i) {
            return i.where ? std::pair(i.where->line, i.where->column)
                           : std::pair(std::numeric_limits<int>::max(), 0);
        };
        return rank(a) < rank(b);
    });
    throw InputError(std::move(issues_));
}

// `key`, a key below it, or the table or array it is in ("domain.cells[0]" of --set
// domain.cells=[...]) was given with --set.
bool Diagnostics::overridden(const std::string& key) const {
    return std::any_of(overridden_.begin(), overridden_.end(), [&](const std::string& o) {
        return o == key || o.rfind(key + ".", 0) == 0 || key.rfind(o + ".", 0) == 0 || key.rfind(o + "[", 0) == 0;
    });
}

} // namespace roughgas::case_file
