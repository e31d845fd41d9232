// roughgas sweep CASE.toml --param KEY=FROM:TO:COUNT --out DIR: runs a case at COUNT values of one
// key, FROM to TO evenly spaced (COUNT = 1: FROM only), and writes one summary row per point to
// DIR/sweep.csv, plus each point's moments.csv in DIR/point_K/.
//
// Every point is validated before any work (exit 2 naming the key and the allowed range). Points
// run in parallel over --threads (OpenMP, dynamic schedule); each point runs its replicas in turn
// and is deterministic from the case's seed, so the files do not depend on the thread count.
// The summary is the steady state of the point (observables/steady_state.hpp, io/steady_csv.hpp):
// for driven runs (uniform shear, a thermostat, boxes whose walls heat or shear the gas: driven() in
// io/case_config.hpp) the steady window of T and P*_ij; for cooling runs the scaled homogeneous cooling
// state (theta, a20, a02 stop drifting while T falls), averaged with batch-means errors.
//
// SIGINT/SIGTERM (stop_signals.hpp): the running points stop at their next step boundary and are
// dropped, the points not started are skipped; the finished points keep DIR/point_K/moments.csv,
// no sweep.csv is written (a summary with points missing would read as the whole sweep), and the
// exit status is 128 + the signal's number. A sweep has no checkpoints: run it again to redo it.
//
// Under an MPI launcher (parallel/communicator.hpp) rank k runs the points k, k + R, k + 2R, ... on
// its threads and sends their rows to rank 0, which writes every file: the same bytes as one process.
//
// run_sweep below is the pipeline; its parts are those of `roughgas run` where they are the same
// (run/setup.hpp's plan_case, run/summary.hpp's summary file) and its own in sweep/ where a point
// differs from a replica: the points (sweep/points.hpp), a point's run, files and gather
// (sweep/point_run.hpp), and sweep.csv (sweep/sweep_table.hpp).
#include "commands.hpp"
#include "memory_check.hpp"
#include "output_dir_lock.hpp"
#include "rank_errors.hpp"
#include "stop_signals.hpp"
#include "sweep/point_run.hpp"
#include "sweep/points.hpp"
#include "sweep/sweep_table.hpp"

#include "roughgas/core/available_cpus.hpp"
#include "roughgas/io/input_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

