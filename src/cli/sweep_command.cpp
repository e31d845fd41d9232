// roughgas sweep CASE.toml --param KEY=FROM:TO:COUNT --out DIR: runs a case at COUNT values of one
// key, FROM to TO evenly spaced (COUNT = 1: FROM only), and writes one summary row per point to
// DIR/sweep.csv, plus each point's moments.csv in DIR/point_K/.
//
// Every point is validated before any work (exit 2 naming the key and the allowed range). Points
// run in parallel over --threads (OpenMP, dynamic schedule); each point runs its replicas in turn
// and is deterministic from the case's seed, so the files do not depend on the thread count.
// The summary is the steady state of the point (observables/steady_state.hpp, io/steady_csv.hpp):
// for driven runs (uniform shear, boxes whose walls heat or shear the gas: driven() in
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
#include "commands.hpp"
#include "memory_check.hpp"
#include "rank_errors.hpp"

#include "roughgas/core/available_cpus.hpp"
#include "output_dir_lock.hpp"
#include "stop_signals.hpp"

#include "roughgas/dsmc/run.hpp"
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/run_spec_from_case.hpp"
#include "roughgas/io/run_states.hpp"
#include "roughgas/io/run_tables.hpp"
#include "roughgas/io/steady_csv.hpp"
#include "roughgas/core/bytes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>

