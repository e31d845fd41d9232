#pragma once
// Each replica's own rows, DIR/replicas/moments_R.csv (runs with replicas > 1): moments.csv holds a
// row once every replica has reached it, so an ensemble stopped or killed while some replicas wait
// for a thread shows nothing of the finished ones there; these files show how far each replica got.
// Each is the moments.csv of that replica alone (the columns of a run with replicas = 1), rewritten
// atomically as its rows come (batched as moments.csv is: the next rewrite waits 10x the last one's
// duration), with the warnings of its own cells' resolution (resolution_watch.hpp), kept when the
// run ends, and the same bytes after --resume: the rows come from the checkpoints. Replica r's file is touched by one thread at a time (add for r from r's thread only;
// write_all outside the replicas' threads), so it needs no lock.
#include "run/resolution_watch.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/moments_csv.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

namespace roughgas::cli {

std::filesystem::path replicas_dir(const std::filesystem::path& run_dir);
std::filesystem::path replica_moments_path(const std::filesystem::path& run_dir, int replica);

class ReplicaFiles {
  public:
    // For the replicas [from, to) of `spec` (which has spec.replicas > 1) that this process runs;
    // `provenance` is the ensemble file's, whose second note (the replicas') each file replaces.
    ReplicaFiles(std::filesystem::path run_dir, const RunSpec& spec, const CsvProvenance& provenance, int from,
                 int to);
    // Replica r's next row (the solver's, as the run's row sink gets it); the file is rewritten
    // unless `write` is false or the batching rule defers it.
    void add(int r, std::span<const double> row, bool write = true);
    // Every file with rows not yet on disk.
    void write_all();
    // Each of its replicas' rows so far (rows[r][k]: replica r's row k, as the run holds them), then
    // write_all.
    void add_rows(const std::vector<std::vector<std::vector<double>>>& rows);

  private:
    struct File {
        MomentsTable table;
        CsvWriter csv;
        ResolutionWatch resolution;
        std::size_t on_disk = 0;
        std::chrono::steady_clock::time_point last_write;
        std::chrono::steady_clock::duration cost{};
    };
    void write(int r, File& f);
    std::filesystem::path dir_;
    int from_ = 0;
    std::vector<std::optional<File>> files_;
};

} // namespace roughgas::cli
