#include "run/provenance.hpp"

#include "roughgas/dsmc/species.hpp"
#include "roughgas/io/run_spec_from_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <numbers>

namespace roughgas::cli {
namespace {

// The box and its cells in mean free paths, and the warnings its cells and steps deserve.
std::vector<std::string> box_notes(const RunSpec& spec) {
    double R = 0;
    for (const SpeciesSpec& s : spec.species)
        R = std::max(R, s.radius);
    const double lambda = mean_free_path(spec.density, 2 * R);
    const DomainSpec& d = *spec.domain;
    double edge = 0;
    for (int a = 0; a < 3; ++a)
        edge = std::max(edge, d.size[a] / d.cells[a]);
    std::string walled; // "y (lower: diffuse, upper: diffuse)", "x (...) and z (...)", ...
    for (int a = 0; a < 3; ++a)
        if (d.walled(a))
            walled += fmt::format("{}{} (lower: {}, upper: {})", walled.empty() ? "" : " and ", "xyz"[a],
                                  wall_kind_names[static_cast<std::size_t>(d.wall(a, false).kind)],
                                  wall_kind_names[static_cast<std::size_t>(d.wall(a, true).kind)]);
    const std::string kind =
        walled.empty() ? std::string("periodic box") : fmt::format("box with walls along {}", walled);
    const std::string gravity =
        d.has_gravity() ? fmt::format("; gravity [{:.6g}, {:.6g}, {:.6g}]", d.gravity[0], d.gravity[1], d.gravity[2])
                        : std::string();
    std::vector<std::string> notes = {fmt::format(
        "{} {:.6g} x {:.6g} x {:.6g} = {:.4g} x {:.4g} x {:.4g} mean free paths (lambda = {:.6g}, the "
        "largest diameter's), {} x {} x {} collision cells (edge up to {:.3g} lambda), {:.4g} grains per cell; "
        "steps of {:.4g} mean free times{}; moments.csv's columns are averages over the box",
        kind, d.size[0], d.size[1], d.size[2], d.size[0] / lambda, d.size[1] / lambda, d.size[2] / lambda, lambda,
        d.cells[0], d.cells[1], d.cells[2], edge / lambda,
        static_cast<double>(spec.particles) / (static_cast<double>(d.cells[0]) * d.cells[1] * d.cells[2]),
        d.time_step, gravity)};
    if (edge > 0.5 * lambda)
        notes.push_back(fmt::format(
            "warning: cells of up to {:.3g} mean free paths (more than 0.5): in gradients the viscosity comes "
            "out too large by about 16/(45 pi) (edge/lambda)^2 = {:.2g} (Alexander, Garcia & Alder 1998){}",
            edge / lambda, 16.0 / (45.0 * std::numbers::pi) * (edge / lambda) * (edge / lambda),
            d.partners == PartnerSelection::nearest
                ? "; with nearest partners the grains' spacing sets it instead, a fraction of that"
                : ""));
    // The steps are domain.time_step mean free times of the densest slab: its value is the step
    // in local mean free times wherever the gas is densest.
    if (d.time_step > 0.25)
        notes.push_back(fmt::format(
            "warning: steps of {:.3g} local mean free times (more than 0.25): the viscosity comes out too "
            "large by about (4/75) s^2 = {:.2g} (Hadjiconstantinou 2000; docs/validation.md)",
            d.time_step, 4.0 / 75.0 * d.time_step * d.time_step));
    return notes;
}

} // namespace

RunProvenance run_provenance(const RunSetup& setup, const MomentsTable& table, bool quiet, bool root) {
    const CaseConfig& cfg = setup.cfg;
    const RunSpec& spec = setup.spec;
    const int K = spec.replicas;
    RunProvenance p;
    CsvProvenance& prov = p.csv;
    // Nothing here may differ between a run and its resumption (the CSVs must be byte-identical):
    // the case file and overrides are those the run was started with, kept in the checkpoint.
    prov.case_file = setup.manifest.run.case_file;
    prov.overrides = setup.manifest.run.overrides;
    prov.seed = cfg.run.seed;
    prov.resolved_case = setup.manifest.run.resolved_case;
    prov.notes = {
        "t in the case's time unit; coll_per_particle = 2 x collisions / N; T in energy units (k_B = 1)",
        fmt::format("replicas: {}{}", K, K > 1 ? " (X = mean over replicas, X_err = its standard error)" : ""),
        unit_system_note(cfg),
    };
    if (spec.shear)
        prov.notes.push_back(fmt::format(
            "uniform shear flow u = a y x, a = {}: V = v - u; Strang steps of {} mean free times; "
            "rows at the end of the first step at or after each output's coll_per_particle",
            spec.shear->rate, spec.shear->time_step));
    if (!setup.start_note.empty()) {
        prov.notes.push_back(setup.start_note);
        if (!quiet)
            std::cerr << "roughgas run: " << setup.start_note << '\n';
    }
    for (const std::string& u : cfg.unused) { // kept in the case, not used by this run
        prov.notes.push_back("warning: " + u);
        if (root)
            std::cerr << "roughgas run: warning: " << u << '\n';
    }
    if (spec.domain) { // the box and its cells in mean free paths, on stderr too
        const std::vector<std::string> notes = box_notes(spec);
        p.box_note = notes[0];
        for (const std::string& note : notes) {
            prov.notes.push_back(note);
            if (!quiet)
                std::cerr << "roughgas run: " << note << '\n';
        }
    }
    if (table.has_theory())
        prov.notes.push_back("*_theory: Maxwellian approximation for constant alpha, beta at the row's t "
                             "(observables/theory.hpp; Haff's law for smooth spheres)");
    prov.units = table.units();
    return p;
}

CsvProvenance file_provenance(const RunProvenance& run, std::string what, const std::vector<std::string>& units) {
    CsvProvenance p = run.csv;
    p.notes = {std::move(what), run.csv.notes[1], run.csv.notes[2], run.box_note};
    p.units = units;
    return p;
}

} // namespace roughgas::cli
