#pragma once
// The resolved case file as plain values: io/case_file.hpp fills these from TOML,
// validated and with every default applied, so nothing downstream ever sees the parser.
// Keys, units, defaults and ranges are listed once, in io/case_schema.hpp (and docs/reference.md's table).
#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/contact_pair.hpp"
#include "roughgas/contact/material.hpp"
#include "roughgas/contact/tolerance.hpp"
#include "roughgas/dsmc/run_spec.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace roughgas {

// Each enum's names are defined once, next to it, so the schema's "allowed" lists and the
// parser cannot drift apart.
enum class RunKind { cooling, shear };
inline constexpr std::array<std::string_view, 2> run_kind_names{"cooling", "shear"};
// Values of run.kernel, in the order of CollisionKernel (dsmc/run_spec.hpp).
inline constexpr std::array<std::string_view, 2> kernel_names{"hard_sphere", "maxwell"};

// Values of run.equation (Boltzmann's for a dilute gas, Enskog's for a moderately dense one) and of
// run.pair_correlation, in the order of PairCorrelationModel (dsmc/run_spec.hpp).
enum class KineticEquation { boltzmann, enskog };
inline constexpr std::array<std::string_view, 2> equation_names{"boltzmann", "enskog"};
inline constexpr std::array<std::string_view, 2> pair_correlation_names{"carnahan_starling", "constant"};

// How output times are spaced: linear (every output_every) or log (output_every x 10^(k/10)).
enum class OutputSpacing { linear, log };
inline constexpr std::array<std::string_view, 2> output_spacing_names{"linear", "log"};

// Spacing of the `roughgas restitution` grid in g_N and g_T.
enum class GridSpacing { log, linear };
inline constexpr std::array<std::string_view, 2> grid_spacing_names{"log", "linear"};

enum class CollisionModel { constant, coulomb, viscoelastic, brilliantov };
inline constexpr std::array<std::string_view, 4> collision_model_names{"constant", "coulomb", "viscoelastic",
                                                                       "brilliantov"};

constexpr std::string_view name(RunKind k) {
    return run_kind_names[static_cast<int>(k)];
}
constexpr std::string_view name(OutputSpacing s) {
    return output_spacing_names[static_cast<int>(s)];
}
constexpr std::string_view name(GridSpacing s) {
    return grid_spacing_names[static_cast<int>(s)];
}
constexpr std::string_view name(KineticEquation e) {
    return equation_names[static_cast<int>(e)];
}
constexpr std::string_view name(PairCorrelationModel m) {
    return pair_correlation_names[static_cast<int>(m)];
}
constexpr std::string_view name(CollisionModel m) {
    return collision_model_names[static_cast<int>(m)];
}

// Does the model integrate the viscoelastic contact (and therefore need [material])?
constexpr bool uses_material(CollisionModel m) {
    return m == CollisionModel::viscoelastic || m == CollisionModel::brilliantov;
}

// [run]
struct RunConfig {
    RunKind kind = RunKind::cooling;
    std::int64_t particles = 0; // simulated particles (statistics only)
    double density = 1.0;       // number density n [1/length^3]: sets the time scale
    std::int64_t replicas = 1;  // independent runs averaged (columns X_err)
    std::int64_t groups = 0;    // per-step random groups of the DSMC (0: automatic)
    CollisionKernel kernel = CollisionKernel::hard_sphere;
    KineticEquation equation = KineticEquation::boltzmann;
    PairCorrelationModel pair_correlation = PairCorrelationModel::carnahan_starling; // enskog
    std::optional<double> chi; // enskog with pair_correlation = constant
    std::uint64_t seed = 1;
    double end = 0;            // collisions per particle (0 with end_time)
    double output_every = 1.0; // collisions per particle (first output for log spacing)
    OutputSpacing output_spacing = OutputSpacing::linear;
    double histogram_every = 0; // collisions per particle; 0: no histograms
    // The time clock (run.end_time): the run's length, output and histogram times in the case's time
    // unit instead of the three above. Set: end_time and output_every_time (end_time/100 if not given).
    std::optional<double> end_time, output_every_time;
    double histogram_every_time = 0; // time; 0: no histograms
    bool time_clock() const { return end_time.has_value(); }
    OutputSpacing histogram_spacing = OutputSpacing::linear;
    std::int64_t histogram_bins = 50;
    double histogram_max = 5.0; // reduced speed range
    bool save_state = false;    // each replica's last grains to DIR/state/ (initial.from of a later run)
    friend bool operator==(const RunConfig&, const RunConfig&) = default;
};

