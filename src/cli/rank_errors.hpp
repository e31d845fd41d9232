#pragma once
// Errors when several MPI ranks run one command (parallel/communicator.hpp).
//
// A command's setup (reading the case, checking the output directory, building the tables) either
// fails on every rank alike or on one (rank 0 alone checks and locks the output directory). Each
// rank runs it inside agree_on_setup: when any rank failed, the lowest failing rank reports its
// error as a one-process run would and every rank leaves with that exit status (no half-started
// job, one message, exit 2 for invalid input as usual). An error after the setup, while the ranks
// work independently (a replica that produced NaN, a disk that filled), is one rank's: main
// reports it naming the rank and ends the whole job (Communicator::abort), before rank 0 has
// written anything of the ensemble.
#include "roughgas/parallel/communicator.hpp"

#include <exception>
#include <functional>
#include <ostream>
#include <string>

namespace roughgas::cli {

// Thrown to leave a command with `status` after the error was reported (or on the ranks that
// report nothing); main returns the status.
struct QuietExit {
    int status = 0;
};

// Prints `error` as the command line reports it ("roughgas: error: ..."; an invalid input's own
// message) with `prefix` after "roughgas: " (e.g. "rank 2 of 3: "), and returns its exit status.
int report_error(std::exception_ptr error, std::ostream& out, const std::string& prefix = "");

// Runs `setup` on this rank; then, with several ranks, agrees with the others (a collective call:
// every rank calls it, in the same order) and throws QuietExit if any failed. One rank: rethrows.
void agree_on_setup(const Communicator& comm, const std::function<void()>& setup);

} // namespace roughgas::cli
