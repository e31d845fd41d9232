// [run]: its build, the checks of run.kernel, the clock (run.end or run.end_time), run.end and
// run.histogram_every, and its emission.
#include "run_table.hpp"

#include "messages.hpp"
#include "thermostat_table.hpp"

#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/theory.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace roughgas::case_file {
namespace {

// A hard-sphere gas cooling with constant restitution loses the share zeta* of its translational
// temperature per collision per particle once its temperatures' ratios have settled (the reduced
// cooling rate of its cooling state, docs/model.md §5): T_tr falls as exp(-zeta* s). Below about
// T_tr/m = 1e-300 (in the case's units) the squares of the velocities underflow and the run would stop
// with an error partway; refused before any work (cooling_reach: the theory's trajectory from the
// species' temperatures). Not for a gas a thermostat heats, nor a box whose walls drive it (a diffuse
// or moving wall holds it at a steady state); with initial.from, run_states.cpp checks it from the
// saved state's.
void check_cooling_reach(BuildContext& ctx, const CaseConfig& c) {
    const std::size_t S = c.species.size();
    std::vector<HcsSpecies> species;
    std::vector<ConstantRestitution> pairs(S * (S + 1) / 2);
    HcsTemperatures T;
    for (std::size_t a = 0; a < S; ++a) {
        const SpeciesConfig& s = c.species[a];
        if (!(s.mass > 0 && s.radius > 0 && s.temperature > 0 && s.rotational_temperature >= 0))
            return; // refused elsewhere
        species.push_back({s.mass, s.radius, s.inertia, s.fraction});
        T.T_tr.push_back(s.temperature);
        T.T_rot.push_back(s.rotational_temperature);
        for (std::size_t b = a; b < S; ++b) {
            const CollisionConfig& cc = collision_for(c, a, b);
            if (cc.model != CollisionModel::constant || !cc.alpha || !cc.beta)
                return; // restitution that depends on the impact speed: the gas cools ever slower
            pairs[pair_index(a, b, S)] = ConstantRestitution{*cc.alpha, *cc.beta};
        }
    }
    double reach = HUGE_VAL;
    try {
        const HcsTheory theory(species, pairs, c.run.density);
        reach = c.run.time_clock() ? cooling_reach_time(theory, T, underflow_temperature_per_mass)
                                   : cooling_reach(theory, T, underflow_temperature_per_mass);
    } catch (const std::invalid_argument&) {
        return; // refused elsewhere
    }
    if (c.run.time_clock()) {
        // Haff's law: T_tr falls as 1/t^2 once the gas cools in its cooling state, so the floor
        // comes at a finite time (some 1e150 mean free times from T_tr/m = 1: collisions per
        // particle grow only as ln t).
        if (*c.run.end_time > reach)
            ctx.add("run.end_time",
                    fmt::format("run.end_time = {}: a gas cooling with constant restitution reaches T_tr/m = 1e-300 "
                                "(velocities squared underflow) at about t = {:.4g} (Haff's law: T_tr ~ 1/t^2): "
                                "end it before (run.end_time < {:.4g})",
                                *c.run.end_time, reach, reach));
        return;
    }
    if (c.run.end > reach)
        ctx.add("run.end",
                fmt::format("run.end = {}: a gas cooling with constant restitution loses a fixed share of its "
                            "temperature per collision and reaches T_tr/m = 1e-300 (velocities squared "
                            "underflow) at about {:.4g} collisions per particle: end it before "
                            "(run.end < {:.4g})",
                            c.run.end, reach, reach));
}

// A gas that nothing drives: not driven(), or held by a thermostat that injects nothing (white
// noise of strength 0 throughout), which is refused with [domain] and so the only drive there is.
bool cools_freely(const CaseConfig& c) {
    return !driven(c) || (c.thermostat && !c.domain && !thermostat_heats(c));
}

// The Maxwell kernel is the reference model with a known answer for constant alpha, beta
// (docs/model.md); it is compiled for constant restitution only.
void check_maxwell_kernel(BuildContext& ctx, const CaseConfig& c) {
    for (std::size_t a = 0; a < c.species.size(); ++a) {
        for (std::size_t b = a; b < c.species.size(); ++b) {
            const CollisionModel m = collision_for(c, a, b).model;
            if (m == CollisionModel::constant)
                continue;
            ctx.add("run.kernel",
                    fmt::format("run.kernel = \"maxwell\": needs model = \"constant\" for every pair, but "
                                "species \"{}\" and \"{}\" collide with model = \"{}\" (the Maxwell kernel is "
                                "the reference model of constant restitution; must be \"hard_sphere\" here)",
                                c.species[a].name, c.species[b].name, name(m)));
            return; // one message
        }
    }
}

// run.equation = "enskog": its chi (a constant needs run.chi, and run.chi needs a constant), and the
// runs it is solved for: the homogeneous gas, cooling, driven or sheared (with the hard-sphere kernel),
// and boxes with random partners and the hard-sphere kernel (periodic, walled or sheared), each
// periodic side at least two diameters long, the smoothing cube odd.
void check_equation(BuildContext& ctx, const CaseConfig& c) {
    if (c.run.equation != KineticEquation::enskog)
        return; // pair_correlation and chi are kept, not read (note_unused_enskog)
    if (c.run.pair_correlation == PairCorrelationModel::constant && !c.run.chi)
        ctx.add("run.chi", fmt::format("run.chi: required key is missing with run.pair_correlation = \"constant\" "
                                       "(must be {})",
                                       expectation(*find_key("run.chi"))));
    if (c.run.pair_correlation != PairCorrelationModel::constant && c.run.chi)
        ctx.add("run.chi", fmt::format("run.chi = {}: a constant chi, but run.pair_correlation = \"{}\" computes it "
                                       "from the solid fraction (set run.pair_correlation = \"constant\", or leave "
                                       "run.chi out)",
                                       *c.run.chi, name(c.run.pair_correlation)));
    if (c.domain) {
        const DomainConfig& d = *c.domain;
        if (c.run.kernel == CollisionKernel::maxwell)
            ctx.add("run.kernel", "run.kernel = \"maxwell\" with run.equation = \"enskog\" and [domain]: a box's "
                                  "Enskog collisions are those of hard spheres a diameter apart (must be "
                                  "\"hard_sphere\" here)");
        if (d.partners != PartnerSelection::random)
            ctx.add("domain.partners", "domain.partners = \"nearest\" with run.equation = \"enskog\": the partner of "
                                       "an Enskog collision is a grain a diameter away, in the cell holding that "
                                       "point (must be \"random\" here)");
        if (d.chi_cells % 2 == 0 && d.chi_cells != 0)
            ctx.add("domain.chi_cells", fmt::format("domain.chi_cells = {}: the smoothing cube is centred on a cell "
                                                    "(must be odd, or 0 for the automatic size)",
                                                    d.chi_cells));
        double sigma = 0;
        for (const SpeciesConfig& s : c.species)
            sigma = std::max(sigma, 2 * s.radius);
        for (std::size_t a = 0; a < 3; ++a)
            if (d.boundary[a] == Boundary::periodic && d.size[a] < 2 * sigma)
                ctx.add("domain.size", fmt::format("domain.size[{}] = {}: a periodic side of an Enskog box shorter "
                                                   "than two grain diameters ({}) lets a grain collide with its "
                                                   "own image (must be >= {})",
                                                   a, d.size[a], 2 * sigma, 2 * sigma));
    } else if (c.run.kind == RunKind::shear && c.run.kernel == CollisionKernel::maxwell)
        ctx.add("run.kernel", "run.kernel = \"maxwell\" with run.equation = \"enskog\" and run.kind = \"shear\": "
                              "the sheared Enskog gas collides grains a diameter apart at the hard spheres' rate, "
                              "which depends on the flow between them (must be \"hard_sphere\" here)");
}

} // namespace

