#pragma once
// What `roughgas check` says of a valid case, as text: the same planning as `roughgas run`
// (run/setup.hpp), so that check refuses what run would refuse, the warnings run would give at its
// set-up, what an Enskog run's chi does (enskog_note.hpp) and the stability statement of a box
// (linear_stability.hpp). Shared by the command
// (check_command.cpp) and the Python module's Case.check().
#include "roughgas/io/case_config.hpp"
#include "roughgas/io/case_file.hpp"

#include <string>
#include <vector>

namespace roughgas::cli {

struct CheckReport {
    std::vector<std::string> warnings; // each printed as "CASE: warning: ..." on stderr
    std::string out;                   // what check prints on stdout
};

// `case_file` names the case in the lines; `print`: the resolved case as TOML instead of "valid".
// Throws InputError for what run would refuse of the case.
CheckReport check_case(const CaseConfig& cfg, const std::string& case_file, CaseUse use, bool print);

} // namespace roughgas::cli
