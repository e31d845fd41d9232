// [domain]: its build (the profile axis resolved), its checks and its emission.
#include "domain_table.hpp"

#include "roughgas/dsmc/species.hpp"
#include "toml_access.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace roughgas::case_file {
namespace {

// The shortest mean free path of the gas, 1/(sqrt(2) pi n sigma^2) with the largest diameter
// sigma = 2 max R: the length the cells must resolve.
double mean_free_path(const CaseConfig& c) {
    return roughgas::mean_free_path(c.run.density, largest_diameter(c.species));
}

} // namespace

std::optional<DomainConfig> build_domain(BuildContext& ctx) {
    const toml::table* t = ctx.root()["domain"].as_table();
    if (t == nullptr)
        return std::nullopt;
    for (const char* k : {"size", "cells"})
        if (!t->contains(k))
            ctx.add(std::string("domain.") + k,
                    fmt::format("[domain] without domain.{}: give {}", k,
                                std::string_view(k) == "size" ? "the box lengths [L_x, L_y, L_z]"
                                                              : "the cells per axis [n_x, n_y, n_z]"));
    const Reader r(t, "domain");
    DomainConfig d;
    d.size = r.real3("size");
    d.cells = r.integer3("cells");
    const std::array<std::string, 3> b = r.string3("boundary");
    for (std::size_t i = 0; i < 3; ++i)
        d.boundary[i] = static_cast<Boundary>(std::find(boundary_names.begin(), boundary_names.end(), b[i]) -
                                              boundary_names.begin());
    d.gravity = r.real3("gravity");
    if (r.has("profile_axis")) {
        d.profile_axis = static_cast<int>(r.string("profile_axis")[0] - 'x');
    } else if (ctx.root()["run"]["kind"].value_or(std::string()) == "shear") {
        d.profile_axis = 1; // the Lees-Edwards gradient
    } else {
        const auto walled = std::find(d.boundary.begin(), d.boundary.end(), Boundary::walls);
        d.profile_axis = walled == d.boundary.end() ? 0 : static_cast<int>(walled - d.boundary.begin());
    }
    d.time_step = r.real("time_step");
    d.allow_coarse = r.boolean("allow_coarse");
    d.partners = r.choice<PartnerSelection>("partners", partner_names);
    d.chi_cells = r.integer("chi_cells");
    return d;
}

void check_domain(BuildContext& ctx, const CaseConfig& c) {
    const DomainConfig& d = *c.domain;
    if (c.run.kind == RunKind::shear) // Lees-Edwards along y: x and y periodic
        for (std::size_t a : {0, 1})
            if (d.boundary[a] == Boundary::walls)
                ctx.add("domain.boundary",
                        fmt::format("domain.boundary[{}] = \"walls\" with run.kind = \"shear\": a sheared box has "
                                    "Lees-Edwards boundaries along y and flows along x, both periodic (walls "
                                    "along z only)",
                                    a));
    if (c.run.histogram_every > 0)
        ctx.add("run.histogram_every", "run.histogram_every with [domain]: histograms are written for the "
                                       "homogeneous gas only (set it to 0)");
    if (c.run.time_clock() && c.run.histogram_every_time > 0)
        ctx.add("run.histogram_every_time", "run.histogram_every_time with [domain]: histograms are written for "
                                            "the homogeneous gas only (set it to 0)");
    const double cells =
        static_cast<double>(d.cells[0]) * static_cast<double>(d.cells[1]) * static_cast<double>(d.cells[2]);
    if (cells > 1e8)
        ctx.add("domain.cells", fmt::format("domain.cells = [{}, {}, {}]: {:.3g} cells, at most 1e8", d.cells[0],
                                            d.cells[1], d.cells[2], cells));
}

void check_cell_size(BuildContext& ctx, const CaseConfig& c) {
    const DomainConfig& d = *c.domain;
    double lambda = mean_free_path(c);
    // A density wave's crest is denser by 1 + |A|: its mean free path shorter by that.
    if (c.initial && c.initial->mode == Perturbation::density)
        lambda /= 1 + std::abs(c.initial->amplitude);
    double edge = 0;
    for (std::size_t i = 0; i < 3; ++i)
        edge = std::max(edge, d.size[i] / static_cast<double>(d.cells[i]));
    if (edge > lambda && !d.allow_coarse)
        ctx.add("domain.cells",
                fmt::format("domain.cells = [{}, {}, {}]: cells of {:.3g} mean free paths (edge {:.4g}, mean free "
                            "path {:.4g} at run.density = {:.4g}): at most 1, or set domain.allow_coarse = true",
                            d.cells[0], d.cells[1], d.cells[2], edge / lambda, edge, lambda, c.run.density));
}

void emit_domain(Emitter& e, const DomainConfig& d) {
    e.header("[domain]");
    e.put("size", d.size);
    e.put("cells", d.cells);
    e.put("boundary", std::array<std::string, 3>{std::string(name(d.boundary[0])), std::string(name(d.boundary[1])),
                                                  std::string(name(d.boundary[2]))});
    e.put("gravity", d.gravity);
    e.put("profile_axis", std::string_view(&"xyz"[d.profile_axis], 1));
    e.put("time_step", d.time_step);
    e.put("allow_coarse", d.allow_coarse);
    e.put("partners", name(d.partners));
    if (d.chi_cells != 0)
        e.put("chi_cells", d.chi_cells);
}

} // namespace roughgas::case_file