RunConfig build_run(const Reader& r) {
    RunConfig c;
    c.kind = r.choice<RunKind>("kind", run_kind_names);
    c.particles = r.integer("particles");
    c.density = r.real("density");
    c.replicas = r.integer("replicas");
    c.groups = r.integer("groups");
    c.kernel = r.choice<CollisionKernel>("kernel", kernel_names);
    c.equation = r.choice<KineticEquation>("equation", equation_names);
    c.pair_correlation = r.choice<PairCorrelationModel>("pair_correlation", pair_correlation_names);
    c.chi = r.opt_real("chi");
    c.seed = static_cast<std::uint64_t>(r.integer("seed"));
    c.end = r.opt_real("end").value_or(0.0);
    c.end_time = r.opt_real("end_time");
    c.output_every = r.real("output_every");
    c.output_every_time = r.opt_real("output_every_time");
    if (c.end_time && !c.output_every_time)
        c.output_every_time = *c.end_time / 100;
    c.output_spacing = r.choice<OutputSpacing>("output_spacing", output_spacing_names);
    c.histogram_every = r.real("histogram_every");
    c.histogram_every_time = r.real("histogram_every_time");
    c.histogram_spacing = r.choice<OutputSpacing>("histogram_spacing", output_spacing_names);
    c.histogram_bins = r.integer("histogram_bins");
    c.histogram_max = r.real("histogram_max");
    c.save_state = r.boolean("save_state");
    return c;
}

