#pragma once
// The steady-state summary (observables/steady_state.hpp) as one CSV row: `steady` (1 if the
// drift criterion was met, else 0: the values are then those of the second half of the run, not
// a steady state), `steady_from` (coll_per_particle of the window's first row), `steady_rows`,
// then every averaged column X followed by X_err (batch-means standard error; none for the
// theory columns *_theory, functions of t whose window mean has no statistical error, nor for the
// constant *_sonine columns). Written by
// `roughgas run` (DIR/steady.csv, shear runs) and, one row per point, by `roughgas sweep`.
#include "roughgas/observables/steady_state.hpp"

#include <string>
#include <vector>

namespace roughgas {

std::vector<std::string> steady_csv_columns(const SteadyResult& r);
// The unit of every column of steady_csv_columns: "-" for steady, steady_from, steady_rows, then each
// value's and its error's from the unit of the moments.csv column of the same name (`names`, `units`).
std::vector<std::string> steady_csv_units(const SteadyResult& r, const std::vector<std::string>& names,
                                          const std::vector<std::string>& units);
std::vector<double> steady_csv_row(const SteadyResult& r, const std::vector<std::string>& names,
                                   const std::vector<std::vector<double>>& rows);

// find_steady_state over moments.csv rows with the monitored quantities of the run's kind
// (coll_per_particle is kept among the averages, t is not); `replicas` behind the rows' X_err.
SteadyResult steady_summary(const std::vector<std::string>& names,
                            const std::vector<std::vector<double>>& rows, bool shear, int replicas);

} // namespace roughgas
