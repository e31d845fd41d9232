// The case-file schema: every key once, in the order docs/reference.md lists them.
#include "roughgas/io/case_schema.hpp"

#include "roughgas/contact/contact_model.hpp"
#include "roughgas/io/case_config.hpp"
#include "roughgas/observables/field_quantity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>

namespace roughgas {
namespace {

// A small builder keeps the list below one readable line per property.
class Key {
  public:
    Key(std::string path, KeyType type) {
        spec_.path = std::move(path);
        spec_.type = type;
    }
    Key& unit(std::string u) {
        spec_.unit = std::move(u);
        return *this;
    }
    Key& fallback(KeyDefault d) {
        spec_.need = Need::defaulted;
        spec_.default_value = std::move(d);
        return *this;
    }
    Key& required() {
        spec_.need = Need::required;
        return *this;
    }
    Key& when(std::string note) {
        spec_.need = Need::conditional;
        spec_.note = std::move(note);
        return *this;
    }
    Key& optional() {
        spec_.need = Need::optional;
        return *this;
    }
    Key& gt(double x, std::string text = {}) {
        spec_.lower = {Bound::open, x, std::move(text)};
        return *this;
    }
    Key& ge(double x, std::string text = {}) {
        spec_.lower = {Bound::closed, x, std::move(text)};
        return *this;
    }
    Key& lt(double x, std::string text = {}) {
        spec_.upper = {Bound::open, x, std::move(text)};
        return *this;
    }
    Key& le(double x, std::string text = {}) {
        spec_.upper = {Bound::closed, x, std::move(text)};
        return *this;
    }
    template <std::size_t N> Key& one_of(const std::array<std::string_view, N>& names) {
        spec_.choices.assign(names.begin(), names.end());
        return *this;
    }
    Key& doc(std::string d) {
        spec_.description = std::move(d);
        return *this;
    }
    Key& because(std::string r) {
        spec_.range_reason = std::move(r);
        return *this;
    }
    KeySpec spec() const { return spec_; }

