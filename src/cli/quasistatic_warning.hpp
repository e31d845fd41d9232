#pragma once
// One warning on stderr when a case drives the contact model outside its quasistatic range
// (contact/quasistatic.hpp): said once per command, never an error.
#include "roughgas/io/case_config.hpp"

#include <iosfwd>
#include <span>
#include <string>

namespace roughgas::cli {

// Checks the pair of species (i, j) at the impact speeds `g_n` (m/s); writes one line to `err` for
// the first speed where the assumption fails (and the range of such speeds). Returns whether it warned.
bool warn_if_not_quasistatic(const CaseConfig& cfg, std::size_t i, std::size_t j, std::span<const double> g_n,
                             const std::string& where, std::ostream& err);

} // namespace roughgas::cli
