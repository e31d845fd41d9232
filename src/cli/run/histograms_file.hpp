#pragma once
// histograms.csv: the distributions of the reduced speed and spin (observables/histograms.hpp) at
// every run.histogram_every time, averaged over the replicas; a time enters once every replica has
// reached it, and the file is rewritten atomically each time one does. Not thread-safe: called
// under the replicas' lock (replica_scheduler.hpp).
#include "run/provenance.hpp"

#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/histograms_csv.hpp"

#include <filesystem>
#include <vector>

namespace roughgas::cli {

class HistogramsFile {
  public:
    HistogramsFile(const std::filesystem::path& dir, const RunSpec& spec, const RunProvenance& provenance);

    // Adds the times every replica has (sets[r][k]: replica r's histograms at time k) beyond those
    // written, and rewrites the file if there were any.
    void update(const std::vector<std::vector<HistogramSet>>& sets);

    std::size_t times() const { return written_; }
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    HistogramsTable table_;
    CsvWriter csv_;
    std::size_t written_ = 0;
};

} // namespace roughgas::cli
