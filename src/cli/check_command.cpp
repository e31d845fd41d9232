// roughgas check CASE.toml [--set KEY=VALUE]... : parse and validate only, writing nothing. For a
// run, the same planning as `roughgas run` (check_report.hpp: the spec, initial.from's state files,
// the memory of the replicas held at a time on this machine's threads), so that check refuses what
// run would refuse before any work, and the warnings run would give at its set-up on stderr; the
// output directory and the tables are run's alone.
#include "check_report.hpp"
#include "commands.hpp"

#include "roughgas/io/case_file.hpp"

#include <iostream>
#include <map>
#include <memory>

namespace roughgas::cli {
namespace {

struct CheckOptions {
    std::string case_file;
    std::vector<std::string> sets;
    CaseUse use = CaseUse::run;
    bool print = false;
};

int run_check(const CheckOptions& o) {
    const CaseConfig cfg = load_case(o.case_file, o.sets, o.use); // throws InputError: exit 2
    const CheckReport report = check_case(cfg, o.case_file, o.use, o.print);
    for (const std::string& w : report.warnings)
        std::cerr << o.case_file << ": warning: " << w << '\n';
    std::cout << report.out;
    return exit_ok;
}

} // namespace

Subcommand add_check_command(CLI::App& parent) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* app =
        parent.add_subcommand("check", "parse and validate a case file (exit 0 valid, 2 invalid)");
    app->add_option("CASE", o->case_file, "case file (TOML)")->required();
    add_set_option(*app, o->sets);
    const std::map<std::string, CaseUse> uses{{"run", CaseUse::run}, {"restitution", CaseUse::restitution}};
    app->add_option("--for", o->use,
                    "validate for: run (default) or restitution (also needs a full [material])")
        ->transform(CLI::CheckedTransformer(uses));
    app->add_flag("--print", o->print, "print the resolved case (every default filled in) as TOML");
    return {app, [o] { return run_check(*o); }};
}

} // namespace roughgas::cli
