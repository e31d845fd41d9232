#pragma once
// The first stage of a run: from the command line to everything the run needs before any work.
// Each step refuses what it cannot run (exit 2 naming the file, key or option; nothing written):
//   the case (CASE.toml with --set) or the checkpoint (--resume DIR)
//   -> the solver's spec, initial.from's state files, the output directory, the memory the
//      replicas held at once need
//   -> the restitution tables.
// `roughgas check` runs the same plan_run as `run` (without the output directory and the tables,
// which write files), so that it refuses what `run` would refuse of the case; `sweep` plans each
// point with plan_case.
#include "run/checkpoints.hpp"

#include "output_dir_lock.hpp"

#include "roughgas/dsmc/run.hpp"
#include "roughgas/io/case_config.hpp"
#include "roughgas/parallel/communicator.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace roughgas::cli {

// `roughgas run`'s command line.
struct RunOptions {
    std::string case_file;
    // The case's TOML when it comes as text (the Python module's cases from a string or a dict):
    // then case_file only names it in messages and in the CSVs' '#' lines, and is not read.
    std::optional<std::string> case_text;
    std::string out;
    std::vector<std::string> sets;
    std::uint64_t seed = 0;
    int threads = 0;
    bool quiet = false;
    bool force = false;
    double checkpoint_every = 0;
    std::string resume;
    std::string replicas; // --replicas FROM:TO
    bool seed_given = false, checkpoint_every_given = false;
};

// The solver's spec of a valid case, with initial.from's state files checked and attached.
struct CasePlan {
    RunSpec spec;
    std::string start_note; // what the run starts from (initial.from), "" for a fresh start
};

// The spec, with initial.from's state attached; `out`: the output directory of a new run (initial.from
// must not be it), or null. Throws InputError for state files that do not fit the case,
// std::runtime_error for a valid case the solver cannot run.
CasePlan plan_case(const CaseConfig& cfg, const std::string& case_file,
                   const std::filesystem::path* out = nullptr);

// plan_case, then the threads and the memory: `threads` is the run's --threads (0: default_threads()),
// `replicas_per_process` the replicas one process runs (its share of the ranks'); the replicas it
// holds at a time, at most one per thread, must fit the memory this process may use (InputError
// naming run.particles otherwise).
CasePlan plan_run(const CaseConfig& cfg, const std::string& case_file, int threads, long long replicas_per_process,
                  const std::filesystem::path* out = nullptr);

// The replicas of the run and which of them this process runs.
struct ReplicaRange {
    int count = 0;                 // run.replicas (K)
    int from = 0, to = 0;          // those of this run: all, or --replicas FROM:TO
    int mine_from = 0, mine_to = 0; // this rank's share of them
    bool partial = false;          // a range of --replicas: checkpoints for `roughgas merge`, no CSVs
    bool mine(int r) const { return r >= mine_from && r < mine_to; }
};

// The run to do: a new one from CASE.toml, or the one stored in DIR/checkpoint (--resume).
struct RunSetup {
    CaseConfig cfg;
    std::filesystem::path dir;
    RunCheckpoint manifest; // the run's identity (also the CSV '#' lines) and checkpoint interval
    bool resuming = false;
    bool manifest_changed = false;                      // a resume with another --checkpoint-every
    std::vector<std::optional<ResumedReplica>> resumed; // per replica (resuming)
    OutputDirLock lock; // held from the first check of the directory to the end of the run
    RunSpec spec;       // spec.threads: the process's threads
    std::string start_note;
    std::shared_ptr<const RestitutionTables> tables;
    ReplicaRange replicas;
};

// The set-up on every rank alike (rank_errors.hpp): rank 0 checks and locks the output directory and
// builds the tables first (saving their cache file), the other ranks then load them.
std::unique_ptr<RunSetup> set_up_run(const RunOptions& o, const Communicator& comm);

// Rank 0 creates and locks the output directory and clears what an earlier run left there (a new run
// with --force: its checkpoint, states, fields and replicas' rows; a resume: temporaries of a kill),
// then writes the checkpoint's run.bin where a kill must leave a resumable run. Collective.
void prepare_output_dir(RunSetup& setup, CheckpointWriter& checkpoints, const Communicator& comm);

// The warnings of the set-up on stderr: the contact model's range at the start, the tables' builds.
void report_contact_range(const CaseConfig& cfg);
void report_tables(const RunSetup& setup);

} // namespace roughgas::cli
