#include "run/replica_scheduler.hpp"

#include "roughgas/io/fields_series.hpp"
#include "roughgas/io/input_error.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

// Thrown from a replica's sinks when another replica failed: ends the run early.
struct Cancelled {};

} // namespace

ReplicaScheduler::ReplicaScheduler(const RunSetup& setup, const MomentsTable& table, ReplicaRecords& records,
                                   RunFiles& files, CheckpointWriter& checkpoints, const StopSignals& signals,
                                   bool quiet)
    : setup_(setup), table_(table), records_(records), files_(files), checkpoints_(checkpoints), signals_(signals),
      progress_(quiet ? nullptr : &std::cerr, std::max(1, setup.replicas.mine_to - setup.replicas.mine_from),
                ::isatty(STDERR_FILENO) == 1) {}

void ReplicaScheduler::save_replica(int r, std::string state) {
    const auto k = static_cast<std::size_t>(r);
    std::vector<std::vector<double>> rows;
    std::vector<HistogramSet> sets;
    {
        std::lock_guard lock(mutex_);
        rows = records_.rows[k];
        sets = records_.histograms[k];
    }
    checkpoints_.save_replica(static_cast<std::uint64_t>(r), std::move(rows), std::move(sets), std::move(state));
}

void ReplicaScheduler::run() {
    const ReplicaRange& range = setup_.replicas;
    for (int r = range.from; r < range.to; ++r)
        if (records_.finished[static_cast<std::size_t>(r)]) {
            records_.final_saved[static_cast<std::size_t>(r)] = 1; // its file says so already
            if (range.mine(r))
                progress_.update(r - range.mine_from, setup_.spec.end, setup_.spec.end, 0);
        }
    std::atomic<bool> cancel{false};
    std::exception_ptr error;
    // --threads T is shared: min(T, K) replicas at a time, each with T/min(T, K) threads.
    RunSpec spec = setup_.spec;
    const int threads = std::min(spec.threads, std::max(1, range.mine_to - range.mine_from));
    spec.threads = std::max(1, spec.threads / threads);
    if (threads > 1 && spec.threads > 1)
        omp_set_max_active_levels(2);
    const double checkpoint_every = setup_.manifest.checkpoint_every;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int r = 0; r < range.count; ++r) {
        const auto k = static_cast<std::size_t>(r);
        try {
            if (cancel)
                throw Cancelled{};
            // Another process's; done in an earlier run; or stopped before it started.
            if (!range.mine(r) || records_.finished[k] || signals_.requested())
                continue;
            const RowSink sink = [&, r](std::span<const double> row) {
                if (cancel)
                    throw Cancelled{};
                table_.check(row);         // NonFiniteValue: stop, naming the column and t
                if (files_.replica_rows) // replica r's own file: its thread's alone, no lock
                    files_.replica_rows->add(r, row);
                std::lock_guard lock(mutex_);
                records_.rows[static_cast<std::size_t>(r)].emplace_back(row.begin(), row.end());
                files_.update(records_, false);
            };
            const ProgressSink report = [&, r](double done, double end, double coll) {
                progress_.update(r - range.mine_from, done, end, coll);
            };
            HistogramSink hsink;
            if (!spec.histogram_times.empty()) {
                hsink = [&, r](const HistogramSet& h) {
                    if (cancel)
                        throw Cancelled{};
                    std::lock_guard lock(mutex_);
                    records_.histograms[static_cast<std::size_t>(r)].push_back(h);
                    files_.update_histograms(records_);
                };
            }
            // The replica's cell fields: each replica to its own files, written behind the run.
            std::optional<FieldsSeries> series;
            FieldSink fsink;
            if (spec.domain && spec.domain->fields && r < spec.domain->fields->replicas) {
                series.emplace(setup_.dir, r, *spec.domain, setup_.resuming);
                fsink = [&series](const FieldSnapshot& s) { series->add(s); };
            }
            ReplicaCheckpoints ck;
            ck.every = checkpoint_every;
            ck.save = [&, r](std::string state) {
                if (series) // the snapshots before a checkpoint are on disk before it
                    series->flush();
                save_replica(r, std::move(state));
            };
            ck.stop = [&] { return signals_.requested(); };
            if (setup_.resuming && setup_.resumed[k]) // checked before the run; read again now (memory)
                ck.resume = read_replica_state(setup_.dir, k, setup_.manifest.run);
            ReplicaEnd end;
            try {
                end = run_replica(spec, *setup_.tables, r, sink, report, &records_.summaries[k], hsink, &ck, fsink);
                if (series)
                    series->flush();
            } catch (const ResumeError& e) {
                const fs::path file = replica_checkpoint_path(setup_.dir, k);
                throw InputError(file.string(), "--resume",
                                 std::string("cannot resume: its state does not fit the case: ") + e.what());
            }
            if (end == ReplicaEnd::finished) {
                records_.finished[k] = 1;
                if (checkpoint_every > 0 || range.partial) { // a resume (or merge) will not run it again
                    save_replica(r, {});
                    records_.final_saved[k] = 1;
                }
            }
        } catch (const Cancelled&) {
        } catch (...) {
            std::lock_guard lock(mutex_);
            if (!error)
                error = std::current_exception();
            cancel = true;
        }
    }
    progress_.finish();
    if (files_.replica_rows) {
        try {
            files_.replica_rows->write_all();
        } catch (...) { // the first error is the one to report
            if (!error)
                error = std::current_exception();
        }
    }
    if (!error)
        return;
    // One rank's (main ends the job) or the one process's.
    std::lock_guard lock(mutex_);
    files_.update(records_, true);
    const std::size_t on_disk = files_.moments ? files_.moments->rows_on_disk() : 0;
    try {
        std::rethrow_exception(error);
    } catch (const NonFiniteValue& e) {
        throw std::runtime_error(
            on_disk > 0
                ? fmt::format("{}; the {} rows before it are in {}", e.what(), on_disk, files_.moments->path().string())
                : fmt::format("{}; no row was complete before it, nothing written", e.what()));
    }
}

} // namespace roughgas::cli
