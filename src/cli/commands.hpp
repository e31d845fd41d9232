#pragma once
// The subcommands of the roughgas executable. Each file registers one subcommand with CLI11 and
// returns what to run once the command line is parsed; CLI11 is used in src/cli/ only.
#include "roughgas/parallel/communicator.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace roughgas::cli {

struct Subcommand {
    CLI::App* app = nullptr;  // parsed() says whether this one was chosen
    std::function<int()> run; // returns the exit status (throws InputError for invalid input)
};

// run and sweep spread their work over the ranks of `comm` (one process: a world of one).
Subcommand add_run_command(CLI::App& parent, const Communicator& comm);
Subcommand add_check_command(CLI::App& parent);
Subcommand add_restitution_command(CLI::App& parent);
Subcommand add_sweep_command(CLI::App& parent, const Communicator& comm);
Subcommand add_merge_command(CLI::App& parent);
Subcommand add_keys_command(CLI::App& parent); // prints the generated tables of docs/reference.md

// The tables of command-line options of `root` and each of its subcommands (docs/reference.md).
std::string cli_options_markdown(const CLI::App& root);

struct RunOptions;
// `roughgas run` with these options in this process alone (no MPI), as the command line runs it
// without a launcher; the Python module's roughgas.run. Returns the exit status (128 + the signal
// when SIGINT or SIGTERM stopped it); throws InputError for invalid input.
int run_in_one_process(const RunOptions& o);

// `roughgas run --resume DIR` (run_command.cpp): continues the run stored in DIR/checkpoint, or,
// when every replica there has finished, only writes its CSVs.
int resume_finished_run(const std::string& dir, int threads, bool quiet);

// `--set KEY=VALUE`, repeatable, one value per occurrence (so it cannot swallow CASE.toml).
inline CLI::Option* add_set_option(CLI::App& app, std::vector<std::string>& sets) {
    return app
        .add_option("--set", sets,
                    "override a case-file key before validation, e.g. collision.alpha=0.7 "
                    "or species.0.radius=0.5 (repeatable)")
        ->allow_extra_args(false);
}

// A number > 0, with a message a user can read (CLI::PositiveNumber prints its bound, DBL_MAX, in
// full): "--checkpoint-every: must be a number > 0, got -1".
inline CLI::Validator positive() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double v = 0;
            try {
                std::size_t used = 0;
                v = std::stod(text, &used);
                if (used != text.size())
                    return "must be a number > 0, got " + text;
            } catch (const std::exception&) {
                return "must be a number > 0, got " + text;
            }
            return v > 0 ? std::string() : "must be a number > 0, got " + text;
        },
        "POSITIVE");
}

// Exit statuses (docs/reference.md); a stop by SIGINT or SIGTERM exits with 128 + the signal.
inline constexpr int exit_ok = 0;
inline constexpr int exit_failure = 1;
inline constexpr int exit_invalid = 2;

} // namespace roughgas::cli
