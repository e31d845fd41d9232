#pragma once
// The summary of a run's rows (observables/steady_state.hpp, io/steady_csv.hpp): for a driven gas
// (uniform shear, a thermostat, walls that heat or shear it: driven() in io/case_config.hpp) the steady
// state, DIR/steady.csv, and for a box its profiles over the same window, DIR/steady_profiles.csv; for a
// cooling gas the scaled homogeneous cooling state, DIR/scaled.csv. The same detector and batch
// means for `run` (over the rows averaged over the replicas) and for each point of `sweep`.
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/steady_csv.hpp"
#include "roughgas/observables/steady_state.hpp"

#include "run/moments_files.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace roughgas::cli {

// Writes the summary file of `rows` (columns `names`, their `units`) into `dir` (steady.csv when
// `steady`, scaled.csv otherwise) with `provenance`'s identity and a note of how it was found.
void write_summary_csv(const std::filesystem::path& dir, bool steady, const SteadyResult& st,
                       const std::vector<std::string>& names, const std::vector<std::string>& units,
                       const std::vector<std::vector<double>>& rows, CsvProvenance provenance);

// What `roughgas run` says of its summary.
struct RunSummary {
    std::string note;     // the end of the report line on stdout ("; scaled state from ...: DIR/scaled.csv")
    std::string headline; // the scaled state's numbers, last on stderr ("" for a steady state)
};

// The summary of a run's ensemble (rank 0, every replica finished): its files, and what to say.
RunSummary summarize_run(const std::filesystem::path& dir, const RunSpec& spec, bool steady, const MomentsFiles& files,
                         const RunProvenance& provenance);

} // namespace roughgas::cli
