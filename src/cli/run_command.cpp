// roughgas run CASE.toml --out DIR ... | roughgas run --resume DIR: the DSMC (issue 3).
// The options of interface.md are all accepted now, so scripts can be written against them.
#include "commands.hpp"

#include "roughgas/io/case_file.hpp"

#include <cstdint>
#include <iostream>
#include <memory>

namespace roughgas::cli {
namespace {

struct RunOptions {
    std::string case_file;
    std::string out;
    std::vector<std::string> sets;
    std::uint64_t seed = 0;
    int threads = 0;
    bool quiet = false;
    bool force = false;
    double checkpoint_every = 0;
    std::string resume;
};

int run_run(const RunOptions& o, const CLI::App& app) {
    if (o.resume.empty()) {
        if (o.case_file.empty() || o.out.empty()) {
            throw InputError("", "", "roughgas run: give CASE.toml and --out DIR, or --resume DIR");
        }
        std::vector<std::string> sets = o.sets;
        if (app.count("--seed") > 0) {
            sets.push_back("run.seed=" + std::to_string(o.seed)); // --seed is --set run.seed=S
        }
        (void)load_case(o.case_file, sets, CaseUse::run); // invalid input is reported now: exit 2
    }
    std::cerr << "roughgas run: not implemented yet (DSMC: issue 3)\n";
    return exit_failure;
}

} // namespace

Subcommand add_run_command(CLI::App& parent) {
    auto o = std::make_shared<RunOptions>();
    CLI::App* app = parent.add_subcommand("run", "run a DSMC simulation (not implemented yet)");
    CLI::Option* case_opt = app->add_option("CASE", o->case_file, "case file (TOML)");
    app->add_option("--out", o->out, "output directory");
    add_set_option(*app, o->sets);
    app->add_option("--seed", o->seed, "random seed (overrides run.seed)");
    app->add_option("--threads", o->threads, "OpenMP threads")->check(CLI::PositiveNumber);
    app->add_flag("--quiet", o->quiet, "no progress output");
    app->add_flag("--force", o->force, "overwrite an existing output directory");
    app->add_option("--checkpoint-every", o->checkpoint_every,
                    "checkpoint interval in collisions per particle")
        ->check(CLI::PositiveNumber);
    app->add_option("--resume", o->resume, "continue the checkpointed run in DIR")->excludes(case_opt);
    return {app, [o, app] { return run_run(*o, *app); }};
}

} // namespace roughgas::cli
