#pragma once
// What one DSMC run needs, as plain values (built from the case file by io/run_spec_from_case.hpp).
// The physics never sees the parser.
#include "roughgas/contact/contact_pair.hpp"
#include "roughgas/contact/tolerance.hpp"
#include "roughgas/dsmc/grain_state.hpp"
#include "roughgas/observables/field_quantity.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace roughgas {

struct SpeciesSpec {
    std::string name = "grain";
    double mass = 1, radius = 0.5, inertia = 0.4; // q = J/(m R^2)
    double fraction = 1;
    double temperature = 1, rotational_temperature = 1; // initial T_tr, T_rot (k_B = 1)
};

// Restitution models of one species pair (docs/reference.md [collision] model = ...).
struct ConstantRestitution { double alpha = 1, beta = -1; };
struct CoulombRestitution { double alpha = 1, beta0 = 1, mu = 0; };         // Walton's model
struct ViscoelasticRestitution { ContactPair pair; double beta = -1; bool direct = false; };
struct BrilliantovRestitution { ContactPair pair; bool direct = false; };
using PairRestitution = std::variant<ConstantRestitution, CoulombRestitution, ViscoelasticRestitution,
                                     BrilliantovRestitution>;

// The collision kernel (docs/model.md §4): hard spheres (each pair at the rate pi sigma^2 |g.n|-weighted,
// i.e. pi sigma^2 |g| in total, n with density |g^.n| on the approaching hemisphere), or the
// Maxwell model: each pair of species (a, b) at the constant rate pi sigma_ab^2 u_ab/V, u_ab =
// sqrt((8/pi)(T_a/m_a + T_b/m_b)) at the species' initial temperatures (the hard-sphere rate of
// the initial Maxwellian state), n uniform on the approaching hemisphere. Its T_tr(t), T_rot(t) obey
// closed linear ODEs exactly (observables/theory.hpp).
enum class CollisionKernel { hard_sphere, maxwell };

// Uniform shear flow u = a y x^ (dsmc/shear.hpp).
struct ShearSpec {
    double rate = 1;        // a, 1/time
    double time_step = 0.2; // Strang step h in mean free times (at each output interval's start)
};

// A wave on the uniform Maxwellian start of a spatially resolved run, wave vector k with
// k_a = 2 pi wave_a / L_a (dsmc/spatial_engine.hpp):
//   transverse    u = A c e sin(k.x), e perpendicular to k (y if k_y = 0, else z if k_z = 0, else k x x/|k x x|);
//   longitudinal  u = A c k/|k| sin(k.x);
//   density       n(x) = n (1 + A sin(k.x));
//   temperature   T(x) = T (1 + A sin(k.x)) (translational and rotational).
// c = sqrt(T/m) with the number-weighted mean T and m of the species.
enum class Perturbation { none, transverse, longitudinal, density, temperature };
struct InitialSpec {
    Perturbation mode = Perturbation::none;
    double amplitude = 0.1;         // A, |A| < 1
    std::array<int, 3> wave{1, 0, 0};
};

// The boundary of one axis of the box: periodic, or two flat walls (at 0 and at L).
enum class Boundary { periodic, walls };

// A flat wall (collision/wall_rule.hpp): the grain collides with an infinitely massive partner
// moving at `velocity` (tangential to the wall) without spin.
//   specular  the normal velocity reversed, nothing else changed;
//   diffuse   re-emitted from the flux-weighted half-Maxwellian at (temperature, velocity), the spin
//             from the Maxwellian at `temperature` (full accommodation);
//   rough     the collision rule with the wall's alpha, beta.
enum class WallKind { specular, diffuse, rough };
struct WallSpec {
    WallKind kind = WallKind::diffuse;
    double temperature = 1;
    std::array<double, 3> velocity{0, 0, 0};
    double alpha = 1, beta = -1;
};

