#pragma once
// The DSMC collision engine of the homogeneous gas: the hard-sphere kernel of docs/model.md §4
// sampled exactly, with the collision rule of docs/model.md §3, for a store layout `Store`, one
// restitution policy type `Policy` and, at compile time, one species or a mixture.
//
// Kernel. In a gas of number density n simulated by N particles (volume V = N/n), each unordered
// pair (i, j) of species (a, b) collides at the rate pi sigma_ab^2 |v_i - v_j| / V, the direction n
// having density proportional to |g^ . n| on the approaching hemisphere (docs/model.md §4). In the
// Enskog equation of a uniform gas (EngineOptions::pair_correlation) every rate is chi_ab times that:
// the candidate rates below carry the factor (PairType::rate_section), nothing else changes.
//
// Exact majorant (sequential thinning). The particles of a species are split into blocks ("speed
// classes") with a bound b on |v| of every grain in the block. For a pair of blocks (x, y),
// g_max,xy = b_x + b_y is a true bound on |v_i - v_j| since |v_i - v_j| <= |v_i| + |v_j|; candidate
// pairs of the block pair form a Poisson process of rate Lambda_xy = P_xy pi sigma_ab^2 g_max,xy / V
// (P_xy distinct pairs), a candidate is a uniformly random pair of the two blocks, accepted with
// probability |g_c|/g_max,xy. The superposition over block pairs is one Poisson clock of rate
// Lambda = sum Lambda_xy whose events pick a block pair with probability Lambda_xy/Lambda. Time
// advances by exponential increments of rate Lambda. When a collision makes a grain faster than
// its block's bound, the bound is raised, or the grain moves to a faster block (trading places with
// a grain of that block that has become slow enough for this one, else moving the boundary between
// the blocks; settle()), whose bound is raised if needed; the rates change at once and the next
// increment is drawn at the new rate (memoryless, so exact: the majorant bounds the true rate at
// every instant and is never exceeded).
// A particle may collide any number of times per step.
//   speed_classes = 1 is the plain scheme g_max,ab = vmax_a + vmax_b per species pair. With K
// classes per species, cut at multiples of the thermal speed, the mean bound per grain falls from
// vmax (5.9 thermal speeds at N = 1e6) towards <|v|> (1.6): the acceptance rises from 0.20 (K = 1)
// to 0.39, 0.46, 0.51 (K = 2, 3, 4), and each rejected candidate costs two random memory accesses;
// but grains cross the cuts in collisions (0.16, 0.30, 0.50 moves per collision for K = 2, 3, 4).
// Measured (tests/bench/dsmc_bench.cpp, BM_Classes; interleaved runs on one core): K = 2 is
// 7% (N = 1e5) to 14% (N = 1e6) faster than K = 1, K = 3 about as fast as K = 2, K = 4 slower: K = 2
// is the default.
//
// Steps. A step lasts `step` mean free times (at the step's start, Maxwellian estimate), and only
// refreshes the bounds: the grains are re-sorted into classes by their current speed (a counting
// sort of their indices, see "Particle order"), each bound is the exact maximum of its class, and the centre-of-mass velocity left by round-off is removed once
// it has grown to 1e-10 of the thermal speed (a Galilean shift, exact for a homogeneous gas). The
// candidate that would fall after the step's end is discarded (memoryless again), so the
// statistics do not depend on the step length (tests/dsmc/engine_test.cpp). Each step draws from its
// own streams (seed, collisions, replica, step, unit), one per group (unit = group index).
//
// Groups (both cores for one run). With `groups` = G > 1 each step starts with a random
// partition of the grains into G groups: grain i goes to group floor(G h_i / 2^64), h_i the i-th
// output of a splitmix64 sequence keyed by (seed, partition, replica, step): independent of the
// state and of everything else, so any two distinct grains share a group with probability 1/G
// exactly. During the step only pairs inside a group can collide, each at G times its rate
// (the volume of a group is V/G): the expected rate of every pair, averaged over the partition, is
// its exact rate pi sigma^2 |g|/V, the direction law is untouched, and the groups are independent
// DSMC gases for one step (a step of one mean free time: about one collision per grain; the
// correlations between grains that a group of n grains builds up within a step are those of an
// n-particle DSMC, O(1/n), and the next partition mixes them out). Each group has its own blocks,
// candidate clock, rings and stream, and its own contiguous range of positions (the positions are
// sorted by (group, class) within their species), so groups run on different OpenMP threads
// without locks. Results depend on G, never on the thread count: group g always uses stream
// unit g, the sort is serial, observers are forked per group and merged in group order.
//   Cost: measured on one core (N = 1e6, rough, interleaved), the grouped loop is as fast as the
// ungrouped one per collision; a partition that moved the 64-byte grains cost ~40 ns per grain
// and step (25% of a step of one mean free time), the counting sort of 4-byte indices a few ns.
//   Stopping in a grouped run. A time stop runs every group to t_stop. A collision target is met
// exactly in global time order: phases run all groups in parallel to a common time chosen to give
// about half the remaining collisions (from the current candidate rate and acceptance), until at
// most `tail_collisions` remain; those are processed one candidate at a time, always in the group
// whose next candidate comes first (the superposition of the groups' clocks). A phase can only
// overshoot if the collision rate doubles within it (counted in `overshoots`; seen only where the
// translational temperature grows some 70-fold within the first collisions per grain: T_rot =
// 400 T_tr, beta = 1, a first target of one collision per grain; tests/dsmc/groups_test.cpp
// checks a tenfold growth). Stretches that need no exact count (run_replica's pauses between
// rows) stop at a time instead (run_about): one phase per step.
//
// Thermostat (set_thermostat; dsmc/thermostat.hpp). A driven gas gets its kicks in the step start's
// first pass over the grains, before they are sorted into classes (so the bounds hold for the kicked
// velocities): no pass of its own. The kicks of the step starting at t0 cover the time from where the
// previous ones ended to the middle of this step, t0 + L/2, L the step length predicted from the last
// step start's collision frequency: the kicks then run half a step ahead at the step's start and half a
// step behind at its end, so that the state averaged over a step lags the drive by O(L^2), not O(L)
// (as in Strang splitting). kicked_until() is that time. Each step's kicks draw from their own streams
// (seed, thermostat, replica, step, species and chunk): the chunks are fixed by the species' size, so
// the kicks do not depend on the threads.
//
// Sheared Enskog gas (set_enskog_shear; docs/model.md, "Uniform shear flow"). In uniform shear flow
// u = a y x^ the partner j of a collision sits at r_i - sigma n, where the flow is a sigma n_y slower
// along x: the relative velocity entering the collision is g_e = g + s n_y x^, s = a sigma_ab, g the
// peculiar one (Montanero, Garzo, Santos & Brey 1999), and the pair collides at the rate density
// chi sigma^2 max(0, -g_e.n) = chi sigma^2 max(0, -g.n - s n_x n_y) over the whole sphere of n. With
// h(n) = max(0, -g.n) and s |n_x n_y| <= s/2 it is sampled by composition: a block pair's candidates
// come at the rate pairs chi pi sigma^2 (g_max + 2 s) (the integral of h + s/2 over the sphere is
// pi (|g| + 2 s)), a candidate is taken with probability (|g| + 2 s)/(g_max + 2 s), its n drawn from
// h (the hard-sphere law) with probability |g|/(|g| + 2 s) and uniformly on the sphere otherwise, and
// the collision happens with probability max(0, -g_e.n)/(h(n) + s/2). The collision rule then acts
// on g_e (the partner's velocity shifted by -s n_y x^ and back, so momentum is conserved); the
// peculiar kinetic energy changes by the rule's change plus s x^.J n_y-terms (the work of the
// collisional transfer, J the impulse on i), and an observer with transfer_of(sigma n, J) sees each
// collision's contribution to the collisional transfer of momentum.
//
// Pauses. run() stops after a given collision count or before a given time, keeping the pending
// candidate: stopping and resuming never changes the trajectory, so the output schedule does not
// influence the results.
//
// Latency. Candidate pairs do not depend on the state, so they are drawn `ring_size` candidates
// ahead (per block pair) and their grains prefetched: the random loads of several candidates are
// in flight at once. What is drawn ahead is one random word per candidate; its two 32-bit halves
// become the two positions only when the candidate is taken, from the blocks' ranges as they are
// then (Lemire's multiply-shift with its rejection, exact), so a candidate is uniform over its
// blocks even if grains have moved between them since it was drawn. The positions the word gives
// over the ranges at the draw are kept beside it, for the prefetches only.
//
// Particle order. The grains never move in the store: blocks are ranges of positions in an index
// array perm_ (4 bytes per grain; the grain at position p is perm_[p]), re-sorted at each step
// start and permuted by promotions. Grain i of the store stays grain i for observers and for
// callers that change velocities between run() calls (uniform shear flow).
#include "roughgas/collision/rule.hpp"
#include "roughgas/collision/sampling.hpp"
#include "roughgas/core/bytes.hpp"
#include "roughgas/core/huge_page_buffer.hpp"
#include "roughgas/core/own_lines.hpp"
#include "roughgas/core/prefetch.hpp"
#include "roughgas/core/rng.hpp"
#include "roughgas/core/worker_team.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/dsmc/thermostat.hpp"

