#include "run/moments_files.hpp"

#include "run/output_files.hpp"
#include "run/setup_warnings.hpp"

#include <algorithm>
#include <iostream>
#include <span>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

// A box run's file beside moments.csv: what it holds, the replicas, the box (none without columns).
std::optional<CsvWriter> box_csv(const std::vector<Column>& columns, const RunProvenance& run, const char* what) {
    std::optional<CsvWriter> w;
    if (!columns.empty())
        w.emplace(column_names(columns), file_provenance(run, what, column_units(columns)));
    return w;
}

} // namespace

MomentsFiles::MomentsFiles(fs::path dir, const RunSpec& spec, const RunProvenance& provenance)
    : dir_(std::move(dir)), path_(dir_ / moments_file), table_(spec),
      csv_(table_.names(), provenance.csv),
      walls_(box_csv(
          table_.wall_table_columns(), provenance,
          "per wall, over the interval since the previous row (physical grains: each simulated one stands for "
          "density x volume / particles): hits per area and time; P_ia, the column a of the pressure tensor at a "
          "wall normal to a (the +a flux of momentum component i); q_a, the +a flux of kinetic energy "
          "(translational and rotational)")),
      profiles_(box_csv(
          table_.profile_table_columns(), provenance,
          "one block of rows per moments.csv row, one row per bin (slab normal to the profile axis, one per "
          "collision cell along it), at that row's t: n, u, T_tr, T_rot, theta, the kinetic (P_ab) and collisional "
          "(Pc_ab, over the interval since the previous row) pressure tensor, the kinetic heat flux q, the mean spin "
          "omega (observables/profiles.hpp)")),
      spectra_(box_csv(
          table_.spectra_table_columns(), provenance,
          "one block of rows per moments.csv row, at that row's t: axis 0 the shells of |k| (n: the shell, k its mean "
          "|k|, n_modes its wave vectors, k and -k apart), axis 1, 2, 3 the wave numbers n along x, y, z; from the "
          "grains on the grid of the collision cells (nearest grid point), velocities about the mass-weighted mean: "
          "the structure factor S, the transverse and longitudinal current spectra E_perp, E_par (per transverse "
          "component) and the spectrum S_T of the kinetic energy at fixed density and composition; a uniform gas "
          "(positions independent of velocities) has S = S_T = 1 and, for one species, E_perp = E_par = T_tr at "
          "every k (observables/spectra.hpp)")),
      modes_(box_csv(
          table_.modes_table_columns(), provenance,
          "one block of rows per moments.csv row, at that row's t: the lowest wave numbers n along each axis "
          "(axis 1, 2, 3: x, y, z; k = 2 pi n / L), the complex amplitudes (2/N) sum_j q_j exp(-i k.x_j) of the "
          "density (q = 1), of the flow velocity (mass-weighted) and of the kinetic temperature relative to its "
          "mean, x_j the centre of grain j's cell: a wave A sin(k x) has the amplitude -i A sinc(k Delta/2), Delta the "
          "cell edge (observables/spectra.hpp)")),
      resolution_(table_.names(), spec.domain ? cells_over_mean_free_path(spec) : 0.0),
      last_write_(std::chrono::steady_clock::now() - std::chrono::hours(1)) {}

void MomentsFiles::update(const std::vector<std::vector<std::vector<double>>>& rows, bool now) {
    std::size_t complete = rows[0].size();
    for (const auto& r : rows)
        complete = std::min(complete, r.size());
    for (std::size_t k = combined_.size(); k < complete; ++k) {
        std::vector<std::span<const double>> spans;
        for (const auto& r : rows)
            spans.emplace_back(r[k]);
        combined_.push_back(table_.combine(spans));
        csv_.add_row(combined_.back());
        for (const std::string& note : resolution_.notes(combined_.back())) {
            csv_.add_note(note);
            if (profiles_)
                profiles_->add_note(note);
            std::cerr << "roughgas run: " << note << '\n';
        }
        if (walls_)
            walls_->add_row(table_.combine_walls(spans));
        if (profiles_) {
            profile_blocks_.push_back(table_.combine_profiles(spans));
            for (const std::vector<double>& r : profile_blocks_.back())
                profiles_->add_row(r);
        }
        if (spectra_) {
            const std::vector<std::vector<double>> block = table_.combine_spectra(spans);
            // Columns t, coll_per_particle, axis, n, ...: the shells of |k| are axis 0.
            const auto smallest = std::find_if(block.begin(), block.end(),
                                               [](const std::vector<double>& r) { return r[2] == 0 && r[3] == 1; });
            smallest_shells_.push_back(smallest == block.end() ? std::vector<double>{} : *smallest);
            for (const std::vector<double>& r : block)
                spectra_->add_row(r);
        }
        if (modes_)
            for (const std::vector<double>& r : table_.combine_modes(spans))
                modes_->add_row(r);
    }
    const auto t = std::chrono::steady_clock::now();
    if (csv_.rows() > on_disk_ && (now || t - last_write_ >= 50 * write_cost_)) {
        write();
        on_disk_ = csv_.rows();
        last_write_ = std::chrono::steady_clock::now();
        write_cost_ = last_write_ - t;
    }
}

void MomentsFiles::write() {
    csv_.write(path_);
    if (walls_)
        walls_->write(dir_ / walls_file);
    if (profiles_)
        profiles_->write(dir_ / profiles_file);
    if (spectra_)
        spectra_->write(dir_ / spectra_file);
    if (modes_)
        modes_->write(dir_ / modes_file);
}

} // namespace roughgas::cli
