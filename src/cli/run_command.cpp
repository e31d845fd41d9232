// roughgas run CASE.toml --out DIR ... : the DSMC of the homogeneous gas, cooling or in
// uniform shear flow, writing DIR/moments.csv (docs/reference.md "Output", io/moments_csv.hpp)
// and, for shear runs, DIR/steady.csv (the steady state found in the rows, io/steady_csv.hpp).
//
// Order of work: validate the case and the output directory (exit 2, nothing written), build the
// restitution tables, then run the replicas (in parallel over --threads when replicas > 1, and the
// groups of one replica over the threads left; each replica is deterministic, so the file does not
// depend on the thread count). The file is rewritten atomically as rows complete (at every output
// time, batched only when rewriting would take more than a tenth of the time, and at the end), so a
// crash or a kill keeps what was computed.
//
// Checkpoints (docs/running.md): with --checkpoint-every X each replica
// saves its state to DIR/checkpoint/replica_R.bin every X collisions per particle (run_checkpoints.hpp,
// io/checkpoint_file.hpp), and `roughgas run --resume DIR` continues from those files: the CSVs come
// out byte for byte as from the run without a stop. SIGINT/SIGTERM (stop_signals.hpp) stop every
// replica at its next boundary with a checkpoint, write the CSV so far and exit 128 + the signal.
//
// Under an MPI launcher (mpirun -np R, srun; parallel/communicator.hpp) each rank runs a contiguous
// share of the replicas on its own threads and sends their rows and histograms to rank 0, which
// alone writes the files: the same bytes as one process, since every replica's streams derive from
// the seed and its index and the rows are combined in replica order. Rank 0 writes the CSVs when
// the ranks have finished (or stopped); each rank writes its own replicas' checkpoint files, so
// DIR must be on a file system every rank sees for --checkpoint-every, --resume and stops.
#include "commands.hpp"
#include "memory_check.hpp"
#include "rank_errors.hpp"
#include "replica_files.hpp"
#include "resolution_watch.hpp"

#include "roughgas/core/available_cpus.hpp"

#include <omp.h>
#include "output_dir_lock.hpp"
#include "progress.hpp"
#include "quasistatic_warning.hpp"
#include "run_checkpoints.hpp"
#include "stop_signals.hpp"

#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/checkpoint_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/fields_series.hpp"
#include "roughgas/io/histograms_csv.hpp"
#include "roughgas/io/moments_csv.hpp"
#include "roughgas/io/run_spec_from_case.hpp"
#include "roughgas/io/run_states.hpp"
#include "roughgas/io/state_file.hpp"
#include "roughgas/io/run_tables.hpp"
#include "roughgas/io/steady_csv.hpp"
#include "roughgas/core/bytes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <unistd.h>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* output_file = "moments.csv";
constexpr const char* histograms_file = "histograms.csv";
constexpr const char* steady_file = "steady.csv";
constexpr const char* scaled_file = "scaled.csv";
constexpr const char* walls_file = "walls.csv";
constexpr const char* profiles_file = "profiles.csv";
constexpr const char* steady_profiles_file = "steady_profiles.csv";
constexpr const char* spectra_file = "spectra.csv";
constexpr const char* modes_file = "modes.csv";

struct RunOptions {
    std::string case_file;
    std::string out;
    std::vector<std::string> sets;
    std::uint64_t seed = 0;
    int threads = 0;
    bool quiet = false;
    bool force = false;
    double checkpoint_every = 0;
    std::string resume;
    std::string replicas; // --replicas FROM:TO
    bool seed_given = false, checkpoint_every_given = false;
};

// --replicas FROM:TO: the replicas FROM, FROM + 1, ..., TO - 1 of run.replicas (0-based).
std::pair<std::uint64_t, std::uint64_t> replica_range(const std::string& text, std::uint64_t replicas) {
    const auto refuse = [&] {
        return InputError("", "--replicas",
                          fmt::format("--replicas {}: give FROM:TO with 0 <= FROM < TO <= run.replicas = {} "
                                      "(the replicas FROM .. TO - 1)",
                                      text, replicas));
    };
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        throw refuse();
    std::uint64_t from = 0, to = 0;
    try {
        std::size_t used = 0;
        const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
        if (a.empty() || b.empty() || a[0] == '-' || b[0] == '-')
            throw refuse();
        from = std::stoull(a, &used);
        if (used != a.size())
            throw refuse();
        to = std::stoull(b, &used);
        if (used != b.size())
            throw refuse();
    } catch (const std::logic_error&) {
        throw refuse();
    }
    if (!(from < to && to <= replicas))
        throw refuse();
    return {from, to};
}

// Never overwrite earlier results by accident: that is an input error, reported before any work.
// A checkpoint of an earlier run counts too: it is continued with --resume, or replaced with --force.
void check_output_dir(const fs::path& dir, bool force, bool histograms, bool shear, bool walls, bool box,
                      bool spectra, bool modes, bool fields) {
    if (fs::exists(dir) && !fs::is_directory(dir))
        throw InputError(dir.string(), "--out", "--out " + dir.string() + ": exists and is not a directory");
    if (force)
        return;
    // First, since a stopped run has its CSVs too, and --force would throw its checkpoint away.
    if (fs::exists(checkpoint_dir(dir)))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: {} exists (continue that run with --resume {}, or start "
                                     "over with --force)",
                                     dir.string(), checkpoint_dir(dir).string(), dir.string()));
    if (fs::exists(state_dir(dir)))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(),
                                     state_dir(dir).string()));
    if (fields && fs::exists(fields_dir(dir)))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(),
                                     fields_dir(dir).string()));
    if (fs::exists(replicas_dir(dir)))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(),
                                     replicas_dir(dir).string()));
    for (const char* file :
         {output_file, histograms_file, steady_file, scaled_file, walls_file, profiles_file, steady_profiles_file,
          spectra_file, modes_file}) {
        if ((file == histograms_file && !histograms) || (file == steady_file && !shear) ||
            (file == spectra_file && !spectra) || (file == modes_file && !modes) ||
            (file == steady_profiles_file && !(shear && box)) ||
            (file == scaled_file && shear) || (file == walls_file && !walls) || (file == profiles_file && !box))
            continue;
        if (fs::exists(dir / file))
            throw InputError(
                dir.string(), "--out",
                fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(), file));
    }
}

