#include "run/provenance.hpp"

#include "run/setup_warnings.hpp"

#include "roughgas/dsmc/species.hpp"
#include "roughgas/io/run_spec_from_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>

namespace roughgas::cli {
namespace {

// The box and its cells in mean free paths (their warnings: run/setup_warnings.hpp).
std::string box_note(const RunSpec& spec) {
    const double lambda = mean_free_path(spec.density, largest_diameter(spec.species));
    const DomainSpec& d = *spec.domain;
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
    return fmt::format(
        "{} {:.6g} x {:.6g} x {:.6g} = {:.4g} x {:.4g} x {:.4g} mean free paths (lambda = {:.6g}, the "
        "largest diameter's), {} x {} x {} collision cells (edge up to {:.3g} lambda), {:.4g} grains per cell; "
        "steps of {:.4g} mean free times{}; moments.csv's columns are averages over the box",
        kind, d.size[0], d.size[1], d.size[2], d.size[0] / lambda, d.size[1] / lambda, d.size[2] / lambda, lambda,
        d.cells[0], d.cells[1], d.cells[2], cells_over_mean_free_path(spec),
        static_cast<double>(spec.particles) / (static_cast<double>(d.cells[0]) * d.cells[1] * d.cells[2]),
        d.time_step, gravity);
}

} // namespace

RunProvenance run_provenance(const RunSetup& setup, const MomentsTable& table, bool root) {
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
    if (spec.clock == Clock::time)
        prov.notes.push_back(spec.domain ? "time clock (run.end_time): rows at the output times t, each the end of a "
                                           "step shortened to end there"
                                         : "time clock (run.end_time): rows at the output times t, each the state "
                                           "after the last collision before t");
    if (spec.shear && spec.clock == Clock::time)
        prov.notes.push_back(fmt::format(
            "uniform shear flow u = a y x, a = {}: V = v - u; Strang steps of {} mean free times, the last one "
            "before each output shortened to end at its t",
            spec.shear->rate, spec.shear->time_step));
    else if (spec.shear)
        prov.notes.push_back(fmt::format(
            "uniform shear flow u = a y x, a = {}: V = v - u; Strang steps of {} mean free times; "
            "rows at the end of the first step at or after each output's coll_per_particle",
            spec.shear->rate, spec.shear->time_step));
    if (!setup.start_note.empty()) {
        prov.notes.push_back(setup.start_note);
        if (root)
            std::cerr << "roughgas run: " << setup.start_note << '\n';
    }
    if (spec.domain) { // the box and its cells in mean free paths, on stderr too
        p.box_note = box_note(spec);
        prov.notes.push_back(p.box_note);
        if (root)
            std::cerr << "roughgas run: " << p.box_note << '\n';
    }
    // Every warning of the set-up, once, whatever --quiet (rank 0's alone on stderr).
    for (const std::string& w : setup_warnings(cfg, spec)) {
        prov.notes.push_back("warning: " + w);
        if (root)
            std::cerr << "roughgas run: warning: " << w << '\n';
    }
    if (table.has_theory() && spec.thermostat)
        prov.notes.push_back("*_theory: Maxwellian approximation for constant alpha, beta of the gas driven by its "
                             "thermostat at the row's t (observables/driven_theory.hpp); *_steady_theory: its steady "
                             "state under the final drives; T_tr_sonine, a20_sonine (smooth grains, white noise): the "
                             "first Sonine approximation's steady state");
    else if (table.has_theory())
        prov.notes.push_back("*_theory: Maxwellian approximation for constant alpha, beta at the row's t "
                             "(observables/theory.hpp; Haff's law for smooth spheres)");
    if (spec.thermostat)
        prov.notes.push_back("thermostat: the kicks of a step come at its start, half a step ahead of the time "
                             "there; the rows' moments are taken at the rows' t (the kicks' map of the moments, "
                             "dsmc/thermostat.hpp), histograms and saved states are the grains as they are");
    if (table.has_sonine())
        prov.notes.push_back("*_sonine: the scaled cooling state in the first Sonine approximation, the same in "
                             "every row (observables/sonine_cooling_state.hpp)");
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