  private:
    KeySpec spec_;
};

using T = KeyType;

// The collision keys appear twice: in [collision] and, inherited from it, in each [[pair]].
std::vector<Key> collision_keys(const std::string& table) {
    const std::string t = table + ".";
    return {
        Key(t + "model", T::string)
            .required()
            .one_of(collision_model_names)
            .doc("restitution model: constant alpha, beta; coulomb (Walton: constant alpha, beta from "
                 "Coulomb friction); viscoelastic (eps^N from the contact, Brilliantov et al. 1996); "
                 "brilliantov (eps^N and eps^T from the contact with asperities, Brilliantov et al. 1996)"),
        Key(t + "alpha", T::real)
            .when("required for model = constant, coulomb")
            .ge(0)
            .le(1)
            .doc("normal restitution coefficient alpha: (g^N)' = -alpha g^N"),
        Key(t + "beta", T::real)
            .when("required for model = constant; viscoelastic: -1.0 (smooth) if unset")
            .ge(-1)
            .le(1)
            .doc("tangential restitution coefficient beta = -eps^T: -1 smooth, +1 perfectly rough"),
        Key(t + "beta0", T::real)
            .when("required for model = coulomb")
            .ge(-1)
            .le(1)
            .doc("coulomb: beta while the contact sticks (beta = min(beta0, Coulomb sliding limit))"),
        Key(t + "friction", T::real)
            .when("required for model = coulomb")
            .ge(0)
            .doc("coulomb: friction coefficient mu of the sliding limit (not the material's)"),
        Key(t + "direct", T::boolean)
            .fallback(false)
            .doc("viscoelastic, brilliantov: integrate the contact at every collision instead of using "
                 "the cached table (contact.cache = false does this for every pair)"),
    };
}

// The keys of [thermostat] that a [[species_thermostat]] may give for its species.
std::vector<Key> thermostat_keys(const std::string& table) {
    const std::string t = table + ".";
    return {
        Key(t + "strength", T::real)
            .unit("length^2/time^3")
            .when("required for kind = white_noise unless schedule is given")
            .ge(0)
            .doc("white_noise: the strength xi0^2 (velocity^2/time): every velocity component gets independent "
                 "Gaussian kicks of variance xi0^2 dt, which alone raise T_tr at the rate m xi0^2; 0: no drive"),
        Key(t + "bath_temperature", T::real)
            .unit("energy")
            .when("required for kind = langevin unless schedule is given")
            .gt(0)
            .doc("langevin: the temperature T_b of the bath (k_B = 1)"),
        Key(t + "rotational_share", T::real)
            .fallback(0.0)
            .ge(0)
            .le(1)
            .doc("white_noise: the share eps of the injected power that kicks the spins instead of the "
                 "velocities: dT_tr/dt = (1 - eps) m xi0^2 and dT_rot/dt = eps m xi0^2 from the kicks"),
        Key(t + "friction", T::real)
            .unit("1/time")
            .when("required for kind = langevin")
            .gt(0)
            .doc("langevin: the friction gamma of the bath, dv = -gamma v dt + sqrt(2 gamma T_b/m) dW: "
                 "dT_tr/dt = 2 gamma (T_b - T_tr) from the bath"),
        Key(t + "rotational_friction", T::real)
            .unit("1/time")
            .fallback(0.0)
            .ge(0)
            .doc("langevin: the friction gamma_rot of the spins with the bath (the same law for omega, with the "
                 "moment of inertia for the mass); 0: the spins feel no bath"),
    };
}

// Appends the keys of a table of overrides (`keys`, made with its paths): each falls back to the
// value of the same key of table `from`, and is described as that key "for `whom`".
void add_overrides(std::vector<Key>& k, std::vector<Key> keys, const std::string& from, const std::string& whom) {
    for (Key& c : keys) {
        const KeySpec s = c.spec();
        const std::string of = from + "." + std::string(s.name());
        c.when("value of " + of).doc("as " + of + ", for " + whom);
        k.push_back(std::move(c));
    }
}

std::vector<Key> keys() {
    std::vector<Key> k = {
        // [run]
        Key("run.kind", T::string)
            .fallback(std::string("cooling"))
            .one_of(run_kind_names)
            .doc("cooling: homogeneous cooling state (a driven gas with [thermostat]); shear: uniform shear flow "
                 "(needs [shear])"),
        Key("run.particles", T::integer)
            .required()
            .ge(2)
            .doc("simulated particles (statistics only: results do not depend on it)"),
        Key("run.density", T::real)
            .unit("1/length^3")
            .fallback(1.0)
            .gt(0)
            .doc("number density n of all the grains (species s: its fraction x n; sets the time scale); their solid "
                 "fraction phi = sum_s x_s n (pi/6) (2 R_s)^3 must be below pi/sqrt(18) = 0.7405 (dilute: phi "
                 "below 0.0193, else a warning)"),
        Key("run.replicas", T::integer)
            .fallback(std::int64_t{1})
            .ge(1)
            .doc("independent runs averaged; each column X gets X_err when > 1"),
        Key("run.groups", T::integer)
            .fallback(std::int64_t{0})
            .ge(0)
            .le(4096)
            .doc("random groups per DSMC step that collide independently (in parallel over --threads); 0: "
                 "automatic, particles/16384 rounded down to a power of two; results depend on it, never on "
                 "the thread count"),
        Key("run.kernel", T::string)
            .fallback(std::string("hard_sphere"))
            .one_of(kernel_names)
            .doc("collision kernel: hard_sphere (rate pi sigma^2 |g|, n weighted by |g.n|); maxwell (each pair at "
                 "the hard-sphere rate of the initial Maxwellian, independent of the velocities, n uniform on the "
                 "approaching hemisphere: T_tr, T_rot follow closed linear ODEs, the theory columns; constant "
                 "restitution only; in a [domain] run each pair of a cell, at the rate with the cell for the "
                 "volume)"),
        Key("run.equation", T::string)
            .fallback(std::string("boltzmann"))
            .one_of(equation_names)
            .doc("the kinetic equation: boltzmann (a dilute gas); enskog (a moderately dense gas, solid fraction "
                 "phi up to about 0.5: every pair collides chi times as often, chi the pair correlation at contact "
                 "(run.pair_correlation), and moments.csv gets the pressure with its collisional part, p_kin, "
                 "p_coll, p; homogeneous runs, cooling, driven or sheared, and boxes, where grains collide a "
                 "diameter apart and the cells may be smaller than a grain)"),
        Key("run.pair_correlation", T::string)
            .fallback(std::string("carnahan_starling"))
            .one_of(pair_correlation_names)
            .doc("with equation = enskog, chi: carnahan_starling ((1 - phi/2)/(1 - phi)^3 from the solid fraction; "
                 "for mixtures each pair's Boublik-Mansoori-Carnahan-Starling-Leland value); constant (run.chi for "
                 "every pair)"),
        Key("run.chi", T::real)
            .when("required for pair_correlation = constant")
            .gt(0)
            .doc("with equation = enskog and pair_correlation = constant: chi of every species pair"),
        Key("run.seed", T::integer).fallback(std::int64_t{1}).ge(0).doc("random seed (same seed, same run)"),
        Key("run.end", T::real)
            .unit("collisions per particle")
            .when("required unless end_time is given")
            .gt(0)
            .doc("length of the run, counted in collisions per particle (the collision clock); exactly one of "
                 "end and end_time"),
        Key("run.end_time", T::real)
            .unit("time")
            .when("unset")
            .gt(0)
            .doc("length of the run in the case's time unit, instead of end (the time clock): output_every_time "
                 "and histogram_every_time replace output_every and histogram_every, and every replica's rows, "
                 "and those of runs started from other states, fall at the same t (a row at time t holds the "
                 "state after the last collision before t; a box's rows end a step shortened to end at t)"),
        Key("run.output_every", T::real)
            .unit("collisions per particle")
            .fallback(1.0)
            .gt(0)
            .doc("linear: interval between outputs; log: time of the first output (with run.end only)"),
        Key("run.output_every_time", T::real)
            .unit("time")
            .when("end_time / 100")
            .gt(0)
            .doc("with run.end_time, instead of output_every: linear: interval between outputs; log: time of the "
                 "first output (spaced as output_spacing)"),
        Key("run.output_spacing", T::string)
            .fallback(std::string("linear"))
            .one_of(output_spacing_names)
            .doc("linear: every output_every (output_every_time); log: at output_every x 10^(k/10), k = 0, 1, "
                 "... (10 per decade); with run.end, an output that would fall on the collision count of the one "
                 "before is left out (with run.end_time every output time is a row)"),
        Key("run.histogram_every", T::real)
            .unit("collisions per particle")
            .fallback(0.0)
            .ge(0)
            .doc("histograms of c*, w*, c*.w* to DIR/histograms.csv at these times (spaced as "
                 "histogram_spacing, always at the end); 0: none. Must be <= end (with run.end only)"),
        Key("run.histogram_every_time", T::real)
            .unit("time")
            .fallback(0.0)
            .ge(0)
            .doc("with run.end_time, instead of histogram_every: the histograms at these times (spaced as "
                 "histogram_spacing, always at the end); 0: none. Must be <= end_time"),
        Key("run.histogram_spacing", T::string)
            .fallback(std::string("linear"))
            .one_of(output_spacing_names)
            .doc("as output_spacing, for the histogram times"),
        Key("run.histogram_bins", T::integer)
            .fallback(std::int64_t{50})
            .ge(1)
            .le(100000)
            .doc("bins per histogram"),
        Key("run.histogram_max", T::real)
            .fallback(5.0)
            .gt(0)
            .doc("range of the histograms: reduced speeds in [0, max), c*.w* in [-max, max) (a "
                 "Maxwellian has 1e-10 of its grains beyond 5)"),
        Key("run.save_state", T::boolean)
            .fallback(false)
            .doc("write each replica's grains at the end (velocities, spins, and positions in a box) to "
                 "DIR/state/replica_R.bin, for initial.from of a later run; 48 bytes per grain, 72 in a box"),
        // [[species]]
        Key("species.name", T::string)
            .fallback(std::string("grain"))
            .doc("unique name, used by [[pair]] and in column names"),
        Key("species.mass", T::real)
            .unit("mass")
            .when("required unless density is given")
            .gt(0)
            .doc("particle mass m"),
        Key("species.density", T::real)
            .unit("mass/length^3")
            .when("unset")
            .gt(0)
            .doc("material density of the grain (uniform sphere): m = (4/3) pi R^3 density, instead of mass"),
        Key("species.radius", T::real).unit("length").required().gt(0).doc("particle radius R"),
        Key("species.inertia", T::real)
            .fallback(0.4)
            .gt(0)
            .le(2.0 / 3.0, "2/3")
            .doc(
                "q = J/(m R^2): 0.4 uniform sphere; 2/3 thin spherical shell, the largest for mass inside R"),
        Key("species.fraction", T::real)
            .fallback(1.0)
            .gt(0)
            .le(1)
            .doc("number fraction; the fractions of all species sum to 1 (within 1e-9)"),
        Key("species.temperature", T::real)
            .unit("energy")
            .fallback(1.0)
            .gt(0)
            .doc("initial translational temperature T_tr (k_B = 1)"),
        Key("species.rotational_temperature", T::real)
            .unit("energy")
            .fallback(1.0)
            .ge(0)
            .doc("initial rotational temperature T_rot"),
    };
    for (Key& c : collision_keys("collision")) {
        k.push_back(std::move(c));
    }
    // [[pair]]: the same keys, each falling back to [collision].
    k.push_back(
        Key("pair.species", T::string_pair)
            .required()
            .doc("the two species of the pair, e.g. [\"a\", \"b\"] (order irrelevant, one table per pair)"));
    add_overrides(k, collision_keys("pair"), "collision", "this pair");
    const std::vector<Key> rest = {
        // [material]
        Key("material.young_modulus", T::real).unit("Pa").required().gt(0).doc("Young's modulus Y"),
        Key("material.poisson_ratio", T::real).required().gt(-1).lt(0.5).doc("Poisson ratio nu"),
        Key("material.dissipation", T::real)
            .unit("s")
            .when("required unless eta1 and eta2 are given")
            .ge(0)
            .doc("dissipative constant A of Brilliantov et al. 1996 eq. 23"),
        Key("material.eta1", T::real)
            .unit("Pa s")
            .optional()
            .ge(0)
            .doc("viscous constant eta_1: with eta2, gives A by Brilliantov et al. 1996 eq. 23 (instead of "
                 "dissipation)"),
        Key("material.eta2", T::real)
            .unit("Pa s")
            .optional()
            .ge(0)
            .doc("viscous constant eta_2 (with eta1; needs poisson_ratio != 0)"),
        Key("material.friction", T::real)
            .when("required for model = brilliantov and roughgas restitution")
            .ge(0)
            .doc("friction coefficient mu of the asperity model (Brilliantov et al. 1996 eqs. 35-37)"),
        Key("material.asperity", T::real)
            .unit("m")
            .when("required for model = brilliantov and roughgas restitution")
            .gt(0)
            .doc("asperity scale zeta_0 (Brilliantov et al. 1996 eq. 32)"),
        // [contact]
        Key("contact.form", T::string)
            .fallback(std::string("eq24"))
            .one_of(normal_form_names)
            .doc("normal force law: Brilliantov et al. 1996 eq. 24 or eq. 25"),
        Key("contact.end", T::string)
            .fallback(std::string("force"))
            .one_of(contact_end_names)
            .doc("end of contact: force (normal force reaches 0) or separation (xi = 0), docs/model.md §6"),
        Key("contact.cache", T::boolean)
            .fallback(true)
            .doc("use a tabulated eps(g) built once; false: integrate every collision directly"),
        Key("contact.cache_file", T::string)
            .fallback(std::string(""))
            .doc("file the table is saved to and reused from; \"\": not saved"),
        Key("contact.tolerance", T::real)
            .fallback(1e-12)
            .ge(1e-15)
            .le(1e-3)
            .doc("relative error tolerance of the contact integration (absolute: tolerance/100)"),
        // [shear]
        Key("shear.rate", T::real)
            .unit("1/time")
            .when("required for run.kind = shear")
            .gt(0)
            .doc("shear rate a of the uniform shear flow u = a y x (peculiar velocities; physical units, "
                 "1/s for SI cases)"),
        Key("shear.time_step", T::real)
            .unit("mean free times")
            .fallback(0.2)
            .gt(0)
            .le(1)
            .doc("Strang splitting step h (stream h/2, collide h, stream h/2), in mean free times of the "
                 "state each step's collisions start from; the error of the steady P*_xy is O(h^2) "
                 "(docs/model.md); a sheared box ([domain]) steps by domain.time_step instead"),
    };
    k.insert(k.end(), rest.begin(), rest.end());
    // [thermostat], then [[species_thermostat]] with the keys it may give
    k.push_back(Key("thermostat.kind", T::string)
                    .fallback(std::string("white_noise"))
                    .one_of(thermostat_kind_names)
                    .doc("white_noise: Gaussian kicks of the velocities (and, by rotational_share, of the spins) "
                         "at every DSMC step; langevin: a heat bath at bath_temperature with friction"));
    for (Key& t : thermostat_keys("thermostat"))
        k.push_back(std::move(t));
    k.push_back(Key("thermostat.exact_energy", T::boolean)
                    .fallback(false)
                    .doc("white_noise: each step's kicks of each species scaled so that they inject exactly the "
                         "intended energy, N_s (3/2) m_s xi0^2 dt (split by rotational_share), not only on average"));
    k.push_back(Key("thermostat.schedule", T::real_pairs)
                    .unit("[time, strength or bath_temperature]")
                    .when("unset: strength or bath_temperature, constant")
                    .ge(0)
                    .doc("the drive over time, piecewise constant, instead of strength (white_noise) or "
                         "bath_temperature (langevin) for every species: [[t0, x0], [t1, x1], ...] drives with "
                         "x_k from time t_k on (in the case's time unit, whichever clock the run counts); "
                         "t0 = 0, times increasing, bath temperatures > 0"));
    k.push_back(Key("species_thermostat.species", T::string)
                    .required()
                    .doc("the species whose thermostat the table sets (one table per species; the others take "
                         "[thermostat]'s values)"));
    add_overrides(k, thermostat_keys("species_thermostat"), "thermostat", "this species");
    const std::vector<Key> box = {
        // [domain]
        Key("domain.size", T::real3)
            .unit("length")
            .when("required in [domain]")
            .gt(0)
            .doc("box lengths [L_x, L_y, L_z] in the length unit of the species radii; run.density is the "
                 "number density of grains in the box, each simulated grain standing for "
                 "density x volume / run.particles of them"),
        Key("domain.cells", T::integer3)
            .when("required in [domain]")
            .ge(1)
            .le(4096)
            .doc("collision cells along x, y, z (a uniform grid); a cell's edge at most one mean free "
                 "path unless domain.allow_coarse = true"),
        Key("domain.boundary", T::string3)
            .fallback(std::string("periodic"))
            .one_of(boundary_names)
            .doc("the boundary of each axis: periodic, or walls (two flat walls, at 0 and at L, described "
                 "in [wall_lower] and [wall_upper], or for one axis in its own [wall_lower_x], [wall_upper_x], "
                 "...); with run.kind = shear, y is Lees-Edwards (the images "
                 "above and below move at +-shear.rate L_y along x) and x must be periodic too"),
        Key("domain.gravity", T::real3)
            .unit("length/time^2")
            .when("[0, 0, 0]")
            .doc("uniform acceleration [g_x, g_y, g_z] of the free flight (v += g dt, x += v dt + g dt^2/2)"),
        Key("domain.profile_axis", T::string)
            .when("y for run.kind = shear, else the first walled axis, else \"x\"")
            .one_of(std::array<std::string_view, 3>{"x", "y", "z"})
            .doc("profiles.csv: the fields averaged over slabs normal to this axis, one slab per cell along it"),
        Key("domain.time_step", T::real)
            .unit("mean free times")
            .fallback(0.2)
            .gt(0)
            .le(1)
            .doc("step of free flight and cell collisions, in mean free times of the current state's "
                 "densest slab (the largest local collision frequency over the profile bins, re-evaluated "
                 "every step: a cooling gas keeps its steps per collision); shortened to end at each "
                 "output row"),
        Key("domain.allow_coarse", T::boolean)
            .fallback(false)
            .doc("accept cells longer than one mean free path (the DSMC's transport errors grow as the "
                 "squared cell size over the mean free path)"),
        Key("domain.partners", T::string)
            .fallback(std::string("random"))
            .one_of(partner_names)
            .doc("the partner of a candidate pair's first grain: random (any other grain of its cell) or "
                 "nearest (the nearest other grain of the cell but the first grain's most recent collision "
                 "partner: collisions between neighbours, and transport errors set by the grains' spacing "
                 "instead of the cell size; costs a pass over the cell per candidate)"),
        Key("domain.chi_cells", T::integer)
            .fallback(std::int64_t{0})
            .ge(0)
            .le(1001)
            .doc("with run.equation = enskog: the cells per side (odd) of the cube over which the local density "
                 "that sets the pair correlation chi at a pair's midpoint is averaged (chi is nonlinear in the "
                 "density: a cube of M grains biases it by about chi''(n) Var(n)/2, 0.3 % at phi = 0.2 for M = "
                 "100, falling as 1/M); 0: the smallest cube holding 1000 grains on average (the whole axis "
                 "where the box is shorter)"),
        // [initial]
        Key("initial.mode", T::string)
            .fallback(std::string("none"))
            .one_of(perturbation_names)
            .doc("a wave on the uniform Maxwellian start of a [domain] run, wave vector k_a = 2 pi wave_a / L_a: "
                 "transverse: u = A c e sin(k.x), e perpendicular to k (y if k_y = 0, else z if k_z = 0, else "
                 "along k x x); longitudinal: u = A c k/|k| sin(k.x); density: n (1 + A sin(k.x)); "
                 "temperature: T (1 + A sin(k.x)); c = sqrt(T/m) of the species' mean T and m"),
        Key("initial.amplitude", T::real)
            .fallback(0.1)
            .gt(-1)
            .lt(1)
            .because("A in units of sqrt(T/m) for a velocity wave, of the mean for a density or temperature wave: "
                     "|A| < 1 keeps the flow below the thermal speed sqrt(T/m) and the density and temperature "
                     "positive")
            .doc("A: of the velocity in units of sqrt(T/m), of the density or temperature relative to its mean"),
        Key("initial.wave", T::integer3)
            .when("[1, 0, 0]")
            .ge(-1000)
            .le(1000)
            .doc("wave numbers [n_x, n_y, n_z] (whole wavelengths in the box), not all 0"),
        Key("initial.from", T::string)
            .when("none: a Maxwellian at the species' temperatures")
            .doc("start from the last state of an earlier run with run.save_state = true: the output "
                 "directory DIR (relative to the working directory); replica r takes DIR/state/replica_r.bin "
                 "(r modulo the files there). The species (names, masses, radii) and their grain counts must "
                 "be the same; velocities and spins are taken as they were; time and collisions count from 0, "
                 "the row at t = 0 being the state. A homogeneous run (no [domain]) takes the velocities and "
                 "spins (of a box's state too), less their mean velocity; a box takes the positions too from a "
                 "box of the same size (else uniform), and a wave of initial.mode is added on top, in units of "
                 "the state's thermal speed. Not with run.kernel = \"maxwell\""),
        // [spectra]
        Key("spectra.modes", T::integer)
            .fallback(std::int64_t{3})
            .ge(0)
            .le(4096)
            .doc("modes.csv: the lowest wave numbers n = 1 ... modes along each axis (fewer where the axis "
                 "has fewer cells: up to (cells - 1)/2); 0: no modes.csv"),
        // [fields]
        Key("fields.quantities", T::string_list)
            .fallback(std::string("n u T_tr T_rot theta omega P q"))
            .one_of(field_quantity_names)
            .doc("the cell fields written: n (number density), u (flow velocity), T_tr, T_rot, theta, omega "
                 "(mean spin), P (kinetic pressure tensor), q (heat flux); defined as the profiles' "
                 "(docs/model.md §8)"),
        Key("fields.every", T::integer)
            .fallback(std::int64_t{1})
            .ge(1)
            .le(1000000)
            .doc("write the fields at every this-many-th row of moments.csv (the first row, t = 0, always)"),
        Key("fields.replicas", T::integer)
            .fallback(std::int64_t{1})
            .ge(1)
            .le(1000000)
            .doc("the replicas 0 ... replicas - 1 write fields, each to its own files"),
        // [restitution]
        Key("restitution.g_n_min", T::real)
            .unit("m/s")
            .fallback(1e-4)
            .gt(0)
            .doc("smallest normal impact speed"),
        Key("restitution.g_n_max", T::real)
            .unit("m/s")
            .fallback(10.0)
            .gt(0)
            .doc("largest normal impact speed (>= g_n_min)"),
        Key("restitution.g_n_points", T::integer)
            .fallback(std::int64_t{60})
            .ge(1)
            .doc("number of g_N values (1: g_n_min only)"),
        Key("restitution.g_t_min", T::real).unit("m/s").fallback(1e-4).gt(0).doc("smallest tangential speed"),
        Key("restitution.g_t_max", T::real)
            .unit("m/s")
            .fallback(10.0)
            .gt(0)
            .doc("largest tangential speed (>= g_t_min)"),
        Key("restitution.g_t_points", T::integer)
            .fallback(std::int64_t{60})
            .ge(1)
            .doc("number of g_T values (1: g_t_min only)"),
        Key("restitution.spacing", T::string)
            .fallback(std::string("log"))
            .one_of(grid_spacing_names)
            .doc("spacing of both grids: log (geometric) or linear"),
    };
    k.insert(k.end(), box.begin(), box.end());
    // [wall_lower], [wall_upper], then each axis's own [wall_lower_x], ...: after [initial]
    std::vector<Key> walls;
    for (const WallTable& table : wall_tables()) {
        const std::string side = table.name;
        const std::string where = std::string(table.upper ? "at L" : "at 0") +
                                  (table.axis < 0 ? std::string(" of every walled axis without a wall of its own")
                                                  : std::string(" of axis ") + "xyz"[table.axis]);
        walls.push_back(Key(side + ".kind", T::string)
                            .fallback(std::string("diffuse"))
                            .one_of(wall_kind_names)
                            .doc("the wall " + where +
                                 ": diffuse (re-emits grains from the flux-weighted "
                                 "Maxwellian at its temperature and velocity, spins from the Maxwellian at its "
                                 "temperature), specular (reverses the normal velocity), rough (the collision "
                                 "rule with an infinitely massive flat partner, its alpha and beta)"));
        walls.push_back(Key(side + ".temperature", T::real)
                            .unit("energy")
                            .when("required for kind = diffuse")
                            .gt(0)
                            .doc("the diffuse wall's temperature T_w (k_B = 1)"));
        walls.push_back(Key(side + ".velocity", T::real3)
                            .unit("length/time")
                            .when("[0, 0, 0]")
                            .doc("the wall's velocity U_w, along the wall (0 along every axis it closes): a "
                                 "Couette flow between walls moving apart; diffuse and rough walls"));
        walls.push_back(Key(side + ".alpha", T::real)
                            .fallback(1.0)
                            .gt(0)
                            .le(1)
                            .doc("rough wall: normal restitution coefficient of a grain with the wall"));
        walls.push_back(Key(side + ".beta", T::real)
                            .fallback(-1.0)
                            .ge(-1)
                            .le(1)
                            .doc("rough wall: tangential restitution coefficient (-1 smooth, +1 perfectly "
                                 "rough); beta > -1 spins the grains, which then carry their rotation even "
                                 "when smooth among themselves"));
    }
    const auto at = std::find_if(k.begin(), k.end(), [](const Key& key) { return key.spec().path == "restitution.g_n_min"; });
    k.insert(at, walls.begin(), walls.end());
    return k;
}

std::string limit_text(const Limit& l) {
    return l.text.empty() ? fmt::format("{}", l.value) : l.text;
}

std::string quoted(std::string_view s) {
    return fmt::format("\"{}\"", s);
}

} // namespace

std::string markdown_cell(std::string s) {
    // A '|' would split the cell.
    std::string out;
    for (char c : s) {
        out += c == '|' ? std::string("\\|") : std::string(1, c);
    }
    return out;
}

std::string toml_real(double x) {
    std::string s = fmt::format("{}", x);
    if (s.find_first_of(".eEn") == std::string::npos) { // "n": inf, nan
        s += ".0";
    }
    return s;
}

std::string_view KeySpec::table() const {
    return std::string_view(path).substr(0, path.find('.'));
}

std::string_view KeySpec::name() const {
    return std::string_view(path).substr(path.find('.') + 1);
}

std::string KeySpec::allowed() const {
    if (!choices.empty()) {
        std::string s = "one of ";
        for (std::size_t i = 0; i < choices.size(); ++i) {
            s += (i ? ", " : "") + roughgas::quoted(choices[i]);
        }
        return s;
    }
    const bool lo = lower.bound != Bound::none;
    const bool hi = upper.bound != Bound::none;
    if (lo && hi) {
        return fmt::format("in {}{}, {}{}", lower.bound == Bound::open ? '(' : '[', limit_text(lower),
                           limit_text(upper), upper.bound == Bound::open ? ')' : ']');
    }
    if (lo) {
        return fmt::format("{} {}", lower.bound == Bound::open ? ">" : ">=", limit_text(lower));
    }
    if (hi) {
        return fmt::format("{} {}", upper.bound == Bound::open ? "<" : "<=", limit_text(upper));
    }
    return {};
}

std::string KeySpec::default_text() const {
    switch (need) {
    case Need::required:
        return "required";
    case Need::conditional:
        return note;
    case Need::optional:
        return "unset";
    case Need::defaulted:
        break;
    }
    struct Text {
        std::string operator()(std::monostate) const { return "unset"; }
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(std::int64_t i) const { return std::to_string(i); }
        std::string operator()(double d) const { return toml_real(d); }
        std::string operator()(const std::string& s) const { return roughgas::quoted(s); }
    };
    if (type == KeyType::string_list && std::holds_alternative<std::string>(default_value)) {
        std::string text;
        for (const std::string& e : default_list())
            text += (text.empty() ? "" : ", ") + roughgas::quoted(e);
        return "[" + text + "]";
    }
    if (type == KeyType::string3 && std::holds_alternative<std::string>(default_value)) {
        const std::string q = roughgas::quoted(std::get<std::string>(default_value));
        return "[" + q + ", " + q + ", " + q + "]";
    }
    return std::visit(Text{}, default_value);
}

std::vector<std::string> KeySpec::default_list() const {
    std::vector<std::string> list;
    if (const auto* d = std::get_if<std::string>(&default_value))
        for (std::size_t a = 0, b = 0; a < d->size(); a = b + 1) {
            b = std::min(d->find(' ', a), d->size());
            list.push_back(d->substr(a, b - a));
        }
    return list;
}

std::string KeySpec::type_name() const {
    switch (type) {
    case KeyType::boolean:
        return "boolean";
    case KeyType::integer:
        return "integer";
    case KeyType::real:
        return "real";
    case KeyType::string:
        return "string";
    case KeyType::string_pair:
        return "[string, string]";
    case KeyType::real3:
        return "[real, real, real]";
    case KeyType::integer3:
        return "[integer, integer, integer]";
    case KeyType::string3:
        return "[string, string, string]";
    case KeyType::string_list:
        return "[string, ...]";
    case KeyType::real_pairs:
        return "[[real, real], ...]";
    }
    return "?";
}

bool KeySpec::allows(double x) const {
    const auto above = [&](const Limit& l) {
        return l.bound == Bound::none || (l.bound == Bound::open ? x > l.value : x >= l.value);
    };
    const auto below = [&](const Limit& l) {
        return l.bound == Bound::none || (l.bound == Bound::open ? x < l.value : x <= l.value);
    };
    return above(lower) && below(upper);
}

bool KeySpec::allows(std::string_view s) const {
    return choices.empty() || std::find(choices.begin(), choices.end(), s) != choices.end();
}

const std::vector<TableSpec>& case_tables() {
    static const std::vector<TableSpec> tables = {
        {"run", false, "required", "what to simulate and for how long"},
        {"species", true, "required (at least one)", "one table per species of grains"},
        {"collision", false, "required", "the collision rule of every pair without a [[pair]] table"},
        {"pair", true, "optional",
         "mixtures: the collision rule of one species pair (keys default to [collision])"},
        {"material", false, "required for model = viscoelastic, brilliantov and roughgas restitution",
         "material of the grains (SI)"},
        {"contact", false, "optional", "how the contact of viscoelastic and brilliantov is integrated"},
        {"shear", false, "required for run.kind = shear", "uniform shear flow"},
        {"thermostat", false, "optional (run.kind = cooling)",
         "a thermostat that drives the gas, white noise or a Langevin bath, homogeneous or every grain of a box "
         "(a driven gas: steady.csv)"},
        {"species_thermostat", true, "optional (with [thermostat])",
         "one species' thermostat (keys default to [thermostat])"},
        {"domain", false, "optional",
         "a spatially resolved run: grains with positions in a box of collision cells (docs/model.md §8)"},
        {"initial", false, "optional",
         "how the run starts: from a saved state (initial.from), and a wave on a spatially resolved run's start"},
        {"spectra", false, "optional (with a periodic [domain])",
         "Fourier spectra of the box's fields at every output row: spectra.csv and modes.csv (docs/model.md §8)"},
        {"fields", false, "optional (with [domain])",
         "the fields of every collision cell at output rows, as HDF5 files with an XDMF sidecar for ParaView "
         "(docs/reference.md)"},
        {"wall_lower", false, "required for domain.boundary with \"walls\" unless every walled axis has its own",
         "the wall at coordinate 0 of every walled axis without a [wall_lower_x], [wall_lower_y] or [wall_lower_z]"},
        {"wall_upper", false, "required for domain.boundary with \"walls\" unless every walled axis has its own",
         "the wall at coordinate L of every walled axis without a [wall_upper_x], [wall_upper_y] or [wall_upper_z]"},
        {"wall_lower_x", false, "optional (with walls along x)",
         "the wall at x = 0 (the keys of [wall_lower]), in place of [wall_lower] there"},
        {"wall_upper_x", false, "optional (with walls along x)",
         "the wall at x = L_x (the keys of [wall_upper]), in place of [wall_upper] there"},
        {"wall_lower_y", false, "optional (with walls along y)",
         "the wall at y = 0 (the keys of [wall_lower]), in place of [wall_lower] there"},
        {"wall_upper_y", false, "optional (with walls along y)",
         "the wall at y = L_y (the keys of [wall_upper]), in place of [wall_upper] there"},
        {"wall_lower_z", false, "optional (with walls along z)",
         "the wall at z = 0 (the keys of [wall_lower]), in place of [wall_lower] there"},
        {"wall_upper_z", false, "optional (with walls along z)",
         "the wall at z = L_z (the keys of [wall_upper]), in place of [wall_upper] there"},
        {"restitution", false, "optional", "the grid that roughgas restitution tabulates"},
    };
    return tables;
}

const std::vector<KeySpec>& case_schema() {
    // Built once on first use; immutable afterwards.
    static const std::vector<KeySpec> schema = [] {
        std::vector<KeySpec> s;
        for (const Key& k : keys()) {
            s.push_back(k.spec());
        }
        return s;
    }();
    return schema;
}

const TableSpec* find_table(std::string_view name) {
    const auto& t = case_tables();
    const auto it = std::find_if(t.begin(), t.end(), [&](const TableSpec& s) { return s.name == name; });
    return it == t.end() ? nullptr : &*it;
}

const KeySpec* find_key(std::string_view path) {
    const auto& s = case_schema();
    const auto it = std::find_if(s.begin(), s.end(), [&](const KeySpec& k) { return k.path == path; });
    return it == s.end() ? nullptr : &*it;
}

std::string case_keys_markdown() {
    std::string md = "| Key | Type | Unit | Default | Allowed | Description |\n"
                     "|-----|------|------|---------|---------|-------------|\n";
    for (const KeySpec& k : case_schema()) {
        const std::string unit = k.unit.empty() ? "-" : k.unit;
        const std::string allowed = k.allowed().empty() ? "any" : k.allowed();
        md += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", k.path, markdown_cell(k.type_name()),
                          markdown_cell(unit), markdown_cell(k.default_text()), markdown_cell(allowed),
                          markdown_cell(k.description));
    }
    return md;
}

std::string case_tables_markdown() {
    std::string md = "| Table | Presence | Contents |\n"
                     "|-------|----------|----------|\n";
    for (const TableSpec& t : case_tables()) {
        const std::string header = t.array ? "[[" + t.name + "]]" : "[" + t.name + "]";
        md += fmt::format("| `{}` | {} | {} |\n", header, markdown_cell(t.requirement),
                          markdown_cell(t.description));
    }
    return md;
}

} // namespace roughgas
