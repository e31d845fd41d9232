#include "resolution_watch.hpp"

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

ResolutionWatch::ResolutionWatch(const std::vector<std::string>& names)
    : resolution_(column(names, "cell_over_lambda")), t_(column(names, "t")),
      coll_per_particle_(column(names, "coll_per_particle")) {}

std::vector<std::string> ResolutionWatch::notes(std::span<const double> row) {
    std::vector<std::string> out;
    if (!resolution_ || !t_ || !coll_per_particle_)
        return out;
    const double r = row[*resolution_], t = row[*t_], c = row[*coll_per_particle_];
    while (r > threshold_) {
        out.push_back(
            threshold_ < 1
                ? fmt::format("warning: from t = {:.6g} ({:.4g} collisions per particle) the cells reach {:.3g} "
                              "local mean free paths in the densest slab (more than 0.5): in gradients there the "
                              "viscosity comes out too large by about 16/(45 pi) (edge/lambda)^2 = {:.2g} "
                              "(column cell_over_lambda of the moments)",
                              t, c, r, 16.0 / (45.0 * std::numbers::pi) * r * r)
                : fmt::format("warning: from t = {:.6g} ({:.4g} collisions per particle) the cells reach {:.3g} "
                              "local mean free paths in the densest slab (more than 1): the cells no longer "
                              "resolve the gas there (refine domain.cells)",
                              t, c, r));
        threshold_ = threshold_ < 1 ? 1.0 : HUGE_VAL;
    }
    return out;
}

} // namespace roughgas::cli
