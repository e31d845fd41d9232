// The set-up of a run (setup.hpp): case or checkpoint, spec, output directory, memory, tables.
#include "run/setup.hpp"

#include "memory_check.hpp"
#include "quasistatic_warning.hpp"
#include "rank_errors.hpp"
#include "run/output_files.hpp"
#include "run/replica_files.hpp"

#include "roughgas/core/available_cpus.hpp"
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/fields_series.hpp"
#include "roughgas/io/input_error.hpp"
#include "roughgas/io/run_spec_from_case.hpp"
#include "roughgas/io/run_states.hpp"
#include "roughgas/io/run_tables.hpp"
#include "roughgas/io/state_file.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <tuple>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

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
void check_output_dir(const fs::path& dir, bool force, const CaseConfig& cfg) {
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
    if (cfg.domain && cfg.fields && fs::exists(fields_dir(dir)))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(),
                                     fields_dir(dir).string()));
    if (fs::exists(replicas_dir(dir)))
        throw InputError(dir.string(), "--out",
                         fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(),
                                     replicas_dir(dir).string()));
    for (const char* file : run_output_files(cfg))
        if (fs::exists(dir / file))
            throw InputError(
                dir.string(), "--out",
                fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(), file));
}

// `root`: this process checks and locks the output directory (rank 0 of the ranks; the others would
// find it locked by rank 0).
std::unique_ptr<RunSetup> new_run(const RunOptions& o, bool root) {
    if (o.case_file.empty() || o.out.empty())
        throw InputError("", "", "roughgas run: give CASE.toml and --out DIR, or --resume DIR");
    std::vector<std::string> sets = o.sets;
    if (o.seed_given)
        sets.push_back("run.seed=" + std::to_string(o.seed)); // --seed is --set run.seed=S
    auto s = std::make_unique<RunSetup>();
    s->cfg = o.case_text ? parse_case(*o.case_text, o.case_file, sets, CaseUse::run)
                         : load_case(o.case_file, sets, CaseUse::run); // invalid input: exit 2
    s->dir = o.out;
    if (root) {
        s->lock.lock_if_exists(s->dir); // before its files are checked: another run may be writing them
        check_output_dir(s->dir, o.force, s->cfg);
    }
    s->manifest.run = {roughgas_version(),
                       o.case_file,
                       sets,
                       emit_case(s->cfg),
                       s->cfg.run.seed,
                       static_cast<std::uint64_t>(s->cfg.run.replicas),
                       static_cast<std::uint64_t>(s->cfg.run.particles)};
    s->manifest.checkpoint_every = o.checkpoint_every;
    s->manifest.replica_from = 0;
    s->manifest.replica_to = s->manifest.run.replicas;
    if (!o.replicas.empty())
        std::tie(s->manifest.replica_from, s->manifest.replica_to) =
            replica_range(o.replicas, s->manifest.run.replicas);
    return s;
}

std::unique_ptr<RunSetup> resume_run(const RunOptions& o, bool root) {
    auto s = std::make_unique<RunSetup>();
    if (root)
        s->lock.lock_if_exists(o.resume, "--resume"); // the run may still be going on in another process
    ResumedRun r = read_resumable_run(o.resume); // refusals: exit 2, nothing written
    s->cfg = std::move(r.cfg);
    s->dir = o.resume;
    s->manifest = std::move(r.manifest);
    s->resuming = true;
    s->resumed = std::move(r.replicas);
    if (o.checkpoint_every_given && o.checkpoint_every != s->manifest.checkpoint_every) {
        s->manifest.checkpoint_every = o.checkpoint_every;
        s->manifest_changed = true;
    }
    return s;
}

// The replicas this process runs: all, or the range of --replicas (a part of an ensemble whose
// replica files `roughgas merge` combines; no CSV here: its rows are not the ensemble's), and this
// rank's share of them (all of them in one process).
ReplicaRange replicas_of(const RunCheckpoint& m, int replicas, const Communicator& comm) {
    ReplicaRange r;
    r.count = replicas;
    r.from = static_cast<int>(m.replica_from);
    r.to = m.replica_to > 0 ? static_cast<int>(m.replica_to) : replicas;
    r.partial = r.from > 0 || r.to < replicas;
    const Share share = share_of(r.to - r.from, comm.rank(), comm.size());
    r.mine_from = r.from + static_cast<int>(share.first);
    r.mine_to = r.from + static_cast<int>(share.last);
    return r;
}

} // namespace

