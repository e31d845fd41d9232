// roughgas run CASE.toml --out DIR ... : the DSMC of the gas, homogeneous or in a box ([domain]),
// cooling, sheared or driven by its walls, writing DIR/moments.csv and the files of docs/reference.md
// "Output". run_run below is the pipeline, each stage a part of its own in run/ (docs/developing.md):
//   1. set-up (run/setup.hpp): the case or the checkpoint of --resume, the solver's spec, the output
//      directory, the memory, the restitution tables; every refusal before any work, nothing written;
//   2. outputs: what the files say of the run (run/provenance.hpp) and one writer per file family
//      (run/run_files.hpp: moments.csv and the box's files, histograms.csv, each replica's rows);
//   3. the replicas over the threads, with their checkpoints and stops (run/replica_scheduler.hpp);
//   4. under MPI, every rank's replicas to rank 0, which alone writes (run/rank_gather.hpp);
//   5. the steady or scaled summary and the report (run/summary.hpp, run/report.hpp).
//
// Checkpoints (docs/running.md): with --checkpoint-every X each replica saves its state to
// DIR/checkpoint/replica_R.bin every X collisions per particle (run/checkpoints.hpp), and
// `roughgas run --resume DIR` continues from those files: the CSVs come out byte for byte as from
// the run without a stop. SIGINT/SIGTERM (stop_signals.hpp) stop every replica at its next boundary
// with a checkpoint, write the CSV so far and exit 128 + the signal.
//
// Under an MPI launcher (mpirun -np R, srun; parallel/communicator.hpp) each rank runs a contiguous
// share of the replicas on its own threads and sends their rows and histograms to rank 0, which
// alone writes the files: the same bytes as one process, since every replica's streams derive from
// the seed and its index and the rows are combined in replica order. Each rank writes its own
// replicas' checkpoint files, so DIR must be on a file system every rank sees for
// --checkpoint-every, --resume and stops.
#include "commands.hpp"
#include "rank_errors.hpp"
#include "run/checkpoints.hpp"
#include "run/provenance.hpp"
#include "run/rank_gather.hpp"
#include "run/replica_records.hpp"
#include "run/replica_scheduler.hpp"
#include "run/report.hpp"
#include "run/run_files.hpp"
#include "run/setup.hpp"
#include "run/summary.hpp"
#include "stop_signals.hpp"

#include "roughgas/io/checkpoint_file.hpp"
#include "roughgas/io/moments_csv.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <system_error>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

