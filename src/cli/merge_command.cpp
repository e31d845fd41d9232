// roughgas merge DIR... --out OUT: combines the replica ranges of one run (`roughgas run --replicas
// FROM:TO`, each in its own directory: a Slurm job array, GNU parallel, several machines) into the
// files one run of all replicas writes, byte for byte.
//
// Every DIR's checkpoint must belong to the same run (program version, case, overrides, seed,
// replicas, particles), its range must have finished, and the ranges must cover every replica
// exactly once: anything else is refused with exit 2 before anything is written. OUT/checkpoint
// then holds the run and every finished replica's file, and the CSVs are written as
// `roughgas run --resume OUT` writes them for a run whose replicas have all finished (the rows of
// each replica, combined in replica order: the same bytes as the run in one process). Each
// replica's final state (run.save_state) and cell fields come from its range's directory: the
// same files (the fields' XDMF sidecar names its HDF5 files relative to its own folder).
#include "commands.hpp"
#include "run/replica_files.hpp"

#include "output_dir_lock.hpp"

#include "roughgas/io/atomic_file.hpp"
#include "roughgas/io/checkpoint_file.hpp"
#include "roughgas/io/fields_series.hpp"
#include "roughgas/io/input_error.hpp"
#include "roughgas/io/state_file.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

struct MergeOptions {
    std::vector<std::string> dirs;
    std::string out;
    int threads = 0;
    bool quiet = false;
    bool force = false;
};

RunCheckpoint read_run(const fs::path& dir) {
    const fs::path file = run_checkpoint_path(dir);
    try {
        return decode_run_checkpoint(read_checkpoint_bytes(file));
    } catch (const std::exception& e) {
        throw InputError(file.string(), "merge", fmt::format("{}: cannot merge: {}", file.string(), e.what()));
    }
}

// `from` copied to `to` through a temporary next to it (complete or absent, as every output), without
// holding the file in memory (a snapshot of every cell of a large box is hundreds of megabytes).
void copy_atomically(const fs::path& from, const fs::path& to) {
    const fs::path tmp = temporary_path(to);
    fs::copy_file(from, tmp, fs::copy_options::overwrite_existing);
    publish_file_atomically(tmp, to);
}

// Replica r's final state and cell fields, if its range wrote them, into `out`.
void copy_replica_files(const fs::path& range, const fs::path& out, std::uint64_t r) {
    if (const fs::path from = state_file_path(range, r); fs::exists(from)) {
        fs::create_directories(state_dir(out));
        copy_atomically(from, state_file_path(out, r));
    }
    const int replica = static_cast<int>(r);
    const fs::path from = fields_replica_dir(range, replica);
    if (!fs::is_directory(from))
        return;
    const fs::path to = fields_replica_dir(out, replica);
    fs::create_directories(to);
    for (const auto& e : fs::directory_iterator(from))
        if (e.is_regular_file() && e.path().extension() == ".h5")
            copy_atomically(e.path(), to / e.path().filename());
    if (const fs::path xdmf = fields_xdmf_path(range, replica); fs::exists(xdmf))
        copy_atomically(xdmf, fields_xdmf_path(out, replica));
}

