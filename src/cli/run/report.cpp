#include "run/report.hpp"

#include "stop_signals.hpp"

#include "roughgas/io/checkpoint_file.hpp"

#include <fmt/format.h>

#include <iostream>

namespace roughgas::cli {

void report_run(const RunFiles& files, const ReplicaRecords& records, const MomentsTable& table, const RunSpec& spec,
                double seconds, const RunSummary& summary) {
    double collisions = 0;
    std::int64_t overshoots = 0;
    std::string kernel; // of a replica that ran in this process (a resumed one may have none left)
    for (const ReplicaSummary& s : records.summaries) {
        collisions += static_cast<double>(s.collisions - s.resumed_at);
        overshoots += s.overshoots;
        if (!s.kernel.empty())
            kernel = s.kernel;
    }
    // A grouped run meets a collision count in parallel phases predicted from the current collision
    // rate; a gas whose rate grows many-fold within one phase can pass the count (dsmc/engine.hpp).
    // The rows stay consistent (each reports its own t and collision count), one may come late.
    if (overshoots > 0)
        std::cerr << fmt::format(
            "roughgas run: warning: {} stop{} at a collision count passed within a parallel "
            "phase (the collision rate grew faster than predicted); a row due there was "
            "taken late, with the t and coll_per_particle of its state\n",
            overshoots, overshoots > 1 ? "s" : "");
    const std::string work =
        kernel.empty() ? std::string("every replica had finished, nothing left to run")
                       : fmt::format("{:.4g} collisions in {:.3g} s ({:.3g} collisions/s; kernel {})", collisions,
                                     seconds, seconds > 0 ? collisions / seconds : 0.0, kernel);
    const int K = spec.replicas;
    std::cout << fmt::format("roughgas run: wrote {} ({} rows, {} columns, {} replica{}): {}{}\n",
                             files.moments->path().string(), files.moments->rows(), table.columns().size(), K,
                             K > 1 ? "s" : "", work, summary.note);
    if (files.histograms)
        std::cout << fmt::format("roughgas run: wrote {} ({} histogram times x {} bins)\n",
                                 files.histograms->path().string(), files.histograms->times(), spec.histogram_bins);
    std::cout.flush();
    std::cerr << summary.headline;
}

void report_stop(const RunFiles& files, const std::filesystem::path& dir, int signal) {
    std::cerr << fmt::format("roughgas run: stopped by {}: {} complete rows in {}; checkpoint in {}; "
                             "continue with: roughgas run --resume {}\n",
                             StopSignals::name_of(signal), files.moments->rows(), files.moments->path().string(),
                             checkpoint_dir(dir).string(), dir.string());
}

} // namespace roughgas::cli
