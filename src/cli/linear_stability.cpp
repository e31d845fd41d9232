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
    if (spec.species.size() != 1 || c == nullptr)
        return std::string("shear mode: the Navier-Stokes critical length is given for grains of one species "
                           "with constant alpha and beta only");
    const bool smooth = c->beta == -1;
    const ShearModeTheory t = rough_shear_mode(c->alpha, c->beta, spec.species[0].inertia);
    const double lambda = mean_free_path(spec.density, 2 * spec.species[0].radius);
    const double L = std::max({spec.domain->size[0], spec.domain->size[1], spec.domain->size[2]}) / lambda;
    if (!std::isfinite(t.critical_length))
        return fmt::format("shear mode: these grains do not cool (alpha = {}, beta = {}), and the box ({:.4g} mean "
                           "free paths) is linearly stable",
                           c->alpha, c->beta, L);
    const double rate = shear_mode_rate(t, 2 * std::numbers::pi / L);
    return fmt::format("shear mode (Navier-Stokes, {}): critical length {:.4g} mean free "
                       "paths; the box's longest side, {:.4g} of them, is {}: its longest transverse wave {} "
                       "against the thermal speed by {:.3g} per collision per particle (docs/model.md §8)",
                       smooth ? fmt::format("smooth grains, alpha = {}", c->alpha)
                              : fmt::format("rough grains, alpha = {}, beta = {}, in their cooling state theta = {:.4g}",
                                            c->alpha, c->beta, t.theta),
                       t.critical_length, L,
                       L > t.critical_length ? "longer: linearly unstable" : "shorter: linearly stable",
                       rate > 0 ? "grows" : "decays", std::abs(rate));
}

} // namespace roughgas::cli