// One [[species]] table.
struct SpeciesConfig {
    std::string name = "grain";
    double mass = 0;                     // m (given, or from density)
    std::optional<double> density;      // material density, when the mass came from it
    double radius = 0;                   // R
    double inertia = 0.4;                // q = J/(m R^2), docs/model.md §1
    double fraction = 1.0;               // number fraction
    double temperature = 1.0;            // initial T_tr (k_B = 1, energy units)
    double rotational_temperature = 1.0; // initial T_rot
    friend bool operator==(const SpeciesConfig&, const SpeciesConfig&) = default;
};

// [collision], or one [[pair]] table merged over it. Parameters a model does not use stay as given
// (they are validated and echoed, never read); the ones it needs are guaranteed present.
struct CollisionConfig {
    CollisionModel model = CollisionModel::constant;
    std::optional<double> alpha; // normal restitution (constant, coulomb)
    std::optional<double> beta; // tangential restitution, beta = -eps^T (constant; viscoelastic: -1 if unset)
    std::optional<double> beta0;    // coulomb: the sticking limit of beta
    std::optional<double> friction; // coulomb: the Coulomb friction coefficient mu of the pair
    bool direct = false;            // integrate every contact (no cached table) for this pair
    friend bool operator==(const CollisionConfig&, const CollisionConfig&) = default;
};

// One [[pair]] table: the collision of species `species[0]` with `species[1]`.
struct PairConfig {
    std::array<std::string, 2> species;
    CollisionConfig collision; // [collision] with this pair's keys on top
    friend bool operator==(const PairConfig&, const PairConfig&) = default;
};

// [material] (SI). The dissipation is always resolved: given, or from eta1 and eta2 by
// Brilliantov et al. (1996) eq. 23.
struct MaterialConfig {
    double young_modulus = 0;       // Y [Pa]
    double poisson_ratio = 0;       // nu
    double dissipation = 0;         // A [s]
    std::optional<double> eta1;     // [Pa s], only when A came from the viscosities
    std::optional<double> eta2;     // [Pa s]
    std::optional<double> friction; // mu of the asperity model (brilliantov)
    std::optional<double> asperity; // zeta_0 [m] (brilliantov)
    friend bool operator==(const MaterialConfig&, const MaterialConfig&) = default;

    // The physics view. Unset friction/asperity only occur when no model reads them.
    Material material() const {
        Material m;
        m.young_modulus = young_modulus;
        m.poisson_ratio = poisson_ratio;
        m.dissipation = dissipation;
        m.friction = friction.value_or(0.0);
        m.asperity = asperity.value_or(m.asperity);
        return m;
    }
};

// [contact]
struct ContactConfig {
    ContactModel model{};   // form (eq24 | eq25), end (force | separation)
    bool cache = true;      // false: integrate every contact directly
    std::string cache_file; // "" : the table is rebuilt on every run
    Tolerance tolerance{};  // rel = contact.tolerance, abs = rel/100 (Hertz-scaled state is O(1))
    friend bool operator==(const ContactConfig&, const ContactConfig&) = default;
};

// [shear]
struct ShearConfig {
    double rate = 0;        // a [1/time]
    double time_step = 0.2; // Strang step h in mean free times (dsmc/shear.hpp)
    friend bool operator==(const ShearConfig&, const ShearConfig&) = default;
};

