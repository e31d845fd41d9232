#pragma once
// The body of one replica's run for one compiled kernel (drive_kernel, declared in drive.hpp):
// included only by the drive_*.cpp files, each of which instantiates it for a few policies, so
// that the engine instantiations (the longest part of the build) compile in parallel, one
// translation unit per family, instead of all in run.cpp.
#include "drive.hpp"
#include "gas_row.hpp"

#include "roughgas/core/bytes.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/dsmc/shear.hpp"
#include "roughgas/dsmc/thermostat.hpp"
#include "roughgas/observables/moments.hpp"
#include "roughgas/observables/pressure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace roughgas::detail {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();


// The Maxwellian collision frequency per grain at the temperatures of `m` (as the engine's step
// length, dsmc/species.hpp).
inline double collision_frequency(const std::vector<PairType>& types, const std::vector<SpeciesBlock>& blocks,
                           const Moments& m, double volume) {
    double N = 0;
    std::vector<double> T_over_m;
    for (std::size_t s = 0; s < blocks.size(); ++s) {
        N += static_cast<double>(blocks[s].count);
        T_over_m.push_back((blocks.size() > 1 ? m.species[s].T_tr : m.all.T_tr) / blocks[s].grain.mass);
    }
    return maxwellian_collision_frequency(types, T_over_m, volume, N);
}

// Between two Strang steps of a shear interval (dsmc/shear.hpp strang_steps): the stream the step
// just done still owes, its length, and what the next step's length is predicted from.
struct StrangState {
    double pending = 0, h_prev = 0, nu_ref = 0;
    PressureTensor P;
};

// drive()'s state besides the engine's, in a checkpoint: where the replica is in its output schedule
// (the next pause; between two Strang steps, the shear interval's state) and what its next row's
// rates are measured from.
struct DriveState {
    std::string kernel; // the specialised loop that saved it: a state of another loop is refused
    std::uint64_t next_pause = 0;
    std::optional<StrangState> strang;
    double t_prev = 0;
    std::int64_t c_prev = 0;
    Tally tally;

    void save(ByteWriter& w) const {
        w.str(kernel);
        w.u64(next_pause);
        w.put(strang.has_value());
        const StrangState s = strang.value_or(StrangState{});
        for (double x : {s.pending, s.h_prev, s.nu_ref, s.P.xx, s.P.yy, s.P.zz, s.P.xy, s.P.xz, s.P.yz})
            w.f64(x);
        w.f64(t_prev);
        w.put(c_prev);
        tally.save(w);
    }
    void load(ByteReader& r) {
        kernel = r.str();
        next_pause = r.u64();
        const bool between = r.get<bool>();
        StrangState s;
        for (double* x :
             {&s.pending, &s.h_prev, &s.nu_ref, &s.P.xx, &s.P.yy, &s.P.zz, &s.P.xy, &s.P.xz, &s.P.yz})
            *x = r.f64();
        strang = between ? std::optional(s) : std::nullopt;
        t_prev = r.f64();
        c_prev = r.get<std::int64_t>();
        tally.load(r);
    }
};

template <class Engine>
void fill_summary(ReplicaSummary* summary, const Engine& engine, const std::string& kernel,
                  std::int64_t clamped, std::int64_t resumed_at,
                  std::chrono::steady_clock::time_point wall0) {
    if (!summary)
        return;
    const EngineCounters& k = engine.counters();
    summary->kernel = kernel;
    summary->groups = static_cast<int>(engine.groups());
    summary->bytes_per_particle = std::remove_cvref_t<decltype(engine.store())>::bytes_per_particle;
    summary->memory_per_particle = engine.bytes_per_particle();
    summary->collisions = k.collisions;
    summary->resumed_at = resumed_at;
    summary->candidates = k.candidates;
    summary->steps = k.steps;
    summary->bound_raises = k.bound_raises;
    summary->promotions = k.promotions;
    summary->beta_clamped = clamped;
    summary->max_mean_drift = k.max_mean_drift;
    summary->recentrings = k.recentrings;
    summary->overshoots = k.overshoots;
    summary->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
}

// Thrown inside drive() once a stop was asked for and the state saved: unwinds the loops.
struct Stopped {};