#include <boost/random/exponential_distribution.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace roughgas {

struct EngineOptions {
    double density = 1; // number density n of the gas
    double step = 1.0;  // step length in mean free times (no influence on the statistics)
    std::uint64_t seed = 1;
    std::uint64_t replica = 0;
    int speed_classes = 2; // blocks per species, 1 .. 6 (no influence on the statistics)
    int groups = 1;        // per-step random partition into groups (1: none); results depend on it
    int threads = 1;       // threads over the groups and chunks (WorkerTeam): no influence on the results
    // The pair correlation at contact chi of each species pair (pair_index order; empty: 1): the
    // Enskog equation of a uniform gas collides every pair chi times as often as the Boltzmann
    // equation, with the same collision rule (dsmc/pair_correlation.hpp).
    std::vector<double> pair_correlation{};
};

enum class StopReason { collisions, time, stalled };

// Counts of what the engine did.
struct EngineCounters {
    std::int64_t collisions = 0;
    std::int64_t candidates = 0;
    std::int64_t steps = 0;
    std::int64_t bound_raises = 0; // collisions after which a bound grew or a grain changed block
    std::int64_t promotions = 0;   // grains moved to a faster block within a step
    std::int64_t range_moves = 0;  // promotions that moved a block boundary (no demotable grain at hand)
    double max_mean_drift = 0; // largest centre-of-mass speed |u| found at a step start, over the rms speed
    std::int64_t recentrings = 0; // steps that removed u (|u| above recentre_threshold of the rms speed)
    std::int64_t phases = 0;      // grouped runs: parallel phases
    std::int64_t overshoots = 0;  // grouped runs: phases that ended past the collision target
};

// An observer that ignores every collision.
struct IgnoreCollisions {
    void operator()(const CollisionRecord&, std::size_t /*species pair*/) const {}
};

// An observer the grouped engine can give each group (and thread) a copy of: fork() returns an
// empty observer of the same kind, merge() adds another's tallies. Merged in group order, so the
// result does not depend on the thread count. Other observers are called from one thread at a time
// (a grouped run then uses one thread); stateless ones (empty classes) are shared.
template <class O>
concept ForkableObserver = requires(const O& c, O& o) {
    { c.fork() } -> std::convertible_to<O>;
    o.merge(c);
};

// Allocates whole cache lines, aligned: the small arrays of one group (blocks, rings, rates), which
// its thread writes at every candidate, never share a line with another group's (no false sharing
// between threads).
template <class T> struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::size_t line = 64;
    CacheLineAllocator() = default;
    template <class U> CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        const std::size_t bytes = (n * sizeof(T) + line - 1) / line * line;
        return static_cast<T*>(::operator new(bytes, std::align_val_t{line}));
    }
    void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t{line}); }
    template <class U> bool operator==(const CacheLineAllocator<U>&) const noexcept { return true; }
};
template <class T> using LineVector = std::vector<T, CacheLineAllocator<T>>;

// Class boundaries in units of the thermal speed sqrt(T/m) (K - 1 cuts for K classes): chosen to
// minimise the mean bound per grain of a Maxwellian at N ~ 1e5 .. 1e6.
inline const std::vector<double>& speed_class_cuts(int classes) {
    static const std::vector<double> cuts[] = {
        {}, {2.3}, {1.9, 3.0}, {1.5, 2.3, 3.2}, {1.4, 2.0, 2.6, 3.4}, {1.3, 1.8, 2.3, 2.8, 3.5}};
    if (classes < 1 || classes > 6)
        throw std::invalid_argument("speed_classes must be in 1 .. 6");
    return cuts[classes - 1];
}

// Kernel = maxwell (run_spec.hpp): the candidate rate of a block pair is its exact collision rate
// (pairs x pi sigma^2 u_ab/V, velocity-independent), every candidate collides, and n is uniform on the
// approaching hemisphere; blocks, groups and steps work as for hard spheres.
template <class Store, class Policy, bool Mixture, CollisionKernel Kernel = CollisionKernel::hard_sphere>
class Engine {
    static_assert(!Policy::needs_rotation || Store::rotation_hot, "a rough policy needs a store with omega");

  public:
    static constexpr unsigned ring_size = 16; // candidates drawn (and prefetched) ahead per block pair
    static constexpr double recentre_threshold = 1e-10;
    // Demotable grains remembered per class (LIFO: the newest are the likeliest still valid).
    static constexpr std::size_t demotable_cap = 4096;
    static constexpr std::uint32_t no_grain = std::numeric_limits<std::uint32_t>::max();
    static constexpr int max_groups = 4096;
    // The step start's two passes run in parallel over chunks of a species' grains, claimed
    // dynamically: at least chunk_grains grains each, at most max_chunks chunks. Small chunks let
    // a thread that joins a pass late still find work (at N = 1e5, 13 chunks instead of two: two
    // threads ran a run of a row per collision per particle 1.85 times faster than one instead of
    // 1.62 times; Zen 5 VM, alternated; docs/performance.md); the cap keeps the per-chunk bucket
    // counts (chunks x groups x classes, reset every step) from growing as N^2. Results depend on
    // the chunks (their sums are combined in chunk order), never on the threads.
    static constexpr std::size_t chunk_grains = std::size_t{1} << 13;
    static constexpr std::size_t max_chunks = 64;
    // Grouped runs with a collision target: collisions processed serially in global time order.
    static constexpr std::int64_t tail_collisions = 256;
    // Block pairs chosen by fixed comparisons instead of a loop: up to small_choice + 1 (choose_block_pair).
    static constexpr std::size_t small_choice = 2;

    // `policies[k]` is the restitution of species pair k (species.hpp); one entry without Mixture.
    Engine(std::vector<SpeciesBlock> species, std::vector<Policy> policies, Store store, EngineOptions opt)
        : species_(std::move(species)), types_(make_pair_types(species_, opt.pair_correlation)), policies_(std::move(policies)),
          store_(std::move(store)), opt_(opt) {
        if (!Mixture && species_.size() != 1)
            throw std::invalid_argument("Engine: one-species engine given a mixture");
        if (policies_.size() != types_.size())
            throw std::invalid_argument("Engine: one policy per species pair");
        std::size_t n = 0;
        for (const auto& s : species_)
            n += s.count;
        if (n != store_.size())
            throw std::invalid_argument("Engine: store size differs from the species counts");
        if (n >= std::numeric_limits<std::uint32_t>::max())
            throw std::invalid_argument("Engine: too many particles");
        if (!(opt_.step > 0))
            throw std::invalid_argument("Engine: step must be > 0");
        if (opt_.groups < 1 || opt_.groups > max_groups)
            throw std::invalid_argument("Engine: groups must be in 1 .. 4096");
        if (opt_.threads < 1)
            throw std::invalid_argument("Engine: threads must be >= 1");
        team_ = std::make_unique<WorkerTeam>(opt_.threads);
        volume_ = static_cast<double>(n) / opt_.density;
        K_ = static_cast<std::size_t>(opt_.speed_classes);
        G_ = static_cast<std::size_t>(opt_.groups);
        prefetch_grains_for_write_ = grains_change_threads();
        cuts_ = speed_class_cuts(opt_.speed_classes);
        const std::size_t S = species_.size();
        groups_.resize(G_);
        for (Group& g : groups_) {
            g.blocks.resize(S * K_);
            for (std::size_t s = 0; s < S; ++s)
                for (std::size_t c = 0; c < K_; ++c) {
                    g.blocks[s * K_ + c].species = static_cast<std::uint32_t>(s);
                    g.blocks[s * K_ + c].has_lower = c > 0;
                }
            for (std::uint32_t x = 0; x < g.blocks.size(); ++x)
                for (std::uint32_t y = x; y < g.blocks.size(); ++y)
                    g.block_pairs.push_back(
                        {x, y, static_cast<std::uint32_t>(pair_index(g.blocks[x].species, g.blocks[y].species, S)),
                         0.0, 0.0, 0.0});
            g.cumulative.assign(g.block_pairs.size(), 0.0);
            g.rings.resize(g.block_pairs.size());
            g.demotable.resize(g.blocks.size());
            for (auto& d : g.demotable)
                d.reserve(G_ > 1 ? demotable_cap / 8 : demotable_cap);
        }
        key_ = HugePageBuffer<std::uint16_t>(K_ * G_ > 1 ? n : 0);
        perm_ = HugePageBuffer<std::uint32_t>(n);
        for (std::size_t i = 0; i < n; ++i)
            perm_[i] = static_cast<std::uint32_t>(i);
        mv2_.assign(S, 0.0);
        T_over_m_.assign(S, 0.0);
        cut2_.assign(cuts_.size(), 0.0);
        count_.assign(K_ * G_, 0);
        max2_.assign(K_ * G_, 0.0);
        thermal_speed_.assign(S, 0.0);
        for (const PairType& t : types_) // u_ab of the Maxwell kernel, from the initial temperatures
            maxwell_speed_.push_back(std::sqrt(8.0 / std::numbers::pi *
                                               (species_[t.a].temperature / species_[t.a].grain.mass +
                                                species_[t.b].temperature / species_[t.b].grain.mass)));
        for (std::size_t s = 0; s < S; ++s) { // the first step's class cuts
            double sum2 = 0;
            for (std::size_t i = species_[s].offset; i < species_[s].offset + species_[s].count; ++i)
                sum2 += norm2(store_.v(i));
            thermal_speed_[s] =
                species_[s].count ? std::sqrt(sum2 / (3.0 * static_cast<double>(species_[s].count))) : 0.0;
        }
    }