int run_sweep(const SweepOptions& o, const Communicator& comm) {
    // First: the signals are blocked in every thread started from here on (the OpenMP pool too).
    const StopSignals signals("sweep",
                              "stopping every point at its next step; the finished points keep "
                              "their point_K/moments.csv, no sweep.csv is written",
                              !comm.under_launcher());
    const bool root = comm.is_root();
    const fs::path dir(o.out);

    // 1. Set-up: every point validated and planned (exit 2) before any work; rank 0 checks and locks
    // the directory (one writer per directory, output_dir_lock.hpp, until the sweep ends).
    SweepPoints points;
    OutputDirLock lock;
    agree_on_setup(comm, [&] {
        points = plan_points(o);
        // Points run at the same time, one replica each at a time: the largest of them, times the threads.
        const RunSpec& largest =
            *std::max_element(points.specs.begin(), points.specs.end(),
                              [](const RunSpec& a, const RunSpec& b) { return a.particles < b.particles; });
        const long long per_rank = (points.count + comm.size() - 1) / comm.size();
        refuse_if_too_large(largest,
                            static_cast<int>(std::max(
                                1LL, std::min<long long>(o.threads > 0 ? o.threads : default_threads(), per_rank))),
                            o.case_file);
        if (!root)
            return;
        if (fs::exists(dir) && !fs::is_directory(dir))
            throw InputError(dir.string(), "--out", "--out " + dir.string() + ": exists and is not a directory");
        lock.lock_if_exists(dir);
        if (!o.force && fs::exists(dir / sweep_file))
            throw InputError(dir.string(), "--out",
                             fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(), sweep_file));
        fs::create_directories(dir);
        lock.lock(dir);
    });
    if (root) {
        for (const std::string& u : points.cases[0].unused) // kept in the case, not used by the sweep's runs
            std::cerr << "roughgas sweep: warning: " << u << '\n';
        if (points.cases[0].run.save_state)
            std::cerr << "roughgas sweep: warning: run.save_state is not used by roughgas sweep (a run of one "
                         "point with roughgas run writes the state)\n";
    }

    // 2. This rank's points, k = rank, rank + R, ... (all of them in one process), in parallel over
    // its threads (dynamic schedule); each point deterministic from the case's seed, so the files do
    // not depend on the thread count. Rank 0 writes each of its points' files as the point ends.
    std::vector<long> mine;
    for (long k = comm.rank(); k < points.count; k += comm.size())
        mine.push_back(k);
    const int threads = std::max<int>(
        1, std::min<int>(o.threads > 0 ? o.threads : default_threads(), static_cast<int>(mine.size())));
    std::vector<PointResult> results(points.values.size());
    std::vector<ReplicaRows> point_rows(points.values.size());
    std::vector<char> done(points.values.size(), 0);
    std::exception_ptr error;
    std::mutex mutex;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::size_t i = 0; i < mine.size(); ++i) {
        const long k = mine[i];
        const auto K = static_cast<std::size_t>(k);
        try {
            {
                std::lock_guard lock(mutex);
                if (error)
                    continue;
            }
            if (signals.requested())
                continue;
            auto rows = run_point(points.specs[K], signals);
            if (!rows)
                continue;
            PointResult p = point_result(points.cases[K], *rows);
            if (root)
                write_point_files(dir, o, points, k, p);
            std::lock_guard lock(mutex);
            if (!o.quiet)
                std::cerr << fmt::format("roughgas sweep: point {} ({} = {:.6g}) done{}\n", k, points.key,
                                         points.values[K], p.steady.reached ? "" : " (steady state NOT reached)");
            results[K] = std::move(p);
            point_rows[K] = std::move(*rows);
            done[K] = 1;
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
        }
    }
    if (error) // one rank's (main ends the job) or the one process's
        std::rethrow_exception(error);
    const int stop_signal = static_cast<int>(comm.max(signals.signal()));

    // 3. Under MPI, every rank's finished points to rank 0, which writes their files.
    if (comm.size() > 1) {
        const std::vector<std::size_t> received = gather_points(comm, mine, point_rows, done);
        if (!root)
            return stop_signal > 0 ? 128 + stop_signal : exit_ok;
        for (std::size_t K : received) {
            results[K] = point_result(points.cases[K], point_rows[K]);
            write_point_files(dir, o, points, static_cast<long>(K), results[K]);
        }
    }
    if (stop_signal > 0) { // a summary with points missing would read as the whole sweep
        std::string finished;
        for (std::size_t k = 0; k < done.size(); ++k)
            if (done[k])
                finished += fmt::format("{}{}", finished.empty() ? "" : ", ", k);
        std::cerr << fmt::format(
            "roughgas sweep: stopped by {}: {} of {} points finished{}{}; no {} written\n",
            StopSignals::name_of(stop_signal), std::count(done.begin(), done.end(), 1), points.count,
            finished.empty() ? "" : " (point_K/moments.csv for K = ", finished.empty() ? "" : finished + ")",
            (dir / sweep_file).string());
        return 128 + stop_signal;
    }

    // 4. The sweep's table.
    const std::size_t columns = write_sweep_csv(dir, o, points, results);
    if (!o.quiet)
        print_sweep_table(points, results);
    std::cout << fmt::format("roughgas sweep: wrote {} ({} points, {} columns)\n", (dir / sweep_file).string(),
                             results.size(), columns);
    return exit_ok;
}

} // namespace

Subcommand add_sweep_command(CLI::App& parent, const Communicator& comm) {
    auto o = std::make_shared<SweepOptions>();
    CLI::App* app =
        parent.add_subcommand("sweep", "run a case over a range of one parameter, writing DIR/sweep.csv "
                                       "(one steady-state summary row per point)");
    app->add_option("CASE", o->case_file, "case file (TOML)")->required();
    app->add_option("--param", o->param, "KEY=FROM:TO:COUNT, e.g. collision.alpha=0.5:0.9:5")->required();
    app->add_option("--out", o->out, "output directory")->required();
    add_set_option(*app, o->sets);
    app->add_option("--threads", o->threads,
                    "threads over the points (default: the CPUs this process may use; results do not depend on it)")
        ->check(positive());
    app->add_flag("--quiet", o->quiet, "no progress output");
    app->add_flag("--force", o->force, "overwrite an existing output directory");
    return {app, [o, &comm] { return run_sweep(*o, comm); }};
}

} // namespace roughgas::cli
