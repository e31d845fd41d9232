#pragma once
// The checkpoints of `roughgas run` (docs/running.md; the file format is
// io/checkpoint_file.hpp): reading and checking DIR/checkpoint for --resume, and writing it while
// a run goes on.
#include "roughgas/dsmc/run.hpp"
#include "roughgas/io/case_config.hpp"
#include "roughgas/io/checkpoint_file.hpp"

#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace roughgas::cli {

// What a replica's file gives back before the replica runs: its rows and histogram sets (its state
// is read again when it starts, so that the states of replicas waiting for a thread are not all
// held in memory at once).
struct ResumedReplica {
    std::vector<std::vector<double>> rows;
    std::vector<HistogramSet> histograms;
    bool finished = false; // nothing left to run
};

struct ResumedRun {
    RunCheckpoint manifest;
    CaseConfig cfg; // parsed from the resolved case, which it emits again byte for byte
    std::vector<std::optional<ResumedReplica>> replicas; // none: no file, the replica starts afresh
};

// Reads DIR/checkpoint: run.bin, then every replica's file there is. Any problem (no such
// directory, no checkpoint, unreadable, truncated or corrupt, another format or program version,
// a replica file of another run or replica, rows of the wrong shape) throws InputError naming the
// file and the reason, before anything is written.
ResumedRun read_resumable_run(const std::filesystem::path& dir);

// Replica r's resumable state, read when it starts (run_replica's ReplicaCheckpoints::resume).
std::string read_replica_state(const std::filesystem::path& dir, std::uint64_t r, const CheckpointRun& run);

// Writes DIR/checkpoint while the replicas run (each file atomically; thread-safe). run.bin goes
// first, once, so that every replica file on disk belongs to a resumable run.
class CheckpointWriter {
  public:
    CheckpointWriter(std::filesystem::path dir, RunCheckpoint manifest, bool manifest_on_disk);
    void write_manifest_once();
    void rewrite_manifest(); // e.g. a resume with another --checkpoint-every
    // Replica r's file: its rows and histograms so far and its state (empty: finished).
    void save_replica(std::uint64_t r, std::vector<std::vector<double>> rows,
                      std::vector<HistogramSet> histograms, std::string state);
    const std::filesystem::path& dir() const { return dir_; }

  private:
    std::filesystem::path dir_;
    RunCheckpoint manifest_;
    std::mutex mutex_;
    bool on_disk_ = false;
};

// Removes what a kill left behind: temporary files of our outputs and checkpoints
// (NAME.tmp.PID, io/atomic_file.hpp) in DIR and its checkpoint, state, fields and replicas directories.
void remove_stale_temporaries(const std::filesystem::path& dir);

} // namespace roughgas::cli
