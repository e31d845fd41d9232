#include "run/resolution_watch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace roughgas::cli {
namespace {

std::optional<std::size_t> column(const std::vector<std::string>& names, const char* name) {
    const auto at = std::find(names.begin(), names.end(), name);
    if (at == names.end())
        return std::nullopt;
    return static_cast<std::size_t>(at - names.begin());
}

} // namespace

ResolutionWatch::ResolutionWatch(const std::vector<std::string>& names, double setup_ratio)
    : t_(column(names, "t")), coll_per_particle_(column(names, "coll_per_particle")) {
    // The set-up warns above 0.5 (and says when above 1): the thresholds left to watch.
    const double threshold = setup_ratio > 1 ? HUGE_VAL : setup_ratio > 0.5 ? 1.0 : 0.5;
    const auto slabs = column(names, "cell_over_lambda");
    if (slabs)
        watched_.push_back({*slabs, "cell_over_lambda", "the densest slab", std::nullopt, threshold});
    if (const auto c = column(names, "cell_over_lambda_cells"))
        watched_.push_back({*c, "cell_over_lambda_cells", "the densest cell", slabs, threshold});
}

std::vector<std::string> ResolutionWatch::notes(std::span<const double> row) {
    std::vector<std::string> out;
    if (!t_ || !coll_per_particle_)
        return out;
    const double t = row[*t_], c = row[*coll_per_particle_];
    for (Watched& w : watched_) {
        const double r = row[w.column];
        if (w.above && !(r > 1.05 * row[*w.above])) // by more than round-off and noise
            continue;
        while (r > w.threshold) {
            out.push_back(
                w.threshold < 1
                    ? fmt::format("warning: from t = {:.6g} ({:.4g} collisions per particle) the cells reach {:.3g} "
                                  "local mean free paths in {} (more than 0.5): in gradients there the "
                                  "viscosity comes out too large by about 16/(45 pi) (edge/lambda)^2 = {:.2g} "
                                  "(column {} of the moments)",
                                  t, c, r, w.where, 16.0 / (45.0 * std::numbers::pi) * r * r, w.name)
                    : fmt::format("warning: from t = {:.6g} ({:.4g} collisions per particle) the cells reach {:.3g} "
                                  "local mean free paths in {} (more than 1): the cells no longer "
                                  "resolve the gas there (refine domain.cells; column {} of the moments)",
                                  t, c, r, w.where, w.name));
            w.threshold = w.threshold < 1 ? 1.0 : HUGE_VAL;
        }
    }
    return out;
}

} // namespace roughgas::cli
