#pragma once
// One replica of a spatially resolved run ([domain]): the engine of dsmc/spatial_engine.hpp driven
// to the output rows, with the columns of the homogeneous runs (gas_row.hpp) over the whole box.
//
// Steps. Each step lasts domain.time_step mean free times of the state it starts from (the
// Maxwellian collision frequency of the current temperatures, so a cooling gas keeps its steps per
// collision), shortened so that it ends at the next output's collisions per particle when that is
// nearer: rows come at the end of the first step at or after each output (a row whose step passed
// several outputs is repeated for each). The step length is part of the discretisation (the
// DSMC's time-step error), so it depends on the output schedule only through those shortened
// steps, which are shorter, never longer, than domain.time_step.
// The time clock (run.end_time): the step that would pass an output's time ends at it exactly
// (SpatialEngine::step_to), so every replica's row is at that t; a step within 1e-9 of it is
// stretched to it instead of leaving a sliver.
//
// Checkpoints: the engine's state (positions included) and the place in the output schedule, at
// step ends; the streams are keyed by the step, so a resumed run draws the same numbers.
//
// The loop of one replica, run_box<Policy>, is compiled once per restitution policy, each in a
// translation unit of its own (box_flight_*.cpp): drive_spatial.cpp only picks one.
#include "drive.hpp"
#include "gas_row.hpp"

#include "roughgas/core/bytes.hpp"
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/spatial_engine.hpp"
#include "roughgas/observables/densest_cell.hpp"
#include "roughgas/observables/pressure.hpp"
#include "roughgas/observables/thermal_temperature.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace roughgas::detail {


// The walls.csv columns (wall_columns, dsmc/run.hpp) from what the grains gave the walls between
// two rows, `dt` apart: each simulated grain stands for F = n V / N physical ones, a wall of axis a
// has the area V / L_a.
inline void append_wall_columns(std::vector<double>& row, const DomainSpec& d, const WallFluxes& now,
                         const WallFluxes& before, double density, double N, double dt) {
    for (int a = 0; a < 3; ++a) {
        if (!d.walled(a))
            continue;
        const double per_area_time = density * d.size[static_cast<std::size_t>(a)] / (N * dt); // F/(A dt)
        for (int upper = 0; upper < 2; ++upper) {
            const auto k = static_cast<std::size_t>(2 * a + upper);
            const double sense = upper ? 1.0 : -1.0; // the +a flux: into the upper wall, out of the lower one
            const Vec3 p = now[k].momentum - before[k].momentum;
            row.push_back((now[k].hits - before[k].hits) * per_area_time);
            for (double c : {p.x, p.y, p.z})
                row.push_back(sense * c * per_area_time);
            row.push_back(sense * (now[k].energy - before[k].energy) * per_area_time);
        }
    }
}

// The smoothing cube of an Enskog box's chi (DomainSpec::chi_cells): the run's, or the smallest odd
// cube (its sides capped at the box's cells) that holds 1000 grains on average.
inline int chi_smoothing_cells(const DomainSpec& d, std::size_t particles) {
    if (d.chi_cells > 0)
        return d.chi_cells;
    const double per_cell = static_cast<double>(particles) / (static_cast<double>(d.cells[0]) * d.cells[1] * d.cells[2]);
    const int longest = std::max({d.cells[0], d.cells[1], d.cells[2]});
    for (int k = 1;; k += 2) {
        double cube = per_cell;
        for (int a = 0; a < 3; ++a)
            cube *= std::min(k, d.cells[static_cast<std::size_t>(a)]);
        if (cube >= 1000 || k >= longest)
            return k;
    }
}