namespace roughgas::cli {
namespace {

struct SweepOptions {
    std::string case_file;
    std::string param;
    std::string out;
    std::vector<std::string> sets;
    int threads = 0;
    bool quiet = false;
    bool force = false;
};

struct Sweep {
    std::string key, from, to;
    long count = 0;
};

// KEY=FROM:TO:COUNT
Sweep parse_sweep(const SweepOptions& o) {
    const auto bad = [&](const std::string& why) {
        return InputError(o.case_file, "--param",
                          "--param " + o.param + ": " + why +
                              " (expected KEY=FROM:TO:COUNT, e.g. collision.alpha=0.5:0.9:5)");
    };
    const std::size_t eq = o.param.find('=');
    const std::size_t c1 = o.param.find(':', eq == std::string::npos ? 0 : eq);
    const std::size_t c2 = c1 == std::string::npos ? c1 : o.param.find(':', c1 + 1);
    if (eq == std::string::npos || eq == 0 || c2 == std::string::npos) {
        throw bad("malformed");
    }
    Sweep s{o.param.substr(0, eq), o.param.substr(eq + 1, c1 - eq - 1), o.param.substr(c1 + 1, c2 - c1 - 1),
            0};
    const std::string count = o.param.substr(c2 + 1);
    const auto [ptr, ec] = std::from_chars(count.data(), count.data() + count.size(), s.count);
    if (ec != std::errc() || ptr != count.data() + count.size() || s.count < 1) {
        throw bad("COUNT must be an integer >= 1");
    }
    return s;
}

namespace fs = std::filesystem;

double parse_number(const SweepOptions& o, const std::string& text) {
    double x = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || ptr != text.data() + text.size())
        throw InputError(o.case_file, "--param",
                         "--param " + o.param + ": FROM and TO must be numbers (expected KEY=FROM:TO:COUNT)");
    return x;
}

// One point: every replica in turn, the rows combined as `roughgas run` does.
struct PointResult {
    std::vector<std::string> names, units;
    std::vector<std::vector<double>> rows;
    SteadyResult steady;
};

// The point's summary from its replicas' rows (rows[r][k]: replica r's row k).
PointResult point_result(const CaseConfig& cfg, const std::vector<std::vector<std::vector<double>>>& rows) {
    const RunSpec spec = run_spec_from_case(cfg);
    MomentsTable table(spec);
    PointResult p{table.names(), table.units(), {}, {}};
    for (std::size_t k = 0; k < rows[0].size(); ++k) {
        std::vector<std::span<const double>> spans;
        for (const auto& r : rows)
            spans.emplace_back(r[k]);
        p.rows.push_back(table.combine(spans));
    }
    p.steady = steady_summary(p.names, p.rows, driven(cfg));
    return p;
}

// Every replica's rows; empty when `signals` asked for a stop before the point ended (its state is dropped).
// `spec`: the point's, with initial.from's state attached (checked before any work).
std::optional<std::vector<std::vector<std::vector<double>>>> run_point(RunSpec spec, const StopSignals& signals) {
    spec.threads = 1;
    MomentsTable table(spec);
    const auto tables = build_run_tables(spec);
    // No checkpoints: only the stop is polled at the replica's boundaries (the state it hands over
    // on a stop is not kept).
    ReplicaCheckpoints stop;
    stop.save = [](std::string) {};
    stop.stop = [&] { return signals.requested(); };
    std::vector<std::vector<std::vector<double>>> rows(static_cast<std::size_t>(spec.replicas));
    for (int r = 0; r < spec.replicas; ++r) {
        const auto sink = [&](std::span<const double> row) {
            table.check(row); // NonFiniteValue: stop, naming the column and t
            rows[static_cast<std::size_t>(r)].emplace_back(row.begin(), row.end());
        };
        if (signals.requested() ||
            run_replica(spec, *tables, r, sink, {}, nullptr, {}, &stop) == ReplicaEnd::stopped)
            return std::nullopt;
    }
    return rows;
}

int run_sweep(const SweepOptions& o, const Communicator& comm) {
    // First: the signals are blocked in every thread started from here on (the OpenMP pool too).
    const StopSignals signals("sweep",
                              "stopping every point at its next step; the finished points keep "
                              "their point_K/moments.csv, no sweep.csv is written",
                              !comm.under_launcher());
    const bool root = comm.is_root();
    Sweep s;
    std::vector<double> values;
    std::vector<CaseConfig> cases;
    std::vector<RunSpec> specs; // the points' (initial.from attached)
    std::vector<std::vector<std::string>> point_sets;
    const fs::path dir(o.out);
    OutputDirLock lock; // one writer per directory (output_dir_lock.hpp), until the sweep ends
    // Every point is validated (exit 2) before any work; rank 0 checks and locks the directory.
    agree_on_setup(comm, [&] {
    s = parse_sweep(o);
    const double from = parse_number(o, s.from), to = parse_number(o, s.to);
    for (long k = 0; k < s.count; ++k) {
        // Rounded to 15 significant digits: the decimal the user means (0.8, not the 0.7999999999999999
        // the arithmetic gives), which the CSVs and messages then show as such.
        const double x = std::stod(fmt::format(
            "{:.15g}", s.count == 1 ? from
                                    : from + (to - from) * static_cast<double>(k) / static_cast<double>(s.count - 1)));
        std::vector<std::string> sets = o.sets;
        sets.push_back(fmt::format("{}={}", s.key, x));
        cases.push_back(load_case(o.case_file, sets, CaseUse::run));
        if (cases.back().fields)
            throw InputError(o.case_file, "fields",
                             "[fields] in a sweep: a sweep writes each point's moments.csv only (run a point with "
                             "roughgas run CASE --set KEY=VALUE for its fields)");
        values.push_back(x);
        point_sets.push_back(sets);
    }
    // Points run at the same time, one replica each at a time: the largest of them, times the threads.
    for (const CaseConfig& c : cases) {
        specs.push_back(run_spec_from_case(c));
        attach_initial_state(specs.back(), c, o.case_file); // initial.from's files checked before any work
    }
    const RunSpec& largest = *std::max_element(
        specs.begin(), specs.end(), [](const RunSpec& a, const RunSpec& b) { return a.particles < b.particles; });
    const long long points = (s.count + comm.size() - 1) / comm.size();
    refuse_if_too_large(largest,
                        static_cast<int>(std::max(1LL, std::min<long long>(o.threads > 0 ? o.threads : default_threads(),
                                                                           points))),
                        o.case_file);
    if (!root)
        return;
    if (fs::exists(dir) && !fs::is_directory(dir))
        throw InputError(dir.string(), "--out", "--out " + dir.string() + ": exists and is not a directory");
    lock.lock_if_exists(dir);
    if (!o.force && fs::exists(dir / "sweep.csv"))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: sweep.csv exists (use --force to overwrite)", dir.string()));
    fs::create_directories(dir);
    lock.lock(dir);
    });

    if (root) {
        for (const std::string& u : cases[0].unused) // kept in the case, not used by the sweep's runs
            std::cerr << "roughgas sweep: warning: " << u << '\n';
        if (cases[0].run.save_state)
            std::cerr << "roughgas sweep: warning: run.save_state is not used by roughgas sweep (a run of one "
                         "point with roughgas run writes the state)\n";
    }
    // This rank's points: k = rank, rank + R, ... (all of them in one process).
    std::vector<long> mine;
    for (long k = comm.rank(); k < s.count; k += comm.size())
        mine.push_back(k);
    const int threads = std::max<int>(
        1, std::min<int>(o.threads > 0 ? o.threads : default_threads(), static_cast<int>(mine.size())));
    std::vector<PointResult> results(values.size());
    std::vector<std::vector<std::vector<std::vector<double>>>> point_rows(values.size()); // [k][replica][row]
    std::vector<char> done(values.size(), 0);
    std::exception_ptr error;
    std::mutex mutex;
    // Point k's moments.csv, written by rank 0 (as each of its own points ends, the others' after the gather).
    const auto write_point = [&](long k, const PointResult& p) {
            CsvProvenance prov;
            prov.case_file = o.case_file;
            prov.overrides = point_sets[static_cast<std::size_t>(k)];
            prov.seed = cases[static_cast<std::size_t>(k)].run.seed;
            prov.resolved_case = emit_case(cases[static_cast<std::size_t>(k)]);
            prov.notes = {fmt::format("sweep point {} of {}: {} = {}", k, s.count, s.key,
                                      values[static_cast<std::size_t>(k)]),
                          unit_system_note(cases[static_cast<std::size_t>(k)])};
            prov.units = p.units;
            CsvWriter csv(p.names, prov);
            for (const auto& row : p.rows)
                csv.add_row(row);
            const fs::path pd = dir / fmt::format("point_{}", k);
            fs::create_directories(pd);
            csv.write(pd / "moments.csv");
            // Its summary beside it: steady.csv for a driven gas (shear, heating walls), scaled.csv for cooling.
            const bool shear = driven(cases[static_cast<std::size_t>(k)]);
            prov.notes.push_back(fmt::format("{} summary of moments.csv: drift criterion on {}; batch means "
                                             "(observables/steady_state.hpp); X_err = batch-means standard error",
                                             shear ? "steady-state" : "scaled-state (late-time)",
                                             fmt::join(p.steady.monitored, ", ")));
            prov.units = steady_csv_units(p.steady, p.names, p.units);
            CsvWriter summary(steady_csv_columns(p.steady), prov);
            summary.add_row(steady_csv_row(p.steady, p.names, p.rows));
            summary.write(pd / (shear ? "steady.csv" : "scaled.csv"));
    };
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::size_t i = 0; i < mine.size(); ++i) {
        const long k = mine[i];
        try {
            {
                std::lock_guard lock(mutex);
                if (error)
                    continue;
            }
            if (signals.requested())
                continue;
            auto rows = run_point(specs[static_cast<std::size_t>(k)], signals);
            if (!rows)
                continue;
            PointResult p = point_result(cases[static_cast<std::size_t>(k)], *rows);
            if (root)
                write_point(k, p);
            std::lock_guard lock(mutex);
            if (!o.quiet)
                std::cerr << fmt::format("roughgas sweep: point {} ({} = {:.6g}) done{}\n", k, s.key,
                                         values[static_cast<std::size_t>(k)],
                                         p.steady.reached ? "" : " (steady state NOT reached)");
            results[static_cast<std::size_t>(k)] = std::move(p);
            point_rows[static_cast<std::size_t>(k)] = std::move(*rows);
            done[static_cast<std::size_t>(k)] = 1;
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
        }
    }
    if (error) // one rank's (main ends the job) or the one process's
        std::rethrow_exception(error);
    const int stop_signal = static_cast<int>(comm.max(signals.signal()));
    if (comm.size() > 1) { // every rank's finished points to rank 0: their replicas' rows
        ByteWriter w;
        for (long k : mine) {
            const auto K = static_cast<std::size_t>(k);
            if (!done[K])
                continue;
            w.u64(K);
            w.u64(point_rows[K].size());
            for (const auto& replica : point_rows[K]) {
                w.u64(replica.size());
                for (const auto& row : replica)
                    w.f64s(row);
            }
        }
        const std::vector<std::string> parts = comm.gather(w.bytes());
        if (!root)
            return stop_signal > 0 ? 128 + stop_signal : exit_ok;
        for (std::size_t p = 1; p < parts.size(); ++p) {
            ByteReader in(parts[p]);
            while (in.remaining() > 0) {
                const auto K = static_cast<std::size_t>(in.u64());
                std::vector<std::vector<std::vector<double>>> rows(in.count(sizeof(std::uint64_t)));
                for (auto& replica : rows) {
                    replica.resize(in.count(sizeof(std::uint64_t)));
                    for (auto& row : replica)
                        row = in.f64s();
                }
                results[K] = point_result(cases[K], rows);
                write_point(static_cast<long>(K), results[K]);
                done[K] = 1;
            }
        }
    }
    if (stop_signal > 0) {
        std::string finished;
        for (std::size_t k = 0; k < done.size(); ++k)
            if (done[k])
                finished += fmt::format("{}{}", finished.empty() ? "" : ", ", k);
        std::cerr << fmt::format(
            "roughgas sweep: stopped by {}: {} of {} points finished{}{}; no {} written\n",
            StopSignals::name_of(stop_signal),
            std::count(done.begin(), done.end(), 1), s.count,
            finished.empty() ? "" : " (point_K/moments.csv for K = ", finished.empty() ? "" : finished + ")",
            (dir / "sweep.csv").string());
        return 128 + stop_signal;
    }

