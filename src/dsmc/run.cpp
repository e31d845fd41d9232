// One replica of a homogeneous cooling run: the kernel is chosen once (std::visit over the pairs'
// restitution models) and the loop below only pauses it at the output times (and
// saves or restores its state for checkpoints, between chunks of the loop).
#include "roughgas/dsmc/run.hpp"

#include "drive.hpp"
#include "roughgas/observables/profiles.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace roughgas {
namespace {

using detail::drive_kernel;
using detail::has_brilliantov;
using detail::is_constant_policy;
using detail::ReplicaIo;

const char* const group_quantities[] = {"T_tr", "T_rot", "theta", "a20", "a02", "a11", "A_cw", "coll_rate"};
const char* const group_units[] = {"energy", "energy", "-", "-", "-", "-", "-", "1/time"};

void require(bool ok, const std::string& what) {
    if (!ok)
        throw std::invalid_argument("run_replica: " + what);
}

void validate(const RunSpec& spec) {
    const std::size_t S = spec.species.size();
    require(S > 0, "no species");
    for (const SpeciesSpec& s : spec.species) {
        require(s.mass > 0 && s.radius > 0 && s.inertia > 0,
                "species " + s.name + ": mass, radius and inertia must be > 0");
        require(s.temperature >= 0 && s.rotational_temperature >= 0,
                "species " + s.name + ": negative temperature");
    }
    require(spec.pairs.size() == S * (S + 1) / 2, "one restitution model per species pair needed");
    require(spec.particles >= 2, "at least two particles needed");
    require(spec.density > 0, "density must be > 0");
    require(spec.step > 0, "step must be > 0");
    require(spec.speed_classes >= 1 && spec.speed_classes <= 6, "speed_classes must be in 1 .. 6");
    require(spec.groups >= 0 && spec.groups <= 4096, "groups must be in 0 .. 4096");
    double prev = 0;
    for (double t : spec.output_times) {
        require(std::isfinite(t) && t > prev, "output times must be positive and increasing");
        prev = t;
    }
    require(!spec.output_times.empty() || (std::isfinite(spec.end) && spec.end > 0), "end must be > 0");
    const double end = spec.output_times.empty() ? spec.end : spec.output_times.back();
    prev = 0;
    for (double t : spec.histogram_times) {
        require(std::isfinite(t) && t > prev && t <= end * (1 + 1e-12),
                "histogram times must be positive, increasing and not after the end");
        prev = t;
    }
    require(spec.histogram_bins >= 1 && spec.histogram_max > 0 && std::isfinite(spec.histogram_max),
            "histogram_bins must be >= 1 and histogram_max > 0");
    if (spec.kernel == CollisionKernel::maxwell)
        require(std::all_of(spec.pairs.begin(), spec.pairs.end(),
                            [](const PairRestitution& p) { return std::holds_alternative<ConstantRestitution>(p); }),
                "the Maxwell kernel needs constant restitution for every pair");
    if (spec.domain) {
        for (int a = 0; a < 3; ++a)
            require(spec.domain->size[a] > 0 && std::isfinite(spec.domain->size[a]) && spec.domain->cells[a] >= 1,
                    "domain sizes must be > 0 and cells >= 1");
        require(spec.domain->time_step > 0 && std::isfinite(spec.domain->time_step), "domain time step must be > 0");
        require(spec.shear.has_value() == spec.domain->lees_edwards() &&
                    (!spec.shear || spec.shear->rate == spec.domain->shear_rate),
                "a sheared box has Lees-Edwards boundaries at the shear rate, and only a sheared box");
        require(!spec.domain->lees_edwards() || (!spec.domain->walled(0) && !spec.domain->walled(1)),
                "Lees-Edwards boundaries need x and y periodic");
        require(!spec.thermostat || !spec.domain->lees_edwards(),
                "a sheared box (Lees-Edwards) takes no thermostat: uniform shear flow heats the gas itself");
        require(spec.histogram_times.empty(), "a spatially resolved run writes no histograms");
        require(spec.domain->profile_axis >= 0 && spec.domain->profile_axis <= 2, "the profile axis must be 0, 1 or 2");
        require(!spec.domain->spectra || (!spec.domain->has_walls() && !spec.domain->lees_edwards()),
                "spectra need a periodic box (no walls, no Lees-Edwards)");
        require(!spec.domain->spectra || (spec.domain->spectra->modes >= 0 && spec.domain->spectra->modes <= 4096),
                "spectra modes must be in [0, 4096]");
        require(!spec.domain->fields || (spec.domain->fields->every >= 1 && spec.domain->fields->replicas >= 1),
                "fields every and replicas must be at least 1");
        for (double g : spec.domain->gravity)
            require(std::isfinite(g), "gravity must be finite");
        for (int axis = 0; axis < 3; ++axis)
            for (const bool upper : {false, true}) {
                if (!spec.domain->walled(axis))
                    continue;
                const WallSpec* w = &spec.domain->wall(axis, upper);
                require(w->kind != WallKind::diffuse || (w->temperature > 0 && std::isfinite(w->temperature)),
                        "a diffuse wall's temperature must be > 0");
                require(w->kind != WallKind::rough || (w->alpha > 0 && w->alpha <= 1 && std::abs(w->beta) <= 1),
                        "a rough wall needs 0 < alpha <= 1 and -1 <= beta <= 1");
                for (const double u : w->velocity)
                    require(std::isfinite(u), "wall velocities must be finite");
                require(w->velocity[static_cast<std::size_t>(axis)] == 0,
                        "a wall moves only along itself (no velocity along its normal)");
            }
    }
    if (spec.enskog) {
        require(spec.enskog->model != PairCorrelationModel::constant ||
                    (std::isfinite(spec.enskog->chi) && spec.enskog->chi > 0),
                "a constant pair correlation chi must be > 0");
        require(!spec.domain || (spec.kernel == CollisionKernel::hard_sphere &&
                                 spec.domain->partners == PartnerSelection::random),
                "an Enskog box needs the hard-sphere kernel and random partners");
        require(!spec.domain || spec.domain->chi_cells == 0 || spec.domain->chi_cells % 2 == 1,
                "the Enskog smoothing cube needs an odd number of cells per side");
        require(!spec.shear || spec.kernel == CollisionKernel::hard_sphere,
                "the sheared Enskog gas needs the hard-sphere kernel");
    }
    if (spec.shear) {
        require(std::isfinite(spec.shear->rate) && spec.shear->rate > 0, "shear rate must be > 0");
        require(std::isfinite(spec.shear->time_step) && spec.shear->time_step > 0,
                "shear time step must be > 0");
    }
}

const char* const shear_quantities[] = {"P_xx",      "P_yy",      "P_zz",      "P_xy",      "P_xz",
                                        "P_yz",      "omega_x",   "omega_y",   "omega_z",   "a_star",
                                        "eta_star",  "P_xx_star", "P_yy_star", "P_zz_star", "P_xy_star",
                                        "P_xz_star", "P_yz_star", "N1_star",   "N2_star"};

} // namespace

