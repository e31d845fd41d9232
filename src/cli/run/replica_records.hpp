#pragma once
// What the replicas of a run have produced so far, per replica r: its rows and histogram sets (a
// resumed run starts from those in its checkpoints), whether it finished and whether its checkpoint
// file says so, and what it did (ReplicaSummary). The scheduler fills this process's replicas; under
// MPI the ranks' records are gathered into rank 0's (rank_gather.hpp).
#include "run/checkpoints.hpp"

#include "roughgas/dsmc/run.hpp"

#include <optional>
#include <vector>

namespace roughgas::cli {

struct ReplicaRecords {
    explicit ReplicaRecords(int replicas)
        : rows(static_cast<std::size_t>(replicas)), histograms(static_cast<std::size_t>(replicas)),
          finished(static_cast<std::size_t>(replicas), 0), final_saved(static_cast<std::size_t>(replicas), 0),
          summaries(static_cast<std::size_t>(replicas)) {}

    // The rows, histograms and ends of the resumed replicas' checkpoints (moved out of `resumed`).
    void restore(std::vector<std::optional<ResumedReplica>>& resumed) {
        for (std::size_t r = 0; r < resumed.size(); ++r) {
            if (!resumed[r])
                continue;
            rows[r] = std::move(resumed[r]->rows);
            histograms[r] = std::move(resumed[r]->histograms);
            finished[r] = resumed[r]->finished;
        }
    }

    std::vector<std::vector<std::vector<double>>> rows; // rows[r][k]: replica r's row at output k
    std::vector<std::vector<HistogramSet>> histograms;  // histograms[r][k]: at histogram time k
    // One byte per replica (not vector<bool>, whose bits share words): each replica's thread writes its own.
    std::vector<char> finished;
    std::vector<char> final_saved; // its checkpoint file holds it finished
    std::vector<ReplicaSummary> summaries;
};

} // namespace roughgas::cli