// How a cell picks the partner of a candidate pair's first grain (dsmc/spatial_engine.hpp):
//   random   any other grain of the cell, uniformly (the standard DSMC);
//   nearest  the nearest other grain of the cell, except the grain's most recent collision partner
//            (Bird 2007; Gallis, Torczynski, Rader & Bird 2009): the collision separation, and
//            with it the cell-size error of the transport coefficients, shrinks from the cell's
//            size to the spacing of its grains.
enum class PartnerSelection { random, nearest };

// Fourier spectra of a periodic box (observables/spectra.hpp): spectra.csv and modes.csv at every
// output row, on the grid of the collision cells; `modes` wave numbers per axis in modes.csv.
struct SpectraSpec {
    int modes = 3;
};

// The fields of every collision cell (observables/cell_fields.hpp) at every `every`-th output row
// (the first included), of the replicas 0 ... replicas - 1: what run_replica gives its FieldSink.
struct FieldsSpec {
    std::vector<FieldQuantity> quantities;
    int every = 1;
    int replicas = 1;
};

// A spatially resolved run (dsmc/spatial_engine.hpp): a box of collision cells.
struct DomainSpec {
    std::array<double, 3> size{1, 1, 1}; // L_x, L_y, L_z (the case's length unit)
    std::array<int, 3> cells{1, 1, 1};   // collision cells along each axis
    std::array<Boundary, 3> boundary{Boundary::periodic, Boundary::periodic, Boundary::periodic};
    // The walls at coordinate 0 (lower) and L (upper) of every walled axis, unless the axis has its
    // own (axis_lower[a], axis_upper[a]: a floor that heats beside side walls that only reflect).
    WallSpec wall_lower, wall_upper;
    std::array<std::optional<WallSpec>, 3> axis_lower, axis_upper;
    std::array<double, 3> gravity{0, 0, 0}; // uniform acceleration
    int profile_axis = 0;                   // profiles.csv: slabs normal to this axis, one per cell along it
    // Lees-Edwards boundaries along y (run.kind = shear): the images above and below move at
    // +-a L_y along x; the gas starts with the flow u_x = a (y - L_y/2). 0: plain periodic.
    double shear_rate = 0;
    double time_step = 0.2;              // in mean free times of the current state
    PartnerSelection partners = PartnerSelection::random;
    // The Enskog equation (RunSpec::enskog): the cells per side of the cube over which the local
    // density that sets chi is averaged (dsmc/enskog_cells.hpp); odd, 0 for the smallest cube that
    // holds 1000 grains on average.
    int chi_cells = 0;
    InitialSpec initial;
    std::optional<SpectraSpec> spectra; // set: spectra.csv and modes.csv (periodic boxes)
    std::optional<FieldsSpec> fields;   // set: cell fields at output rows

    bool walled(int axis) const { return boundary[static_cast<std::size_t>(axis)] == Boundary::walls; }
    // The wall at 0 (upper: at L) of `axis`.
    const WallSpec& wall(int axis, bool upper) const {
        const std::optional<WallSpec>& own = (upper ? axis_upper : axis_lower)[static_cast<std::size_t>(axis)];
        return own ? *own : upper ? wall_upper : wall_lower;
    }
    // The walls the walled axes use, lower then upper per axis.
    std::vector<const WallSpec*> walls_in_use() const {
        std::vector<const WallSpec*> w;
        for (int a = 0; a < 3; ++a)
            if (walled(a))
                for (const bool upper : {false, true})
                    w.push_back(&wall(a, upper));
        return w;
    }
    bool has_walls() const { return walled(0) || walled(1) || walled(2); }
    bool has_gravity() const { return gravity[0] != 0 || gravity[1] != 0 || gravity[2] != 0; }
    bool lees_edwards() const { return shear_rate != 0; }
    // The flight needs more than adding and wrapping.
    bool general_flight() const { return has_walls() || has_gravity() || lees_edwards(); }
};