    // Advances until `collision_target` collisions in all (returns `collisions` right after that
    // collision, time() being its time) or until the next candidate would come at or after
    // `t_stop` (returns `time`, time() = t_stop if t_stop is finite). `stalled`: no collision can
    // ever happen (every grain at rest in the centre-of-mass frame).
    // `obs(const CollisionRecord&, std::size_t species_pair)` sees every collision; with groups > 1
    // and threads > 1 it should be a ForkableObserver (or stateless) to be called from several threads.
    template <class Observer> StopReason run(std::int64_t collision_target, double t_stop, Observer&& obs) {
        if (collisions() >= collision_target)
            return StopReason::collisions;
        if (G_ == 1)
            return run_one(collision_target, t_stop, obs);
        using O = std::remove_cvref_t<Observer>;
        if constexpr (ForkableObserver<O>) {
            std::vector<OwnLines<O>> local; // each group's copy in its own cache lines (core/own_lines.hpp)
            local.reserve(G_);
            for (std::size_t g = 0; g < G_; ++g)
                local.push_back({obs.fork()});
            const StopReason r = run_groups(collision_target, t_stop, opt_.threads,
                                            [&](std::size_t g) -> O& { return local[g].value; });
            for (const OwnLines<O>& o : local)
                obs.merge(o.value);
            return r;
        } else {
            const int threads = std::is_empty_v<O> ? opt_.threads : 1;
            return run_groups(collision_target, t_stop, threads, [&](std::size_t) -> Observer& { return obs; });
        }
    }
    StopReason run_collisions(std::int64_t collision_target) {
        return run(collision_target, std::numeric_limits<double>::infinity(), IgnoreCollisions{});
    }

    // About `n` more collisions, never past `collision_target`: a stretch of a run between two of
    // its pauses (progress reports, checkpoints). Runs to the time at which the current rate
    // (candidates times acceptance) gives n collisions, or exactly to the target if that comes
    // first. Why a time: a collision target is met exactly by halving phases (run_groups), about
    // log2(n / tail_collisions) parallel regions, each with its load imbalance, and a serial tail;
    // a time stop takes one phase per step. Neither kind of stop changes the trajectory, so only the
    // pauses move (measured, N = 1e6, rough: two threads 3-9 % faster in the stretches between rows).
    // The count finishes the stretch (returning `stalled` where no collision can happen) when there
    // is no rate yet, or when the time stop brought fewer than n/4 collisions (the rate fell, or
    // t + n/rate rounds to t): every call advances by at least min(n/4, the remainder) unless the gas
    // stalls.
    template <class Observer>
    StopReason run_about(std::int64_t n, std::int64_t collision_target, Observer&& obs) {
        const std::int64_t c0 = collisions();
        if (G_ > 1 && collision_target - c0 > n) {
            const double rate = candidate_rate() * measured_acceptance(); // NaN before 1000 candidates
            if (rate > 0 && std::isfinite(rate)) {
                const StopReason r = run(collision_target, t_ + static_cast<double>(n) / rate, obs);
                if (r != StopReason::time || collisions() - c0 >= n / 4)
                    return r;
            }
        }
        return run(std::min(collision_target, c0 + n), std::numeric_limits<double>::infinity(), obs);
    }

    // The same towards a time: about `n` more collisions, never past `t_stop` (the time clock's
    // stretches between pauses). Returns `time` once at t_stop (time() = t_stop exactly, the state
    // that of the last collision before it), else `collisions`. Grouped runs stop at the time the
    // current rate gives n collisions (one phase per step, as run_about), ungrouped ones at the count.
    template <class Observer> StopReason run_about_until(std::int64_t n, double t_stop, Observer&& obs) {
        const std::int64_t c0 = collisions();
        if (G_ > 1) {
            const double rate = candidate_rate() * measured_acceptance(); // NaN before 1000 candidates
            if (rate > 0 && std::isfinite(rate)) {
                const double t_chunk = t_ + static_cast<double>(n) / rate;
                if (!(t_chunk < t_stop))
                    return run(std::numeric_limits<std::int64_t>::max(), t_stop, obs);
                const StopReason r = run(std::numeric_limits<std::int64_t>::max(), t_chunk, obs);
                if (collisions() - c0 >= n / 4)
                    return r == StopReason::time ? StopReason::collisions : r;
            }
        }
        return run(c0 + n, t_stop, obs);
    }

    // Ends the current step now: the next run() refreshes the bounds first. Required after the
    // state was changed from outside (e.g. velocities rescaled); exact, since the pending candidate
    // is discarded (memoryless clock).
    void restart_step() {
        if (stalled_)
            return;
        t_step_end_ = t_;
        for (Group& g : groups_)
            g.t_next = t_;
    }

    // Uniform shear flow u = a y x^ in the Enskog equation: collisions between grains a diameter apart,
    // whose flows differ by a sigma n_y (see "Sheared Enskog gas"); from the next step on. 0: none.
    void set_enskog_shear(double rate) {
        if (Kernel != CollisionKernel::hard_sphere && rate != 0)
            throw std::invalid_argument("Engine: the sheared Enskog collision is the hard spheres'");
        if (!(rate >= 0) || !std::isfinite(rate))
            throw std::invalid_argument("Engine: the shear rate must be finite and >= 0");
        shear_shift_.clear();
        for (const PairType& t : types_)
            shear_shift_.push_back(rate * t.pc.sigma);
        sheared_ = rate > 0;
        restart_step();
    }

    // Drives the gas with `th` (one entry per species) from the next step on; before the first run().
    void set_thermostat(ThermostatSpec th) {
        if (th.species.size() != species_.size())
            throw std::invalid_argument("Engine: one thermostat entry per species");
        thermostat_ = std::move(th);
        kicks_.assign(species_.size(), {});
    }
    const std::optional<ThermostatSpec>& thermostat() const { return thermostat_; }
    // The time up to which the thermostat's kicks have been given (see "Thermostat").
    double kicked_until() const { return t_kick_; }

    // Threads over the groups and chunks (no influence on the results).
    void set_threads(int threads) {
        if (threads < 1)
            throw std::invalid_argument("Engine: threads must be >= 1");
        if (threads != opt_.threads)
            team_ = std::make_unique<WorkerTeam>(threads);
        opt_.threads = threads;
        prefetch_grains_for_write_ = grains_change_threads();
    }
    // The replica's threads, for other passes over its grains (the rows' moments).
    WorkerTeam& team() { return *team_; }

    double time() const { return t_; }
    std::int64_t collisions() const {
        std::int64_t c = 0;
        for (const Group& g : groups_)
            c += g.c.collisions;
        return c;
    }
    EngineCounters counters() const {
        EngineCounters c = c_;
        for (const Group& g : groups_) {
            c.collisions += g.c.collisions;
            c.candidates += g.c.candidates;
            c.bound_raises += g.c.bound_raises;
            c.promotions += g.c.promotions;
            c.range_moves += g.c.range_moves;
        }
        return c;
    }
    const Store& store() const { return store_; }
    Store& store() { return store_; }
    const std::vector<SpeciesBlock>& species() const { return species_; }
    const std::vector<PairType>& pair_types() const { return types_; }
    const std::vector<Policy>& policies() const { return policies_; }
    double volume() const { return volume_; }
    std::size_t particles() const { return store_.size(); }
    std::size_t groups() const { return G_; }
    // Memory per grain: the store, the index array and the step start's bucket keys.
    std::size_t bytes_per_particle() const {
        return Store::bytes_per_particle + sizeof(std::uint32_t) + (key_.size() ? sizeof(std::uint16_t) : 0);
    }
    double step_length() const { return step_length_; }
    // The Maxwellian collision frequency per grain at the start of the current step (0 before the
    // first step): what the step length is measured in.
    double collision_frequency() const { return nu_; }
    // Candidates per unit time, summed over the groups.
    double candidate_rate() const {
        double r = 0;
        for (const Group& g : groups_)
            r += g.rate;
        return r;
    }
    // The bound on |v| of species s: its fastest class's bound over the groups (its maximum speed
    // at the step start).
    double vmax(std::size_t s) const {
        double b = 0;
        for (const Group& g : groups_)
            b = std::max(b, g.blocks[s * K_ + K_ - 1].bound);
        return b;
    }