template <class Policy, bool General>
ReplicaEnd run_box_flight(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks, std::vector<Policy> policies,
                   int replica, const ReplicaIo& io) {
    const auto wall0 = std::chrono::steady_clock::now();
    const DomainSpec& domain = *spec.domain;
    SpatialEngine<Policy, General> engine(domain, blocks, std::move(policies), spec.density, spec.seed,
                                          static_cast<std::uint64_t>(replica), std::max(1, spec.threads),
                                          spec.kernel, spec.initial_state);
    if (spec.thermostat) // a uniformly heated box (before a resume's restore: its state holds the kicks' time)
        engine.set_thermostat(*spec.thermostat);
    if (spec.enskog) // collisions a diameter apart (dsmc/spatial_engine.hpp, "Enskog collisions")
        engine.set_enskog(pair_correlations(spec),
                          spec.enskog->model == PairCorrelationModel::constant ? spec.enskog->chi : 0.0,
                          chi_smoothing_cells(domain, engine.particles()));
    const double N = static_cast<double>(engine.particles());
    const std::size_t S = blocks.size();
    const std::vector<SpeciesSlice> slices = species_slices(blocks);
    const std::vector<PairType>& types = engine.pair_types();
    const bool clamp_column = has_brilliantov(spec);
    const std::size_t columns = replica_row_columns(spec).size();
    const std::string kernel = std::string("box of ") + std::to_string(engine.cells()) + " cells" +
                               (domain.has_walls() ? ", walls" : "") + (domain.has_gravity() ? ", gravity" : "") +
                               (domain.lees_edwards() ? ", Lees-Edwards" : "") +
                               (spec.kernel == CollisionKernel::maxwell ? ", Maxwell kernel" : "") +
                               (spec.thermostat ? ", thermostat" : "") + (spec.enskog ? ", Enskog" : "") + ", " +
                               std::string(Policy::name);

    std::vector<double> outputs = spec.output_times;
    if (outputs.empty())
        outputs.push_back(spec.end);
    const double end = outputs.back();

    Tally tally;
    tally.assign(types.size());
    double t_prev = 0;
    std::int64_t c_prev = 0;
    std::size_t next = 0; // the next output
    const ReplicaCheckpoints* ck = io.checkpoints;
    const double every = ck ? ck->every : 0;
    double next_save = every;
    std::int64_t resumed_at = 0;
    WallFluxes walls_prev{}; // the walls' tallies at the previous row
    ProfileGeometry profile_geometry;
    profile_geometry.axis = domain.profile_axis;
    profile_geometry.bins = domain.cells[static_cast<std::size_t>(domain.profile_axis)];
    profile_geometry.length = domain.size[static_cast<std::size_t>(domain.profile_axis)];
    const double box_volume = domain.size[0] * domain.size[1] * domain.size[2];
    profile_geometry.bin_volume = box_volume / profile_geometry.bins;
    profile_geometry.weight = spec.density * box_volume / N;
    profile_geometry.periodic = !domain.walled(domain.profile_axis);
    profile_geometry.rotation = Policy::needs_rotation;
    profile_geometry.shear_rate = domain.shear_rate;
    profile_geometry.box = domain.size;
    const bool sheared = domain.lees_edwards();
    std::vector<Vec3> peculiar(sheared ? engine.particles() : 0), spin(sheared ? engine.particles() : 0);
    std::vector<UsfSpecies> usf_species;
    for (const SpeciesBlock& b : blocks)
        usf_species.push_back({static_cast<double>(b.count) / N, b.grain.mass, b.grain.radius});
    double T0_tr = 0; // the initial translational temperature of the mixture (the Maxwell kernel's rates)
    for (const SpeciesBlock& b : blocks)
        T0_tr += b.temperature * static_cast<double>(b.count) / N;
    double edge = 0, sigma_max = 0; // the longest cell edge, the largest diameter
    for (std::size_t a = 0; a < 3; ++a)
        edge = std::max(edge, domain.size[a] / domain.cells[a]);
    std::vector<double> masses; // per species: T_th's mass weights
    for (const SpeciesBlock& b : blocks) {
        sigma_max = std::max(sigma_max, 2 * b.grain.radius);
        masses.push_back(b.grain.mass);
    }
    profile_geometry.gravity = {domain.gravity[0], domain.gravity[1], domain.gravity[2]};
    std::optional<Spectra> spectra; // planned once per replica
    if (domain.spectra)
        spectra.emplace(spectra_geometry(domain));
    // The cell fields: of the replicas below fields.replicas, at every fields.every-th row, computed
    // once per state (a row repeated for outputs its step passed has the same fields).
    const bool writes_fields = domain.fields && io.fields && replica < domain.fields->replicas;
    const std::array<bool, 3> walled{domain.walled(0), domain.walled(1), domain.walled(2)};
    std::shared_ptr<const CellFields> cell_fields;
    // Two buffers for them, each reused once its snapshot is written (io/fields_series.hpp writes
    // one snapshot behind the run).
    std::array<std::shared_ptr<CellFields>, 2> field_buffers;
    const auto field_buffer = [&]() -> CellFields& {
        auto& buffer = field_buffers[0].use_count() <= 1 ? field_buffers[0] : field_buffers[1];
        if (!buffer || buffer.use_count() > 1)
            buffer = std::make_shared<CellFields>();
        cell_fields = buffer;
        return *buffer;
    };
    CellFieldsScratch fields_scratch;
    const auto fields_at = [&](std::size_t row_index) {
        return writes_fields && row_index % static_cast<std::size_t>(domain.fields->every) == 0;
    };
    // A row that writes fields takes its profiles from the cells' sums, one pass over the grains for
    // both, where the profile bins are layers of cells with walls only across them.
    bool other_walls = false;
    for (int a = 0; a < 3; ++a)
        other_walls = other_walls || (a != domain.profile_axis && domain.walled(a));
    const bool fused_profiles = !other_walls;

    const auto state = [&] {
        ByteWriter w;
        w.str(kernel);
        engine.save(w);
        w.u64(next);
        w.f64(t_prev);
        w.put(c_prev);
        tally.save(w);
        w.f64(next_save);
        if (domain.has_walls())
            save(w, walls_prev);
        return w.take();
    };

    std::vector<double> row;
    std::optional<double> nu_ahead; // the collision frequency a row found for the step that follows it
    // Row `row_index` of moments.csv (0: t = 0).
    const auto emit = [&](bool repeat, std::size_t row_index) {
        if (!repeat) {
            cell_fields.reset();
            const double t = engine.time();
            const std::int64_t c = engine.collisions();
            const bool first = c == 0 && t == 0;
            const double nan = std::numeric_limits<double>::quiet_NaN();
            const double inv_dt = !first && t > t_prev ? 1.0 / (t - t_prev) : nan;
            // The profiles, sampled in the middle of the flight of the step that follows (its length
            // before any shortening for an output), give the cells' resolution of the densest slab.
            const double nu = engine.collision_frequency();
            nu_ahead = nu; // the next step starts from this state
            profile_geometry.half_flight = nu > 0 && std::isfinite(nu) ? 0.5 * domain.time_step / nu : 0.0;
            profile_geometry.time = t;
            const std::vector<Virial> virial = engine.take_virial();
            const double profile_dt = first ? nan : t - t_prev;
            const std::vector<double> profiles =
                fused_profiles && fields_at(row_index)
                    ? compute_cell_fields_and_profiles(profile_geometry, domain.cells, walled,
                                                       domain.fields->quantities, engine.positions(),
                                                       engine.velocities(), engine.angular_velocities(), blocks,
                                                       virial, profile_dt, field_buffer(), fields_scratch)
                    : compute_profiles(profile_geometry, engine.positions(), engine.velocities(),
                                       engine.angular_velocities(), blocks, virial, profile_dt, &engine.team());
            // A sheared box: the moments of the peculiar velocities (about the images' flow) in the
            // middle of the next flight, as the profiles (observables/profiles.hpp) and as the
            // homogeneous shear runs' Strang steps report them (half a stream after the collisions:
            // V_x - a (h/2) V_y); the spins about their mean.
            Vec3 Omega{};
            const std::vector<Vec3>& w_store = engine.angular_velocities(); // the spins in store order
            Vec3Column v_col = column_of(engine.velocities().data(), 0);
            Vec3Column w_col = column_of(w_store.data(), 0);
            if (sheared) {
                Omega = mean_spin(w_col, slices);
                for (std::size_t i = 0; i < engine.particles(); ++i) {
                    peculiar[i] = engine.peculiar_velocity(i, profile_geometry.half_flight);
                    spin[i] = w_store[i] - Omega;
                }
                v_col = column_of(peculiar.data(), 0);
                w_col = column_of(spin.data(), 0);
            }
            Moments m = compute_moments(v_col, w_col, slices, engine.team());
            if (spec.thermostat) // the moments at the row's time, not at the kicks' (dsmc/thermostat.hpp)
                m = moments_at_drive_time(m, slices, *spec.thermostat, t, engine.kicked_until());
            row.clear();
            append_row_head(row, t, c, c_prev, N, m, inv_dt, tally, engine.volume());
            if (spec.enskog) { // p_kin = n T_tr, p_coll the trace over 3 of the interval's virial per volume
                double trace = 0;
                for (const Virial& b : virial)
                    trace += b[0] + b[1] + b[2];
                const double p_kin = N / engine.volume() * m.all.T_tr, p_coll = trace / (3 * engine.volume()) * inv_dt;
                row.push_back(p_kin);
                row.push_back(p_coll);
                row.push_back(p_kin + p_coll);
            }
            if (sheared) {
                // Kinetic plus collisional (the interval's cell collisions: impulse times separation);
                // of an Enskog box, the collisional part in columns of its own (as the homogeneous
                // sheared Enskog gas's).
                PressureTensor P = pressure_tensor(v_col, slices, engine.volume(), m.mean_velocity);
                PressureTensor Pc{};
                PressureTensor& to = spec.enskog ? Pc : P;
                if (!first) {
                    const double f = 1.0 / (engine.volume() * (t - t_prev));
                    for (const Virial& b : virial) {
                        to.xx += f * b[0];
                        to.yy += f * b[1];
                        to.zz += f * b[2];
                        to.xy += f * b[3];
                        to.xz += f * b[4];
                        to.yz += f * b[5];
                    }
                }
                append_shear_columns(row, P, Omega, spec.shear->rate, usf_species, spec.density, m.all.T_tr,
                                     spec.enskog ? std::optional(Pc) : std::nullopt);
            }
            append_row_tail(row, m, tally, types, blocks, inv_dt, clamp_column);
            if (domain.initial.mode != Perturbation::none)
                for (double a : engine.wave_amplitudes())
                    row.push_back(a);
            double n_max = 0;
            for (std::size_t b = 0; b < profiles.size(); b += profile_field_count)
                n_max = std::max(n_max, profiles[b]);
            // The Maxwell kernel's rate stays that of the initial temperature T0 while the grains slow
            // down: its mean free path, <v>/nu, is the hard spheres' times sqrt(T/T0).
            const double kernel_path =
                spec.kernel == CollisionKernel::maxwell && m.all.T_tr > 0 ? std::sqrt(m.all.T_tr / T0_tr) : 1.0;
            row.push_back(edge / (kernel_path * mean_free_path(n_max, sigma_max)));
            row.push_back(edge / (kernel_path * mean_free_path(densest_cell_density(engine.cell_sums(),
                                                                                    engine.cell_sum_fields, S,
                                                                                    engine.cells(), spec.density),
                                                               sigma_max)));
            row.push_back(thermal_temperature(engine.cell_sums(), engine.cell_sum_fields, masses));
            append_wall_columns(row, domain, engine.wall_fluxes(), walls_prev, spec.density, N,
                                first ? std::numeric_limits<double>::quiet_NaN() : t - t_prev);
            walls_prev = engine.wall_fluxes();
            row.insert(row.end(), profiles.begin(), profiles.end());
            if (spectra) {
                // The engine's cells are the spectra's grid: its sums per cell, with no pass over positions.
                const std::vector<double> spins =
                    domain.spectra->modes > 0 ? engine.cell_spin_sums() : std::vector<double>{};
                const std::vector<double> s = spectra->compute_from_cell_sums(
                    engine.cell_sums(), engine.cell_sum_fields, spins, engine.velocities(), blocks, engine.team());
                row.insert(row.end(), s.begin(), s.end());
            }
            if (row.size() != columns)
                throw std::logic_error("run_replica: row and columns differ");
            t_prev = t;
            c_prev = c;
            tally.next_interval();
        }
        if (fields_at(row_index)) {
            if (!cell_fields) // a repeated row's state, or walls across another axis than the profiles'
                compute_cell_fields(profile_geometry, domain.cells, walled, domain.fields->quantities,
                                    engine.positions(), engine.velocities(), engine.angular_velocities(), blocks,
                                    field_buffer(), fields_scratch);
            io.fields(FieldSnapshot{row_index, engine.time(), 2.0 * static_cast<double>(engine.collisions()) / N,
                                    cell_fields});
        }
        io.sink(row);
    };

    if (ck && !ck->resume.empty()) {
        try {
            ByteReader in(ck->resume);
            if (const std::string k = in.str(); k != kernel)
                throw ResumeError("saved by the loop \"" + k + "\", this run's is \"" + kernel + "\"");
            engine.restore(in);
            next = static_cast<std::size_t>(in.u64());
            t_prev = in.f64();
            c_prev = in.get<std::int64_t>();
            const std::size_t pairs = tally.per_type.size();
            tally.load(in);
            if (tally.per_type.size() != pairs)
                throw ResumeError("the state has another number of species pairs");
            next_save = in.f64();
            if (domain.has_walls())
                load(in, walls_prev);
            if (in.remaining() != 0 || next > outputs.size())
                throw ResumeError("the state does not fit the case");
        } catch (const ResumeError&) {
            throw;
        } catch (const std::exception& e) {
            throw ResumeError(e.what());
        }
        resumed_at = engine.collisions();
    } else {
        emit(false, 0); // t = 0
    }

    const auto coll_per_particle = [&] { return 2.0 * static_cast<double>(engine.collisions()) / N; };
    // Where the run is on its clock (RunSpec::clock): collisions per particle, or time.
    const bool time_clock = spec.clock == Clock::time;
    const auto clock = [&] { return time_clock ? engine.time() : coll_per_particle(); };
    while (next < outputs.size()) {
        const double nu = nu_ahead ? *nu_ahead : engine.collision_frequency();
        nu_ahead.reset();
        if (!(nu > 0) || !std::isfinite(nu))
            throw std::runtime_error("the gas has stopped colliding (collision frequency " + std::to_string(nu) +
                                     ") before the end of the run");
        if (time_clock) {
            // The step that would reach the output ends at its time, exactly.
            const double dt = domain.time_step / nu;
            if (engine.time() + dt >= outputs[next] * (1 - 1e-9))
                engine.step_to(outputs[next], tally);
            else
                engine.step(dt, tally);
        } else {
            const double to_row = outputs[next] - coll_per_particle();
            const double h = std::min(domain.time_step, std::max(to_row, 0.01 * domain.time_step));
            engine.step(h / nu, tally);
        }
        bool repeat = false;
        while (next < outputs.size() && clock() >= outputs[next] * (1 - 1e-12)) {
            emit(repeat, next + 1);
            repeat = true;
            ++next;
        }
        if (io.progress)
            io.progress(std::min(clock(), end), end, static_cast<double>(engine.collisions()));
        if (ck && ck->save) {
            const bool stop = ck->stop && ck->stop();
            if (stop || (every > 0 && coll_per_particle() >= next_save && next < outputs.size())) {
                if (every > 0)
                    next_save = (std::floor(coll_per_particle() / every) + 1) * every;
                ck->save(state());
                if (stop)
                    break;
            }
        }
    }
    if (io.summary) {
        ReplicaSummary& s = *io.summary;
        s.kernel = kernel;
        s.bytes_per_particle = engine.bytes_per_particle();
        s.memory_per_particle = s.bytes_per_particle;
        s.collisions = engine.collisions();
        s.resumed_at = resumed_at;
        s.steps = engine.steps();
        s.beta_clamped = tally.clamped;
        s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    }
    if (next < outputs.size())
        return ReplicaEnd::stopped;
    if (spec.final_state) {
        GrainState g = engine.grain_state();
        g.coll_per_particle = coll_per_particle();
        spec.final_state(replica, g);
    }
    return ReplicaEnd::finished;
}