std::size_t box_bytes_per_particle(const DomainSpec& d) {
    return 6 * sizeof(Vec3) + sizeof(std::uint32_t) +
           (d.partners == PartnerSelection::nearest ? 4 * sizeof(std::uint32_t) : 0);
}

std::size_t memory_per_particle_bound(const RunSpec& spec) {
    // A state saved or read, by a box or the homogeneous gas (dsmc/grain_state.hpp): its copy and the
    // file's bytes, at the end or start, each at most positions, velocities and spins (a homogeneous
    // run may start from a box's state, whose positions it reads and drops).
    const std::size_t state = spec.final_state || spec.initial_state ? 6 * sizeof(Vec3) : 0;
    if (spec.domain) // the store, and at most one count of the sort per grain
        return box_bytes_per_particle(*spec.domain) + sizeof(std::uint32_t) + state;
    // The largest store (a 64-byte rough grain), its index and class key, a shear row's spins.
    return 64 + sizeof(std::uint32_t) + sizeof(std::uint16_t) + sizeof(Vec3) + state;
}

std::size_t memory_per_replica_fixed_bound(const RunSpec& spec) {
    if (!spec.domain)
        return 0;
    const DomainSpec& d = *spec.domain;
    const double cells = static_cast<double>(d.cells[0]) * d.cells[1] * d.cells[2];
    const std::size_t S = spec.species.size();
    // Per cell: each species' start, the sort's counts of up to 64 chunks, the collisional virial,
    // each species' 5 sums for the local collision frequencies, and a share of the per-unit tallies
    // (one per 64 cells: a cache line for the unit, and a pair count each with a line of slack,
    // plus the allocator's header).
    // With spectra: five fields on the grid of the cells, their half-spectrum transforms and each
    // stored wave vector's shell (observables/spectra.hpp): (G_z/2 + 1)/G_z of a cell's each.
    const double half = (std::floor(d.cells[2] / 2.0) + 1) / d.cells[2];
    const double per_cell = 4.0 * static_cast<double>(S + 1) + 4.0 * 64 + 6 * sizeof(double) +
                            5.0 * sizeof(double) * static_cast<double>(S) +
                            (64.0 + 8.0 * static_cast<double>(spec.pairs.size() + 8) + 16) / 64 +
                            (d.spectra ? 5 * sizeof(double) + (5 * 2 * sizeof(double) + sizeof(int)) * half : 0);
    // The rows the replica keeps until the run ends (the sink's copy and the ensemble's): with the
    // profiles, every bin's fields in every row.
    const double rows = (static_cast<double>(spec.output_times.size()) + 1) *
                        static_cast<double>(replica_row_columns(spec).size()) * sizeof(double) * 2;
    return static_cast<std::size_t>(cells * per_cell + rows);
}

