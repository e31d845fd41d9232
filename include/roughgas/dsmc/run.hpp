#pragma once
// One DSMC run of the homogeneous gas: the columns it reports and the run itself.
#include "roughgas/dsmc/output_columns.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/cell_fields.hpp"
#include "roughgas/observables/histograms.hpp"
#include "roughgas/observables/spectra.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace roughgas {

class RestitutionTables; // dsmc/tables.hpp

// Progress of a run: collisions per particle done so far, the end, and collisions done.
using ProgressSink = std::function<void(double done, double end, double collisions)>;

// The histograms of one replica at one of spec.histogram_times.
struct HistogramSet {
    double t = 0, coll_per_particle = 0;
    std::vector<SpeciesHistograms> species; // in spec.species order
};
using HistogramSink = std::function<void(const HistogramSet&)>;

// The cell fields of one replica at output row `row` (0: t = 0), every spec.domain->fields->every
// rows, for the replicas below spec.domain->fields->replicas.
// Shared, not copied: a sink may write it on another thread while the run goes on.
struct FieldSnapshot {
    std::size_t row = 0;
    double t = 0, coll_per_particle = 0;
    std::shared_ptr<const CellFields> fields;
};
using FieldSink = std::function<void(const FieldSnapshot&)>;

// Columns of moments.csv for this spec, in the order of docs/reference.md: t, coll_per_particle, T_tr,
// T_rot, theta, a20, a02, a11, A_cw, coll_rate, E_diss_rate, then per species X.NAME and ratios
// (mixtures). Replica errors (X_err) and theory columns are added by the writer, not here.
// Definitions (dsmc/run.cpp has the details): coll_per_particle = 2 x collisions / N; coll_rate =
// collisions per particle per unit time (2 x collisions / N / time) over the interval since the
// previous row; E_diss_rate = energy dissipated per unit volume and time over that interval; both
// are NaN in the row at t = 0. Mixtures: T_tr, T_rot, theta, a20, a02, a11, A_cw, coll_rate per species
// (coll_rate.NAME: collisions of a NAME grain per NAME grain and unit time), then T_tr.A/T_tr.B and
// T_rot.A/T_rot.B for every species pair A before B. Runs with a brilliantov pair end with
// beta_clamped: collisions so far whose model beta left [-1, 1] (restitution_policy.hpp, clamp_beta).
// Box runs: u_wave, n_wave, e_wave (with an [initial] wave), then cell_over_lambda: the largest cell
// edge over the local mean free path 1/(sqrt(2) pi n_b sigma^2) among the profile slabs (n_b the
// slab's density, sigma the largest diameter).
std::vector<Column> dsmc_columns(const RunSpec& spec);

// Columns of walls.csv after t and coll_per_particle (runs with walls; empty otherwise): per walled
// axis a (x, y, z in order), its lower wall (at 0) then its upper wall (at L_a), each
//   a_lower.hits            grains hitting the wall per area and time,
//   a_lower.P_xa, P_ya, P_za  the column a of the pressure tensor at the wall: the flux of momentum
//                            component i in the +a direction (at the lower wall minus, at the upper
//                            wall plus the momentum the grains give the wall per area and time),
//   a_lower.q_a             the energy flux in the +a direction (translational and rotational
//                            kinetic energy; in the same sense),
// over the interval since the previous row, for the physical grains (each simulated one standing
// for n V / N); NaN in the row at t = 0.
std::vector<Column> wall_columns(const RunSpec& spec);

// The profiles.csv fields of every bin (box runs; empty otherwise): bin b's fields
// (observables/profiles.hpp, profile_fields) named "binB.FIELD", bin after bin; the bins are the
// cells along domain.profile_axis.
std::vector<Column> profile_columns(const RunSpec& spec);

// The spectra.csv fields of every spectrum bin, then the modes.csv fields of every mode (box runs
// with spectra; empty otherwise; observables/spectra.hpp): "kA.N.FIELD" (A the axis: 0 for the
// shells, 1, 2, 3 along x, y, z; N the shell or wave number) and "modeA.N.FIELD".
std::vector<Column> spectra_columns(const RunSpec& spec);
// The grid of a box's spectra: its collision cells (modes: 0 without spectra).
SpectraGeometry spectra_geometry(const DomainSpec& d);

// What a replica's row holds (the RowSink's values): dsmc_columns, wall_columns, profile_columns,
// spectra_columns.
std::vector<Column> replica_row_columns(const RunSpec& spec);

