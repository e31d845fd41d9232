#pragma once
// The writers of a run's files, each of one family: the ensemble's moments.csv with the box's files
// beside it and histograms.csv (rank 0's, as rows complete), and each replica's own rows
// (replicas/moments_R.csv, replica_files.hpp). The replicas' cell fields have their own writer per
// replica (io/fields_series.hpp), made by the scheduler; the summaries are written at the end
// (summary.hpp).
#include "run/histograms_file.hpp"
#include "run/moments_files.hpp"
#include "run/replica_files.hpp"
#include "run/replica_records.hpp"

#include <optional>

namespace roughgas::cli {

struct RunFiles {
    std::optional<MomentsFiles> moments;        // rank 0
    std::optional<HistogramsFile> histograms;   // rank 0, with run.histogram_every
    std::optional<ReplicaFiles> replica_rows;   // one process running a whole ensemble (replicas > 1)

    // The rows and histograms complete in every replica into the ensemble's files (`now`: rewrite
    // moments.csv whatever the batching rule says).
    void update(const ReplicaRecords& records, bool now) {
        if (moments)
            moments->update(records.rows, now);
    }
    void update_histograms(const ReplicaRecords& records) {
        if (histograms)
            histograms->update(records.histograms);
    }
};

} // namespace roughgas::cli
