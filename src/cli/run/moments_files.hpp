#pragma once
// The ensemble's files of a run, rewritten together as rows complete: moments.csv and, for a box,
// walls.csv, profiles.csv, spectra.csv and modes.csv. A row enters once every replica has reached
// it (the replicas' rows at the same output time, combined by MomentsTable). Each file is rewritten
// atomically (temporary, fsync, rename), so a crash or a kill keeps every complete row; only when
// rewriting would take more than a fiftieth of the run's time (a large file and dense outputs: each
// rewrite costs O(file size), and its syncs slow the run's own threads on a virtual machine) are
// rows batched, the next rewrite waiting until 50x the last one's duration has passed.
//
// The box's cells' resolution is watched as the rows come (resolution_watch.hpp): its warnings go
// into moments.csv's and profiles.csv's headers and on stderr. Not thread-safe: the replicas' sinks
// call it under their lock (replica_scheduler.hpp).
#include "run/provenance.hpp"
#include "run/resolution_watch.hpp"

#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/moments_csv.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <vector>

namespace roughgas::cli {

class MomentsFiles {
  public:
    // `spec`: the run's (the files combine its replicas' rows with a MomentsTable of their own, which
    // integrates the theory columns from row to row).
    MomentsFiles(std::filesystem::path dir, const RunSpec& spec, const RunProvenance& provenance);

    // Combines the rows every replica has (rows[r][k]: replica r's row k) beyond those combined
    // already, then rewrites the files if `now` or the batching rule allows.
    void update(const std::vector<std::vector<std::vector<double>>>& rows, bool now);
    // Writes every file as it is (the header alone when no row is complete): a stopped run's files exist.
    void write();

    std::size_t rows() const { return csv_.rows(); }       // combined
    std::size_t rows_on_disk() const { return on_disk_; }
    const std::filesystem::path& path() const { return path_; } // moments.csv
    // The combined rows of moments.csv and, per row, the block of profiles.csv's rows.
    const std::vector<std::vector<double>>& combined() const { return combined_; }
    const std::vector<std::vector<std::vector<double>>>& profile_blocks() const { return profile_blocks_; }
    // Per row, spectra.csv's row of the smallest |k| shell (axis 0, n 1): what tells whether the box
    // is still uniform (summary.hpp). Empty without [spectra].
    const std::vector<std::vector<double>>& smallest_shells() const { return smallest_shells_; }
    bool has_profiles() const { return profiles_.has_value(); }
    const MomentsTable& table() const { return table_; }

  private:
    std::filesystem::path dir_, path_;
    MomentsTable table_;
    CsvWriter csv_;
    std::optional<CsvWriter> walls_, profiles_, spectra_, modes_;
    ResolutionWatch resolution_;
    std::vector<std::vector<double>> combined_;
    std::vector<std::vector<std::vector<double>>> profile_blocks_;
    std::vector<std::vector<double>> smallest_shells_;
    std::size_t on_disk_ = 0;
    std::chrono::steady_clock::time_point last_write_;
    std::chrono::steady_clock::duration write_cost_{};
};

} // namespace roughgas::cli
