#pragma once
// A case as the command line takes it: a case file (read again by each run, as `roughgas run CASE`
// does) or TOML text (the Python module's cases from a string or a dict), with its --set
// overrides in order, validated like the command line at every change.
#include "roughgas/io/case_config.hpp"
#include "roughgas/io/case_file.hpp"

#include <optional>
#include <string>
#include <vector>

namespace roughgas::python {

struct CaseSource {
    std::string name;                // the case file as given, or "<string>", "<dict>"
    std::optional<std::string> text; // the TOML, for a case that is not a file
    bool positions = true;           // false for text made from a dict: its lines are not the user's
    std::vector<std::string> sets;   // "KEY=VALUE" as --set takes them
    CaseConfig cfg;                  // validated for a run

    // Reads and validates the case with `sets` (throws InputError as the command line exits 2).
    CaseConfig parse(const std::vector<std::string>& sets, CaseUse use = CaseUse::run) const;
};

} // namespace roughgas::python