template <class Policy>
ReplicaEnd run_box(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks, std::vector<Policy> policies,
                   int replica, const ReplicaIo& io) {
    // No wall code in the flight of a periodic box without gravity.
    if (spec.domain->general_flight())
        return run_box_flight<Policy, true>(spec, blocks, std::move(policies), replica, io);
    return run_box_flight<Policy, false>(spec, blocks, std::move(policies), replica, io);
}


// The policies run_box is compiled for (box_flight_*.cpp).
#define ROUGHGAS_BOX_FLIGHT(Policy) \
    template ReplicaEnd run_box<Policy>(const RunSpec&, const std::vector<SpeciesBlock>&, std::vector<Policy>, int, \
                                        const ReplicaIo&)
#define ROUGHGAS_EXTERN_BOX_FLIGHT(Policy) extern ROUGHGAS_BOX_FLIGHT(Policy)
ROUGHGAS_EXTERN_BOX_FLIGHT(SmoothConstant);
ROUGHGAS_EXTERN_BOX_FLIGHT(RoughConstant);
ROUGHGAS_EXTERN_BOX_FLIGHT(Brilliantov);
ROUGHGAS_EXTERN_BOX_FLIGHT(AnySmoothPolicy);
ROUGHGAS_EXTERN_BOX_FLIGHT(AnyRoughPolicy);

} // namespace roughgas::detail
