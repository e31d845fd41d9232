// roughgas: the command line (docs/reference.md). Exit status 0 ok, 2 invalid input, 1 anything else;
// run and sweep add 128 + the signal's number when SIGINT or SIGTERM stops them.
//
// Under an MPI launcher (mpirun -np R roughgas run|sweep ...: docs/running.md) every rank parses the
// same command line; rank 0 alone prints what the command line itself produces (help, parse
// errors), and an error while the ranks work ends the whole job naming its rank (rank_errors.hpp).
#include "commands.hpp"
#include "rank_errors.hpp"

#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/input_error.hpp"
#include "roughgas/io/nearest_word.hpp"

#include <algorithm>
#include <csignal>
#include <pthread.h>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

// After a parse error: "did you mean --threads?" for each word of the command line that looks like
// an option (--word) but is none of the chosen command's.
void suggest_options(const CLI::App& app, int argc, char** argv, std::ostream& err) {
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
            err << word << ": did you mean " << *near << "?\n";
    }
}

int run_cli(int argc, char** argv, const roughgas::Communicator& comm) {
    using namespace roughgas::cli;
    CLI::App app{"roughgas: kinetic (DSMC) solver for granular gases of rough inelastic particles"};
    app.set_version_flag("--version", "roughgas " + roughgas::roughgas_version() +
                                          (roughgas::built_with_mpi() ? " (MPI)" : ""));
    app.require_subcommand(1);
    const std::vector<Subcommand> commands = {add_run_command(app, comm), add_check_command(app),
                                              add_restitution_command(app), add_sweep_command(app, comm),
                                              add_merge_command(app), add_keys_command(app)};
    // The options are in --help; everything else a user scripts against is in the reference.
    const std::string footer = "Reference (commands, options, case-file keys, output columns, exit codes): "
                               "docs/reference.md in the roughgas sources.";
    app.footer(footer);
    for (const Subcommand& c : commands)
        c.app->footer(footer);
    std::ostringstream muted; // the other ranks' copy of what rank 0 prints
    std::ostream& out = comm.is_root() ? std::cout : muted;
    std::ostream& err = comm.is_root() ? std::cerr : muted;
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version are "errors" with status 0; a malformed command line is invalid input.
        const int status = app.exit(e, out, err);
        if (status != 0)
            suggest_options(app, argc, argv, err);
        return status == 0 ? exit_ok : exit_invalid;
    }
    for (const Subcommand& c : commands) {
        if (!c.app->parsed())
            continue;
        const std::string name = c.app->get_name();
        if (comm.size() > 1 && name != "run" && name != "sweep") {
            err << "roughgas " << name << ": runs in one process; under an MPI launcher (" << comm.size()
                << " ranks) only run and sweep spread their work over the ranks\n";
            return exit_invalid;
        }
        return c.run();
    }
    return exit_invalid; // unreachable: require_subcommand(1)
}

} // namespace

int main(int argc, char** argv) {
    using namespace roughgas::cli;
    const roughgas::Launch launch = roughgas::launch_from_environment();
    sigset_t unblocked;
    sigemptyset(&unblocked);
    if (launch.by_mpi_launcher) {
        // Before MPI starts its own threads, which inherit the mask: SIGINT and SIGTERM must reach
        // the command's StopSignals thread (stop_signals.hpp), never take their default action on
        // one of MPI's threads.
        sigset_t stop;
        sigemptyset(&stop);
        sigaddset(&stop, SIGINT);
        sigaddset(&stop, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &stop, &unblocked);
    }
    std::optional<roughgas::Communicator> comm;
    try {
        comm.emplace(launch);
    } catch (const std::exception& e) {
        if (launch.rank == 0)
            std::cerr << "roughgas: error: " << e.what() << '\n';
        // Launched as several ranks by a build without MPI: a usage error; MPI failing to start: not.
        return roughgas::built_with_mpi() ? exit_failure : exit_invalid;
    }
    if (launch.by_mpi_launcher) // MPI's threads keep the blocked mask; this thread takes signals again
        pthread_sigmask(SIG_SETMASK, &unblocked, nullptr);
    try {
        return run_cli(argc, argv, *comm);
    } catch (const QuietExit& q) {
        return q.status;
    } catch (...) {
        if (comm->size() == 1)
            return report_error(std::current_exception(), std::cerr);
        // One rank's error while the others work: the job ends here, before rank 0 writes the ensemble.
        const int status = report_error(std::current_exception(), std::cerr,
                                        "rank " + std::to_string(comm->rank()) + " of " +
                                            std::to_string(comm->size()) + ": ");
        std::cerr.flush();
        comm->abort(status);
    }
}