// Thrown from a replica's row sink when another replica failed: ends the run early.
struct Cancelled {};

// The run to do: a new one from CASE.toml, or the one stored in DIR/checkpoint (--resume).
struct RunSetup {
    CaseConfig cfg;
    fs::path dir;
    RunCheckpoint manifest; // the run's identity (also the CSV '#' lines) and checkpoint interval
    bool resuming = false;
    bool manifest_changed = false;                      // a resume with another --checkpoint-every
    std::vector<std::optional<ResumedReplica>> resumed; // per replica (resuming)
    OutputDirLock lock; // held from the first check of the directory to the end of the run
};

// `root`: this process checks and locks the output directory (rank 0 of the ranks; the others would
// find it locked by rank 0).
RunSetup new_run(const RunOptions& o, bool root) {
    if (o.case_file.empty() || o.out.empty())
        throw InputError("", "", "roughgas run: give CASE.toml and --out DIR, or --resume DIR");
    std::vector<std::string> sets = o.sets;
    if (o.seed_given)
        sets.push_back("run.seed=" + std::to_string(o.seed)); // --seed is --set run.seed=S
    RunSetup s;
    s.cfg = load_case(o.case_file, sets, CaseUse::run); // invalid input: exit 2
    s.dir = o.out;
    if (root) {
        s.lock.lock_if_exists(s.dir); // before its files are checked: another run may be writing them
        check_output_dir(s.dir, o.force, s.cfg.run.histogram_every > 0, driven(s.cfg),
                         s.cfg.domain && s.cfg.domain->has_walls(), s.cfg.domain.has_value(),
                         s.cfg.domain && s.cfg.spectra, s.cfg.domain && s.cfg.spectra && s.cfg.spectra->modes > 0,
                         s.cfg.domain && s.cfg.fields);
    }
    s.manifest.run = {roughgas_version(),
                      o.case_file,
                      sets,
                      emit_case(s.cfg),
                      s.cfg.run.seed,
                      static_cast<std::uint64_t>(s.cfg.run.replicas),
                      static_cast<std::uint64_t>(s.cfg.run.particles)};
    s.manifest.checkpoint_every = o.checkpoint_every;
    s.manifest.replica_from = 0;
    s.manifest.replica_to = s.manifest.run.replicas;
    if (!o.replicas.empty())
        std::tie(s.manifest.replica_from, s.manifest.replica_to) = replica_range(o.replicas, s.manifest.run.replicas);
    return s;
}