std::vector<Column> wall_columns(const RunSpec& spec) {
    std::vector<Column> c;
    if (!spec.domain)
        return c;
    for (int a = 0; a < 3; ++a) {
        if (!spec.domain->walled(a))
            continue;
        const char axis = "xyz"[a];
        for (const char* side : {"lower", "upper"}) {
            const std::string w = std::string(1, axis) + "_" + side + ".";
            c.push_back({w + "hits", "1/(length^2*time)"});
            for (const char i : {'x', 'y', 'z'})
                c.push_back({w + "P_" + i + axis, "energy/volume"});
            c.push_back({w + "q_" + axis, "energy/(length^2*time)"});
        }
    }
    return c;
}

std::vector<Column> profile_columns(const RunSpec& spec) {
    std::vector<Column> c;
    if (!spec.domain)
        return c;
    const std::vector<Column> fields = profile_field_columns();
    for (int b = 0; b < spec.domain->cells[static_cast<std::size_t>(spec.domain->profile_axis)]; ++b)
        for (const Column& f : fields)
            c.push_back({"bin" + std::to_string(b) + "." + f.name, f.unit});
    return c;
}

SpectraGeometry spectra_geometry(const DomainSpec& d) {
    SpectraGeometry g;
    g.grid = d.cells;
    g.box = d.size;
    g.modes = d.spectra ? d.spectra->modes : 0;
    return g;
}

std::vector<Column> spectra_columns(const RunSpec& spec) {
    std::vector<Column> c;
    if (!spec.domain || !spec.domain->spectra)
        return c;
    const SpectraGeometry g = spectra_geometry(*spec.domain);
    const std::vector<Column> fields = spectrum_field_columns(), mode_fields = mode_field_columns();
    for (const SpectrumBin& b : spectrum_bins(g))
        for (const Column& f : fields)
            c.push_back({"k" + std::to_string(b.axis) + "." + std::to_string(b.n) + "." + f.name, f.unit});
    for (const ModeIndex& m : mode_indices(g))
        for (const Column& f : mode_fields)
            c.push_back({"mode" + std::to_string(m.axis) + "." + std::to_string(m.n) + "." + f.name, f.unit});
    return c;
}

std::vector<Column> replica_row_columns(const RunSpec& spec) {
    std::vector<Column> c = dsmc_columns(spec);
    for (std::vector<Column> part : {wall_columns(spec), profile_columns(spec), spectra_columns(spec)})
        for (Column& w : part)
            c.push_back(std::move(w));
    return c;
}

std::vector<Column> dsmc_columns(const RunSpec& spec) {
    std::vector<Column> c = {{"t", "time"},
                             {"coll_per_particle", "-"},
                             {"T_tr", "energy"},
                             {"T_rot", "energy"},
                             {"theta", "-"},
                             {"a20", "-"},
                             {"a02", "-"},
                             {"a11", "-"},
                             {"A_cw", "-"},
                             {"coll_rate", "1/time"},
                             {"E_diss_rate", "energy/(volume*time)"}};
    if (spec.enskog) // the pressure with its collisional transfer part (dsmc/gas_row.hpp)
        for (const char* q : {"p_kin", "p_coll", "p"})
            c.push_back({q, "energy/volume"});
    if (spec.shear) {
        for (const char* q : shear_quantities) {
            const std::string name = q;
            c.push_back({name, name.starts_with("P_") && !name.ends_with("_star") ? "energy/volume"
                               : name.starts_with("omega")                        ? "1/time"
                                                                                  : "-"});
        }
        if (spec.enskog) // the collisional transfer part (dsmc/gas_row.hpp)
            for (const char* q : {"P_coll_xx", "P_coll_yy", "P_coll_zz", "P_coll_xy", "P_coll_xz", "P_coll_yz"})
                c.push_back({q, "energy/volume"});
    }
    const std::size_t S = spec.species.size();
    if (S > 1) {
        for (const SpeciesSpec& s : spec.species)
            for (std::size_t q = 0; q < std::size(group_quantities); ++q)
                c.push_back({std::string(group_quantities[q]) + "." + s.name, group_units[q]});
        for (std::size_t a = 0; a < S; ++a) {
            for (std::size_t b = a + 1; b < S; ++b) {
                const std::string& A = spec.species[a].name;
                const std::string& B = spec.species[b].name;
                c.push_back({"T_tr." + A + "/T_tr." + B, "-"});
                c.push_back({"T_rot." + A + "/T_rot." + B, "-"});
            }
        }
    }
    if (has_brilliantov(spec))
        c.push_back({"beta_clamped", "-"});
    if (spec.domain && spec.domain->initial.mode != Perturbation::none) // the initial wave's amplitudes
        for (const Column& w : {Column{"u_wave", "length/time"}, Column{"n_wave", "-"}, Column{"e_wave", "-"}})
            c.push_back(w);
    if (spec.domain) { // the cells' resolution of the densest slab, and of the densest cell
        c.push_back({"cell_over_lambda", "-"});
        c.push_back({"cell_over_lambda_cells", "-"});
        c.push_back({"T_th", "energy"}); // about each cell's flow (observables/thermal_temperature.hpp)
    }
    return c;
}

