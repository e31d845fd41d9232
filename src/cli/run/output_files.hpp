#pragma once
// The files a run writes in its output directory (docs/reference.md "Output"): their names, and
// which of them a case writes (those an earlier run's files must not be overwritten by, without --force).
#include "roughgas/io/case_config.hpp"

#include <vector>

namespace roughgas::cli {

inline constexpr const char* moments_file = "moments.csv";
inline constexpr const char* histograms_file = "histograms.csv";
inline constexpr const char* steady_file = "steady.csv";
inline constexpr const char* scaled_file = "scaled.csv";
inline constexpr const char* walls_file = "walls.csv";
inline constexpr const char* profiles_file = "profiles.csv";
inline constexpr const char* steady_profiles_file = "steady_profiles.csv";
inline constexpr const char* spectra_file = "spectra.csv";
inline constexpr const char* modes_file = "modes.csv";

// The CSVs of a run of `cfg` (its replicas' own files, checkpoints, states and fields aside).
std::vector<const char*> run_output_files(const CaseConfig& cfg);

} // namespace roughgas::cli
