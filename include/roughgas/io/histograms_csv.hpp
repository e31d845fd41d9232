#pragma once
// The rows of histograms.csv: at every run.histogram_every time, one row per bin, with the columns
//
//   coll_per_particle, t, c_star, f_c, f_c_maxwell, w_star, f_w, f_w_maxwell, cw_star, f_cw, f_cw_maxwell
//
// (observables/histograms.hpp: x_star the bin centre, f_x the density averaged over the bin,
// f_x_maxwell the Maxwellian's bin average). Mixtures have f_x.NAME per species in place of f_x.
// With replicas > 1, t and every f_x are the means over replicas, each f_x followed by f_x_err
// (standard error of the mean), t by t_err.
#include "roughgas/dsmc/output_columns.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/run_spec.hpp"

#include <span>
#include <string>
#include <vector>

namespace roughgas {

class HistogramsTable {
  public:
    explicit HistogramsTable(const RunSpec& spec);

    const std::vector<Column>& columns() const { return columns_; }
    std::vector<std::string> names() const { return column_names(columns_); }
    std::vector<std::string> units() const { return column_units(columns_); }

    // The rows (one per bin) from the replicas' sets of the same histogram time, in replica order.
    std::vector<std::vector<double>> combine(std::span<const HistogramSet> replicas) const;

  private:
    std::vector<Column> columns_;
    std::vector<std::string> species_;
    int replicas_ = 1;
    bool time_clock_ = false; // run.end_time: the replicas share t, not the collision count
    HistogramGrid grid_;
    std::vector<double> speed_x_, product_x_, speed_ref_, product_ref_;
};

// The docs/reference.md table of histograms.csv columns (`roughgas keys --output`).
std::string histograms_columns_markdown();

} // namespace roughgas
