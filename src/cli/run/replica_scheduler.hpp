#pragma once
// Runs this process's replicas of a run (its share of the range, setup.hpp's ReplicaRange) over its
// threads: min(T, replicas) replicas at a time, each with T/min(T, replicas) threads over the groups
// of its steps (dsmc/engine.hpp). Neither changes the results: each replica is deterministic from
// the seed and its index, and the rows are combined in replica order.
//
// Each replica's rows and histograms go into the run's records and, under one lock, into the
// ensemble's files as they complete (run_files.hpp); its cell fields into its own files, written
// behind the run (io/fields_series.hpp). With --checkpoint-every it saves its state every X
// collisions per particle (checkpoints.hpp); a stop signal stops every replica at its next boundary
// with a checkpoint. The first error (a NaN in a row, a full disk) cancels the others.
#include "run/checkpoints.hpp"
#include "run/progress.hpp"
#include "run/replica_records.hpp"
#include "run/run_files.hpp"
#include "run/setup.hpp"
#include "stop_signals.hpp"

#include "roughgas/io/moments_csv.hpp"

#include <mutex>
#include <string>

namespace roughgas::cli {

class ReplicaScheduler {
  public:
    ReplicaScheduler(const RunSetup& setup, const MomentsTable& table, ReplicaRecords& records, RunFiles& files,
                     CheckpointWriter& checkpoints, const StopSignals& signals, bool quiet);

    // Runs the replicas not finished yet; returns when each has finished or stopped. A replica's
    // error is rethrown after every replica has ended and the complete rows are on disk (a NaN:
    // its message says how many rows the file kept).
    void run();

    // Replica r's checkpoint file: its rows and histograms so far with its state (empty: finished).
    void save_replica(int r, std::string state);

    double seconds() const { return progress_.seconds(); } // since the scheduler was made

  private:
    void run_one(int r);
    const RunSetup& setup_;
    const MomentsTable& table_;
    ReplicaRecords& records_;
    RunFiles& files_;
    CheckpointWriter& checkpoints_;
    const StopSignals& signals_;
    ProgressLine progress_;
    std::mutex mutex_; // the records' rows and histograms, and the ensemble's files
};

} // namespace roughgas::cli