    // Checkpoints (io/checkpoint_file.hpp). The complete dynamic state: every grain's v and omega,
    // the index array, and per group the blocks, rates, pre-drawn candidates, demotable lists,
    // stream and clock and counters; the time, the step's end, length and collision frequency, and
    // the engine's counters. An engine
    // constructed with the same species, policies and options (threads aside: they never change the
    // results) that loads it continues bit for bit as this one would: the pending candidate, the
    // rings and the demotable lists all shape the trajectory, so nothing is recomputed. Scratch of
    // begin_step (bucket keys, per-chunk sums) is rewritten before it is read and is left out.
    void save_state(ByteWriter& w) const {
        const std::size_t n = store_.size();
        w.reserve(n * (6 * sizeof(double) + sizeof(std::uint32_t)) + 4096);
        for (const std::size_t v : {n, species_.size(), K_, G_})
            w.u64(v);
        for (std::size_t i = 0; i < n; ++i)
            for (const Vec3& x : {store_.v(i), store_.w(i)})
                for (double c : {x.x, x.y, x.z})
                    w.f64(c);
        for (std::uint32_t p : perm_)
            w.put(p);
        w.f64s(thermal_speed_);
        for (double x : {t_, t_step_end_, step_length_, nu_})
            w.f64(x);
        w.put(stalled_);
        for (std::int64_t x : {c_.collisions, c_.candidates, c_.steps, c_.bound_raises, c_.promotions,
                               c_.range_moves, c_.recentrings, c_.phases, c_.overshoots})
            w.put(x);
        w.f64(c_.max_mean_drift);
        for (const Group& g : groups_) {
            for (const Block& b : g.blocks) {
                for (std::uint32_t x : {b.begin, b.end, b.species})
                    w.put(x);
                for (double x : {b.ceiling2, b.bound, b.bound2})
                    w.f64(x);
            }
            for (const BlockPair& bp : g.block_pairs) {
                for (std::uint32_t x : {bp.x, bp.y, bp.species_pair})
                    w.put(x);
                for (double x : {bp.gmax, bp.rate, bp.pairs})
                    w.f64(x);
            }
            for (double x : g.cumulative)
                w.f64(x);
            for (const Ring& r : g.rings) {
                for (const Candidate& c : r.c) {
                    w.u64(c.word);
                    w.put(c.i_hint);
                    w.put(c.j_hint);
                }
                w.put(r.head);
            }
            for (const auto& d : g.demotable) {
                w.u64(d.size());
                for (std::uint32_t x : d)
                    w.put(x);
            }
            for (std::uint64_t x : g.rng.state())
                w.u64(x);
            for (double x : {g.rate, g.inv_rate, g.t, g.t_next})
                w.f64(x);
            for (std::int64_t x : {g.c.collisions, g.c.candidates, g.c.bound_raises, g.c.promotions,
                                   g.c.range_moves})
                w.put(x);
        }
        if (thermostat_)
            w.f64(t_kick_);
    }

    // Loads what save_state wrote. Throws std::runtime_error when the state does not fit this engine
    // (other particle count, species, speed classes or groups) or is malformed.
    void load_state(ByteReader& r) {
        const std::size_t n = store_.size();
        const auto expect = [](std::uint64_t got, std::size_t want, const char* what) {
            if (got != want)
                throw std::runtime_error("engine state: " + std::to_string(got) + " " + what + ", expected " +
                                         std::to_string(want));
        };
        expect(r.u64(), n, "particles");
        expect(r.u64(), species_.size(), "species");
        expect(r.u64(), K_, "speed classes");
        expect(r.u64(), G_, "groups");
        const auto index = [&](std::uint32_t x, std::size_t limit) {
            if (x > limit)
                throw std::runtime_error("engine state: index out of range");
            return x;
        };
        r.need(n * 6 * sizeof(double));
        for (std::size_t i = 0; i < n; ++i)
            for (Vec3* x : {&store_.v(i), &store_.w(i)}) {
                x->x = r.f64();
                x->y = r.f64();
                x->z = r.f64();
            }
        for (std::uint32_t& p : perm_)
            p = index(r.get<std::uint32_t>(), n - 1);
        std::vector<double> thermal = r.f64s();
        expect(thermal.size(), thermal_speed_.size(), "species speeds");
        thermal_speed_ = std::move(thermal);
        t_ = r.f64();
        t_step_end_ = r.f64();
        step_length_ = r.f64();
        nu_ = r.f64();
        stalled_ = r.get<bool>();
        for (std::int64_t* x : {&c_.collisions, &c_.candidates, &c_.steps, &c_.bound_raises, &c_.promotions,
                                &c_.range_moves, &c_.recentrings, &c_.phases, &c_.overshoots})
            *x = r.get<std::int64_t>();
        c_.max_mean_drift = r.f64();
        for (Group& g : groups_) {
            for (Block& b : g.blocks) {
                b.begin = index(r.get<std::uint32_t>(), n);
                b.end = index(r.get<std::uint32_t>(), n);
                b.species = index(r.get<std::uint32_t>(), species_.size() - 1);
                b.ceiling2 = r.f64();
                b.bound = r.f64();
                b.bound2 = r.f64();
                if (b.end < b.begin)
                    throw std::runtime_error("engine state: block range reversed");
            }
            for (BlockPair& bp : g.block_pairs) {
                bp.x = index(r.get<std::uint32_t>(), g.blocks.size() - 1);
                bp.y = index(r.get<std::uint32_t>(), g.blocks.size() - 1);
                bp.species_pair = index(r.get<std::uint32_t>(), types_.size() - 1);
                bp.gmax = r.f64();
                bp.rate = r.f64();
                bp.pairs = r.f64();
            }
            for (double& x : g.cumulative)
                x = r.f64();
            set_first_cumulative(g);
            for (Ring& ring : g.rings) {
                for (Candidate& c : ring.c) {
                    c.word = r.u64();
                    c.i_hint = index(r.get<std::uint32_t>(), n - 1);
                    c.j_hint = index(r.get<std::uint32_t>(), n - 1);
                }
                ring.head = index(r.get<unsigned>(), ring_size - 1);
            }
            for (auto& d : g.demotable) {
                // The lists never grow past the capacity reserved at construction (settle()), and
                // clear() + push_back keeps it: the same lists fill up at the same collision.
                const std::size_t size = r.count(sizeof(std::uint32_t));
                if (size > d.capacity())
                    throw std::runtime_error("engine state: demotable list too long");
                d.clear();
                for (std::size_t k = 0; k < size; ++k)
                    d.push_back(index(r.get<std::uint32_t>(), n - 1));
            }
            std::array<std::uint64_t, CollisionRng::state_words> s;
            for (std::uint64_t& x : s)
                x = r.u64();
            g.rng.set_state(s); // throws std::runtime_error for a position past the buffer
            g.rate = r.f64();
            g.inv_rate = r.f64();
            g.t = r.f64();
            g.t_next = r.f64();
            for (std::int64_t* x : {&g.c.collisions, &g.c.candidates, &g.c.bound_raises, &g.c.promotions,
                                    &g.c.range_moves})
                *x = r.get<std::int64_t>();
        }
        if (thermostat_)
            t_kick_ = r.f64();
    }

  private:
    // Speed class c of species s: the store range [begin, end); every grain in it has |v| <= bound.
    struct Block {
        std::uint32_t begin = 0, end = 0;
        std::uint32_t species = 0;
        bool has_lower = false; // a slower class of the same species exists (x % K != 0, without a division)
        double ceiling2 = 0; // grains above sqrt(ceiling2) move to the next class (top: infinity)
        double bound = 0, bound2 = 0;
        std::uint32_t size() const { return end - begin; }
    };
    struct BlockPair {
        std::uint32_t x, y; // blocks, x <= y
        std::uint32_t species_pair;
        double gmax, rate, pairs;
    };
    // A pre-drawn candidate: its random word, and the positions it gave over the blocks' ranges
    // when drawn (in range, 0 for an empty block): prefetch hints, never used as the candidate.
    struct Candidate {
        std::uint64_t word;
        std::uint32_t i_hint, j_hint;
    };
    struct Ring {
        std::array<Candidate, ring_size> c{};
        unsigned head = 0;
    };
    struct GroupCounters {
        std::int64_t collisions = 0, candidates = 0, bound_raises = 0, promotions = 0, range_moves = 0;
    };
    // One group: a DSMC gas of its own for the step (blocks species-major, s K + c). Aligned to a
    // cache line, so that groups on different threads share none.
    struct alignas(64) Group {
        LineVector<Block> blocks;
        LineVector<BlockPair> block_pairs; // all x <= y
        LineVector<double> cumulative;
        std::array<double, small_choice> first_cumulative{}; // set_first_cumulative()
        LineVector<Ring> rings;
        LineVector<LineVector<std::uint32_t>> demotable; // per block: grains slow enough for the class below
        CollisionRng rng{};
        boost::random::exponential_distribution<double> exponential{1.0};
        double rate = 0, inv_rate = 0;
        double t = 0, t_next = 0;
        GroupCounters c{};
    };