// An upper bound of the memory one replica holds per grain while it runs (the particle store, the
// engine's index and sort arrays, a row's scratch): what a command checks against the machine's
// free memory before any work (core/available_memory.hpp).
std::size_t memory_per_particle_bound(const RunSpec& spec);
// A bound of a box's store per grain (dsmc/spatial_engine.hpp): positions, velocities and spins
// twice (the sort; smooth grains keep one copy of their spins and an identity, 20 bytes less), the
// cell key, with nearest partners the identities and last partners twice.
std::size_t box_bytes_per_particle(const DomainSpec& d);
// The same for what does not grow with the grains: a box's per-cell arrays and the rows it keeps
// (its profiles: bins x fields per row) (0 without [domain]).
std::size_t memory_per_replica_fixed_bound(const RunSpec& spec);

// Runs replica `replica` (0-based; its RNG streams derive from spec.seed and the replica index),
// calling `sink` once per spec.output_times entry (and once at t = 0 first). Deterministic for a
// given (spec, replica) whatever spec.threads is.
// Builds (or loads from spec.cache_file) the restitution tables first: defined in roughgas_io
// (src/io/run_tables.cpp), since it reads the cache file. To run several replicas, build the tables
// once with build_run_tables (io/run_tables.hpp) and call the overload below.
void run_replica(const RunSpec& spec, int replica, const RowSink& sink, const ProgressSink& progress = {});

// What one replica did, for the caller to report (the solver never prints).
struct ReplicaSummary {
    std::string kernel;             // the specialised collision loop that ran, e.g. "RoughAoS, constant, one species"
    std::size_t bytes_per_particle = 0;   // the particle store (dsmc/particles.hpp)
    std::size_t memory_per_particle = 0;  // the store, the engine's index array and its step-start scratch
    int groups = 1;                 // random groups per step (dsmc/engine.hpp), run in parallel
    std::int64_t collisions = 0;
    std::int64_t resumed_at = 0;    // collisions before the checkpoint it resumed from (an earlier run's)
    std::int64_t candidates = 0;    // candidate pairs drawn (collisions/candidates: the majorant's acceptance)
    std::int64_t steps = 0;
    std::int64_t bound_raises = 0;  // collisions that raised the majorant within a step
    std::int64_t promotions = 0;    // grains moved to a faster speed class within a step
    std::int64_t beta_clamped = 0;  // collisions whose model beta was clamped to [-1, 1]
    double max_mean_drift = 0;      // largest centre-of-mass speed over the rms speed seen at a step start:
                                    // round-off, removed once above 1e-10 (dsmc/engine.hpp)
    std::int64_t recentrings = 0;   // steps that removed it
    std::int64_t overshoots = 0;    // grouped runs: collision counts passed in a phase (engine.hpp)
    double seconds = 0;             // wall time of the collision loop and the moments
};

// Checkpoints of one replica: its complete resumable state as opaque bytes (the caller stores them,
// cli/run/checkpoints.hpp and io/checkpoint_file.hpp). States are taken at boundaries where the run can
// stop without changing its trajectory: cooling runs after every chunk of the collision loop
// (max(65536, N/2) collisions, and at every row and histogram time), shear runs after every Strang
// step (the end of its collision part, before the merged stream: dsmc/shear.hpp). No pause is
// added for them: the sequence of engine calls, and so every bit of the output, is the same with
// checkpoints, without them and after a resume.
struct ReplicaCheckpoints {
    // A state at the first boundary at or after every multiple of `every` collisions per particle
    // (0: none but the one of a stop).
    double every = 0;
    // Receives the state, on the replica's thread, after every row and histogram set before it has
    // gone to the sinks (so the caller stores the rows with it).
    std::function<void(std::string state)> save;
    // Polled at every boundary: once it returns true, the replica saves its state and returns
    // ReplicaEnd::stopped.
    std::function<bool()> stop;
    // Non-empty: continue from this state, saved by `save` for the same spec and replica. The rows
    // and histograms before it are not sent again.
    std::string resume;
};

enum class ReplicaEnd { finished, stopped };

// A resume state that does not fit the spec (another kernel, particle count, schedule) or is malformed.
struct ResumeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The same with tables built by the caller (RestitutionTables::build, or build_run_tables for the
// cache file): in the physics library. `summary` (optional) receives what the run did; `histograms`
// (optional) is called at every spec.histogram_times entry; `checkpoints` (optional) saves and
// resumes states; `fields` (optional) receives the cell fields of box runs with spec.domain->fields.
ReplicaEnd run_replica(const RunSpec& spec, const RestitutionTables& tables, int replica, const RowSink& sink,
                       const ProgressSink& progress = {}, ReplicaSummary* summary = nullptr,
                       const HistogramSink& histograms = {}, const ReplicaCheckpoints* checkpoints = nullptr,
                       const FieldSink& fields = {});

} // namespace roughgas