// [thermostat]: a driven homogeneous gas (ThermostatSpec, dsmc/run_spec.hpp).
// Values of thermostat.kind, in the order of ThermostatKind.
inline constexpr std::array<std::string_view, 2> thermostat_kind_names{"white_noise", "langevin"};
constexpr std::string_view name(ThermostatKind k) {
    return thermostat_kind_names[static_cast<std::size_t>(k)];
}
// The values of [thermostat] that a [[species_thermostat]] may set for its species. Those of the
// other kind are refused, so they stay unset; in a [[species_thermostat]] what it does not give stays
// unset (the species takes [thermostat]'s).
struct ThermostatValues {
    std::optional<double> strength;            // xi0^2 (white_noise; unset with a schedule)
    std::optional<double> bath_temperature;    // T_b (langevin; unset with a schedule)
    std::optional<double> rotational_share;    // eps (white_noise; [thermostat]: 0 if not given)
    std::optional<double> friction;            // gamma (langevin)
    std::optional<double> rotational_friction; // gamma_rot (langevin; [thermostat]: 0 if not given)
    friend bool operator==(const ThermostatValues&, const ThermostatValues&) = default;
};
struct ThermostatConfig {
    ThermostatKind kind = ThermostatKind::white_noise;
    ThermostatValues values;
    bool exact_energy = false;                   // white_noise
    std::vector<std::array<double, 2>> schedule; // [time, drive] pairs; empty: the constant drive
    friend bool operator==(const ThermostatConfig&, const ThermostatConfig&) = default;
};
// One [[species_thermostat]] table.
struct SpeciesThermostatConfig {
    std::string species;
    ThermostatValues values; // what it gives
    friend bool operator==(const SpeciesThermostatConfig&, const SpeciesThermostatConfig&) = default;
};

// [domain]: a spatially resolved run (dsmc/spatial_engine.hpp); Boundary and WallKind are the
// solver's (dsmc/run_spec.hpp).
inline constexpr std::array<std::string_view, 2> boundary_names{"periodic", "walls"};
struct DomainConfig {
    std::array<double, 3> size{};            // L_x, L_y, L_z
    std::array<std::int64_t, 3> cells{};     // collision cells per axis
    std::array<Boundary, 3> boundary{Boundary::periodic, Boundary::periodic, Boundary::periodic};
    std::array<double, 3> gravity{};         // uniform acceleration
    int profile_axis = 0;                    // 0, 1, 2: profiles.csv's axis (resolved: the first walled axis, else x)
    double time_step = 0.2;                  // in mean free times of the current state
    bool allow_coarse = false;               // cells longer than a mean free path accepted
    PartnerSelection partners = PartnerSelection::random;
    std::int64_t chi_cells = 0;              // run.equation = enskog: the smoothing cube's cells per side (0: auto)
    friend bool operator==(const DomainConfig&, const DomainConfig&) = default;
    bool has_walls() const {
        return std::find(boundary.begin(), boundary.end(), Boundary::walls) != boundary.end();
    }
};

// [wall_lower], [wall_upper]: the walls at coordinate 0 and L of every walled axis (WallSpec).
inline constexpr std::array<std::string_view, 3> wall_kind_names{"specular", "diffuse", "rough"};
constexpr std::string_view name(WallKind k) {
    return wall_kind_names[static_cast<std::size_t>(k)];
}
struct WallConfig {
    WallKind kind = WallKind::diffuse;
    std::optional<double> temperature; // required for diffuse walls
    std::array<double, 3> velocity{};
    std::optional<double> alpha, beta; // rough walls (defaults 1 and -1), echoed only when given
    friend bool operator==(const WallConfig&, const WallConfig&) = default;
};
constexpr std::string_view name(Boundary b) {
    return boundary_names[static_cast<std::size_t>(b)];
}
inline constexpr std::array<std::string_view, 2> partner_names{"random", "nearest"};
constexpr std::string_view name(PartnerSelection p) {
    return partner_names[static_cast<std::size_t>(p)];
}

// [initial]: a wave on the start of a [domain] run (InitialSpec, dsmc/run_spec.hpp).
inline constexpr std::array<std::string_view, 5> perturbation_names{"none", "transverse", "longitudinal", "density",
                                                                   "temperature"};
constexpr std::string_view name(Perturbation p) {
    return perturbation_names[static_cast<std::size_t>(p)];
}
struct InitialConfig {
    Perturbation mode = Perturbation::none;
    double amplitude = 0.1;
    std::array<std::int64_t, 3> wave{1, 0, 0};
    std::string from; // "" or the output directory of an earlier run with run.save_state
    friend bool operator==(const InitialConfig&, const InitialConfig&) = default;
};

