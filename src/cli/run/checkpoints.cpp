// Reading, checking and writing DIR/checkpoint for `roughgas run` (see checkpoints.hpp).
#include "run/checkpoints.hpp"

#include "run/replica_files.hpp"

#include "roughgas/io/atomic_file.hpp"
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/fields_series.hpp"
#include "roughgas/io/input_error.hpp"
#include "roughgas/io/run_spec_from_case.hpp"
#include "roughgas/io/state_file.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const fs::path& file, const std::string& why) {
    throw InputError(file.string(), "--resume", "cannot resume: " + why);
}

// Reads and decodes one file, turning every failure into a refusal that names it.
template <class Decode> auto read_checked(const fs::path& file, Decode&& decode) {
    std::string bytes;
    try {
        bytes = read_checkpoint_bytes(file);
    } catch (const std::exception& e) {
        refuse(file, e.what());
    }
    try {
        return decode(bytes);
    } catch (const CheckpointError& e) {
        refuse(file, e.what());
    }
}

ReplicaCheckpoint read_replica(const fs::path& file, std::uint64_t r, const CheckpointRun& run,
                               const fs::path& manifest) {
    ReplicaCheckpoint c = read_checked(file, decode_replica_checkpoint);
    if (const std::string d = checkpoint_difference(c.run, run); !d.empty())
        refuse(file, fmt::format("from another run than {} ({})", manifest.string(), d));
    if (c.replica != r)
        refuse(file, fmt::format("the checkpoint of replica {}, not {}", c.replica, r));
    return c;
}

// Rows and histograms of the shape this case produces: a file that passed its checksum but does
// not fit would otherwise fail deep inside the CSV writer.
void check_shape(const fs::path& file, const ReplicaCheckpoint& c, const RunSpec& spec) {
    const std::size_t rows = std::max<std::size_t>(1, spec.output_times.size()) + 1; // t = 0 first
    const std::size_t columns = replica_row_columns(spec).size();
    const std::size_t sets = spec.histogram_times.size();
    const bool finished = c.state.empty();
    if (c.rows.size() > rows || (finished && c.rows.size() != rows) || c.rows.empty())
        refuse(file, fmt::format("{} rows, the case has {}", c.rows.size(), rows));
    for (const std::vector<double>& row : c.rows)
        if (row.size() != columns)
            refuse(file, fmt::format("a row of {} values, the case has {} columns", row.size(), columns));
    if (c.histograms.size() > sets || (finished && c.histograms.size() != sets))
        refuse(file, fmt::format("{} histogram sets, the case has {}", c.histograms.size(), sets));
    const auto bins = static_cast<std::size_t>(spec.histogram_bins);
    for (const HistogramSet& h : c.histograms) {
        if (h.species.size() != spec.species.size())
            refuse(file, "histograms of another number of species");
        for (const SpeciesHistograms& s : h.species)
            if (s.c.size() != bins || s.w.size() != bins || s.cw.size() != bins)
                refuse(file, fmt::format("histograms of another bin count (the case has {})", bins));
    }
}

} // namespace

ResumedRun read_resumable_run(const fs::path& dir) {
    if (!fs::is_directory(dir))
        refuse(dir, "no such directory");
    const fs::path manifest = run_checkpoint_path(dir);
    if (!fs::exists(manifest))
        refuse(manifest, "no checkpoint (the run was started without --checkpoint-every and was not stopped "
                         "by SIGINT or SIGTERM)");
    ResumedRun run;
    run.manifest = read_checked(manifest, decode_run_checkpoint);
    const CheckpointRun& id = run.manifest.run;
    if (id.program_version != roughgas_version())
        refuse(manifest, fmt::format("written by roughgas {}, this is roughgas {} (resume with the version "
                                     "that started the run)",
                                     id.program_version, roughgas_version()));
    try {
        run.cfg = parse_case(id.resolved_case, manifest.string() + " (resolved case)");
    } catch (const InputError& e) {
        refuse(manifest, std::string("its case no longer validates: ") + e.what());
    }
    // The resolved case must read back to itself, or the resumed run would not be the same run.
    if (emit_case(run.cfg) != id.resolved_case)
        refuse(manifest, "its case does not read back to the same resolved case");
    if (run.cfg.run.seed != id.seed || static_cast<std::uint64_t>(run.cfg.run.replicas) != id.replicas ||
        static_cast<std::uint64_t>(run.cfg.run.particles) != id.particles)
        refuse(manifest, "seed, replicas or particles differ from its case");
    const RunSpec spec = run_spec_from_case(run.cfg);
    for (std::uint64_t r = 0; r < id.replicas; ++r) {
        const fs::path file = replica_checkpoint_path(dir, r);
        if (!fs::exists(file)) {
            run.replicas.emplace_back();
            continue;
        }
        ReplicaCheckpoint c = read_replica(file, r, id, manifest);
        check_shape(file, c, spec);
        run.replicas.push_back(ResumedReplica{std::move(c.rows), std::move(c.histograms), c.state.empty()});
    }
    return run;
}

std::string read_replica_state(const fs::path& dir, std::uint64_t r, const CheckpointRun& run) {
    return read_replica(replica_checkpoint_path(dir, r), r, run, run_checkpoint_path(dir)).state;
}

CheckpointWriter::CheckpointWriter(fs::path dir, RunCheckpoint manifest, bool manifest_on_disk)
    : dir_(std::move(dir)), manifest_(std::move(manifest)), on_disk_(manifest_on_disk) {}

void CheckpointWriter::write_manifest_once() {
    std::lock_guard lock(mutex_);
    if (on_disk_)
        return;
    fs::create_directories(checkpoint_dir(dir_));
    write_file_atomically(run_checkpoint_path(dir_), encode_checkpoint(manifest_));
    on_disk_ = true;
}

void CheckpointWriter::rewrite_manifest() {
    {
        std::lock_guard lock(mutex_);
        on_disk_ = false;
    }
    write_manifest_once();
}

void CheckpointWriter::save_replica(std::uint64_t r, std::vector<std::vector<double>> rows,
                                    std::vector<HistogramSet> histograms, std::string state) {
    write_manifest_once();
    ReplicaCheckpoint c{manifest_.run, r, std::move(rows), std::move(histograms), std::move(state)};
    write_file_atomically(replica_checkpoint_path(dir_, r), encode_checkpoint(c));
}

void remove_stale_temporaries(const fs::path& dir) {
    std::vector<fs::path> dirs = {dir, checkpoint_dir(dir), state_dir(dir), fields_dir(dir), replicas_dir(dir)};
    std::error_code error;
    for (const auto& e : fs::directory_iterator(fields_dir(dir), error))
        if (e.is_directory())
            dirs.push_back(e.path());
    for (const fs::path& d : dirs) {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(d, ec)) {
            const std::string name = e.path().filename().string();
            bool ours = d != dir && (name.find(".bin.tmp.") != std::string::npos ||
                                     (d == replicas_dir(dir) && name.find(".csv.tmp.") != std::string::npos) ||
                                     name.find(".h5.tmp.") != std::string::npos ||
                                     name.find(".xmf.tmp.") != std::string::npos);
            for (const char* csv : {"moments", "histograms", "steady", "scaled", "walls", "profiles", "steady_profiles",
                                    "spectra", "modes"})
                ours |= name.starts_with(std::string(csv) + ".csv.tmp.");
            if (ours && e.is_regular_file())
                fs::remove(e.path(), ec);
        }
    }
}

} // namespace roughgas::cli