CasePlan plan_case(const CaseConfig& cfg, const std::string& case_file, const fs::path* out) {
    CasePlan p;
    try {
        p.spec = run_spec_from_case(cfg);
    } catch (const std::invalid_argument& e) { // a valid case the solver cannot run
        throw std::runtime_error(e.what());
    }
    p.start_note = attach_initial_state(p.spec, cfg, case_file);
    if (!p.start_note.empty() && out) {
        std::error_code ec;
        if (fs::weakly_canonical(cfg.initial->from, ec) == fs::weakly_canonical(*out, ec))
            throw InputError(case_file, "initial.from",
                             fmt::format("initial.from = \"{}\" is the output directory: the run would replace "
                                         "the state it starts from (give another --out)",
                                         cfg.initial->from));
    }
    return p;
}

CasePlan plan_run(const CaseConfig& cfg, const std::string& case_file, int threads, long long replicas_per_process,
                  const fs::path* out) {
    CasePlan p = plan_case(cfg, case_file, out);
    p.spec.threads = threads > 0 ? threads : default_threads();
    refuse_if_too_large(p.spec,
                        static_cast<int>(std::max(1LL, std::min<long long>(p.spec.threads, replicas_per_process))),
                        case_file);
    return p;
}

std::unique_ptr<RunSetup> set_up_run(const RunOptions& o, const Communicator& comm) {
    const bool root = comm.is_root();
    std::unique_ptr<RunSetup> s;
    agree_on_setup(comm, [&] {
        s = o.resume.empty() ? new_run(o, root) : resume_run(o, root);
        const RunCheckpoint& m = s->manifest;
        // The replicas this process holds at a time: its share of the range, over its threads.
        const auto range = static_cast<long long>((m.replica_to > 0 ? m.replica_to : m.run.replicas) - m.replica_from);
        CasePlan plan = plan_run(s->cfg, m.run.case_file, o.threads, (range + comm.size() - 1) / comm.size(),
                                 s->resuming ? nullptr : &s->dir);
        s->spec = std::move(plan.spec);
        s->start_note = std::move(plan.start_note);
        attach_final_state(s->spec, s->cfg, s->dir);
        omp_set_num_threads(s->spec.threads); // the table builds use the same threads
        if (root)
            s->tables = build_run_tables(s->spec); // before anything is written: a failure writes nothing
    });
    // The other ranks after rank 0, so that they load the cache file it saved instead of each
    // building the tables and writing the same file.
    agree_on_setup(comm, [&] {
        if (!root)
            s->tables = build_run_tables(s->spec);
    });
    s->replicas = replicas_of(s->manifest, s->spec.replicas, comm);
    return s;
}

void prepare_output_dir(RunSetup& setup, CheckpointWriter& checkpoints, const Communicator& comm) {
    agree_on_setup(comm, [&] {
        if (!comm.is_root())
            return;
        const fs::path& dir = setup.dir;
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
        // A kill before the first replica checkpoint still leaves a resumable run.
        if (setup.manifest.checkpoint_every > 0 || setup.replicas.partial || comm.size() > 1)
            checkpoints.write_manifest_once();
    });
}

// The contact model's range at the start (the hottest moment of a cooling run): the rms impact
// speed of each pair with a contact model, sqrt(3 (T_a/m_a + T_b/m_b)), and three times it (the tail).
void report_contact_range(const CaseConfig& cfg) {
    for (std::size_t a = 0; a < cfg.species.size(); ++a)
        for (std::size_t b = a; b < cfg.species.size(); ++b) {
            if (!uses_material(collision_for(cfg, a, b).model))
                continue;
            const double g = std::sqrt(3.0 * (cfg.species[a].temperature / cfg.species[a].mass +
                                              cfg.species[b].temperature / cfg.species[b].mass));
            const double speeds[] = {g, 3.0 * g};
            if (warn_if_not_quasistatic(cfg, a, b, speeds, "initial rms impact speed and 3x it", std::cerr))
                return;
        }
}

void report_tables(const RunSetup& setup) {
    const RestitutionTables& tables = *setup.tables;
    if (!tables.cache_rejected().empty())
        std::cerr << fmt::format("roughgas: cache file {} rejected ({}): rebuilt\n", setup.spec.cache_file.string(),
                                 tables.cache_rejected());
    for (const TableBuildInfo& i : tables.info())
        std::cerr << fmt::format("roughgas: {}: {}\n", i.what,
                                 i.from_cache ? fmt::format("loaded from {}", setup.spec.cache_file.string())
                                              : fmt::format("built in {:.2f} s", i.seconds));
}

} // namespace roughgas::cli