// [spectra]: Fourier spectra of a periodic [domain] run (SpectraSpec, dsmc/run_spec.hpp).
struct SpectraConfig {
    std::int64_t modes = 3;
    friend bool operator==(const SpectraConfig&, const SpectraConfig&) = default;
};

// [fields]: the cell fields of a [domain] run in HDF5 files with an XDMF sidecar (FieldsSpec,
// dsmc/run_spec.hpp).
struct FieldsConfig {
    std::vector<FieldQuantity> quantities;
    std::int64_t every = 1;
    std::int64_t replicas = 1;
    friend bool operator==(const FieldsConfig&, const FieldsConfig&) = default;
};

// [restitution]: the grid of `roughgas restitution` (speeds in m/s).
struct RestitutionGridConfig {
    double g_n_min = 1e-4;
    double g_n_max = 10.0;
    std::int64_t g_n_points = 60;
    double g_t_min = 1e-4;
    double g_t_max = 10.0;
    std::int64_t g_t_points = 60;
    GridSpacing spacing = GridSpacing::log;
    friend bool operator==(const RestitutionGridConfig&, const RestitutionGridConfig&) = default;
};

struct CaseConfig {
    RunConfig run;
    std::vector<SpeciesConfig> species; // at least one
    CollisionConfig collision;
    std::vector<PairConfig> pairs;          // overrides of [collision] for species pairs
    std::optional<MaterialConfig> material; // present iff [material] was given
    ContactConfig contact;
    std::optional<ShearConfig> shear; // present iff [shear] was given (required for kind = shear)
    std::optional<ThermostatConfig> thermostat; // present iff [thermostat] was given: a driven gas
    std::vector<SpeciesThermostatConfig> species_thermostats; // overrides of [thermostat] for species
    std::optional<DomainConfig> domain; // present iff [domain] was given: a spatially resolved run
    std::optional<InitialConfig> initial; // present iff [initial] was given
    std::optional<SpectraConfig> spectra; // present iff [spectra] was given
    std::optional<FieldsConfig> fields;   // present iff [fields] was given
    std::optional<WallConfig> wall_lower, wall_upper; // present iff given
    // [wall_lower_x], [wall_upper_x], ... _y, _z: one axis's own walls, present iff given.
    std::array<std::optional<WallConfig>, 3> axis_wall_lower, axis_wall_upper;
    // Keys and tables given but not used by the chosen models or run kind (kept, not refused: a user
    // may switch the model or kind with --set and back); commands print them as warnings.
    std::vector<std::string> unused;
    RestitutionGridConfig restitution;
    friend bool operator==(const CaseConfig&, const CaseConfig&) = default;
};

// The wall tables: [wall_lower] and [wall_upper] serve every walled axis (axis -1) that has no
// table of its own, [wall_lower_x], [wall_upper_x], ... _y, _z (axis 0, 1, 2).
struct WallTable {
    std::string name; // "wall_lower", "wall_upper_y", ...
    int axis = -1;
    bool upper = false;
};
inline std::vector<WallTable> wall_tables() {
    std::vector<WallTable> t{{"wall_lower", -1, false}, {"wall_upper", -1, true}};
    for (int a = 0; a < 3; ++a)
        for (const bool upper : {false, true})
            t.push_back({std::string(upper ? "wall_upper_" : "wall_lower_") + "xyz"[a], a, upper});
    return t;
}
// The table's WallConfig in `c` (CaseConfig or const CaseConfig).
template <class Config> auto& wall_config(Config& c, const WallTable& t) {
    if (t.axis < 0)
        return t.upper ? c.wall_upper : c.wall_lower;
    return (t.upper ? c.axis_wall_upper : c.axis_wall_lower)[static_cast<std::size_t>(t.axis)];
}
// The table that describes the wall at 0 (upper: at L) of `axis`: its own, else the shared one.
inline WallTable wall_table_of(const CaseConfig& c, int axis, bool upper) {
    const WallTable own{std::string(upper ? "wall_upper_" : "wall_lower_") + "xyz"[axis], axis, upper};
    if (wall_config(c, own))
        return own;
    return {upper ? "wall_upper" : "wall_lower", -1, upper};
}

