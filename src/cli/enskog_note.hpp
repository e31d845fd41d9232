#pragma once
// What `roughgas check` says of a run of the Enskog equation: its solid fraction, its pair
// correlations at contact and what they do to the rates and the pressure.
#include "roughgas/dsmc/run_spec.hpp"

#include <optional>
#include <string>

namespace roughgas::cli {

// For run.equation = "enskog": phi, chi (each pair's for a mixture), and for one species with a
// constant alpha the homogeneous gas's p/(n T_tr) = 1 + 2 (1 + alpha) phi chi; nothing for other runs.
std::optional<std::string> enskog_note(const RunSpec& spec);

} // namespace roughgas::cli