    // The loop of one group: processes its candidates while the next one comes before `t_limit`,
    // up to `quota` collisions. Returns the collisions done; g.t is the time of the last candidate.
    // Never inlined: one compiled body serves every caller (serial, parallel phase, tail), so the
    // compiler's floating-point contraction (FMA) is the same wherever a collision is computed and
    // the trajectory is bitwise independent of the threads and of where run() pauses.
    // Flattened: everything it calls is inlined into it (but the stream's refill, which is marked
    // noinline), whatever else the translation unit holds. Without it GCC's unit-wide inlining budget
    // decides, and code added for one policy can move another's: the table policies' flat cells left
    // the exponential draw of the constant rough loop out of line, 7 % slower (measured, N = 1e6).
    template <class Observer>
    [[gnu::noinline, gnu::flatten]] std::int64_t advance(Group& g, double t_limit, std::int64_t quota, Observer& obs) {
        std::int64_t done = 0;
        while (done < quota && g.t_next < t_limit) {
            g.t = g.t_next;
            ++g.c.candidates;
            const std::size_t k = choose_block_pair(g);
            const BlockPair& bp = g.block_pairs[k];
            std::uint32_t i, j;
            take_candidate(g, k, i, j);
            const std::uint32_t gi = perm_[i], gj = perm_[j];
            Vec3& v_i = store_.v(gi);
            Vec3& v_j = store_.v(gj);
            const Vec3 g_c = v_i - v_j;
            const double g2 = norm2(g_c);
            bool accepted;
            Vec3 n_sheared{};
            if constexpr (Kernel == CollisionKernel::maxwell) {
                accepted = true; // the rate is exact: no thinning
            } else {
                if (sheared_) {
                    accepted = sheared_impact(g, bp, g_c, g2, n_sheared);
                } else {
                    const double x = uniform01(g.rng) * bp.gmax;
                    accepted = x * x < g2; // with probability |g_c|/g_max
                }
            }
            if (accepted) {
                const std::size_t sp = Mixture ? bp.species_pair : 0;
                const PairConstants& pc = types_[sp].pc;
                const Policy& policy = policies_[sp];
                CollisionRecord rec;
                if (Kernel == CollisionKernel::hard_sphere && sheared_) {
                    rec = collide_sheared(pc, policy, gi, gj, n_sheared, sp, obs);
                } else if constexpr (Kernel == CollisionKernel::maxwell) {
                    Vec3 n = uniform_direction(g.rng);
                    if (dot(n, g_c) > 0) // onto the approaching hemisphere: uniform there
                        n = -1.0 * n;
                    if constexpr (Policy::needs_rotation)
                        rec = collide(pc, policy, v_i, store_.w(gi), v_j, store_.w(gj), n);
                    else
                        rec = collide(pc, policy, v_i, v_j, n);
                } else if constexpr (Policy::needs_rotation) {
                    const Vec3 n = sample_impact_normal(g.rng, g_c, sqrt_nonneg(g2));
                    rec = collide(pc, policy, v_i, store_.w(gi), v_j, store_.w(gj), n);
                } else { // smooth hard spheres: g^N is drawn directly, n is never formed
                    rec = collide_normal_part(pc, policy, v_i, v_j,
                                              sample_impact_normal_part(g.rng, g_c, sqrt_nonneg(g2)));
                }
                ++g.c.collisions;
                ++done;
                obs(rec, sp);
                const double vi2 = norm2(v_i), vj2 = norm2(v_j);
                std::uint32_t x_i = bp.x, x_j = bp.y;
                bool rates_changed = false;
                rates_changed |= settle(g, i, x_i, vi2, j, x_j);
                rates_changed |= settle(g, j, x_j, vj2, i, x_i);
                if (rates_changed) [[unlikely]] {
                    ++g.c.bound_raises;
                    update_rates(g);
                }
            }
            g.t_next = g.t + g.exponential(g.rng) * g.inv_rate;
        }
        return done;
    }

    // The sheared Enskog gas's thinning and direction (see "Sheared Enskog gas"): whether the candidate
    // of block pair `bp` with peculiar relative velocity g_c collides, and its n.
    [[gnu::always_inline]] bool sheared_impact(Group& g, const BlockPair& bp, const Vec3& g_c, double g2, Vec3& n) {
        const double s = shear_shift_[bp.species_pair], g_abs = sqrt_nonneg(g2);
        if (!(uniform01(g.rng) * (bp.gmax + 2 * s) < g_abs + 2 * s))
            return false;
        n = uniform01(g.rng) * (g_abs + 2 * s) < g_abs ? sample_impact_normal(g.rng, g_c, g_abs)
                                                        : uniform_direction(g.rng);
        const double gn = -dot(g_c, n); // h(n) = max(0, gn)
        const double approach = gn - s * n.x * n.y; // -g_e.n
        return approach > 0 && uniform01(g.rng) * (std::max(gn, 0.0) + 0.5 * s) < approach;
    }

    // The collision rule on g_e: the partner's velocity shifted by -s n_y x^ for the rule and back.
    template <class Observer>
    [[gnu::always_inline]] CollisionRecord collide_sheared(const PairConstants& pc, const Policy& policy,
                                                           std::uint32_t gi, std::uint32_t gj, const Vec3& n,
                                                           std::size_t sp, Observer& obs) {
        const Vec3 shift{-shear_shift_[sp] * n.y, 0.0, 0.0};
        Vec3& v_i = store_.v(gi);
        Vec3& v_j = store_.v(gj);
        const Vec3 v_i0 = v_i;
        v_j += shift;
        CollisionRecord rec;
        if constexpr (Policy::needs_rotation)
            rec = collide(pc, policy, v_i, store_.w(gi), v_j, store_.w(gj), n);
        else
            rec = collide(pc, policy, v_i, v_j, n);
        v_j -= shift;
        // The rule counted the partner's energy at its shifted velocity: the peculiar energy's change
        // differs by -m_j shift.dv_j = shift.J (momentum conservation, J = m_i dv_i on i; the rule moved
        // v_i by (m_eff/m_i) P/m_eff).
        const Vec3 J = (pc.m_eff / pc.m_eff_over_m_i) * (v_i - v_i0);
        rec.dE_tr += dot(shift, J);
        if constexpr (requires { obs.transfer_of(n, J); })
            obs.transfer_of(pc.sigma * n, J);
        return rec;
    }

    // One group: the plain event loop.
    template <class Observer> StopReason run_one(std::int64_t collision_target, double t_stop, Observer& obs) {
        Group& g = groups_[0];
        for (;;) {
            if (g.t_next >= t_step_end_) {
                if (stalled_)
                    return stall(t_stop);
                begin_step();
                continue;
            }
            if (g.t_next >= t_stop) {
                t_ = t_stop;
                return StopReason::time;
            }
            advance(g, std::min(t_stop, t_step_end_), collision_target - g.c.collisions, obs);
            t_ = g.t;
            if (g.c.collisions >= collision_target)
                return StopReason::collisions;
        }
    }

    StopReason stall(double t_stop) {
        if (std::isfinite(t_stop))
            t_ = std::max(t_, t_stop);
        return std::isfinite(t_stop) ? StopReason::time : StopReason::stalled;
    }

    // Collisions per candidate over the run so far (the phases' and run_about's rate is the
    // candidate rate times this); NaN before 1000 candidates, too few to tell.
    double measured_acceptance() const {
        const EngineCounters c = counters();
        return c.candidates > 1000 ? static_cast<double>(c.collisions) / static_cast<double>(c.candidates)
                                   : std::numeric_limits<double>::quiet_NaN();
    }

