// The shear and heat modes' critical lengths for `roughgas check`: linear_stability.hpp.
#include "linear_stability.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/longitudinal_modes.hpp"
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
    if (spec.thermostat)
        return std::string("a heated box: the critical lengths of the cooling state do not apply (the steady state "
                           "of white noise has no linear instability: van Noije, Ernst, Brito & Orza 1997)");
    const std::optional<ShearModeTheory> theory = shear_mode_theory(spec);
    if (!theory) {
        const auto* c = spec.pairs.size() == 1 ? std::get_if<ConstantRestitution>(&spec.pairs[0]) : nullptr;
        if (spec.enskog && spec.species.size() == 1 && c != nullptr)
            return fmt::format("shear mode (Enskog equation, phi = {:.4g}, chi = {:.4g}): the finite-phi critical "
                               "length is given for smooth grains only (beta = {} here)",
                               solid_fraction(spec.density, spec.species), pair_correlations(spec)[0], c->beta);
        return std::string("shear mode: the Navier-Stokes critical length is given for grains of one species "
                           "with constant alpha and beta only");
    }
    const ShearModeTheory& t = *theory;
    const bool smooth = t.beta == -1;
    const double lambda = mean_free_path(spec.density, 2 * spec.species[0].radius);
    const double L = std::max({spec.domain->size[0], spec.domain->size[1], spec.domain->size[2]}) / lambda;
    if (!std::isfinite(t.critical_length))
        return fmt::format("shear mode: these grains do not cool (alpha = {}, beta = {}), and the box ({:.4g} mean "
                           "free paths) is linearly stable",
                           t.alpha, t.beta, L);
    const double rate = shear_mode_rate(t, 2 * std::numbers::pi / L);
    // Also the longitudinal (clustering) instability, whose critical length is the longer one for
    // smooth grains with alpha > 0.37 and for rough grains (observables/longitudinal_modes.hpp).
    std::string heat;
    if (spec.enskog) {
        heat = "; heat mode (density clusters): its critical length is given for the Boltzmann equation only";
    } else if (const std::optional<LongitudinalModeTheory> l = longitudinal_mode_theory(spec)) {
        const LongitudinalModeTheory& lt = *l;
        const double heat_rate = longitudinal_max_rate(lt, 2 * std::numbers::pi / L);
        heat = fmt::format("; heat mode (density clusters): critical length {:.4g} mean free paths, the box is {}: "
                           "the heat mode of its longest wave {} by {:.3g} per collision per particle",
                           lt.critical_length, L > lt.critical_length ? "longer" : "shorter",
                           heat_rate > 0 ? "grows" : "decays", std::abs(heat_rate));
    }
    // The Enskog theory's lengths stay in the dilute gas's mean free path 1/(sqrt(2) pi n sigma^2).
    return fmt::format("shear mode (Navier-Stokes, {}): critical length {:.4g} {}mean free "
                       "paths; the box's longest side, {:.4g} of them, is {}: its longest transverse wave {} "
                       "against the thermal speed by {:.3g} per collision per particle{} (docs/model.md §8)",
                       spec.enskog ? fmt::format("Enskog equation at phi = {:.4g}, chi = {:.4g}, smooth grains, "
                                                 "alpha = {}",
                                                 t.phi, t.chi, t.alpha)
                       : smooth    ? fmt::format("smooth grains, alpha = {}", t.alpha)
                                   : fmt::format("rough grains, alpha = {}, beta = {}, in their cooling state theta = {:.4g}",
                                                 t.alpha, t.beta, t.theta),
                       t.critical_length, spec.enskog ? "dilute " : "", L,
                       L > t.critical_length ? "longer: linearly unstable" : "shorter: linearly stable",
                       rate > 0 ? "grows" : "decays", std::abs(rate), heat);
}

} // namespace roughgas::cli
