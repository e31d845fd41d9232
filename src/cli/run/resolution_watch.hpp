#pragma once
// The cells' resolution of a box run, watched as its rows come, in its densest slab and in its
// densest cell (cell_over_lambda and cell_over_lambda_cells of moments.csv): a cooling gas's
// clusters or a heated floor can bring the local mean free path below the cells' size while the
// run goes on, and a cluster can do so in a few cells while its slab's mean stays resolved. For
// each, the first row past 0.5 local mean free paths gives a warning (in gradients the viscosity
// comes out too large by about 16/(45 pi) (edge/lambda)^2), the first past 1 another (the cells no
// longer resolve the gas there). What the set-up warned of already (run/setup_warnings.hpp: the
// box's cells against the mean free path at the mean density) is not said again: the first row's
// slabs read that ratio and its noise. One watch per file that carries the warnings: the ensemble's
// moments.csv and profiles.csv, and each replica's own moments_R.csv.
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace roughgas::cli {

class ResolutionWatch {
  public:
    // `names`: the columns of the rows to watch; without cell_over_lambda (not a box run) it never warns.
    // `setup_ratio`: the cells over the mean free path the set-up warned of (cells_over_mean_free_path),
    // whose thresholds are passed already.
    ResolutionWatch(const std::vector<std::string>& names, double setup_ratio);
    // The warnings this row brings (none, one, or both at once), each once per run.
    std::vector<std::string> notes(std::span<const double> row);

  private:
    struct Watched {
        std::size_t column;
        const char* name;  // the column's
        const char* where; // "the densest slab", "the densest cell"
        // The densest cell is watched only where it reads 5 % above the densest slab: a gas uniform
        // within its slabs has the slabs' warnings alone.
        std::optional<std::size_t> above;
        double threshold = 0.5;
    };
    std::vector<Watched> watched_;
    std::optional<std::size_t> t_, coll_per_particle_;
};

} // namespace roughgas::cli