    // Several groups (see "Groups" above). `obs_of(g)` is the observer of group g.
    template <class ObsOf>
    StopReason run_groups(std::int64_t collision_target, double t_stop, int threads, ObsOf&& obs_of) {
        const bool counting = collision_target < std::numeric_limits<std::int64_t>::max();
        for (;;) {
            double first = std::numeric_limits<double>::infinity();
            for (const Group& g : groups_)
                first = std::min(first, g.t_next);
            if (first >= t_step_end_) {
                if (stalled_)
                    return stall(t_stop);
                begin_step();
                continue;
            }
            if (first >= t_stop) {
                t_ = t_stop;
                return StopReason::time;
            }
            const double t_limit = std::min(t_stop, t_step_end_);
            const std::int64_t remaining = collision_target - collisions();
            if (!counting || remaining > tail_collisions) {
                // A parallel phase to a common time: about half the remaining collisions.
                double t_phase = t_limit;
                if (counting) {
                    const double measured = measured_acceptance();
                    const double acceptance = std::isnan(measured) ? 1.0 : std::max(0.01, measured);
                    t_phase = std::min(t_limit, std::max(t_, first) + 0.5 * static_cast<double>(remaining) /
                                                                          (candidate_rate() * acceptance));
                }
                parallel_advance(t_phase, threads, obs_of);
                ++c_.phases;
                t_ = t_phase;
                if (counting && collisions() >= collision_target) {
                    if (collisions() > collision_target)
                        ++c_.overshoots;
                    return StopReason::collisions;
                }
                continue;
            }
            // The tail: one candidate at a time, in the group whose next candidate comes first.
            for (;;) {
                std::size_t a = 0;
                double second = std::numeric_limits<double>::infinity();
                for (std::size_t g = 1; g < G_; ++g) {
                    if (groups_[g].t_next < groups_[a].t_next) {
                        second = groups_[a].t_next;
                        a = g;
                    } else {
                        second = std::min(second, groups_[g].t_next);
                    }
                }
                Group& ga = groups_[a];
                if (ga.t_next >= t_limit)
                    break;
                if (advance(ga, std::min(second, t_limit), 1, obs_of(a)) &&
                    collisions() >= collision_target) {
                    t_ = ga.t;
                    return StopReason::collisions;
                }
            }
            t_ = t_limit;
        }
    }

    template <class ObsOf> void parallel_advance(double t_phase, int threads, ObsOf& obs_of) {
        const auto G = static_cast<std::int64_t>(G_);
        if (threads <= 1) {
            for (std::int64_t g = 0; g < G; ++g)
                advance(groups_[g], t_phase, std::numeric_limits<std::int64_t>::max(), obs_of(g));
            return;
        }
        // Units claimed dynamically: a thread that is waiting for a time slice holds no group
        // and delays nothing (core/worker_team.hpp).
        team_->for_each(static_cast<std::size_t>(G), [&](std::size_t g) {
            advance(groups_[g], t_phase, std::numeric_limits<std::int64_t>::max(), obs_of(g));
        });
    }

    // The position in block b that 32 random bits u give by multiply-shift, without Lemire's
    // rejection (a prefetch hint); 0 for an empty block, so that perm_ may be read there.
    static std::uint32_t position_hint(const Block& b, std::uint32_t u) {
        return b.size() ? b.begin + static_cast<std::uint32_t>((std::uint64_t{u} * b.size()) >> 32) : 0;
    }
    // A position uniform over block b (not empty) from 32 random bits u: Lemire's multiply-shift
    // with rejection of the (2^32 mod n) low values that would make some positions likelier; a
    // rejected u (probability < n/2^32) is replaced by a fresh 64-bit draw.
    std::uint32_t position_in(Group& g, const Block& b, std::uint32_t u) {
        const std::uint32_t n = b.size();
        const std::uint64_t m = std::uint64_t{u} * n;
        if (static_cast<std::uint32_t>(m) < n) [[unlikely]] {
            const std::uint32_t threshold = (0u - n) % n;
            if (static_cast<std::uint32_t>(m) < threshold)
                return b.begin + static_cast<std::uint32_t>(uniform_index(g.rng, n));
        }
        return b.begin + static_cast<std::uint32_t>(m >> 32);
    }

    Candidate draw_candidate(Group& g, std::size_t k) {
        const BlockPair& bp = g.block_pairs[k];
        const std::uint64_t word = g.rng();
        Candidate c{word, position_hint(g.blocks[bp.x], static_cast<std::uint32_t>(word)),
                    position_hint(g.blocks[bp.y], static_cast<std::uint32_t>(word >> 32))};
        // Stage 1 of 2: the index entries (the grains follow half a ring later, take_candidate).
        prefetch_line(&perm_[c.i_hint]);
        prefetch_line(&perm_[c.j_hint]);
        return c;
    }

    void take_candidate(Group& g, std::size_t k, std::uint32_t& i, std::uint32_t& j) {
        Ring& r = g.rings[k];
        const Candidate c = r.c[r.head];
        r.c[r.head] = draw_candidate(g, k);
        r.head = (r.head + 1) % ring_size;
        // Stage 2 of 2: the grains of the candidate half a ring ahead, whose index entries were
        // prefetched half a ring ago (a hint only: perm_ may have changed since, which costs a miss).
        const Candidate& ahead = r.c[(r.head + ring_size / 2) % ring_size];
        store_.prefetch(perm_[ahead.i_hint], prefetch_grains_for_write_);
        store_.prefetch(perm_[ahead.j_hint], prefetch_grains_for_write_);
        const BlockPair& bp = g.block_pairs[k];
        const Block& X = g.blocks[bp.x];
        // The chosen block pair has a positive rate: both blocks hold grains (two for x == y).
        i = position_in(g, X, static_cast<std::uint32_t>(c.word));
        j = position_in(g, g.blocks[bp.y], static_cast<std::uint32_t>(c.word >> 32));
        if (bp.x == bp.y) { // i and j drawn independently from one block: a distinct pair by rejection
            while (j == i)
                [[unlikely]] j = X.begin + static_cast<std::uint32_t>(uniform_index(g.rng, X.size()));
        }
    }

    // The block pair of the next candidate, with probability rate/total: the number of cumulative
    // rates at or below a uniform point (branch-free: the outcome is unpredictable). Up to three
    // block pairs (one species with K = 2, the default) by two fixed comparisons with the group's
    // `first_cumulative` (padded with +infinity): the same k as the loop, without its loop control.
    std::size_t choose_block_pair(Group& g) {
        const std::size_t n = g.cumulative.size();
        if (n == 1)
            return 0;
        const double x = uniform01(g.rng) * g.rate;
        if (n <= small_choice + 1) {
            const std::array<double, small_choice>& c = g.first_cumulative;
            return std::size_t{x >= c[0]} + std::size_t{x >= c[1]};
        }
        std::size_t k = 0;
        for (std::size_t q = 0; q + 1 < n; ++q)
            k += x >= g.cumulative[q];
        return k;
    }
    // The cumulative rates the comparisons of choose_block_pair read: all but the last (the total,
    // which a uniform point below it never reaches), then +infinity.
    static void set_first_cumulative(Group& g) {
        g.first_cumulative.fill(std::numeric_limits<double>::infinity());
        for (std::size_t q = 0; q + 1 < g.cumulative.size() && q < small_choice; ++q)
            g.first_cumulative[q] = g.cumulative[q];
    }

    // After a collision, grain i of block x has |v|^2 = v2. Keeps every block's bound true:
    //  - above the block's ceiling: the grain moves up a class (repeatedly). Preferably it trades
    //    places with a grain of the next class that has become slow enough for this one (a
    //    "demotable" grain, remembered when it collided): the blocks keep their ranges. Else the
    //    grain is swapped with the last grain of its block and the boundary between the two blocks
    //    moves by one.
    //  - above the bound (below the ceiling): the bound is raised to |v|;
    //  - slow enough for the class below: remembered as demotable.
    // `other`, `other_block`: the collision partner, which follows if it was moved.
    // Returns whether a bound or a block range changed (the rates must then be updated).
    bool settle(Group& g, std::uint32_t& i, std::uint32_t& x, double v2, std::uint32_t& other,
                std::uint32_t& other_block) {
        LineVector<Block>& blocks = g.blocks;
        bool changed = false;
        while (v2 > blocks[x].ceiling2) {
            const std::uint32_t y =
                x + 1; // the next class of the same species (the top class has no ceiling)
            LineVector<std::uint32_t>& cand = g.demotable[y];
            std::uint32_t k = no_grain;
            while (!cand.empty()) {
                const std::uint32_t q = cand.back();
                cand.pop_back();
                if (q >= blocks[y].begin && q < blocks[y].end && norm2(store_.v(perm_[q])) <= blocks[x].ceiling2) {
                    k = q;
                    break;
                }
            }
            if (k != no_grain) {
                std::swap(perm_[i], perm_[k]);
                if (other == k) { // the partner was the demotable grain: now at i's place, in block x
                    other = i;
                    other_block = x;
                }
                const double w2 = norm2(store_.v(perm_[i])); // the demoted grain, now in block x
                if (w2 > blocks[x].bound2) {
                    blocks[x].bound2 = w2;
                    blocks[x].bound = sqrt_nonneg(w2);
                    changed = true;
                }
                i = k;
                ++g.c.promotions;
            } else {
                Block& b = blocks[x];
                const std::uint32_t last = b.end - 1;
                if (i != last) {
                    std::swap(perm_[i], perm_[last]);
                    if (other == last)
                        other = i; // stays in block x
                    i = last;
                }
                --b.end;
                --blocks[y].begin;
                ++g.c.promotions;
                ++g.c.range_moves;
                changed = true;
            }
            x = y;
        }
        Block& b = blocks[x];
        if (v2 > b.bound2) {
            b.bound2 = v2;
            b.bound = sqrt_nonneg(v2);
            return true;
        }
        if (b.has_lower && v2 <= blocks[x - 1].ceiling2 && g.demotable[x].size() < g.demotable[x].capacity())
            g.demotable[x].push_back(i);
        return changed;
    }

