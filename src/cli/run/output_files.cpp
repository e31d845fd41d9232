#include "run/output_files.hpp"

namespace roughgas::cli {

std::vector<const char*> run_output_files(const CaseConfig& cfg) {
    // A steady state (uniform shear, a thermostat, driving walls): steady.csv.
    const bool steady = driven(cfg);
    const bool box = cfg.domain.has_value();
    std::vector<const char*> files = {moments_file};
    if (cfg.run.histogram_every > 0)
        files.push_back(histograms_file);
    files.push_back(steady ? steady_file : scaled_file);
    if (box && cfg.domain->has_walls())
        files.push_back(walls_file);
    if (box)
        files.push_back(profiles_file);
    if (box && steady)
        files.push_back(steady_profiles_file);
    if (box && cfg.spectra) {
        files.push_back(spectra_file);
        if (cfg.spectra->modes > 0)
            files.push_back(modes_file);
    }
    return files;
}

} // namespace roughgas::cli