int run_run(const RunOptions& o, const Communicator& comm) {
    // First: the signals are blocked in every thread started from here on (the OpenMP pool too).
    // Under a launcher rank 0 writes the CSV only once every rank has stopped: when the stop comes
    // because the launcher ends the job after a rank died, there is none to write.
    const StopSignals signals("run",
                              comm.under_launcher()
                                  ? "stopping at the next step and writing the replicas' checkpoints (rank 0 "
                                    "writes the CSV so far once every rank has stopped)"
                                  : "stopping at the next step, writing a checkpoint and the CSV so far",
                              !comm.under_launcher());
    const bool root = comm.is_root();
    // The messages are rank 0's; --quiet leaves out the progress line alone, never a warning or the
    // headline of the result.
    const bool quiet = o.quiet || !root;

    // 1. Set-up: the case or checkpoint, the spec, the output directory, the memory, the tables.
    const std::unique_ptr<RunSetup> setup = set_up_run(o, comm);
    const RunSpec& spec = setup->spec;
    const ReplicaRange& range = setup->replicas;
    if (root)
        report_contact_range(setup->cfg);

    // 2. Outputs: what the files say of the run, and their writers.
    const MomentsTable table(spec);
    const RunProvenance provenance = run_provenance(*setup, table, root);
    RunFiles files;
    if (root) {
        files.moments.emplace(setup->dir, spec, provenance);
        if (!spec.histogram_times.empty())
            files.histograms.emplace(setup->dir, spec, provenance);
    }
    if (root)
        report_tables(*setup);
    // Rank 0 prepares the directory; the other ranks' replica files come after its run.bin (several
    // ranks write one at a stop even without --checkpoint-every: theirs must belong to a resumable run).
    CheckpointWriter checkpoints(setup->dir, setup->manifest,
                                 !root || (setup->resuming && !setup->manifest_changed));
    prepare_output_dir(*setup, checkpoints, comm);
    ReplicaRecords records(range.count);
    records.restore(setup->resumed);
    // Each replica's own rows beside the ensemble's, written as they come by the one process of a
    // whole run; under MPI rank 0 writes them all once it has every rank's rows (the directory need
    // not be shared), and a range of --replicas leaves them to `roughgas merge`.
    if (range.count > 1 && !range.partial && comm.size() == 1) {
        files.replica_rows.emplace(setup->dir, spec, provenance.csv, range.mine_from, range.mine_to);
        files.replica_rows->add_rows(records.rows); // a resumed run: the rows of its checkpoints
    }

    // 3. The replicas, over this process's threads, with their checkpoints and stops.
    ReplicaScheduler scheduler(*setup, table, records, files, checkpoints, signals, quiet);
    scheduler.run();
    // The signal that stopped a replica of this rank (0: none); with several ranks, of any rank.
    const auto unfinished_in = [&](int a, int b) {
        return std::find(records.finished.begin() + a, records.finished.begin() + b, 0) != records.finished.begin() + b;
    };
    const int stop_signal =
        static_cast<int>(comm.max(unfinished_in(range.mine_from, range.mine_to) ? signals.signal() : 0));

    // 4. Every rank's replicas to rank 0, which alone writes from here on.
    gather_replicas(comm, *setup, records);
    if (!root)
        return stop_signal > 0 ? 128 + stop_signal : exit_ok;
    if (comm.size() > 1 && range.count > 1 && !range.partial) // every replica's own rows, as one process writes them
        ReplicaFiles(setup->dir, spec, provenance.csv, range.from, range.to).add_rows(records.rows);
    files.update(records, true);
    files.update_histograms(records); // a resumed run whose replicas had all finished: from the checkpoints
    if (unfinished_in(range.from, range.to)) {
        // Stopped by a signal: the running replicas saved their states; the finished ones save their
        // rows now, so that a resume runs neither again (not-started ones start afresh).
        checkpoints.write_manifest_once();
        if (files.moments->rows_on_disk() == 0 && !range.partial)
            files.moments->write(); // the header, even when no row is complete yet: the run's file exists
        for (int r = range.from; r < range.to; ++r)
            if (records.finished[static_cast<std::size_t>(r)] && !records.final_saved[static_cast<std::size_t>(r)])
                scheduler.save_replica(r, {});
        report_stop(files, setup->dir, stop_signal);
        return 128 + stop_signal;
    }
    if (comm.size() > 1 && setup->manifest.checkpoint_every == 0 && !range.partial &&
        !setup->resuming) { // run.bin was for a stop only
        std::error_code ec;
        fs::remove_all(checkpoint_dir(setup->dir), ec);
    }
    if (range.partial) {
        std::cout << fmt::format("roughgas run: replicas {} .. {} of {} finished: {} (combine the ranges with "
                                 "roughgas merge DIR... --out DIR)\n",
                                 range.from, range.to - 1, range.count, checkpoint_dir(setup->dir).string());
        return exit_ok;
    }

    // 5. The summary and the report.
    const RunSummary summary =
        summarize_run(setup->dir, spec, driven(setup->cfg), *files.moments, provenance);
    report_run(files, records, table, spec, scheduler.seconds(), summary);
    return exit_ok;
}

} // namespace

Subcommand add_run_command(CLI::App& parent, const Communicator& comm) {
    auto o = std::make_shared<RunOptions>();
    CLI::App* app = parent.add_subcommand(
        "run", "run a DSMC simulation of a cooling, thermostat-driven or uniformly sheared gas, "
               "homogeneous or in a box ([domain]), writing DIR/moments.csv");
    CLI::Option* case_opt = app->add_option("CASE", o->case_file, "case file (TOML)");
    CLI::Option* out = app->add_option("--out", o->out, "output directory (moments.csv)");
    CLI::Option* set = add_set_option(*app, o->sets);
    CLI::Option* seed = app->add_option("--seed", o->seed, "random seed (overrides run.seed)");
    app->add_option(
           "--threads", o->threads,
           "threads for the replicas and within each replica (default: the CPUs this process may use; results do not depend on it)")
        ->check(positive());
    app->add_flag("--quiet", o->quiet, "no progress line (warnings and the result's lines still print)");
    CLI::Option* force = app->add_flag(
        "--force", o->force, "overwrite the CSVs and checkpoint of an earlier run in the output directory");
    app->add_option("--checkpoint-every", o->checkpoint_every,
                    "save each replica's state to DIR/checkpoint every X collisions per particle")
        ->check(positive());
    CLI::Option* resume = app->add_option("--resume", o->resume,
                                          "continue the run in DIR from DIR/checkpoint (its case, seed, --set)");
    resume->excludes(case_opt)->excludes(out)->excludes(set)->excludes(seed)->excludes(force);
    app->add_option("--replicas", o->replicas,
                    "run only the replicas FROM .. TO-1 of run.replicas (0-based), writing DIR/checkpoint "
                    "for `roughgas merge` instead of the CSVs")
        ->excludes(resume);
    return {app, [o, app, &comm] {
                o->seed_given = app->count("--seed") > 0;
                o->checkpoint_every_given = app->count("--checkpoint-every") > 0;
                return run_run(*o, comm);
            }};
}

int run_in_one_process(const RunOptions& o) {
    const Communicator one_process{Launch{}};
    return run_run(o, one_process);
}

int resume_finished_run(const std::string& dir, int threads, bool quiet) {
    RunOptions o;
    o.resume = dir;
    o.threads = threads;
    o.quiet = quiet;
    return run_in_one_process(o);
}

} // namespace roughgas::cli
