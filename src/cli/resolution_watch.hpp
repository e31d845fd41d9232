#pragma once
// The cells' resolution of a box run's densest slab, watched as its rows come (cell_over_lambda of
// moments.csv): a cooling gas's clusters or a heated floor can bring the local mean free path below
// the cells' size while the run goes on. The first row past 0.5 local mean free paths gives a
// warning (in gradients the viscosity comes out too large by about 16/(45 pi) (edge/lambda)^2), the
// first past 1 another (the cells no longer resolve the gas there). One watch per file that carries
// the warnings: the ensemble's moments.csv and profiles.csv, and each replica's own moments_R.csv.
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace roughgas::cli {

class ResolutionWatch {
  public:
    // `names`: the columns of the rows to watch; without cell_over_lambda (not a box run) it never warns.
    explicit ResolutionWatch(const std::vector<std::string>& names);
    // The warnings this row brings (none, one, or both at once), each once per run.
    std::vector<std::string> notes(std::span<const double> row);

  private:
    std::optional<std::size_t> resolution_, t_, coll_per_particle_;
    double threshold_ = 0.5;
};

} // namespace roughgas::cli
