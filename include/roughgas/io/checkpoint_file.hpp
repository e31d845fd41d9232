#pragma once
// Checkpoint files of `roughgas run` (docs/running.md), in DIR/checkpoint/:
//
//   run.bin          the run: program version, the case as the user named it, the --set overrides,
//                    the resolved case (emit_case: every default filled in), seed, replicas,
//                    particles, and the checkpoint interval. Written before the first replica state,
//                    so `roughgas run --resume DIR` needs nothing else: a replica without a file
//                    starts from the beginning (the run is deterministic, so the output is the same).
//   replica_R.bin    replica R's latest state: the same run identity (a file of another run is
//                    refused), the rows and histogram sets it has produced, and its resumable state
//                    (run_replica's ReplicaCheckpoints: engine, schedule, tallies), empty once the
//                    replica has finished.
//
// Layout (this machine's byte order, core/bytes.hpp):
//   "RGCHECKP" | u64 format version | u64 kind (1 run, 2 replica) | payload | u64 FNV-1a of all before
// The version is read before the checksum, so a file of another format version is named as such.
// Every file is written atomically (temporary name, fsync, rename: io/atomic_file.hpp), so a kill
// while writing leaves the previous checkpoint.
#include "roughgas/dsmc/run.hpp"

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas {

// What must be the same for a checkpoint to continue a run.
struct CheckpointRun {
    std::string program_version; // roughgas_version() of the writer
    std::string case_file;       // as the user gave it (echoed in the CSV '#' lines)
    std::vector<std::string> overrides;
    std::string resolved_case;
    std::uint64_t seed = 0, replicas = 1, particles = 0;
    friend bool operator==(const CheckpointRun&, const CheckpointRun&) = default;
};

// What differs between a file's identity and the expected one, in words ("" if nothing), e.g.
// "seed 8, expected 7".
std::string checkpoint_difference(const CheckpointRun& file, const CheckpointRun& expected);

struct RunCheckpoint {
    CheckpointRun run;
    double checkpoint_every = 0; // collisions per particle; 0: checkpoints only on a stop
    // The replicas this directory runs, [replica_from, replica_to) (`roughgas run --replicas`); a
    // range that is not all of them writes no CSV (`roughgas merge` combines the ranges). 0, 0: all.
    std::uint64_t replica_from = 0, replica_to = 0;
};

struct ReplicaCheckpoint {
    CheckpointRun run;
    std::uint64_t replica = 0;
    std::vector<std::vector<double>> rows; // run_replica's rows so far (t = 0 first)
    std::vector<HistogramSet> histograms;  // its histogram sets so far
    std::string state;                     // ReplicaCheckpoints state; empty: the replica had finished
};

// A file that cannot be used: the message says why (the caller names the file).
struct CheckpointError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint64_t checkpoint_format_version = 5;

std::string encode_checkpoint(const RunCheckpoint& c);
std::string encode_checkpoint(const ReplicaCheckpoint& c);
// Throw CheckpointError: bad header, other format version, checksum mismatch (truncated or
// corrupt), the other kind of file, malformed payload.
RunCheckpoint decode_run_checkpoint(std::string_view bytes);
ReplicaCheckpoint decode_replica_checkpoint(std::string_view bytes);

std::filesystem::path checkpoint_dir(const std::filesystem::path& out);
std::filesystem::path run_checkpoint_path(const std::filesystem::path& out);
std::filesystem::path replica_checkpoint_path(const std::filesystem::path& out, std::uint64_t replica);

// The whole file; throws std::system_error if it cannot be read.
std::string read_checkpoint_bytes(const std::filesystem::path& path);

} // namespace roughgas