// Exactly one clock: run.end (collisions per particle) or run.end_time (time), and the output and
// histogram keys of that clock only, since the other clock's numbers mean something else.
void check_clock(BuildContext& ctx, const CaseConfig& c) {
    const toml::table* run = ctx.root()["run"].as_table();
    const auto given = [&](const char* key) { return run != nullptr && run->get(key) != nullptr; };
    const bool end = given("end"), end_time = given("end_time");
    if (end && end_time)
        ctx.add("run.end_time", fmt::format("run.end_time = {}: give either run.end (collisions per particle) or "
                                            "run.end_time (time), not both",
                                            *c.run.end_time));
    else if (!end && !end_time)
        ctx.add("run.end", fmt::format("run.end: required key is missing (must be {}; or give run.end_time, {})",
                                       expectation(*find_key("run.end")), expectation(*find_key("run.end_time"))));
    const auto wrong_clock = [&](const char* key, const char* instead) {
        if (!given(key))
            return;
        ctx.add(std::string("run.") + key,
                end_time ? fmt::format("run.{}: in collisions per particle, but this run is clocked by run.end_time "
                                       "(time): use run.{} instead",
                                       key, instead)
                         : fmt::format("run.{}: a time, for a run clocked by run.end_time, but this run ends at run.end "
                                       "(collisions per particle): use run.{} instead",
                                       key, instead));
    };
    if (end_time) {
        wrong_clock("output_every", "output_every_time");
        wrong_clock("histogram_every", "histogram_every_time");
    } else {
        wrong_clock("output_every_time", "output_every");
        wrong_clock("histogram_every_time", "histogram_every");
    }
}

// A run lists its output times before it starts (io/run_spec_from_case.cpp), so a linear cadence
// that gives more rows than max_rows would spend the memory and time of that list, and write a CSV
// of gigabytes, before a single collision. (Log-spaced rows, ten per decade, never come close.)
void check_rows(BuildContext& ctx, const char* key, double every, const char* end_key, double end,
                OutputSpacing spacing) {
    constexpr double max_rows = 1e7;
    if (spacing != OutputSpacing::linear || !(every > 0) || !(end > 0) || !(end / every > max_rows))
        return;
    ctx.add(std::string("run.") + key,
            fmt::format("run.{} = {}: {:.3g} rows to run.{} = {}, more than a run writes (must be >= run.{}/{:g} = {:g}, "
                        "or output_spacing = \"log\")",
                        key, every, end / every, end_key, end, end_key, max_rows, end / max_rows));
}