    // Candidate rates of a group: a pair inside a group collides at G times its rate in the whole
    // gas (the group's volume is V/G), so that averaged over the partition every pair has its rate.
    void update_rates(Group& g) {
        const double scale = static_cast<double>(G_) / volume_;
        double total = 0;
        for (std::size_t k = 0; k < g.block_pairs.size(); ++k) {
            BlockPair& bp = g.block_pairs[k];
            const Block& X = g.blocks[bp.x];
            const Block& Y = g.blocks[bp.y];
            const double nx = X.size(), ny = Y.size();
            bp.pairs = bp.x == bp.y ? 0.5 * nx * (nx - 1.0) : nx * ny;
            // (1 + 1e-12): the computed |g_c| of two grains at their bounds, head-on, may round above
            // the computed sum of the bounds; the inflation keeps the acceptance probability below 1.
            bp.gmax = (X.bound + Y.bound) * (1.0 + 1e-12);
            double speed = Kernel == CollisionKernel::maxwell ? maxwell_speed_[bp.species_pair] : bp.gmax;
            if (sheared_) // the composition's majorant ("Sheared Enskog gas")
                speed += 2 * shear_shift_[bp.species_pair];
            bp.rate = bp.pairs * types_[bp.species_pair].rate_section() * speed * scale;
            total += bp.rate;
            g.cumulative[k] = total;
        }
        set_first_cumulative(g);
        g.rate = total;
        g.inv_rate = total > 0 ? 1.0 / total : std::numeric_limits<double>::infinity();
    }

    // f(ch) for every chunk ch in [0, C): on the team's threads (each chunk writes only its own
    // outputs, combined in chunk order afterwards, so the results do not depend on the threads).
    template <class F> void for_chunks(std::size_t C, F&& f) { team_->for_each(C, f); }

    // The thermostat's kicks of the step starting now (see "Thermostat"): over [t_kick_, t0 + L/2], L the
    // step length at the last step start's collision frequency (the initial state's at the first).
    // Returns whether any grain is kicked.
    bool plan_kicks() {
        if (!thermostat_)
            return false;
        double nu = nu_;
        if (!(nu > 0)) {
            for (std::size_t s = 0; s < species_.size(); ++s)
                T_over_m_[s] = thermal_speed_[s] * thermal_speed_[s];
            nu = maxwellian_collision_frequency(types_, T_over_m_, volume_, static_cast<double>(store_.size()));
        }
        if (!(nu > 0) || !std::isfinite(nu)) // a gas at rest: no step length to place the kicks by
            return false;
        return plan_species_kicks(*thermostat_, species_, t_step_end_ + 0.5 * opt_.step / nu, t_kick_, kicks_);
    }

    // Where species s's kicks of this step come from (dsmc/thermostat.hpp).
    KickSource kick_source(std::size_t s) const {
        return KickSource::of(opt_.seed, opt_.replica, static_cast<std::uint64_t>(c_.steps), s, species_[s]);
    }

    // Species s's kicks of this step in C chunks of `chunk` grains: the bridge's scales, the chunks'
    // sums and, for exact energy, the factors on the kicks (a first pass that draws them without
    // applying them; prepare_step_kick, dsmc/thermostat.hpp).
    void prepare_kicks(std::size_t s, std::size_t chunk, std::size_t C, StepKick& k) {
        const std::size_t n_s = species_[s].count;
        std::vector<std::size_t> sizes(C);
        for (std::size_t ch = 0; ch < C; ++ch)
            sizes[ch] = std::min(chunk, n_s - ch * chunk);
        prepare_step_kick(
            kick_source(s), sizes, thermostat_->exact_energy, k,
            [&](std::size_t chunks, auto&& f) { for_chunks(chunks, f); },
            [&](std::size_t ch, KickEnergy* e) {
                const std::size_t lo = species_[s].offset + ch * chunk;
                kick_chunk(s, ch, lo, std::min(lo + chunk, species_[s].offset + n_s), k, e);
            });
    }

    // Species s's kicks in chunk ch (grains lo .. hi - 1), from the chunk's own stream: applied
    // (energy == nullptr) or only summed into *energy. Never inlined, like advance(): the team runs
    // chunks inline on one thread and through its workers on several, and two inlined copies were
    // contracted into FMAs differently (the exact-energy sums, and with them the kicks, differed in
    // their last bits between one and two threads; tests/dsmc/thermostat_test.cpp).
    [[gnu::noinline]] void kick_chunk(std::size_t s, std::size_t ch, std::size_t lo, std::size_t hi, const StepKick& k,
                                      KickEnergy* energy) {
        kick_grains(
            kick_source(s), ch, hi - lo, k, [&](std::size_t q) -> Vec3& { return store_.v(lo + q); },
            [&](std::size_t q) -> Vec3& { return store_.w(lo + q); }, energy);
    }