template <class Policy, bool Mixture, CollisionKernel Kernel>
ReplicaEnd drive(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks, std::vector<Policy> policies,
                 int replica, const ReplicaIo& io) {
    using Store = StoreFor<Policy>;
    const RowSink& sink = io.sink;
    const ProgressSink& progress = io.progress;
    const HistogramSink& histograms = io.histograms;
    const ReplicaCheckpoints* const ckpt = io.checkpoints;
    const auto wall0 = std::chrono::steady_clock::now();
    const std::size_t N = static_cast<std::size_t>(spec.particles);
    const auto rep = static_cast<std::uint64_t>(replica);
    Store store(N);
    // A saved state (RunSpec::initial_state) starts a new run; a resumed one takes its grains from
    // the checkpoint below, so it does not read the state again.
    if (spec.initial_state && !(ckpt && !ckpt->resume.empty()))
        init_from_state(store, blocks, spec.initial_state(replica));
    else
        init_maxwellian(store, blocks, spec.seed, rep);
    Engine<Store, Policy, Mixture, Kernel> engine(
        blocks, std::move(policies), std::move(store),
        EngineOptions{spec.density, spec.step, spec.seed, rep, spec.speed_classes, effective_groups(spec),
                      std::max(1, spec.threads), pair_correlations(spec)});
    if (spec.thermostat)
        engine.set_thermostat(*spec.thermostat);
    if (spec.enskog && spec.shear) // collisions a diameter apart across the shear flow
        engine.set_enskog_shear(spec.shear->rate);

    const std::size_t S = blocks.size();
    const std::vector<SpeciesSlice> slices = species_slices(blocks);
    const auto& types = engine.pair_types();
    const bool clamp_column = has_brilliantov(spec);
    const std::size_t columns = dsmc_columns(spec).size();

    Tally tally;
    tally.assign(types.size());
    double t_prev = 0;
    std::int64_t c_prev = 0;
    std::vector<double> row;
    row.reserve(columns);

    std::vector<UsfSpecies> usf_species;
    for (const SpeciesBlock& b : blocks)
        usf_species.push_back(
            {static_cast<double>(b.count) / static_cast<double>(N), b.grain.mass, b.grain.radius});
    std::vector<Vec3> spin; // shear: omega - Omega, so that T_rot is about the mean spin
    // On the replica's threads (the engine's): a row streams the whole store from memory twice,
    // which takes as long as the collisions between two rows where rows are dense.
    WorkerTeam& team = engine.team();
    const auto moments_now = [&](Vec3& Omega) {
        if (!spec.shear)
            return compute_moments(engine.store().velocities(), engine.store().angular_velocities(), slices, team);
        const Vec3Column w = engine.store().angular_velocities();
        Omega = mean_spin(w, slices);
        spin.resize(N);
        for (std::size_t i = 0; i < N; ++i)
            spin[i] = w[i] - Omega;
        return compute_moments(engine.store().velocities(), column_of(spin.data(), 0), slices, team);
    };

    const auto emit = [&] {
        Vec3 Omega{};
        Moments m = moments_now(Omega);
        if (spec.thermostat) // the moments at the row's time, not at the kicks' (dsmc/thermostat.hpp)
            m = moments_at_drive_time(m, slices, *spec.thermostat, engine.time(), engine.kicked_until());
        const double t = engine.time();
        const std::int64_t c = engine.collisions();
        const double dt = t - t_prev;
        const bool first = c == 0 && t == 0;
        const double inv_dt = !first && dt > 0 ? 1.0 / dt : nan;
        row.clear();
        append_row_head(row, t, c, c_prev, static_cast<double>(N), m, inv_dt, tally, engine.volume());
        if (spec.enskog)
            append_pressure_columns(row, m, slices, types, tally, engine.volume(), inv_dt);
        if (spec.shear) {
            const PressureTensor P =
                pressure_tensor(engine.store().velocities(), slices, engine.volume(), m.mean_velocity);
            append_shear_columns(row, P, Omega, spec.shear->rate, usf_species, spec.density, m.all.T_tr,
                                 spec.enskog ? std::optional(collisional_pressure_tensor(tally, engine.volume(), inv_dt))
                                             : std::nullopt);
        }
        append_row_tail(row, m, tally, types, blocks, inv_dt, clamp_column);
        if (row.size() != columns)
            throw std::logic_error("run_replica: row and columns differ");
        sink(row);
        t_prev = t;
        c_prev = c;
        tally.next_interval();
    };

    const HistogramGrid grid{spec.histogram_bins, spec.histogram_max};
    const auto emit_histograms = [&] {
        const auto& store = engine.store();
        Vec3 Omega{};
        const Moments m = moments_now(Omega); // shear: omega about the mean spin, as the rows
        const Vec3Column w = spec.shear ? column_of(spin.data(), 0) : store.angular_velocities();
        HistogramSet h;
        h.t = engine.time();
        h.coll_per_particle = 2.0 * static_cast<double>(engine.collisions()) / static_cast<double>(N);
        h.species = compute_histograms(store.velocities(), w, slices, m, grid);
        histograms(h);
    };

    std::vector<double> outputs = spec.output_times;
    if (outputs.empty())
        outputs.push_back(spec.end);
    const double end = outputs.back();
    // The pauses: output rows and histograms, in order of their collision counts, or with the time
    // clock of their times (a pause keeps the engine's pending candidate, so the trajectory does not
    // depend on where it pauses).
    const bool time_clock = spec.clock == Clock::time;
    struct Pause {
        std::int64_t target; // the collision clock's count
        bool row, histogram;
        double time = 0;     // the time clock's time (target unused)
    };
    const auto target_of = [&](double x) {
        return static_cast<std::int64_t>(std::llround(x * static_cast<double>(N) / 2.0));
    };
    std::vector<Pause> pauses;
    for (double out : outputs)
        pauses.push_back(time_clock ? Pause{0, true, false, out} : Pause{target_of(out), true, false});
    if (histograms)
        for (double h : spec.histogram_times)
            pauses.push_back(time_clock ? Pause{0, false, true, h} : Pause{target_of(h), false, true});
    if (time_clock)
        std::stable_sort(pauses.begin(), pauses.end(), [](const Pause& a, const Pause& b) { return a.time < b.time; });
    else
        std::stable_sort(pauses.begin(), pauses.end(),
                         [](const Pause& a, const Pause& b) { return a.target < b.target; });
    const std::int64_t chunk = std::max<std::int64_t>(std::int64_t{1} << 16, spec.particles / 2);

    // Checkpoints (run.hpp ReplicaCheckpoints): a DriveState, then the engine's state.
    const std::string kernel = std::string(Store::name) + ", " + std::string(Policy::name) + ", " +
                               (Mixture ? std::to_string(S) + " species" : "one species") +
                               (Kernel == CollisionKernel::maxwell ? ", Maxwell kernel" : "");
    std::size_t first_pause = 0;
    std::optional<StrangState> strang; // resumed between two Strang steps of a shear interval
    if (ckpt && !ckpt->resume.empty()) {
        try {
            ByteReader r(ckpt->resume);
            DriveState d;
            d.load(r);
            if (d.kernel != kernel)
                throw ResumeError("saved by the loop \"" + d.kernel + "\", this run's is \"" + kernel + "\"");
            if (d.next_pause > pauses.size() || (d.strang && (!spec.shear || d.next_pause == pauses.size())))
                throw ResumeError("the state's place in the output schedule does not fit the case");
            if (d.tally.per_type.size() != tally.per_type.size())
                throw ResumeError("the state has another number of species pairs");
            first_pause = d.next_pause;
            strang = d.strang;
            t_prev = d.t_prev;
            c_prev = d.c_prev;
            tally = std::move(d.tally);
            engine.load_state(r);
            if (r.remaining() != 0)
                throw ResumeError("trailing bytes after the engine state");
        } catch (const ResumeError&) {
            throw;
        } catch (const std::exception& e) { // ByteReader, Engine::load_state
            throw ResumeError(e.what());
        }
    } else {
        emit();
    }
    const std::int64_t resumed_at = engine.collisions();
    // The k-th checkpoint is due at target_of(k every); the next one is the first after the
    // current count, so a resumed run keeps the schedule.
    std::int64_t next_checkpoint = std::numeric_limits<std::int64_t>::max();
    const auto schedule_next_checkpoint = [&] {
        if (!ckpt || !(ckpt->every > 0))
            return;
        double k =
            std::floor(2.0 * static_cast<double>(engine.collisions()) / static_cast<double>(N) / ckpt->every);
        while (target_of(k * ckpt->every) <= engine.collisions())
            k += 1;
        next_checkpoint = target_of(k * ckpt->every);
    };
    schedule_next_checkpoint();
    // A point where the run may stop unchanged: pause p next; `between`, when it lies between two
    // Strang steps of a shear interval.
    const auto boundary = [&](std::size_t p, const std::optional<StrangState>& between) {
        if (!ckpt)
            return;
        const bool stop = ckpt->stop && ckpt->stop();
        if (!stop && engine.collisions() < next_checkpoint)
            return;
        ByteWriter w;
        DriveState{kernel, p, between, t_prev, c_prev, tally}.save(w);
        engine.save_state(w);
        ckpt->save(w.take());
        if (stop)
            throw Stopped{};
        schedule_next_checkpoint();
    };
    const auto report = [&] {
        if (progress) {
            const auto c = static_cast<double>(engine.collisions());
            progress(time_clock ? std::min(engine.time(), end) : 2.0 * c / static_cast<double>(N), end, c);
        }
    };
    report();

    // Uniform shear flow: Strang steps (dsmc/shear.hpp) of h = time_step mean free times each, the
    // mean free time of the state each step's collisions start from (strang_step_length predicts it
    // through the stream before them), so that the steps follow the temperature through a transient
    // (heated by 10^10 in one stream, or cooled by 10^-20 while a tiny shear rate catches up:
    // tests/stress). A pause (row or histogram) comes at the end of the first step at or after its
    // collision count, a step shortened to end a few collisions after it. Checkpoints come between
    // two steps (after a step's collisions, before the merged stream: `resume` goes on from there).
    // The time clock: the steps as above, the last one before the pause shortened to end at its time
    // t_pause exactly (the collisions stop at t_pause, the streams cover the same time).
    const auto advance_shear = [&](std::int64_t target, std::int64_t cap, std::size_t p,
                                   const std::optional<StrangState>& resume, double t_pause) {
        const double a = spec.shear->rate;
        // The state the next step is predicted from: its pressure tensor (times the volume) and
        // collision frequency. At an interval's start, the current state; later, the state after the
        // last stream (its sums from the stream's pass, its frequency from the engine's step start).
        PressureTensor P;
        double nu_ref = 0, h_prev = 0;
        if (resume) {
            P = resume->P;
            nu_ref = resume->nu_ref;
            h_prev = resume->h_prev;
        } else {
            Vec3 Omega{};
            P = pressure_tensor(engine.store().velocities(), slices, 1.0, Vec3{});
            nu_ref = collision_frequency(types, blocks, moments_now(Omega), engine.volume());
        }
        const auto stream = [&](double s) {
            P = stream_shear(engine.store(), a, s, slices);
            engine.restart_step(); // the velocities changed: refresh the engine's bounds (exact)
        };
        const auto collide = [&](double h) {
            const double t0 = engine.time();
            if (time_clock) { // the step that reaches the pause ends at t_pause, not at t0 + h
                const double t_stop = t0 + h >= t_pause * (1 - 1e-14) ? t_pause : t0 + h;
                engine.run(std::numeric_limits<std::int64_t>::max(), t_stop, tally);
                nu_ref = engine.collision_frequency();
                return engine.time() - t0;
            }
            const StopReason stop = engine.run(cap, t0 + h, tally);
            nu_ref = engine.collision_frequency(); // its step start: the state after the stream, P's
            return stop == StopReason::collisions ? engine.time() - t0 : h;
        };
        // The time clock: no step past the pause's time.
        const auto clip = [&](double h) { return time_clock ? std::min(h, t_pause - engine.time()) : h; };
        const auto step = [&](double& pending) {
            // A step expects tau x N/2 collisions; the last one before the pause expects only the
            // remaining r and a margin of 1 + 3 sqrt(r) (it falls short with probability ~1e-3, and
            // then one more short step follows), so that one step never spans two output rows.
            const auto r = static_cast<double>(target - engine.collisions());
            const double tau = time_clock ? spec.shear->time_step
                                          : std::min(spec.shear->time_step,
                                                     2.0 * (r + 1.0 + 3.0 * std::sqrt(r)) / static_cast<double>(N));
            const double h = clip(strang_step_length(tau, nu_ref, P, a, h_prev));
            // P is the state before the last step's collisions. In a transient where the stream
            // ahead would more than double T or halve it (at a/nu = 1e6 it heats by orders of
            // magnitude), those collisions matter: they move energy from P_xx into P_yy, which the
            // stream amplifies by (a s)^2, and a step predicted from the old P held up to 1.6
            // collisions per grain instead of tau/2 (tests/stress, 6 of 32 seeds). Then the owed
            // half-stream is done first and the step predicted from the exact P after it (nu
            // scaled by sqrt(T)). Not in a steady state: a step of one mean free time heats by
            // ~30 % there, and one rule for every step length keeps the splitting error c h^2 with
            // one c (tests/validation/usf_test.cpp).
            const double heating = streamed_temperature_ratio(P, a, 0.5 * (h_prev + h));
            if (pending != 0 && (heating > 2.0 || heating < 0.5)) {
                const double trace = P.trace();
                stream(pending);
                pending = 0;
                nu_ref *= std::sqrt(P.trace() / trace);
                h_prev = clip(strang_step_length(tau, nu_ref, P, a, 0.0));
            } else {
                h_prev = h;
            }
            return h_prev;
        };
        strang_steps(
            step, stream, collide,
            [&](double pending) {
                report();
                if (time_clock ? engine.time() >= t_pause : engine.collisions() >= target)
                    return true;
                boundary(p, StrangState{pending, h_prev, nu_ref, P});
                return false;
            },
            resume ? std::optional(resume->pending) : std::nullopt);
    };
    try {
        for (std::size_t p = first_pause; p < pauses.size(); ++p) {
            const Pause& pause = pauses[p];
            const std::int64_t target = pause.target;
            if (!strang) // resumed between two Strang steps: that interval goes on first
                boundary(p, std::nullopt);
            if (time_clock) {
                if (spec.shear && (strang || engine.time() < pause.time))
                    advance_shear(0, 0, p, strang, pause.time);
                strang.reset();
                while (engine.time() < pause.time) {
                    // About a chunk, by collisions or time, exactly to the pause's time.
                    engine.run_about_until(chunk, pause.time, tally);
                    report();
                    boundary(p, std::nullopt);
                }
            } else {
                if (spec.shear && (strang || engine.collisions() < target)) {
                    // A step reaching the next pause's count is cut there (rare: the last step aims at
                    // this target), so that no two pauses share one step (an empty interval between
                    // two rows).
                    std::int64_t cap = std::numeric_limits<std::int64_t>::max();
                    for (std::size_t q = p + 1;
                         q < pauses.size() && cap == std::numeric_limits<std::int64_t>::max(); ++q)
                        if (pauses[q].target > target)
                            cap = pauses[q].target - 1;
                    advance_shear(target, cap, p, strang, 0.0);
                    strang.reset();
                }
                while (engine.collisions() < target) {
                    // About a chunk, by time (Engine::run_about: no halving phases), exactly to the row.
                    if (engine.run_about(chunk, target, tally) == StopReason::stalled) {
                        throw std::runtime_error(
                            "run_replica: no collision can happen: every grain is at rest in the "
                            "centre-of-mass frame (translational temperature 0)");
                    }
                    report();
                    boundary(p, std::nullopt);
                }
            }
            if (pause.row)
                emit();
            if (pause.histogram)
                emit_histograms();
        }
    } catch (const Stopped&) {
        fill_summary(io.summary, engine, kernel, tally.clamped, resumed_at, wall0);
        return ReplicaEnd::stopped;
    }
    fill_summary(io.summary, engine, kernel, tally.clamped, resumed_at, wall0);
    if (spec.final_state) {
        GrainState g;
        g.t = engine.time();
        g.coll_per_particle = 2.0 * static_cast<double>(engine.collisions()) / static_cast<double>(N);
        g.v.resize(N);
        g.w.resize(N);
        for (std::size_t i = 0; i < N; ++i) {
            g.v[i] = engine.store().v(i);
            g.w[i] = engine.store().w(i);
        }
        spec.final_state(replica, g);
    }
    return ReplicaEnd::finished;
}

// The kernel is a compile-time choice too: one switch per run.
template <class Policy, bool Mixture>
ReplicaEnd drive_kernel(const RunSpec& spec, const std::vector<SpeciesBlock>& blocks,
                        std::vector<Policy> policies, int replica, const ReplicaIo& io) {
    if constexpr (is_constant_policy<Policy>) {
        if (spec.kernel == CollisionKernel::maxwell)
            return drive<Policy, Mixture, CollisionKernel::maxwell>(spec, blocks, std::move(policies),
                                                                    replica, io);
    } else if (spec.kernel == CollisionKernel::maxwell) {
        throw std::logic_error("run_replica: the Maxwell kernel with a non-constant policy"); // validate()
    }
    return drive<Policy, Mixture, CollisionKernel::hard_sphere>(spec, blocks, std::move(policies), replica,
                                                                io);
}

} // namespace roughgas::detail
