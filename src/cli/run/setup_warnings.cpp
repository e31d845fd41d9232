#include "run/setup_warnings.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/species.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace roughgas::cli {
namespace {

double largest_edge(const DomainSpec& d) {
    double edge = 0;
    for (int a = 0; a < 3; ++a)
        edge = std::max(edge, d.size[a] / d.cells[a]);
    return edge;
}

// The Boltzmann collision rate is the dilute gas's: a denser gas collides chi times as often
// (Enskog's factor, dsmc/pair_correlation.hpp). A homogeneous gas's evolution per collision is the
// same, so its clock t is what comes out off by chi, and its pressure lacks the collisional part; in
// gradients the Enskog transport coefficients differ from the Boltzmann ones by chi and by the
// collisional transfer of momentum and energy. An Enskog run beyond the freezing point describes a
// metastable fluid with an extrapolated chi.
void dense_gas(const RunSpec& spec, std::vector<std::string>& out) {
    const double phi = solid_fraction(spec.density, spec.species);
    if (spec.enskog) {
        if (spec.enskog->model == PairCorrelationModel::carnahan_starling && phi > hard_sphere_freezing)
            out.push_back(fmt::format(
                "solid fraction phi = {:.3g} (run.density = {:.4g}), above the freezing point of hard spheres, "
                "phi = {:g} (Hoover & Ree 1968): the uniform fluid the Enskog equation describes is metastable "
                "there, and Carnahan & Starling's chi = {:.3g} an extrapolation of the fluid's",
                phi, spec.density, hard_sphere_freezing, carnahan_starling_chi(phi)));
        return;
    }
    const double chi = carnahan_starling_chi(phi);
    if (!(chi - 1 > dense_gas_excess))
        return;
    out.push_back(fmt::format(
        "solid fraction phi = {:.3g} (run.density = {:.4g}): the Boltzmann equation describes a dilute gas, but at "
        "this density the grains meet chi = {:.3g} times as often as it says (the pair correlation at contact, "
        "chi = (1 - phi/2)/(1 - phi)^3, Carnahan & Starling 1969; more than {:g} % above 1): the run's clock t, "
        "its rates and its transport coefficients are off by a factor of about chi, its pressure by the "
        "collisional part 4 phi chi n T, while its collisions per particle and what a collision does are not; "
        "run.equation = \"enskog\" solves the Enskog equation of a dense gas",
        phi, spec.density, chi, 100 * dense_gas_excess));
}

// The box's cells against the mean free path (Alexander, Garcia & Alder 1998) and a grain, the
// grains they hold, and the steps (Hadjiconstantinou 2000).
void box(const RunSpec& spec, std::vector<std::string>& out) {
    const DomainSpec& d = *spec.domain;
    const double sigma = largest_diameter(spec.species);
    const double edge = largest_edge(d);
    const double ratio = cells_over_mean_free_path(spec);
    if (ratio > 0.5)
        out.push_back(fmt::format(
            "cells of up to {:.3g} mean free paths (more than 0.5{}): in gradients the viscosity comes out too "
            "large by about 16/(45 pi) (edge/lambda)^2 = {:.2g} (Alexander, Garcia & Alder 1998){}",
            ratio, ratio > 1 ? "; more than 1 with domain.allow_coarse: the cells do not resolve the gas" : "",
            16.0 / (45.0 * std::numbers::pi) * ratio * ratio,
            d.partners == PartnerSelection::nearest
                ? "; with nearest partners the grains' spacing sets it instead, a fraction of that"
                : ""));
    // The cells resolve the mean free path, many grains across in a dilute gas: a cell smaller than a
    // grain along every axis cannot hold one whole, and the Boltzmann equation says nothing of lengths
    // below a grain (its collisions are local on the scale of the mean free path).
    if (edge < sigma && !spec.enskog)
        out.push_back(fmt::format(
            "cells of edge up to {:.4g}, smaller than a grain (diameter sigma = {:.4g}, the largest): the Boltzmann "
            "equation describes the gas on lengths well above a grain, and no cell this small holds one whole "
            "(cells of half a mean free path are many diameters across in a dilute gas)",
            edge, sigma));
    const double per_cell =
        static_cast<double>(spec.particles) /
        (static_cast<double>(d.cells[0]) * static_cast<double>(d.cells[1]) * static_cast<double>(d.cells[2]));
    // The Enskog collisions draw a grain's partner from the cells a diameter away, about
    // n_sim 4 pi sigma^2 h grains around each grain (n_sim the simulated grains per volume, h the
    // cell's size): a pair that has just collided recedes yet stays among them, drawn again and
    // rejected, so the collision frequency comes out low by about one over that count
    // (docs/validation.md measures it from 0.01 to 1.4 %).
    const double cell_volume = d.size[0] * d.size[1] * d.size[2] / (static_cast<double>(d.cells[0]) *
                                                                      static_cast<double>(d.cells[1]) *
                                                                      static_cast<double>(d.cells[2]));
    const double pool = per_cell / cell_volume * 4 * std::numbers::pi * sigma * sigma * std::cbrt(cell_volume);
    if (spec.enskog && 1 / pool > enskog_partner_deficit)
        out.push_back(fmt::format(
            "{:.3g} grains per cell on average, about {:.3g} in the cells a diameter from a grain: an Enskog "
            "collision's partner comes from those cells, where a grain that has just collided, now receding, "
            "stays and is drawn again; the collision frequency and the collisional pressure come out low by "
            "about 1/{:.3g} = {:.2g} % (docs/validation.md); give more run.particles",
            per_cell, pool, pool, 100 / pool));
    else if (per_cell < fewest_grains_per_cell)
        out.push_back(fmt::format(
            "{:.3g} grains per cell on average (fewer than {:g}): a cell's few grains collide with the same partners "
            "again and again instead of with the gas, and the run's state is biased by it (docs/validation.md: "
            "a cooling box's a20 comes out about 0.003 too high at 5 grains per cell and 0.01 at 1, its theta "
            "1 % low at 1); give more run.particles or fewer domain.cells",
            per_cell, fewest_grains_per_cell));
    // The steps are domain.time_step mean free times of the densest slab: its value is the step
    // in local mean free times wherever the gas is densest.
    if (d.time_step > 0.25)
        out.push_back(fmt::format(
            "steps of {:.3g} local mean free times (more than 0.25): the viscosity comes out too large by about "
            "(4/75) s^2 = {:.2g} (Hadjiconstantinou 2000; docs/validation.md)",
            d.time_step, 4.0 / 75.0 * d.time_step * d.time_step));
}

} // namespace

double cells_over_mean_free_path(const RunSpec& spec) {
    return largest_edge(*spec.domain) / mean_free_path(spec.density, largest_diameter(spec.species));
}

std::vector<std::string> setup_warnings(const CaseConfig& cfg, const RunSpec& spec) {
    std::vector<std::string> out = cfg.unused; // kept in the case, not read by this run
    dense_gas(spec, out);
    if (spec.domain)
        box(spec, out);
    return out;
}

} // namespace roughgas::cli