// A thermostat: energy fed to the grains at every DSMC step (dsmc/thermostat.hpp; docs/model.md, "The
// DSMC" and "Maxwellian theory of the driven gas").
//   white_noise  every velocity component gets an independent Gaussian kick of variance xi0^2 dt
//                (xi0^2 the strength, velocity^2/time), so that the kicks alone give dT_tr/dt = m xi0^2;
//                the share eps (rotational_share) of that power goes to the spins instead, by kicks of
//                omega of variance eps m xi0^2 dt/I (and those of v shrink to (1 - eps) xi0^2 dt):
//                dT_tr/dt = (1 - eps) m xi0^2, dT_rot/dt = eps m xi0^2 from the kicks;
//   langevin     a bath at T_b with friction: dv = -gamma v dt + sqrt(2 gamma T_b/m) dW, and the spins
//                with gamma_rot (0: the spins feel no bath): dT_tr/dt = 2 gamma (T_b - T_tr) from the bath.
// The kicks of a step carry zero total momentum per species (dsmc/thermostat.hpp).
enum class ThermostatKind { white_noise, langevin };

// A piecewise-constant function of time: value[k] on [t[k], t[k+1]), value.back() from t.back() on;
// t[0] = 0, t increasing.
struct DriveSchedule {
    std::vector<double> t{0.0}, value{0.0};
    double at(double time) const;
    // The integral of the function over [t0, t1] (t0 <= t1).
    double integral(double t0, double t1) const;
    // The integral of value(s) exp(-r (t1 - s)) ds over [t0, t1] (r >= 0): the Langevin bath's noise.
    double decaying_integral(double t0, double t1, double r) const;
    bool constant() const { return t.size() == 1; }
};

// One species' thermostat: `drive` is the white noise's strength xi0^2 or the Langevin bath's
// temperature T_b, over time.
struct SpeciesThermostat {
    DriveSchedule drive;
    double rotational_share = 0;                  // eps (white noise)
    double friction = 0, rotational_friction = 0; // gamma, gamma_rot (langevin), 1/time
};

struct ThermostatSpec {
    ThermostatKind kind = ThermostatKind::white_noise;
    // White noise: each step's kicks scaled per species so that they inject exactly the intended
    // energy (N_s (3/2) m_s xi0^2 dt, split by eps), not only in expectation.
    bool exact_energy = false;
    std::vector<SpeciesThermostat> species; // one per RunSpec::species entry
};

// The Enskog equation of a moderately dense gas (run.equation = "enskog"; dsmc/pair_correlation.hpp):
// every pair collides chi times as often as in the Boltzmann equation, chi the pair correlation at
// contact, and each collision carries momentum across the grains' distance sigma (the collisional
// pressure). chi from the solid fraction (carnahan_starling: Carnahan & Starling 1969 for one species,
// the Boublik-Mansoori-Carnahan-Starling-Leland form for mixtures), or one constant for every pair.
enum class PairCorrelationModel { carnahan_starling, constant };
struct EnskogSpec {
    PairCorrelationModel model = PairCorrelationModel::carnahan_starling;
    double chi = 1; // constant: chi of every pair
};

// What a run's end, output times and histogram times count (run.end or run.end_time):
//   collisions  collisions per particle, 2 x collisions / N: the work done; a row is the state right
//               after the collision that completes its count;
//   time        the case's time unit: rows of every replica, and of runs started from other states (a
//               hot and a cold gas), at the same t. The homogeneous gas's row at t is its state at t,
//               after the last collision before t (Engine::run stops at t exactly: the DSMC state is
//               constant between collisions); a box's row ends a step shortened to end at t.
enum class Clock { collisions, time };

