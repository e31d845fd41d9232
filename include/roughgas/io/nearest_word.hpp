#pragma once
// "Did you mean": the candidate nearest to a mistyped word (a case-file key, a table, a value, a
// command-line option).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas {

// Optimal-string-alignment distance: a swapped pair of letters counts as one edit.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The nearest candidate, if it is near enough to be a typo (about one edit per three letters).
std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates);

} // namespace roughgas