void check_run(BuildContext& ctx, const CaseConfig& c) {
    check_clock(ctx, c);
    check_equation(ctx, c);
    if (c.run.time_clock()) {
        check_rows(ctx, "output_every_time", c.run.output_every_time.value_or(0.0), "end_time", *c.run.end_time,
                   c.run.output_spacing);
        check_rows(ctx, "histogram_every_time", c.run.histogram_every_time, "end_time", *c.run.end_time,
                   c.run.histogram_spacing);
    } else {
        check_rows(ctx, "output_every", c.run.output_every, "end", c.run.end, c.run.output_spacing);
        check_rows(ctx, "histogram_every", c.run.histogram_every, "end", c.run.end, c.run.histogram_spacing);
    }
    if (c.run.time_clock() && c.run.histogram_every_time > *c.run.end_time)
        ctx.add("run.histogram_every_time",
                fmt::format("run.histogram_every_time = {}: after the end of the run (must be <= run.end_time = {})",
                            c.run.histogram_every_time, *c.run.end_time));
    if (c.run.kernel == CollisionKernel::maxwell)
        check_maxwell_kernel(ctx, c);
    else if (c.run.kind == RunKind::cooling && ctx.use() == CaseUse::run && cools_freely(c) &&
             !(c.initial && !c.initial->from.empty()))
        check_cooling_reach(ctx, c); // from a saved state: its own temperatures (io/run_states.cpp)
    if (!c.run.time_clock() && c.run.histogram_every > c.run.end) {
        ctx.add("run.histogram_every",
                fmt::format("run.histogram_every = {}: after the end of the run (must be <= run.end = {})",
                            c.run.histogram_every, c.run.end));
    }
}

// The Enskog equation's keys in a run of the Boltzmann equation: kept (a --set may switch the equation),
// not read, reported as warnings (CaseConfig::unused).
void note_unused_enskog(const toml::table& root, CaseConfig& c) {
    const toml::table* run = root["run"].as_table();
    if (run == nullptr || c.run.equation == KineticEquation::enskog)
        return;
    for (const char* key : {"pair_correlation", "chi"})
        if (run->get(key) != nullptr)
            c.unused.push_back(fmt::format("run.{} is not used by run.equation = \"boltzmann\" (the pair correlation "
                                           "of the Enskog equation)",
                                           key));
    if (const toml::table* domain = root["domain"].as_table(); domain && domain->get("chi_cells") != nullptr)
        c.unused.push_back("domain.chi_cells is not used by run.equation = \"boltzmann\" (the smoothing of the "
                           "Enskog equation's pair correlation)");
}

void emit_run(Emitter& e, const RunConfig& r) {
    e.header("[run]");
    e.put("kind", name(r.kind));
    e.put("particles", r.particles);
    e.put("density", r.density);
    e.put("replicas", r.replicas);
    e.put("groups", r.groups);
    e.put("kernel", kernel_names[static_cast<int>(r.kernel)]);
    e.put("equation", equation_names[static_cast<int>(r.equation)]);
    if (r.equation == KineticEquation::enskog) {
        e.put("pair_correlation", pair_correlation_names[static_cast<int>(r.pair_correlation)]);
        if (r.chi)
            e.put("chi", *r.chi);
    }
    e.put("seed", r.seed);
    if (r.time_clock()) { // the keys of the time clock, and none of the collision clock's
        e.put("end_time", r.end_time);
        e.put("output_every_time", r.output_every_time);
        e.put("output_spacing", name(r.output_spacing));
        e.put("histogram_every_time", r.histogram_every_time);
    } else {
        e.put("end", r.end);
        e.put("output_every", r.output_every);
        e.put("output_spacing", name(r.output_spacing));
        e.put("histogram_every", r.histogram_every);
    }
    e.put("histogram_spacing", name(r.histogram_spacing));
    e.put("histogram_bins", r.histogram_bins);
    e.put("histogram_max", r.histogram_max);
    e.put("save_state", r.save_state);
}

} // namespace roughgas::case_file