RunSetup resume_run(const RunOptions& o, bool root) {
    RunSetup s;
    if (root)
        s.lock.lock_if_exists(o.resume, "--resume"); // the run may still be going on in another process
    ResumedRun r = read_resumable_run(o.resume); // refusals: exit 2, nothing written
    s.cfg = std::move(r.cfg);
    s.dir = o.resume;
    s.manifest = std::move(r.manifest);
    s.resuming = true;
    s.resumed = std::move(r.replicas);
    if (o.checkpoint_every_given && o.checkpoint_every != s.manifest.checkpoint_every) {
        s.manifest.checkpoint_every = o.checkpoint_every;
        s.manifest_changed = true;
    }
    return s;
}

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
    const bool quiet = o.quiet || !root; // the progress and the report are rank 0's
    // The setup, on every rank alike (rank_errors.hpp): the case or checkpoint, the tables.
    std::optional<RunSetup> prepared;
    RunSpec spec;
    std::string start_note; // initial.from's description
    std::shared_ptr<const RestitutionTables> tables;
    agree_on_setup(comm, [&] {
        prepared.emplace(o.resume.empty() ? new_run(o, root) : resume_run(o, root));
        try {
            spec = run_spec_from_case(prepared->cfg);
        } catch (const std::invalid_argument& e) { // a valid case the solver cannot run
            throw std::runtime_error(e.what());
        }
        start_note = attach_initial_state(spec, prepared->cfg, prepared->manifest.run.case_file);
        if (!start_note.empty() && !prepared->resuming) {
            std::error_code ec;
            if (fs::weakly_canonical(prepared->cfg.initial->from, ec) == fs::weakly_canonical(prepared->dir, ec))
                throw InputError(prepared->manifest.run.case_file, "initial.from",
                                 fmt::format("initial.from = \"{}\" is the output directory: the run would replace "
                                             "the state it starts from (give another --out)",
                                             prepared->cfg.initial->from));
        }
        attach_final_state(spec, prepared->cfg, prepared->dir);
        spec.threads = o.threads > 0 ? o.threads : default_threads();
        omp_set_num_threads(spec.threads); // the table builds use the same threads
        // The replicas this process holds at a time: its share of the range, over its threads.
        const RunCheckpoint& m = prepared->manifest;
        const auto range = static_cast<long long>((m.replica_to > 0 ? m.replica_to : m.run.replicas) - m.replica_from);
        const long long share = (range + comm.size() - 1) / comm.size();
        refuse_if_too_large(spec, static_cast<int>(std::max(1LL, std::min<long long>(spec.threads, share))),
                            m.run.case_file);
        if (root)
            tables = build_run_tables(spec); // before anything is written: a failure writes nothing
    });
    // The other ranks after rank 0, so that they load the cache file it saved instead of each
    // building the tables and writing the same file.
    agree_on_setup(comm, [&] {
        if (!root)
            tables = build_run_tables(spec);
    });
    RunSetup& setup = *prepared;
    const CaseConfig& cfg = setup.cfg;
    const fs::path& dir = setup.dir;
    const double checkpoint_every = setup.manifest.checkpoint_every;
    // The contact model's range at the start (the hottest moment of a cooling run): the rms impact
    // speed of each pair with a contact model, sqrt(3 (T_a/m_a + T_b/m_b)), and three times it (the tail).
    if (!quiet) {
        bool warned = false;
        for (std::size_t a = 0; a < cfg.species.size() && !warned; ++a)
            for (std::size_t b = a; b < cfg.species.size() && !warned; ++b) {
                if (!uses_material(collision_for(cfg, a, b).model))
                    continue;
                const double g = std::sqrt(3.0 * (cfg.species[a].temperature / cfg.species[a].mass +
                                                  cfg.species[b].temperature / cfg.species[b].mass));
                const double speeds[] = {g, 3.0 * g};
                warned = warn_if_not_quasistatic(cfg, a, b, speeds, "initial rms impact speed and 3x it",
                                                 std::cerr);
            }
    }
    const int K = spec.replicas;
    // The replicas this process runs: all, or the range of --replicas (a part of an ensemble whose
    // replica files `roughgas merge` combines; no CSV here: its rows are not the ensemble's).
    const int from = static_cast<int>(setup.manifest.replica_from);
    const int to = setup.manifest.replica_to > 0 ? static_cast<int>(setup.manifest.replica_to) : K;
    const bool partial = from > 0 || to < K;
    // This rank's share of them (all of them in one process).
    const Share share = share_of(to - from, comm.rank(), comm.size());
    const int mine_from = from + static_cast<int>(share.first), mine_to = from + static_cast<int>(share.last);
    const auto in_range = [&](int r) { return r >= mine_from && r < mine_to; };

    MomentsTable table(spec);
    // Nothing here may differ between a run and its resumption (the CSVs must be byte-identical):
    // the case file and overrides are those the run was started with, kept in the checkpoint.
    CsvProvenance prov;
    prov.case_file = setup.manifest.run.case_file;
    prov.overrides = setup.manifest.run.overrides;
    prov.seed = cfg.run.seed;
    prov.resolved_case = setup.manifest.run.resolved_case;
    prov.notes = {
        "t in the case's time unit; coll_per_particle = 2 x collisions / N; T in energy units (k_B = 1)",
        fmt::format("replicas: {}{}", K,
                    K > 1 ? " (X = mean over replicas, X_err = its standard error)" : ""),
        unit_system_note(cfg),
    };
    if (spec.shear)
        prov.notes.push_back(fmt::format(
            "uniform shear flow u = a y x, a = {}: V = v - u; Strang steps of {} mean free times; "
            "rows at the end of the first step at or after each output's coll_per_particle",
            spec.shear->rate, spec.shear->time_step));
    if (!start_note.empty()) {
        prov.notes.push_back(start_note);
        if (!quiet)
            std::cerr << "roughgas run: " << start_note << '\n';
    }
    for (const std::string& u : cfg.unused) { // kept in the case, not used by this run
        prov.notes.push_back("warning: " + u);
        if (root)
            std::cerr << "roughgas run: warning: " << u << '\n';
    }
    std::string box_note; // the box's description, also in walls.csv and profiles.csv
    if (spec.domain) { // the box and its cells in mean free paths, on stderr too
        double R = 0;
        for (const SpeciesSpec& s : spec.species)
            R = std::max(R, s.radius);
        const double lambda = mean_free_path(spec.density, 2 * R);
        const DomainSpec& d = *spec.domain;
        double edge = 0;
        for (int a = 0; a < 3; ++a)
            edge = std::max(edge, d.size[a] / d.cells[a]);
        std::string walled; // "y (lower: diffuse, upper: diffuse)", "x (...) and z (...)", ...
        for (int a = 0; a < 3; ++a)
            if (d.walled(a))
                walled += fmt::format("{}{} (lower: {}, upper: {})", walled.empty() ? "" : " and ", "xyz"[a],
                                      wall_kind_names[static_cast<std::size_t>(d.wall(a, false).kind)],
                                      wall_kind_names[static_cast<std::size_t>(d.wall(a, true).kind)]);
        const std::string kind =
            walled.empty() ? std::string("periodic box") : fmt::format("box with walls along {}", walled);
        const std::string gravity =
            d.has_gravity() ? fmt::format("; gravity [{:.6g}, {:.6g}, {:.6g}]", d.gravity[0], d.gravity[1], d.gravity[2])
                            : std::string();
        prov.notes.push_back(fmt::format(
            "{} {:.6g} x {:.6g} x {:.6g} = {:.4g} x {:.4g} x {:.4g} mean free paths (lambda = {:.6g}, the "
            "largest diameter's), {} x {} x {} collision cells (edge up to {:.3g} lambda), {:.4g} grains per cell; "
            "steps of {:.4g} mean free times{}; moments.csv's columns are averages over the box",
            kind, d.size[0], d.size[1], d.size[2], d.size[0] / lambda, d.size[1] / lambda, d.size[2] / lambda, lambda,
            d.cells[0], d.cells[1], d.cells[2], edge / lambda,
            static_cast<double>(spec.particles) / (static_cast<double>(d.cells[0]) * d.cells[1] * d.cells[2]),
            d.time_step, gravity));
        box_note = prov.notes.back();
        const std::size_t first_note = prov.notes.size() - 1;
        if (edge > 0.5 * lambda)
            prov.notes.push_back(fmt::format(
                "warning: cells of up to {:.3g} mean free paths (more than 0.5): in gradients the viscosity comes "
                "out too large by about 16/(45 pi) (edge/lambda)^2 = {:.2g} (Alexander, Garcia & Alder 1998){}",
                edge / lambda, 16.0 / (45.0 * std::numbers::pi) * (edge / lambda) * (edge / lambda),
                d.partners == PartnerSelection::nearest
                    ? "; with nearest partners the grains' spacing sets it instead, a fraction of that"
                    : ""));
        // The steps are domain.time_step mean free times of the densest slab: its value is the step
        // in local mean free times wherever the gas is densest.
        if (d.time_step > 0.25)
            prov.notes.push_back(fmt::format(
                "warning: steps of {:.3g} local mean free times (more than 0.25): the viscosity comes out too "
                "large by about (4/75) s^2 = {:.2g} (Hadjiconstantinou 2000; docs/validation.md)",
                d.time_step, 4.0 / 75.0 * d.time_step * d.time_step));
        if (!quiet)
            for (std::size_t k = first_note; k < prov.notes.size(); ++k)
                std::cerr << "roughgas run: " << prov.notes[k] << '\n';
    }
    if (table.has_theory())
        prov.notes.push_back("*_theory: Maxwellian approximation for constant alpha, beta at the row's t "
                             "(observables/theory.hpp; Haff's law for smooth spheres)");
    prov.units = table.units();
    CsvWriter csv(table.names(), prov);
    // A box run's walls.csv and profiles.csv: what the file holds, the replicas, the box.
    const auto box_csv = [&](const std::vector<Column>& columns, const char* what) {
        std::optional<CsvWriter> w;
        if (!columns.empty()) {
            CsvProvenance p = prov;
            p.notes = {what, prov.notes[1], prov.notes[2], box_note};
            p.units = column_units(columns);
            w.emplace(column_names(columns), p);
        }
        return w;
    };
    std::optional<CsvWriter> wcsv = box_csv(
        table.wall_table_columns(),
        "per wall, over the interval since the previous row (physical grains: each simulated one stands for "
        "density x volume / particles): hits per area and time; P_ia, the column a of the pressure tensor at a "
        "wall normal to a (the +a flux of momentum component i); q_a, the +a flux of kinetic energy "
        "(translational and rotational)");
    std::optional<CsvWriter> pcsv = box_csv(
        table.profile_table_columns(),
        "one block of rows per moments.csv row, one row per bin (slab normal to the profile axis, one per "
        "collision cell along it), at that row's t: n, u, T_tr, T_rot, theta, the kinetic (P_ab) and collisional "
        "(Pc_ab, over the interval since the previous row) pressure tensor, the kinetic heat flux q, the mean spin "
        "omega (observables/profiles.hpp)");
    std::optional<CsvWriter> scsv = box_csv(
        table.spectra_table_columns(),
        "one block of rows per moments.csv row, at that row's t: axis 0 the shells of |k| (n: the shell, k its mean "
        "|k|, n_modes its wave vectors, k and -k apart), axis 1, 2, 3 the wave numbers n along x, y, z; from the "
        "grains on the grid of the collision cells (nearest grid point), velocities about the mass-weighted mean: "
        "the structure factor S, the transverse and longitudinal current spectra E_perp, E_par (per transverse "
        "component) and the spectrum S_T of the kinetic energy at fixed density and composition; a uniform gas "
        "(positions independent of velocities) has S = S_T = 1 and, for one species, E_perp = E_par = T_tr at "
        "every k (observables/spectra.hpp)");
    std::optional<CsvWriter> mcsv = box_csv(
        table.modes_table_columns(),
        "one block of rows per moments.csv row, at that row's t: the lowest wave numbers n along each axis "
        "(axis 1, 2, 3: x, y, z; k = 2 pi n / L), the complex amplitudes (2/N) sum_j q_j exp(-i k.x_j) of the "
        "density (q = 1), of the flow velocity (mass-weighted) and of the kinetic temperature relative to its "
        "mean, x_j the centre of grain j's cell: a wave A sin(k x) has the amplitude -i A sinc(k Delta/2), Delta the "
        "cell edge (observables/spectra.hpp)");
    const auto write_box_csvs = [&] { // beside every write of moments.csv
        if (wcsv)
            wcsv->write(dir / walls_file);
        if (pcsv)
            pcsv->write(dir / profiles_file);
        if (scsv)
            scsv->write(dir / spectra_file);
        if (mcsv)
            mcsv->write(dir / modes_file);
    };
    std::optional<HistogramsTable> htable;
    std::optional<CsvWriter> hcsv;
    if (!spec.histogram_times.empty()) {
        htable.emplace(spec);
        CsvProvenance hprov = prov;
        hprov.notes = {
            "one row per bin at every run.histogram_every time; reduced variables per species: c* = "
            "c sqrt(m/(2 T_tr)), w* = omega sqrt(J/(2 T_rot)) (observables/histograms.hpp)",
            prov.notes[1], prov.notes[2]};
        hprov.units = htable->units();
        hcsv.emplace(htable->names(), hprov);
    }

    if (!quiet) {
        if (!tables->cache_rejected().empty())
            std::cerr << fmt::format("roughgas: cache file {} rejected ({}): rebuilt\n",
                                     spec.cache_file.string(), tables->cache_rejected());
        for (const TableBuildInfo& i : tables->info())
            std::cerr << fmt::format("roughgas: {}: {}\n", i.what,
                                     i.from_cache ? fmt::format("loaded from {}", spec.cache_file.string())
                                                  : fmt::format("built in {:.2f} s", i.seconds));
    }
    // Rank 0 prepares the directory; the other ranks' replica files come after its run.bin (several
    // ranks write one at a stop even without --checkpoint-every: theirs must belong to a resumable run).
    CheckpointWriter checkpoints(dir, setup.manifest, !root || (setup.resuming && !setup.manifest_changed));
    agree_on_setup(comm, [&] {
        if (!root)
            return;
        fs::create_directories(dir);
        setup.lock.lock(dir); // a new directory (an existing one is locked already)
        if (setup.resuming) {
            remove_stale_temporaries(dir);
        } else {
            // --force (checked above): an earlier run's checkpoint must not be resumed into this one,
            // nor its state files be taken for this run's.
            std::error_code ec;
            fs::remove_all(checkpoint_dir(dir), ec);
            fs::remove_all(state_dir(dir), ec);
            fs::remove_all(fields_dir(dir), ec); // an earlier run's snapshots would mix with this run's
            fs::remove_all(replicas_dir(dir), ec);
        }
        if (checkpoint_every > 0 || partial || comm.size() > 1) // a kill before the first replica
            checkpoints.write_manifest_once();                  // checkpoint still leaves a resumable run
    });
    const fs::path path = dir / output_file;
    const fs::path hpath = dir / histograms_file;
    // sets[r][k]: replica r's histograms at histogram time k; written (atomically) as they complete.
    std::vector<std::vector<HistogramSet>> hsets(static_cast<std::size_t>(K));
    std::size_t sets_written = 0;
    const auto flush_histograms = [&] { // under `mutex`; rank 0 alone writes
        if (!root)
            return;
        std::size_t complete = hsets[0].size();
        for (const auto& r : hsets)
            complete = std::min(complete, r.size());
        if (complete == sets_written)
            return;
        for (; sets_written < complete; ++sets_written) {
            std::vector<HistogramSet> same_time;
            for (const auto& r : hsets)
                same_time.push_back(r[sets_written]);
            for (const std::vector<double>& row : htable->combine(same_time))
                hcsv->add_row(row);
        }
        hcsv->write(hpath);
    };

    // rows[r][k]: replica r's row at output k. A row goes to the file once every replica has it.
    std::vector<std::vector<std::vector<double>>> rows(static_cast<std::size_t>(K));
    // A resumed run starts from the rows and histograms in the checkpoints.
    // One byte per replica (not vector<bool>, whose bits share words): each replica's thread writes its own.
    std::vector<char> finished(static_cast<std::size_t>(K), 0);
    for (std::size_t r = 0; r < setup.resumed.size(); ++r) {
        if (!setup.resumed[r])
            continue;
        rows[r] = std::move(setup.resumed[r]->rows);
        hsets[r] = std::move(setup.resumed[r]->histograms);
        finished[r] = setup.resumed[r]->finished;
    }
    // Each replica's own rows beside the ensemble's (replicas > 1), written as they come by the one
    // process of a whole run; under MPI rank 0 writes them all once it has every rank's rows (the
    // directory need not be shared), and a range of --replicas leaves them to `roughgas merge`.
    std::optional<ReplicaFiles> replica_files;
    if (K > 1 && !partial && comm.size() == 1) {
        replica_files.emplace(dir, spec, prov, mine_from, mine_to);
        replica_files->add_rows(rows); // a resumed run: the rows of its checkpoints
    }
    std::mutex mutex;
    std::size_t combined = 0, on_disk = 0;
    std::vector<std::vector<double>> table_rows; // the combined rows, for the steady-state summary
    std::vector<std::vector<std::vector<double>>> profile_blocks; // profiles.csv's rows per output time
    // Box runs: the cells' resolution of the densest slab, watched as the rows come
    // (resolution_watch.hpp): its warnings in the CSV headers and on stderr.
    ResolutionWatch resolution(table.names());
    const auto watch_resolution = [&](const std::vector<double>& row) {
        for (const std::string& note : resolution.notes(row)) {
            csv.add_note(note);
            if (pcsv)
                pcsv->add_note(note);
            if (!quiet)
                std::cerr << "roughgas run: " << note << '\n';
        }
    };
    // The file is rewritten (atomically: temporary, fsync, rename) at every output time whose row
    // is complete, so a crash keeps every row computed; only when rewriting would take more than a
    // fiftieth of the run's time (a large file and dense outputs: each rewrite costs O(file size),
    // and its syncs slow the run's own threads on a virtual machine) are rows batched, the next
    // rewrite waiting until 50x the last one's duration has passed.
    auto last_write = std::chrono::steady_clock::now() - std::chrono::hours(1);
    std::chrono::steady_clock::duration write_cost{};
    const auto flush = [&](bool now) { // under `mutex`; rank 0 alone writes
        if (!root)
            return;
        std::size_t complete = rows[0].size();
        for (const auto& r : rows)
            complete = std::min(complete, r.size());
        for (; combined < complete; ++combined) {
            std::vector<std::span<const double>> spans;
            for (const auto& r : rows)
                spans.emplace_back(r[combined]);
            table_rows.push_back(table.combine(spans));
            csv.add_row(table_rows.back());
            watch_resolution(table_rows.back());
            if (wcsv)
                wcsv->add_row(table.combine_walls(spans));
            if (pcsv) {
                profile_blocks.push_back(table.combine_profiles(spans));
                for (const std::vector<double>& r : profile_blocks.back())
                    pcsv->add_row(r);
            }
            if (scsv)
                for (const std::vector<double>& r : table.combine_spectra(spans))
                    scsv->add_row(r);
            if (mcsv)
                for (const std::vector<double>& r : table.combine_modes(spans))
                    mcsv->add_row(r);
        }
        const auto t = std::chrono::steady_clock::now();
        if (csv.rows() > on_disk && (now || t - last_write >= 50 * write_cost)) {
            csv.write(path);
            write_box_csvs();
            on_disk = csv.rows();
            last_write = std::chrono::steady_clock::now();
            write_cost = last_write - t;
        }
    };
    // Replica r's checkpoint: its rows and histograms so far with its state (empty: finished).
    const auto save_replica = [&](int r, std::string state) {
        std::vector<std::vector<double>> r_rows;
        std::vector<HistogramSet> r_sets;
        {
            std::lock_guard lock(mutex);
            r_rows = rows[static_cast<std::size_t>(r)];
            r_sets = hsets[static_cast<std::size_t>(r)];
        }
        checkpoints.save_replica(static_cast<std::uint64_t>(r), std::move(r_rows), std::move(r_sets),
                                 std::move(state));
    };

    ProgressLine progress(quiet ? nullptr : &std::cerr, std::max(1, mine_to - mine_from),
                          ::isatty(STDERR_FILENO) == 1);
    std::vector<ReplicaSummary> summaries(static_cast<std::size_t>(K));
    std::vector<char> final_saved(static_cast<std::size_t>(K), 0);
    for (int r = from; r < to; ++r)
        if (finished[static_cast<std::size_t>(r)]) {
            final_saved[static_cast<std::size_t>(r)] = 1; // its file says so already
            if (in_range(r))
                progress.update(r - mine_from, cfg.run.end, cfg.run.end, 0);
        }
    std::atomic<bool> cancel{false};
    std::exception_ptr error;
    // --threads T is shared: min(T, K) replicas at a time, each with T/min(T, K) threads over the
    // groups of its steps (dsmc/engine.hpp). Neither changes the results.
    const int threads = std::min(spec.threads, std::max(1, mine_to - mine_from));
    spec.threads = std::max(1, spec.threads / threads);
    if (threads > 1 && spec.threads > 1)
        omp_set_max_active_levels(2);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int r = 0; r < K; ++r) {
        const auto k = static_cast<std::size_t>(r);
        try {
            if (cancel)
                throw Cancelled{};
            if (!in_range(r) || finished[k] || signals.requested()) // another process's; done in an
                continue;                                        // earlier run; or stopped before it started
            const RowSink sink = [&, r](std::span<const double> row) {
                if (cancel)
                    throw Cancelled{};
                table.check(row); // NonFiniteValue: stop, naming the column and t
                if (replica_files) // replica r's own file: its thread's alone, no lock
                    replica_files->add(r, row);
                std::lock_guard lock(mutex);
                rows[static_cast<std::size_t>(r)].emplace_back(row.begin(), row.end());
                flush(false);
            };
            const ProgressSink report = [&, r](double done, double end, double coll) {
                progress.update(r - mine_from, done, end, coll);
            };
            HistogramSink hsink;
            if (htable) {
                hsink = [&, r](const HistogramSet& h) {
                    if (cancel)
                        throw Cancelled{};
                    std::lock_guard lock(mutex);
                    hsets[static_cast<std::size_t>(r)].push_back(h);
                    flush_histograms();
                };
            }
            // The replica's cell fields: each replica to its own files, written behind the run
            // (io/fields_series.hpp).
            std::optional<FieldsSeries> series;
            FieldSink fsink;
            if (spec.domain && spec.domain->fields && r < spec.domain->fields->replicas) {
                series.emplace(dir, r, *spec.domain, setup.resuming);
                fsink = [&series](const FieldSnapshot& s) { series->add(s); };
            }
            ReplicaCheckpoints ck;
            ck.every = checkpoint_every;
            ck.save = [&, r](std::string state) {
                if (series) // the snapshots before a checkpoint are on disk before it
                    series->flush();
                save_replica(r, std::move(state));
            };
            ck.stop = [&] { return signals.requested(); };
            if (setup.resuming && setup.resumed[k]) // checked before the run; read again now (memory)
                ck.resume = read_replica_state(dir, k, setup.manifest.run);
            ReplicaEnd end;
            try {
                end = run_replica(spec, *tables, r, sink, report, &summaries[k], hsink, &ck, fsink);
                if (series)
                    series->flush();
            } catch (const ResumeError& e) {
                const fs::path file = replica_checkpoint_path(dir, k);
                throw InputError(file.string(), "--resume",
                                 std::string("cannot resume: its state does not fit the case: ") + e.what());
            }
            if (end == ReplicaEnd::finished) {
                finished[k] = 1;
                if (checkpoint_every > 0 || partial) { // a resume (or merge) will not run it again
                    save_replica(r, {});
                    final_saved[k] = 1;
                }
            }
        } catch (const Cancelled&) {
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
            cancel = true;
        }
    }
    progress.finish();
    if (replica_files) {
        try {
            replica_files->write_all();
        } catch (...) { // the first error is the one to report
            if (!error)
                error = std::current_exception();
        }
    }
    if (error) { // one rank's (main ends the job) or the one process's
        std::lock_guard lock(mutex);
        flush(true);
        try {
            std::rethrow_exception(error);
        } catch (const NonFiniteValue& e) {
            throw std::runtime_error(
                on_disk > 0 ? fmt::format("{}; the {} rows before it are in {}", e.what(), on_disk, path.string())
                            : fmt::format("{}; no row was complete before it, nothing written", e.what()));
        }
    }
    // The signal that stopped a replica of this rank (0: none); with several ranks, of any rank.
    const auto unfinished_in = [&](int a, int b) {
        return std::find(finished.begin() + a, finished.begin() + b, 0) != finished.begin() + b;
    };
    const int stop_signal = static_cast<int>(comm.max(unfinished_in(mine_from, mine_to) ? signals.signal() : 0));
    if (comm.size() > 1) {
        // Every rank's replicas to rank 0: finished or not, whether its last file is saved, what it did,
        // and its rows and histograms (in the encoding of a replica's checkpoint file).
        ByteWriter w;
        for (int r = mine_from; r < mine_to; ++r) {
            const auto k = static_cast<std::size_t>(r);
            w.u64(k);
            w.u64(finished[k]);
            w.u64(final_saved[k]);
            const ReplicaSummary& s = summaries[k];
            w.str(s.kernel);
            w.put(s.collisions);
            w.put(s.resumed_at);
            w.put(s.overshoots);
            w.str(encode_checkpoint(ReplicaCheckpoint{setup.manifest.run, k, rows[k], hsets[k], {}}));
        }
        const std::vector<std::string> parts = comm.gather(w.bytes());
        if (!root)
            return stop_signal > 0 ? 128 + stop_signal : exit_ok;
        for (std::size_t p = 1; p < parts.size(); ++p) {
            ByteReader in(parts[p]);
            while (in.remaining() > 0) {
                const auto k = static_cast<std::size_t>(in.u64());
                finished[k] = static_cast<char>(in.u64());
                final_saved[k] = static_cast<char>(in.u64());
                ReplicaSummary& s = summaries[k];
                s.kernel = in.str();
                s.collisions = in.get<std::int64_t>();
                s.resumed_at = in.get<std::int64_t>();
                s.overshoots = in.get<std::int64_t>();
                ReplicaCheckpoint c = decode_replica_checkpoint(in.str());
                rows[k] = std::move(c.rows);
                hsets[k] = std::move(c.histograms);
            }
        }
        if (K > 1 && !partial) { // every replica's own rows, as one process writes them
            ReplicaFiles(dir, spec, prov, from, to).add_rows(rows);
        }
    }
    {
        std::lock_guard lock(mutex);
        flush(true);
        if (htable)
            flush_histograms(); // a resumed run whose replicas had all finished: from the checkpoints
    }
    if (unfinished_in(from, to)) {
        // Stopped by a signal: the running replicas saved their states; the finished ones save their
        // rows now, so that a resume runs neither again (not-started ones start afresh).
        checkpoints.write_manifest_once();
        if (on_disk == 0 && !partial) {
            csv.write(path); // the header, even when no row is complete yet: the run's file exists
            write_box_csvs();
        }
        for (int r = from; r < to; ++r)
            if (finished[static_cast<std::size_t>(r)] && !final_saved[static_cast<std::size_t>(r)])
                save_replica(r, {});
        std::cerr << fmt::format("roughgas run: stopped by {}: {} complete rows in {}; checkpoint in {}; "
                                 "continue with: roughgas run --resume {}\n",
                                 StopSignals::name_of(stop_signal), csv.rows(), path.string(),
                                 checkpoint_dir(dir).string(), dir.string());
        return 128 + stop_signal;
    }
    if (comm.size() > 1 && checkpoint_every == 0 && !partial && !setup.resuming) { // run.bin was for a stop only
        std::error_code ec;
        fs::remove_all(checkpoint_dir(dir), ec);
    }
    if (partial) {
        std::cout << fmt::format("roughgas run: replicas {} .. {} of {} finished: {} (combine the ranges with "
                                 "roughgas merge DIR... --out DIR)\n",
                                 from, to - 1, K, checkpoint_dir(dir).string());
        return exit_ok;
    }

    // The steady state of a shear run (DIR/steady.csv), the scaled homogeneous cooling state of a
    // cooling run (DIR/scaled.csv): the same detector and batch means (io/steady_csv.hpp), over the
    // rows averaged over the replicas.
    std::string steady_note, scaled_headline;
    {
        const std::vector<std::string> names = table.names();
        const bool shear = driven(cfg); // a steady state (uniform shear, driving walls): steady.csv
        const SteadyResult st = steady_summary(names, table_rows, shear);
        const char* file = shear ? steady_file : scaled_file;
        CsvProvenance sp = prov;
        sp.units = steady_csv_units(st, names, table.units());
        sp.notes.push_back(std::string(shear ? "steady-state" : "scaled-state (late-time)") +
                           " summary of moments.csv: drift criterion on " + fmt::format("{}", fmt::join(st.monitored, ", ")) +
                           "; batch means (observables/steady_state.hpp); X_err = batch-means standard error");
        CsvWriter steady(steady_csv_columns(st), sp);
        steady.add_row(steady_csv_row(st, names, table_rows));
        steady.write(dir / file);
        if (shear && pcsv && profile_blocks.size() == table_rows.size()) {
            // The profiles over the same window: per bin, every field's batch mean and error.
            const std::vector<Column>& pc = table.profile_table_columns();
            std::vector<std::string> names_p = {pc[2].name, pc[3].name};
            std::vector<std::string> units_p = {pc[2].unit, pc[3].unit};
            std::vector<std::size_t> fields;
            for (std::size_t j = 4; j < pc.size(); ++j)
                if (!pc[j].name.ends_with("_err")) {
                    fields.push_back(j);
                    names_p.insert(names_p.end(), {pc[j].name, pc[j].name + "_err"});
                    units_p.insert(units_p.end(), {pc[j].unit, pc[j].unit});
                }
            CsvProvenance spp = prov;
            spp.notes = {fmt::format("profiles.csv averaged over the steady window of moments.csv ({} rows from "
                                     "coll_per_particle = {:.6g}{}); X_err = batch-means standard error",
                                     st.rows, table_rows[st.first_row][1],
                                     st.reached ? "" : "; NOT steady: the second half of the run"),
                         prov.notes[1], prov.notes[2], box_note};
            spp.units = units_p;
            CsvWriter sp_csv(names_p, spp);
            for (std::size_t b = 0; b < profile_blocks[0].size(); ++b) {
                std::vector<double> row = {profile_blocks[0][b][2], profile_blocks[0][b][3]};
                std::vector<double> x;
                for (std::size_t j : fields) {
                    x.clear();
                    for (std::size_t r = st.first_row; r < profile_blocks.size(); ++r)
                        x.push_back(profile_blocks[r][b][j]);
                    const SteadyValue v = batch_mean(x, SteadyOptions{}.batches);
                    row.push_back(v.mean);
                    row.push_back(v.err);
                }
                sp_csv.add_row(row);
            }
            sp_csv.write(dir / steady_profiles_file);
        }
        const auto cpp = std::find(names.begin(), names.end(), "coll_per_particle") - names.begin();
        const char* what = shear ? "steady" : "scaled state";
        // With restitution that depends on the impact speed, a cooling gas has no scaled state: its
        // collisions grow more elastic as it cools, so theta and the cumulants drift for ever.
        const bool speed_dependent =
            std::any_of(spec.pairs.begin(), spec.pairs.end(), [](const PairRestitution& p) {
                return std::holds_alternative<ViscoelasticRestitution>(p) ||
                       std::holds_alternative<BrilliantovRestitution>(p);
            });
        const bool no_scaled_state = !shear && speed_dependent;
        const std::string not_reached =
            no_scaled_state ? std::string(" NOT reached: none exists for restitution that depends on the impact "
                                          "speed (the collisions grow more elastic as the gas cools)")
                            : std::string(" NOT reached");
        // Such a run's window is where the drift fell below the noise, not where it ended.
        const std::string caveat = no_scaled_state ? " (the restitution depends on the impact speed: no true "
                                                     "scaled state exists; the drift fell below the noise here)"
                                                   : "";
        steady_note = st.reached
                          ? fmt::format("; {} from {:.4g} collisions per particle ({} rows averaged){}: {}", what,
                                        table_rows[st.first_row][static_cast<std::size_t>(cpp)], st.rows, caveat,
                                        (dir / file).string())
                          : fmt::format("; {}{} (a drift of {} resolved); {} holds the second half's averages",
                                        what, not_reached, fmt::join(st.monitored, ", "), (dir / file).string());
        if (!shear && !quiet) { // the headline numbers of the scaled state, last on stderr
            std::vector<std::string> parts;
            for (const SteadyValue& v : st.values)
                if (std::find(st.monitored.begin(), st.monitored.end(), v.name) != st.monitored.end())
                    parts.push_back(fmt::format("{} = {:.5g} +- {:.2g}", v.name, v.mean, v.err));
            scaled_headline = fmt::format("roughgas run: scaled state{}: {}\n",
                                          st.reached ? fmt::format(" from {:.4g} collisions per particle{}",
                                                                   table_rows[st.first_row][static_cast<std::size_t>(cpp)],
                                                                   caveat)
                                                     : not_reached + "; the second half's averages",
                                          fmt::join(parts, ", "));
        }
    }
    double collisions = 0, seconds = progress.seconds();
    std::int64_t overshoots = 0;
    std::string kernel; // of a replica that ran in this process (a resumed one may have none left)
    for (const ReplicaSummary& s : summaries) {
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
                       : fmt::format("{:.4g} collisions in {:.3g} s ({:.3g} collisions/s; kernel {})",
                                     collisions, seconds, seconds > 0 ? collisions / seconds : 0.0, kernel);
    std::cout << fmt::format("roughgas run: wrote {} ({} rows, {} columns, {} replica{}): {}{}\n",
                             path.string(), csv.rows(), table.columns().size(), K, K > 1 ? "s" : "", work,
                             steady_note);
    if (hcsv)
        std::cout << fmt::format("roughgas run: wrote {} ({} histogram times x {} bins)\n", hpath.string(),
                                 sets_written, spec.histogram_bins);
    std::cout.flush();
    std::cerr << scaled_headline;
    return exit_ok;
}

} // namespace

Subcommand add_run_command(CLI::App& parent, const Communicator& comm) {
    auto o = std::make_shared<RunOptions>();
    CLI::App* app =
        parent.add_subcommand("run", "run a DSMC simulation of a cooling or uniformly sheared gas, "
                                     "homogeneous or in a box ([domain]), writing DIR/moments.csv");
    CLI::Option* case_opt = app->add_option("CASE", o->case_file, "case file (TOML)");
    CLI::Option* out = app->add_option("--out", o->out, "output directory (moments.csv)");
    CLI::Option* set = add_set_option(*app, o->sets);
    CLI::Option* seed = app->add_option("--seed", o->seed, "random seed (overrides run.seed)");
    app->add_option(
           "--threads", o->threads,
           "threads for the replicas and within each replica (default: the CPUs this process may use; results do not depend on it)")
        ->check(positive());
    app->add_flag("--quiet", o->quiet, "no progress output");
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

int resume_finished_run(const std::string& dir, int threads, bool quiet) {
    RunOptions o;
    o.resume = dir;
    o.threads = threads;
    o.quiet = quiet;
    const Communicator one_process{Launch{}};
    return run_run(o, one_process);
}

} // namespace roughgas::cli
