// roughgas: the command line (docs/reference.md). Exit status 0 ok, 2 invalid input, 1 anything else;
// run and sweep add 128 + the signal's number when SIGINT or SIGTERM stops them.
#include "commands.hpp"

#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/input_error.hpp"
#include "roughgas/io/nearest_word.hpp"

#include <algorithm>
#include <exception>
#include <optional>
#include <string>
#include <vector>
#include <iostream>

namespace {

// After a parse error: "did you mean --threads?" for each word of the command line that looks like
// an option (--word) but is none of the chosen command's.
void suggest_options(const CLI::App& app, int argc, char** argv) {
    const CLI::App* command = &app;
    for (const CLI::App* sub : app.get_subcommands({}))
        if (argc > 1 && sub->get_name() == argv[1])
            command = sub;
    std::vector<std::string> names;
    for (const CLI::Option* o : command->get_options())
        for (const std::string& n : o->get_lnames())
            names.push_back("--" + n);
    for (int i = 1; i < argc; ++i) {
        std::string word = argv[i];
        if (word.rfind("--", 0) != 0)
            continue;
        word = word.substr(0, word.find('='));
        if (std::find(names.begin(), names.end(), word) != names.end())
            continue;
        if (const std::optional<std::string> near = roughgas::nearest(word, names))
            std::cerr << word << ": did you mean " << *near << "?\n";
    }
}

int run_cli(int argc, char** argv) {
    using namespace roughgas::cli;
    CLI::App app{"roughgas: kinetic (DSMC) solver for granular gases of rough inelastic particles"};
    app.set_version_flag("--version", "roughgas " + roughgas::roughgas_version());
    app.require_subcommand(1);
    const std::vector<Subcommand> commands = {add_run_command(app), add_check_command(app),
                                              add_restitution_command(app), add_sweep_command(app),
                                              add_merge_command(app), add_keys_command(app)};
    // The options are in --help; everything else a user scripts against is in the reference.
    const std::string footer = "Reference (commands, options, case-file keys, output columns, exit codes): "
                               "docs/reference.md in the roughgas sources.";
    app.footer(footer);
    for (const Subcommand& c : commands)
        c.app->footer(footer);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version are "errors" with status 0; a malformed command line is invalid input.
        const int status = app.exit(e);
        if (status != 0)
            suggest_options(app, argc, argv);
        return status == 0 ? exit_ok : exit_invalid;
    }
    for (const Subcommand& c : commands) {
        if (c.app->parsed()) {
            return c.run();
        }
    }
    return exit_invalid; // unreachable: require_subcommand(1)
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run_cli(argc, argv);
    } catch (const roughgas::InputError& e) {
        std::cerr << e.what() << '\n';
        return roughgas::cli::exit_invalid;
    } catch (const std::exception& e) {
        std::cerr << "roughgas: error: " << e.what() << '\n';
        return roughgas::cli::exit_failure;
    } catch (...) {
        std::cerr << "roughgas: unknown error\n";
        return roughgas::cli::exit_failure;
    }
}