    // Refreshes the partition, the classes, bounds and frame, sets the step length, and starts the
    // groups' streams. Pass 1 reads every grain once (statistics, bucket sizes, each grain's bucket
    // (group, class) into a 16-bit key per grain); pass 2 writes the positions (perm_) bucket by
    // bucket. Both in parallel over fixed chunks, with results that do not depend on the threads.
    [[gnu::noinline]] void begin_step() {
        const std::size_t S = species_.size();
        const std::size_t B = G_ * K_; // buckets per species, group-major
        for (Group& g : groups_)
            for (auto& d : g.demotable)
                d.clear();
        // The partition: grain i goes to group floor(G h_i / 2^64), h_i the i-th output of a
        // splitmix64 sequence keyed by (seed, partition, replica, step).
        const std::uint64_t partition_key = stream_hash(
            StreamKey{opt_.seed, Stream::partition, opt_.replica, static_cast<std::uint64_t>(c_.steps), 0});
        Vec3 momentum{};
        double mass = 0, mv2_all = 0;
        std::fill(mv2_.begin(), mv2_.end(), 0.0);
        const bool driving = plan_kicks();
        for (std::size_t s = 0; s < S; ++s) {
            const SpeciesBlock& sp = species_[s];
            for (std::size_t c = 0; c < cuts_.size(); ++c) {
                const double cut = cuts_[c] * thermal_speed_[s];
                cut2_[c] = cut * cut;
            }
            // Pass 1, in parallel over fixed chunks of the species' range (the chunks, and the order
            // their sums are combined in, do not depend on the threads): statistics, bucket sizes and
            // each grain's bucket.
            const std::size_t n_s = sp.count;
            const std::size_t chunk = std::max(chunk_grains, (n_s + max_chunks - 1) / max_chunks);
            const std::size_t C = (n_s + chunk - 1) / chunk;
            ccount_.assign(C * B, 0);
            cmax2_.assign(C * B, 0.0);
            csum2_.assign(C, 0.0);
            cps_.assign(C, Vec3{});
            StepKick* const kick = driving && kicks_[s].kick.moves() ? &kicks_[s] : nullptr;
            if (kick)
                prepare_kicks(s, chunk, C, *kick);
            for_chunks(C, [&](std::size_t ch) {
                const std::size_t lo = sp.offset + ch * chunk;
                const std::size_t hi = std::min(lo + chunk, sp.offset + n_s);
                if (kick) // the chunk's kicks while its grains are in this core's cache, then their classes
                    kick_chunk(s, ch, lo, hi, *kick, nullptr);
                std::uint32_t* count = &ccount_[ch * B];
                double* max2 = &cmax2_[static_cast<std::size_t>(ch) * B];
                double sum2 = 0;
                Vec3 ps{};
                for (std::size_t i = lo; i < hi; ++i) {
                    const Vec3& v = store_.v(i);
                    const double v2 = norm2(v);
                    std::uint32_t c = 0;
                    for (std::size_t q = 0; q < cuts_.size(); ++q)
                        c += v2 > cut2_[q];
                    if (G_ > 1) {
                        std::uint64_t h = partition_key + i * 0x9e3779b97f4a7c15ULL; // the i-th splitmix64 state
                        const auto gi =
                            static_cast<std::uint32_t>((static_cast<__uint128_t>(splitmix64(h)) * G_) >> 64);
                        c += gi * static_cast<std::uint32_t>(K_);
                    }
                    if (B > 1)
                        key_[i] = static_cast<std::uint16_t>(c);
                    ++count[c];
                    max2[c] = std::max(max2[c], v2);
                    sum2 += v2;
                    ps += v;
                }
                csum2_[ch] = sum2;
                cps_[ch] = ps;
            });
            std::fill(count_.begin(), count_.end(), 0);
            std::fill(max2_.begin(), max2_.end(), 0.0);
            double sum2 = 0;
            Vec3 ps{};
            for (std::size_t ch = 0; ch < C; ++ch) {
                sum2 += csum2_[ch];
                ps += cps_[ch];
                for (std::size_t q = 0; q < B; ++q) {
                    count_[q] += ccount_[ch * B + q];
                    max2_[q] = std::max(max2_[q], cmax2_[ch * B + q]);
                }
            }
            // Pass 2: the positions of each bucket, grains in increasing index order (a counting sort
            // of the indices, in parallel over the chunks; the grains themselves never move).
            std::uint32_t start = static_cast<std::uint32_t>(sp.offset);
            for (std::size_t q = 0; q < B; ++q) {
                const std::size_t g = q / K_, c = q % K_;
                Block& b = groups_[g].blocks[s * K_ + c];
                b.begin = start;
                for (std::size_t ch = 0; ch < C; ++ch) {
                    const std::uint32_t n = ccount_[ch * B + q];
                    ccount_[ch * B + q] = start; // now the chunk's first position in bucket q
                    start += n;
                }
                b.end = start;
                b.ceiling2 = c + 1 < K_ ? cut2_[c] : std::numeric_limits<double>::infinity();
                b.bound2 = max2_[q];
                b.bound = sqrt_nonneg(max2_[q]);
            }
            for_chunks(C, [&](std::size_t ch) {
                const std::size_t lo = sp.offset + ch * chunk;
                const std::size_t hi = std::min(lo + chunk, sp.offset + n_s);
                std::uint32_t* next = &ccount_[ch * B];
                if (B > 1) {
                    // Each bucket's positions are written in increasing order, one stream per bucket
                    // (G K of them, 64 at N = 1e6): too many for the hardware prefetchers, so each
                    // store missed. When a bucket starts a cache line, the line two ahead is
                    // prefetched for writing (measured: this pass 2.5 -> 1.6 ms at N = 1e6, one thread).
                    std::uint32_t* const perm = perm_.data();
                    const std::uint16_t* const key = key_.data();
                    constexpr std::uint32_t line = 64 / sizeof(std::uint32_t);
                    const std::size_t ahead_limit = perm_.size() > 2 * line ? perm_.size() - 2 * line : 0;
                    for (std::size_t i = lo; i < hi; ++i) {
                        const std::uint32_t p = next[key[i]]++;
                        if (p % line == 0 && p < ahead_limit)
                            prefetch_line_for_write(perm + p + 2 * line);
                        perm[p] = static_cast<std::uint32_t>(i);
                    }
                } else {
                    for (std::size_t i = lo; i < hi; ++i)
                        perm_[i] = static_cast<std::uint32_t>(i);
                }
            });
            mv2_[s] = sp.grain.mass * sum2;
            mv2_all += mv2_[s];
            momentum += sp.grain.mass * ps;
            mass += sp.grain.mass * static_cast<double>(sp.count);
            thermal_speed_[s] = sp.count ? std::sqrt(sum2 / (3.0 * static_cast<double>(sp.count))) : 0.0;
        }
        // Recentring (rare): a Galilean shift by u; |v - u| <= |v| + |u| keeps every bound exact.
        const Vec3 u = (1.0 / mass) * momentum;
        if (mv2_all > 0) {
            const double drift = norm(u) / std::sqrt(mv2_all / mass);
            c_.max_mean_drift = std::max(c_.max_mean_drift, drift);
            if (drift > recentre_threshold) {
                const double u_abs = norm(u);
                for (const SpeciesBlock& sp : species_)
                    for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i)
                        store_.v(i) -= u;
                for (Group& g : groups_) {
                    for (Block& b : g.blocks) {
                        b.bound += u_abs;
                        b.bound2 = b.bound * b.bound;
                    }
                }
                ++c_.recentrings;
            }
        }

        // Mean free time from the Maxwellian collision frequency at the species' temperatures.
        for (std::size_t s = 0; s < S; ++s) {
            const double N = static_cast<double>(species_[s].count);
            T_over_m_[s] = N > 0 ? mv2_[s] / (3.0 * N * species_[s].grain.mass) : 0.0; // mv2 = m sum v^2 = 3 N T
        }
        const double nu =
            maxwellian_collision_frequency(types_, T_over_m_, volume_, static_cast<double>(store_.size()));
        double rate = 0;
        for (std::size_t q = 0; q < G_; ++q) {
            Group& g = groups_[q];
            update_rates(g);
            rate += g.rate;
            g.rng = make_collision_stream(StreamKey{opt_.seed, Stream::collisions, opt_.replica,
                                                    static_cast<std::uint64_t>(c_.steps), q});
        }
        ++c_.steps;
        const double t0 = t_step_end_;
        if (!(rate > 0) || !(nu > 0)) { // nothing moves: no collision can ever happen
            stalled_ = true;
            nu_ = 0;
            step_length_ = std::numeric_limits<double>::infinity();
            t_step_end_ = std::numeric_limits<double>::infinity();
            for (Group& g : groups_)
                g.t_next = std::numeric_limits<double>::infinity();
            return;
        }
        nu_ = nu;
        step_length_ = opt_.step / nu;
        t_step_end_ = t0 + step_length_;
        for (Group& g : groups_) {
            for (std::size_t k = 0; k < g.block_pairs.size(); ++k) {
                Ring& r = g.rings[k];
                r.head = 0;
                for (auto& c : r.c)
                    c = draw_candidate(g, k);
            }
            g.t = t0;
            g.t_next = g.rate > 0 ? t0 + g.exponential(g.rng) * g.inv_rate : std::numeric_limits<double>::infinity();
        }
    }

    std::vector<SpeciesBlock> species_;
    std::vector<PairType> types_;
    std::vector<Policy> policies_;
    Store store_;
    EngineOptions opt_;
    double volume_ = 0;
    std::size_t K_ = 1, G_ = 1;
    std::vector<double> cuts_;
    std::vector<double> thermal_speed_; // per species: sqrt(<v^2>/3) at the last step start
    std::vector<double> maxwell_speed_; // per species pair: u_ab of the Maxwell kernel
    std::vector<Group> groups_;
    std::unique_ptr<WorkerTeam> team_; // the threads of this replica (opt_.threads - 1 workers)
    // perm_[p]: the grain at position p. Blocks are ranges of positions; the grains stay where they are.
    // On huge pages: stage 1 of the prefetch (take_candidate) reads random entries of it.
    HugePageBuffer<std::uint32_t> perm_;
    // The grains of a candidate are prefetched for writing (with ownership) when the groups run on
    // several threads: each step's partition leaves half of a group's grains in the cache of the
    // thread that ran them last, and a read prefetch then brings a shared copy whose first write
    // costs a second trip between the cores (measured, Zen 5 VM whose vCPUs are 235 ns apart, N = 1e5
    // dense: the parallel phases 10 % shorter on two threads, unchanged on one and at N = 1e6).
    // On one thread a read prefetch: most candidates are rejected and never written.
    bool prefetch_grains_for_write_ = false;
    bool grains_change_threads() const { return opt_.threads > 1 && G_ > 1; }
    // Scratch of begin_step: each grain's bucket (2 bytes per grain, K G > 1 only), per-species sums.
    HugePageBuffer<std::uint16_t> key_;
    std::vector<double> mv2_, T_over_m_, cut2_, max2_;
    std::vector<std::uint32_t> count_, ccount_;        // per bucket; per (chunk, bucket)
    std::vector<double> cmax2_, csum2_;                 // per (chunk, bucket); per chunk
    std::vector<Vec3> cps_;                             // per chunk
    double t_ = 0, t_step_end_ = 0, step_length_ = 0, nu_ = 0;
    bool stalled_ = false;
    // The thermostat (unset: free cooling), the time its kicks reached, and per species the current
    // step's kicks (StepKick).
    std::optional<ThermostatSpec> thermostat_;
    double t_kick_ = 0;
    // The sheared Enskog gas (set_enskog_shear): a sigma_ab per pair type.
    bool sheared_ = false;
    std::vector<double> shear_shift_;
    std::vector<StepKick> kicks_;
    EngineCounters c_{}; // the engine's own counts (steps, frame, phases); the groups keep the rest
};

} // namespace roughgas