// The walled axes whose wall `t` describes (none when it is not used).
inline std::vector<int> wall_axes(const CaseConfig& c, const WallTable& t) {
    std::vector<int> axes;
    if (!c.domain)
        return axes;
    for (int a = 0; a < 3; ++a)
        if (c.domain->boundary[static_cast<std::size_t>(a)] == Boundary::walls && wall_table_of(c, a, t.upper).name == t.name)
            axes.push_back(a);
    return axes;
}

// The collision rule of species i with species j: its [[pair]] table, else [collision].
inline const CollisionConfig& collision_for(const CaseConfig& cfg, std::size_t i, std::size_t j) {
    for (const PairConfig& p : cfg.pairs) {
        const std::string& a = cfg.species[i].name;
        const std::string& b = cfg.species[j].name;
        if ((p.species[0] == a && p.species[1] == b) || (p.species[0] == b && p.species[1] == a)) {
            return p.collision;
        }
    }
    return cfg.collision;
}

// The thermostat of species i: its [[species_thermostat]]'s values, the others [thermostat]'s;
// requires cfg.thermostat.
inline ThermostatValues thermostat_for(const CaseConfig& cfg, std::size_t i) {
    ThermostatValues v = cfg.thermostat.value().values;
    for (const SpeciesThermostatConfig& s : cfg.species_thermostats)
        if (s.species == cfg.species[i].name) {
            for (auto field : {&ThermostatValues::strength, &ThermostatValues::bath_temperature,
                               &ThermostatValues::rotational_share, &ThermostatValues::friction,
                               &ThermostatValues::rotational_friction})
                if (s.values.*field)
                    v.*field = s.values.*field;
        }
    return v;
}

// The '#' line of the CSV files naming their units: SI when a pair integrates the viscoelastic
// contact (its [material] is in SI, and so must the species' masses, radii and temperatures be);
// otherwise the case's own units, whatever consistent ones it was written in.
inline constexpr const char* si_unit_system_note = "unit system: SI (time s, length m, mass kg, energy J, volume m^3)";
inline std::string unit_system_note(const CaseConfig& cfg) {
    for (std::size_t i = 0; i < cfg.species.size(); ++i)
        for (std::size_t j = i; j < cfg.species.size(); ++j)
            if (uses_material(collision_for(cfg, i, j).model))
                return si_unit_system_note;
    return "unit system: the case's own (any consistent units with k_B = 1: temperatures are energies)";
}

// Runs that reach a steady state (steady.csv) rather than a scaled cooling state (scaled.csv):
// uniform shear flow, a gas heated by a thermostat, and boxes whose walls drive the gas (a diffuse
// wall holds its temperature, a moving wall shears).
inline bool driven(const CaseConfig& c) {
    if (c.run.kind == RunKind::shear || c.thermostat)
        return true;
    if (!c.domain || !c.domain->has_walls())
        return false;
    for (int a = 0; a < 3; ++a)
        for (const bool upper : {false, true}) {
            if (c.domain->boundary[static_cast<std::size_t>(a)] != Boundary::walls)
                continue;
            const std::optional<WallConfig>& w = wall_config(c, wall_table_of(c, a, upper));
            if (w && (w->kind == WallKind::diffuse || w->velocity != std::array<double, 3>{}))
                return true;
        }
    return false;
}

// Contact constants of species i with species j; requires cfg.material (validated for such uses).
inline ContactPair contact_pair(const CaseConfig& cfg, std::size_t i, std::size_t j) {
    const SpeciesConfig& a = cfg.species[i];
    const SpeciesConfig& b = cfg.species[j];
    return make_contact_pair(cfg.material.value().material(), cfg.contact.model, a.mass, a.radius, a.inertia,
                             b.mass, b.radius, b.inertia);
}

// `roughgas restitution` tabulates one pair: the first two species, or the only one with itself.
inline std::pair<std::size_t, std::size_t> restitution_species(const CaseConfig& cfg) {
    return {0, cfg.species.size() > 1 ? 1 : 0};
}

} // namespace roughgas
