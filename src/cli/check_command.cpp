// roughgas check CASE.toml [--set KEY=VALUE]... : parse and validate only, writing nothing. For a
// run, the same planning as `roughgas run` (run/setup.hpp: the spec, initial.from's state files, the
// memory of the replicas held at a time on this machine's threads), so that check refuses what run
// would refuse before any work, and the warnings run would give at its set-up (run/setup_warnings.hpp)
// on stderr; the output directory and the tables are run's alone.
#include "commands.hpp"
#include "enskog_note.hpp"
#include "linear_stability.hpp"
#include "run/setup.hpp"
#include "run/setup_warnings.hpp"

#include "roughgas/io/case_file.hpp"

#include <iostream>
#include <map>
#include <memory>
#include <optional>

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
    std::optional<std::string> stability, enskog;
    std::vector<std::string> warnings = cfg.unused;
    if (o.use == CaseUse::run) {
        const CasePlan plan = plan_run(cfg, o.case_file, 0, cfg.run.replicas);
        stability = linear_stability_note(plan.spec);
        enskog = enskog_note(plan.spec);
        warnings = setup_warnings(cfg, plan.spec);
    }
    for (const std::string& w : warnings)
        std::cerr << o.case_file << ": warning: " << w << '\n';
    if (o.print) {
        std::cout << emit_case(cfg);
    } else {
        std::cout << o.case_file << ": valid\n";
        if (enskog)
            std::cout << o.case_file << ": " << *enskog << '\n';
        if (stability)
            std::cout << o.case_file << ": " << *stability << '\n';
    }
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