struct RunSpec {
    std::vector<SpeciesSpec> species;
    // Model of species pair (a, b), a <= b, at index pair_index(a, b, species.size()).
    std::vector<PairRestitution> pairs;
    std::int64_t particles = 1000;
    double density = 1;                 // number density n
    std::uint64_t seed = 1;
    int replicas = 1;
    Clock clock = Clock::collisions;    // what end, output_times and histogram_times count
    double end = 10;                    // collisions per particle (the time clock: time)
    std::vector<double> output_times;   // in the clock's unit, increasing, the last one == end
    // Histograms of c*, w*, c*.w* (observables/histograms.hpp) at these times (in the clock's unit,
    // increasing, <= end; empty: none), with `histogram_bins` bins over [0, histogram_max)
    // (speeds) and [-histogram_max, histogram_max) (c*.w*). Pausing there does not change the run.
    std::vector<double> histogram_times;
    int histogram_bins = 50;
    double histogram_max = 5.0;
    // OpenMP threads of one replica (the groups of a step run in parallel): no influence on the
    // results. The command line shares --threads between replicas and groups (cli/run/replica_scheduler.cpp).
    int threads = 1;
    // Random groups per DSMC step (dsmc/engine.hpp, "Groups"); 0: automatic, auto_groups(particles).
    int groups = 0;
    CollisionKernel kernel = CollisionKernel::hard_sphere;
    // DSMC step length in mean free times. A step only refreshes the collision majorant (and the
    // frame); the collision statistics do not depend on it (dsmc/engine.hpp).
    double step = 1.0;
    // Speed classes per species of the collision majorant (dsmc/engine.hpp), 1 .. 6: 1 is the plain
    // bound vmax_a + vmax_b; no influence on the statistics, only on the speed.
    int speed_classes = 2;
    // Contact tables (viscoelastic, brilliantov): integration tolerance, cache file ("" = none),
    // and the range of g_N the tangential tables cover (outside: direct integration).
    Tolerance contact_tolerance{};
    std::filesystem::path cache_file;
    bool use_cache = true;
    double table_g_min = 1e-6, table_g_max = 1e2;
    // Uniform shear flow instead of free cooling (run.kind = "shear").
    std::optional<ShearSpec> shear;
    // A thermostat ([thermostat]): a driven gas instead of a freely cooling one.
    std::optional<ThermostatSpec> thermostat;
    // Set: the Enskog equation (run.equation = "enskog") instead of the Boltzmann equation.
    std::optional<EnskogSpec> enskog;
    // Positions, streaming and collision cells instead of the homogeneous gas ([domain]).
    std::optional<DomainSpec> domain;
    // Set: each replica starts from this state (initial.from) instead of the Maxwellian at the
    // species' temperatures; time and collisions count from 0, the row at t = 0 is the state.
    //   homogeneous  the velocities and spins (a box's positions are not used), the total momentum
    //                removed (dsmc/init.hpp init_from_state);
    //   box          the velocities and spins, the positions too when the state is of a box of the
    //                same size (else uniform), then DomainSpec::initial's wave (dsmc/spatial_engine.hpp).
    // A resumed homogeneous replica does not call it (its checkpoint holds the grains); a box does.
    GrainStateSource initial_state;
    // Set: called with each replica's state when it finishes (not when it stops early).
    GrainStateSink final_state;
};

// The automatic group count: particles/16384 rounded down to a power of two (at least 1, at most
// 4096), so that a group of rough grains (64 bytes each) takes about 1 MiB and stays in one core's
// L2 (4 MiB here) while it collides. Depends on the particle count only, never on the threads.
constexpr int auto_groups(std::int64_t particles) {
    int g = 1;
    while (g < 4096 && particles / (2 * g) >= 16384)
        g *= 2;
    return g;
}
constexpr int effective_groups(const RunSpec& spec) {
    return spec.groups > 0 ? spec.groups : auto_groups(spec.particles);
}

constexpr std::size_t pair_index(std::size_t a, std::size_t b, std::size_t n_species) {
    if (a > b) { const std::size_t t = a; a = b; b = t; }
    return a * n_species - a * (a + 1) / 2 + b; // upper triangle, row-major
}

} // namespace roughgas