    std::vector<std::string> columns = {s.key};
    const std::vector<std::string> steady_cols = steady_csv_columns(results[0].steady);
    columns.insert(columns.end(), steady_cols.begin(), steady_cols.end());
    CsvProvenance prov;
    prov.case_file = o.case_file;
    prov.overrides = o.sets;
    prov.seed = cases[0].run.seed;
    prov.resolved_case = emit_case(cases[0]);
    prov.notes = {
        fmt::format("sweep of {} from {} to {} ({} points); one row per point: the {} state, drift criterion "
                    "on {}, batch means (io/steady_csv.hpp); each point's rows in point_K/moments.csv, its "
                    "summary in point_K/{}",
                    s.key, s.from, s.to, s.count, driven(cases[0]) ? "steady" : "scaled",
                    fmt::join(results[0].steady.monitored, ", "),
                    driven(cases[0]) ? "steady.csv" : "scaled.csv"),
        unit_system_note(cases[0])};
    // The swept key's unit (its schema entry), then the summary's.
    const KeySpec* key_spec = find_key_of(s.key);
    prov.units = {key_spec && !key_spec->unit.empty() ? key_spec->unit : "-"};
    for (const std::string& u : steady_csv_units(results[0].steady, results[0].names, results[0].units))
        prov.units.push_back(u);
    CsvWriter csv(columns, prov);
    for (std::size_t k = 0; k < results.size(); ++k) {
        if (steady_csv_columns(results[k].steady) != steady_cols)
            throw std::runtime_error("roughgas sweep: the points have different columns (a sweep changes one "
                                     "scalar key only)");
        std::vector<double> row = {values[k]};
        const std::vector<double> st = steady_csv_row(results[k].steady, results[k].names, results[k].rows);
        row.insert(row.end(), st.begin(), st.end());
        csv.add_row(row);
    }
    csv.write(dir / "sweep.csv");
    if (!o.quiet) { // the headline quantities of every point, compact, on stderr
        std::vector<std::string> headline;
        // Uniform shear: its rheology; otherwise (cooling, wall-driven boxes) the monitored columns.
        const bool shear = cases[0].run.kind == RunKind::shear;
        std::vector<std::string> wanted = {"a_star", "eta_star", "theta", "N1_star"};
        if (!shear) { // the species' temperature ratios first, then theta and the cumulants
            wanted = results[0].steady.monitored;
            std::stable_partition(wanted.begin(), wanted.end(),
                                  [](const std::string& c) { return c.find('/') != std::string::npos; });
        }
        for (const std::string& c : wanted)
            for (const SteadyValue& v : results[0].steady.values)
                if (v.name == c && headline.size() < 6)
                    headline.push_back(c);
        std::string table = fmt::format("roughgas sweep: {:>12} {:>7}", s.key, "from");
        for (const std::string& h : headline)
            table += fmt::format(" {:>22}", h);
        table += "\n";
        for (std::size_t k = 0; k < results.size(); ++k) {
            const SteadyResult& st = results[k].steady;
            const auto cpp = std::find(results[k].names.begin(), results[k].names.end(), "coll_per_particle") -
                             results[k].names.begin();
            table += fmt::format("roughgas sweep: {:>12.6g} {:>7}", values[k],
                                 st.reached ? fmt::format("{:.3g}", results[k].rows[st.first_row][static_cast<std::size_t>(cpp)])
                                            : std::string("none"));
            for (const std::string& h : headline)
                for (const SteadyValue& v : st.values)
                    if (v.name == h)
                        table += fmt::format(" {:>22}", fmt::format("{:.5g} +- {:.2g}", v.mean, v.err));
            table += "\n";
        }
        std::cerr << table;
    }
    std::cout << fmt::format("roughgas sweep: wrote {} ({} points, {} columns)\n",
                             (dir / "sweep.csv").string(), results.size(), columns.size());
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
