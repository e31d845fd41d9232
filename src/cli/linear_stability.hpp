#pragma once
// What `roughgas check` says of a cooling box's linear stability (observables/shear_mode.hpp).
#include "roughgas/dsmc/run_spec.hpp"

#include <optional>
#include <string>

namespace roughgas::cli {

// For a cooling box without walls or gravity: the shear mode's critical length against the box's
// longest side (grains of one species with constant alpha and beta; for the Enskog equation smooth
// grains at the run's phi and chi, in dilute mean free paths, and no heat mode), or why there is no
// such statement for it; nothing for other runs.
std::optional<std::string> linear_stability_note(const RunSpec& spec);

} // namespace roughgas::cli
