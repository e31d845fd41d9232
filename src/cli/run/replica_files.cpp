#include "run/replica_files.hpp"

#include "run/setup_warnings.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace roughgas::cli {

namespace fs = std::filesystem;

fs::path replicas_dir(const fs::path& run_dir) {
    return run_dir / "replicas";
}

fs::path replica_moments_path(const fs::path& run_dir, int replica) {
    return replicas_dir(run_dir) / fmt::format("moments_{}.csv", replica);
}

ReplicaFiles::ReplicaFiles(fs::path run_dir, const RunSpec& spec, const CsvProvenance& provenance, int from, int to)
    : dir_(std::move(run_dir)), from_(from) {
    if (provenance.notes.size() < 2)
        throw std::invalid_argument("ReplicaFiles: the ensemble's notes name the replicas second");
    fs::create_directories(replicas_dir(dir_)); // here, not beside each replica's thread
    RunSpec one = spec;
    one.replicas = 1;
    for (int r = from; r < to; ++r) {
        MomentsTable table(one);
        CsvProvenance p = provenance;
        p.notes[1] = fmt::format("replica {} of {}: its own rows (DIR/moments.csv holds the mean over the replicas)",
                                 r, spec.replicas);
        p.units = table.units();
        CsvWriter csv(table.names(), p);
        ResolutionWatch resolution(table.names(), spec.domain ? cells_over_mean_free_path(spec) : 0.0);
        files_.emplace_back(File{std::move(table), std::move(csv), std::move(resolution), 0,
                                 std::chrono::steady_clock::now() - std::chrono::hours(1), {}});
    }
}

void ReplicaFiles::add(int r, std::span<const double> row, bool write_now) {
    std::optional<File>& f = files_.at(static_cast<std::size_t>(r - from_));
    const std::span<const double> rows[] = {row};
    const std::vector<double> own = f->table.combine(rows);
    f->csv.add_row(own);
    for (const std::string& note : f->resolution.notes(own))
        f->csv.add_note(note);
    if (write_now && std::chrono::steady_clock::now() - f->last_write >= 10 * f->cost)
        write(r, *f);
}

void ReplicaFiles::write_all() {
    for (std::size_t k = 0; k < files_.size(); ++k)
        if (files_[k]->csv.rows() > files_[k]->on_disk)
            write(from_ + static_cast<int>(k), *files_[k]);
}

void ReplicaFiles::add_rows(const std::vector<std::vector<std::vector<double>>>& rows) {
    for (std::size_t k = 0; k < files_.size(); ++k) {
        const int r = from_ + static_cast<int>(k);
        for (const std::vector<double>& row : rows.at(static_cast<std::size_t>(r)))
            add(r, row, false);
    }
    write_all();
}

void ReplicaFiles::write(int r, File& f) {
    const auto t = std::chrono::steady_clock::now();
    f.csv.write(replica_moments_path(dir_, r));
    f.on_disk = f.csv.rows();
    f.last_write = std::chrono::steady_clock::now();
    f.cost = f.last_write - t;
}

} // namespace roughgas::cli
