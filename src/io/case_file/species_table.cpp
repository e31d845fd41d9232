// [[species]]: its build (the mass given or from the density), its checks (with the solid fraction the
// radii fill at run.density) and its emission.
#include "species_table.hpp"

#include "messages.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/species.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace roughgas::case_file {
namespace {

// m is given directly or from the density of a uniform sphere: never both, never neither.
double mass(BuildContext& ctx, const Reader& r, const SpeciesConfig& s) {
    if (r.has("mass")) {
        if (s.density)
            ctx.add("species.mass", "species.mass: give either mass or density, not both");
        return r.real("mass");
    }
    if (!s.density) {
        ctx.add("species.mass", fmt::format("species.mass: required key is missing (must be {}; or give density)",
                                            expectation(*find_key("species.mass"))));
        return 0;
    }
    return 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius * *s.density;
}

// run.density with the radii and fractions fills the solid fraction phi = sum_s x_s n (pi/6) sigma_s^3
// (dsmc/species.hpp): at or beyond the densest packing of equal spheres no gas exists, dilute or
// dense, and the Boltzmann collision rate of such a case would describe nothing (docs/model.md §4).
void check_packing(BuildContext& ctx, const CaseConfig& c) {
    for (const SpeciesConfig& s : c.species)
        if (!(s.radius > 0 && s.fraction >= 0))
            return; // refused elsewhere
    const double phi = solid_fraction(c.run.density, c.species);
    if (phi >= close_packing)
        ctx.add("run.density",
                fmt::format("run.density = {}: the grains fill the solid fraction phi = {:.4g} (the sum over the "
                            "species of fraction x n (pi/6) (2 R)^3), at or beyond the densest packing of equal spheres, "
                            "pi/sqrt(18) = {:.4f}: no gas (must give phi < {:.4f}; a Boltzmann gas is dilute, "
                            "phi of order 0.01 or less, and run.equation = \"enskog\" describes a fluid up to "
                            "about phi = 0.5)",
                            c.run.density, phi, close_packing, close_packing));
}

} // namespace

SpeciesConfig build_species(BuildContext& ctx, const Reader& r) {
    SpeciesConfig s;
    s.name = r.string("name");
    s.radius = r.real("radius");
    s.density = r.opt_real("density");
    s.mass = mass(ctx, r, s);
    s.inertia = r.real("inertia");
    s.fraction = r.real("fraction");
    s.temperature = r.real("temperature");
    s.rotational_temperature = r.real("rotational_temperature");
    return s;
}

void check_species(BuildContext& ctx, const CaseConfig& c) {
    double sum = 0;
    for (std::size_t i = 0; i < c.species.size(); ++i) {
        const SpeciesConfig& s = c.species[i];
        sum += s.fraction;
        for (std::size_t j = 0; j < i; ++j) {
            if (c.species[j].name == s.name) {
                ctx.add(fmt::format("species.{}.name", i),
                        fmt::format("species.{}.name = \"{}\": must be unique (species.{} has it)", i, s.name, j),
                        fmt::format("species.{}", i));
            }
        }
        // Each species needs at least one simulated particle.
        if (static_cast<double>(c.run.particles) * s.fraction < 1) {
            ctx.add("run.particles",
                    fmt::format("run.particles = {}: species \"{}\" (fraction {}) gets no particle "
                                "(must be >= 1/fraction = {})",
                                c.run.particles, s.name, s.fraction, std::ceil(1 / s.fraction)));
        }
    }
    if (ctx.use() == CaseUse::run)
        check_packing(ctx, c);
    if (!c.species.empty() && std::abs(sum - 1) > 1e-9) {
        ctx.add("species.fraction",
                fmt::format("species.fraction: the fractions sum to {}, must sum to 1 (within "
                            "1e-9)",
                            sum),
                "species.0.fraction");
    }
}

void emit_species(Emitter& e, const std::vector<SpeciesConfig>& species) {
    for (const SpeciesConfig& s : species) {
        e.header("[[species]]");
        e.put("name", s.name);
        if (s.density) { // the mass was derived: echo what the user gave, so that it reads back the same
            e.put("density", s.density);
        } else {
            e.put("mass", s.mass);
        }
        e.put("radius", s.radius);
        e.put("inertia", s.inertia);
        e.put("fraction", s.fraction);
        e.put("temperature", s.temperature);
        e.put("rotational_temperature", s.rotational_temperature);
    }
}

} // namespace roughgas::case_file
