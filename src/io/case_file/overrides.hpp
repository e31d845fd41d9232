#pragma once
// `--set KEY=VALUE`: each override is written into the parsed TOML before any check runs, so that
// an overridden value is validated exactly like one in the file (its messages say "set with --set").
#include "diagnostics.hpp"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace roughgas::case_file {

// Writes one "KEY=VALUE" into `root`, creating tables and at most one new [[array]] element on the
// way; a malformed argument is reported to `d` and leaves `root` as it was.
void apply_override(toml::table& root, const std::string& arg, Diagnostics& d);

// The clock of the run: an override of run.end_time (and not of run.end) switches a case written for
// run.end to the time clock: the file's run.end, run.output_every and run.histogram_every are left
// out, so that e.g. --set run.end_time=5 runs it by time; an override of run.end switches back the
// same way. Keys of the other clock set with --set stay, and are refused by the checks of [run].
void switch_clock(toml::table& root, const std::vector<std::string>& overrides);

std::vector<std::string> split_path(const std::string& key);     // "species.1.mass" -> species, 1, mass
std::string schema_path(const std::vector<std::string>& segments); // array indices left out: "species.mass"

} // namespace roughgas::case_file
