#pragma once
// DIR/sweep.csv: one row per point, the swept key's value and its point's steady or scaled state
// (run/summary.hpp) with errors; and the same compact on stderr.
#include "sweep/point_run.hpp"
#include "sweep/points.hpp"

#include <filesystem>
#include <vector>

namespace roughgas::cli {

inline constexpr const char* sweep_file = "sweep.csv";

// Writes DIR/sweep.csv from every point's result; returns its number of columns. Throws
// std::runtime_error when the points' summaries have different columns.
std::size_t write_sweep_csv(const std::filesystem::path& dir, const SweepOptions& o, const SweepPoints& points,
                            const std::vector<PointResult>& results);

// The headline quantities of every point, compact, on stderr: for uniform shear its rheology,
// otherwise (cooling, wall-driven boxes) the species' temperature ratios, theta and the cumulants.
void print_sweep_table(const SweepPoints& points, const std::vector<PointResult>& results);

} // namespace roughgas::cli
