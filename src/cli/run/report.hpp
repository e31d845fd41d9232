#pragma once
// What `roughgas run` says at its end: on stdout the files it wrote, the work done and the summary's
// note; on stderr the warnings about the work (stops passed in a parallel phase) and the summary's
// headline, last.
#include "run/replica_records.hpp"
#include "run/run_files.hpp"
#include "run/summary.hpp"

namespace roughgas::cli {

void report_run(const RunFiles& files, const ReplicaRecords& records, const MomentsTable& table, const RunSpec& spec,
                double seconds, const RunSummary& summary);

// A run stopped by `signal`: where its rows and checkpoint are, and how to continue it.
void report_stop(const RunFiles& files, const std::filesystem::path& dir, int signal);

} // namespace roughgas::cli