int run_merge(const MergeOptions& o) {
    // Every range: the same run, finished, each replica once.
    std::vector<RunCheckpoint> runs;
    for (const std::string& d : o.dirs)
        runs.push_back(read_run(d));
    const CheckpointRun& run = runs[0].run;
    const std::uint64_t K = run.replicas;
    std::vector<int> owner(K, -1);
    std::vector<std::string> replica_bytes(K);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const fs::path dir = o.dirs[i];
        if (const std::string d = checkpoint_difference(runs[i].run, run); !d.empty())
            throw InputError(dir.string(), "merge",
                             fmt::format("{}: another run than {} ({})", dir.string(), o.dirs[0], d));
        const std::uint64_t from = runs[i].replica_from, to = runs[i].replica_to > 0 ? runs[i].replica_to : K;
        for (std::uint64_t r = from; r < to; ++r) {
            if (owner[r] >= 0)
                throw InputError(dir.string(), "merge",
                                 fmt::format("replica {} is in both {} and {}", r, o.dirs[owner[r]], dir.string()));
            const fs::path file = replica_checkpoint_path(dir, r);
            ReplicaCheckpoint c;
            try {
                replica_bytes[r] = read_checkpoint_bytes(file);
                c = decode_replica_checkpoint(replica_bytes[r]);
            } catch (const std::exception& e) {
                throw InputError(file.string(), "merge",
                                 fmt::format("{}: cannot merge: {} (continue that range with roughgas run "
                                             "--resume {})",
                                             file.string(), e.what(), dir.string()));
            }
            if (const std::string d = checkpoint_difference(c.run, run); !d.empty() || c.replica != r)
                throw InputError(file.string(), "merge",
                                 fmt::format("{}: not replica {} of this run ({})", file.string(), r,
                                             d.empty() ? fmt::format("replica {}", c.replica) : d));
            if (!c.state.empty())
                throw InputError(file.string(), "merge",
                                 fmt::format("{}: replica {} has not finished (continue it with roughgas run "
                                             "--resume {})",
                                             file.string(), r, dir.string()));
            owner[r] = static_cast<int>(i);
        }
    }
    std::vector<std::string> missing;
    for (std::uint64_t r = 0; r < K; ++r)
        if (owner[r] < 0)
            missing.push_back(std::to_string(r));
    if (!missing.empty())
        throw InputError(o.dirs[0], "merge",
                         fmt::format("replica{} {} of {} in none of the directories (run them with roughgas "
                                     "run --replicas FROM:TO)",
                                     missing.size() > 1 ? "s" : "", fmt::join(missing, ", "), K));

    // OUT: a checkpoint of the whole run with every replica finished; then its CSVs.
    const fs::path out = o.out;
    for (const std::string& d : o.dirs) // its --force clears what the ranges' files are read from
        if (fs::exists(out) && fs::equivalent(out, d))
            throw InputError(out.string(), "--out",
                             fmt::format("--out {}: is one of the ranges' directories (merge into another)",
                                         out.string()));
    {
        OutputDirLock lock;
        lock.lock_if_exists(out);
        if (fs::exists(out) && !fs::is_directory(out))
            throw InputError(out.string(), "--out", "--out " + out.string() + ": exists and is not a directory");
        for (const fs::path& p : {checkpoint_dir(out), out / "moments.csv"})
            if (!o.force && fs::exists(p))
                throw InputError(out.string(), "--out",
                                 fmt::format("--out {}: {} exists (use --force to overwrite)", out.string(),
                                             p.string()));
        fs::create_directories(checkpoint_dir(out));
        lock.lock(out);
        for (const auto& e : fs::directory_iterator(checkpoint_dir(out))) // --force: no stale replica files
            fs::remove(e.path());
        fs::remove_all(replicas_dir(out)); // nor another run's replicas' rows, states or fields
        fs::remove_all(state_dir(out));
        fs::remove_all(fields_dir(out));
        RunCheckpoint whole = runs[0];
        whole.replica_from = 0;
        whole.replica_to = K;
        whole.checkpoint_every = 0;
        write_file_atomically(run_checkpoint_path(out), encode_checkpoint(whole));
        for (std::uint64_t r = 0; r < K; ++r) {
            write_file_atomically(replica_checkpoint_path(out, r), replica_bytes[r]);
            copy_replica_files(o.dirs[static_cast<std::size_t>(owner[r])], out, r);
        }
    } // the lock is released: the resume below takes it again
    return resume_finished_run(out.string(), o.threads, o.quiet);
}

} // namespace

Subcommand add_merge_command(CLI::App& parent) {
    auto o = std::make_shared<MergeOptions>();
    CLI::App* app = parent.add_subcommand(
        "merge", "combine the replica ranges of one run (roughgas run --replicas FROM:TO, one directory each) "
                 "into the files one run of all replicas writes");
    app->add_option("DIR", o->dirs, "the directories of the ranges (their checkpoint/)")->required();
    app->add_option("--out", o->out, "output directory (moments.csv, histograms.csv, steady.csv, checkpoint/)")
        ->required();
    app->add_option("--threads", o->threads, "threads (default: the CPUs this process may use)")->check(positive());
    app->add_flag("--quiet", o->quiet, "no progress output");
    app->add_flag("--force", o->force, "overwrite an earlier merge or run in the output directory");
    return {app, [o] { return run_merge(*o); }};
}

} // namespace roughgas::cli
