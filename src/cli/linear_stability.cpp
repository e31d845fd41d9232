// The shear mode's critical length for `roughgas check`: linear_stability.hpp.
#include "linear_stability.hpp"

#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/shear_mode.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

namespace roughgas::cli {

std::optional<std::string> linear_stability_note(const RunSpec& spec) {
    if (!spec.domain || spec.shear || spec.domain->has_walls() || spec.domain->has_gravity())
        return std::nullopt;
    const auto* c = spec.pairs.size() == 1 ? std::get_if<ConstantRestitution>(&spec.pairs[0]) : nullptr;
    if (spec.species.size() != 1 || c == nullptr || c->beta != -1)
        return std::string("shear mode: the Navier-Stokes critical length is given for smooth grains "
                           "(collision.beta = -1) of one species with constant alpha only");
    const ShearModeTheory t = smooth_shear_mode(c->alpha);
    const double lambda = mean_free_path(spec.density, 2 * spec.species[0].radius);
    const double L = std::max({spec.domain->size[0], spec.domain->size[1], spec.domain->size[2]}) / lambda;
    if (!std::isfinite(t.critical_length))
        return fmt::format("shear mode: elastic grains (alpha = 1) do not cool, and the box ({:.4g} mean free "
                           "paths) is linearly stable",
                           L);
    const double rate = shear_mode_rate(t, 2 * std::numbers::pi / L);
    return fmt::format("shear mode (Navier-Stokes, smooth grains, alpha = {}): critical length {:.4g} mean free "
                       "paths; the box's longest side, {:.4g} of them, is {}: its longest transverse wave {} "
                       "against the thermal speed by {:.3g} per collision per particle (docs/model.md §8)",
                       c->alpha, t.critical_length, L,
                       L > t.critical_length ? "longer: linearly unstable" : "shorter: linearly stable",
                       rate > 0 ? "grows" : "decays", std::abs(rate));
}

} // namespace roughgas::cli
