#pragma once
// The points of `roughgas sweep CASE --param KEY=FROM:TO:COUNT`: COUNT values of one key, FROM to TO
// evenly spaced (COUNT = 1: FROM only), each a case validated and planned as `roughgas run` plans
// its case (run/setup.hpp) before any work: exit 2 naming the key and the allowed range.
#include "roughgas/dsmc/run.hpp"
#include "roughgas/io/case_config.hpp"

#include <string>
#include <vector>

namespace roughgas::cli {

// `roughgas sweep`'s command line.
struct SweepOptions {
    std::string case_file;
    std::string param;
    std::string out;
    std::vector<std::string> sets;
    int threads = 0;
    bool quiet = false;
    bool force = false;
};

struct SweepPoints {
    std::string key, from, to; // as written in --param
    long count = 0;
    std::vector<double> values;                   // the key's value at each point
    std::vector<std::vector<std::string>> sets;   // each point's overrides: --set, then KEY=VALUE
    std::vector<CaseConfig> cases;
    std::vector<RunSpec> specs; // initial.from's state attached
};

// Throws InputError for a malformed --param or an invalid point, before any work.
SweepPoints plan_points(const SweepOptions& o);

} // namespace roughgas::cli