ReplicaEnd run_replica(const RunSpec& spec, const RestitutionTables& tables, int replica, const RowSink& sink,
                       const ProgressSink& progress, ReplicaSummary* summary, const HistogramSink& histograms,
                       const ReplicaCheckpoints* checkpoints, const FieldSink& fields) {
    validate(spec);
    const ReplicaIo io{sink, progress, summary, histograms, checkpoints, fields};
    require(replica >= 0, "negative replica index");
    const std::vector<SpeciesBlock> blocks = make_species_blocks(spec.species, spec.particles);
    const std::vector<PairType> types = make_pair_types(blocks);
    std::vector<AnyPolicy> policies;
    for (std::size_t k = 0; k < types.size(); ++k)
        policies.push_back(make_policy(spec, tables, k, types[k]));
    // In a mixture with a rough pair, smooth pairs take their rough form (beta = -1), so that e.g.
    // constant smooth and constant rough pairs share one policy type and need no per-collision variant.
    // A rough wall turns the spins of grains smooth among themselves: they need their rotation too.
    const auto rough_wall = [&](const WallSpec& w) { return w.kind == WallKind::rough && w.beta != -1; };
    bool spun_by_walls = false;
    if (spec.domain)
        for (const WallSpec* w : spec.domain->walls_in_use())
            spun_by_walls = spun_by_walls || rough_wall(*w);
    if (spun_by_walls ||
        std::any_of(policies.begin(), policies.end(), [](const AnyPolicy& p) { return needs_rotation(p); }))
        for (AnyPolicy& p : policies)
            p = as_rough(p);

    if (spec.domain) // positions, streaming and collision cells
        return detail::drive_spatial(spec, blocks, policies, replica, io);
    if (blocks.size() == 1) { // one species, one model: a fully specialised loop
        return std::visit(
            [&](const auto& p) {
                using P = std::decay_t<decltype(p)>;
                return drive_kernel<P, false>(spec, blocks, {p}, replica, io);
            },
            policies[0]);
    }
    const bool same_type = std::all_of(policies.begin(), policies.end(),
                                       [&](const AnyPolicy& p) { return p.index() == policies[0].index(); });
    if (same_type) { // one constant policy type, per-pair values: no variant in the loop
        std::optional<ReplicaEnd> done;
        std::visit(
            [&](const auto& p0) {
                using P = std::decay_t<decltype(p0)>;
                if constexpr (is_constant_policy<P>) {
                    std::vector<P> v;
                    for (const AnyPolicy& p : policies)
                        v.push_back(std::get<P>(p));
                    done = drive_kernel<P, true>(spec, blocks, std::move(v), replica, io);
                }
            },
            policies[0]);
        if (done)
            return *done;
    }
    if (std::none_of(policies.begin(), policies.end(),
                     [](const AnyPolicy& p) { return needs_rotation(p); })) {
        std::vector<AnySmoothPolicy> v;
        for (const AnyPolicy& p : policies)
            v.push_back(to_any_smooth(p));
        return drive_kernel<AnySmoothPolicy, true>(spec, blocks, std::move(v), replica, io);
    }
    std::vector<AnyRoughPolicy> v;
    for (const AnyPolicy& p : policies)
        v.push_back(to_any_rough(p));
    return drive_kernel<AnyRoughPolicy, true>(spec, blocks, std::move(v), replica, io);
}

} // namespace roughgas
