// Checkpoints of the DSMC (dsmc/engine.hpp save_state/load_state; dsmc/run.hpp ReplicaCheckpoints):
// a state saved and loaded into a fresh engine continues bit for bit, whatever the threads; taking
// checkpoints changes no row; a replica resumed from any of its checkpoints, or stopped and
// resumed, gives the rows and histograms of the uninterrupted run bit for bit (cooling and shear:
// the shear states lie between two Strang steps); a state of another engine or kernel is refused.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/particles.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/tables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace roughgas {
namespace {

template <class Store, bool Mixture, class Policy>
Engine<Store, Policy, Mixture> make_engine(const std::vector<SpeciesSpec>& species, std::int64_t N,
                                           std::vector<Policy> policies, EngineOptions opt,
                                           std::uint64_t init_seed) {
    const auto blocks = make_species_blocks(species, N);
    Store store(static_cast<std::size_t>(N));
    init_maxwellian(store, blocks, init_seed, opt.replica);
    return Engine<Store, Policy, Mixture>(blocks, std::move(policies), std::move(store), opt);
}

template <class E> std::string state_of(const E& e) {
    ByteWriter w;
    e.save_state(w);
    return w.take();
}

// Every particle's v and omega, bitwise.
template <class E> bool same_particles(const E& a, const E& b) {
    for (std::size_t i = 0; i < a.particles(); ++i)
        for (const auto& [x, y] :
             {std::pair{a.store().v(i), b.store().v(i)}, {a.store().w(i), b.store().w(i)}})
            if (std::memcmp(&x, &y, sizeof x) != 0)
                return false;
    return true;
}

// Saves `e` after `first` collisions, loads the state into an engine started from other
// velocities (and, for groups, run on `threads_after` threads), then advances both by a
// collision target and by a time: the two must stay identical in every bit.
template <class Store, bool Mixture, class Policy>
void expect_round_trip(const std::vector<SpeciesSpec>& species, std::int64_t N, std::vector<Policy> policies,
                       EngineOptions opt, int threads_after) {
    auto e = make_engine<Store, Mixture>(species, N, policies, opt, opt.seed);
    const std::int64_t first = 3 * N + 17; // mid-step: a pending candidate, pre-drawn rings
    e.run_collisions(first);
    const std::string saved = state_of(e);

    auto f = make_engine<Store, Mixture>(species, N, policies, opt, opt.seed + 1000);
    ASSERT_FALSE(same_particles(e, f)); // the load below has something to do
    f.set_threads(threads_after);
    ByteReader r(saved);
    f.load_state(r);
    EXPECT_EQ(r.remaining(), 0u);
    EXPECT_EQ(state_of(f), saved);

    for (auto* x : {&e, &f}) {
        x->run_collisions(first + 5 * N + 3);
        x->run(std::numeric_limits<std::int64_t>::max(), x->time() + 0.731, IgnoreCollisions{});
    }
    EXPECT_TRUE(same_particles(e, f));
    EXPECT_EQ(e.time(), f.time());
    EXPECT_EQ(e.collisions(), f.collisions());
    EXPECT_EQ(e.counters().candidates, f.counters().candidates);
    EXPECT_EQ(e.counters().steps, f.counters().steps);
    EXPECT_EQ(state_of(e), state_of(f)); // the rest too: blocks, rings, streams, clocks
}

SpeciesSpec grain(double m = 1, double R = 0.5, double T = 1, double fraction = 1) {
    SpeciesSpec s;
    s.mass = m;
    s.radius = R;
    s.temperature = T;
    s.fraction = fraction;
    return s;
}

TEST(EngineState, RoughOneGroupContinuesBitForBit) {
    expect_round_trip<RoughAoS, false>({grain()}, 3000, std::vector{make_rough_constant(0.8, 0.3)},
                                       EngineOptions{1.0, 1.0, 5, 2, 2, 1, 1}, 1);
}

TEST(EngineState, GroupedRunContinuesBitForBitOnOtherThreads) {
    // 4 groups, saved from one thread, continued on two (the groups in parallel).
    expect_round_trip<RoughAoS, false>({grain()}, 8000, std::vector{make_rough_constant(0.7, -0.2)},
                                       EngineOptions{1.0, 0.5, 9, 0, 3, 4, 1}, 2);
}

TEST(EngineState, SmoothMixtureContinuesBitForBit) {
    expect_round_trip<SmoothAoS, true>(
        {grain(1, 0.5, 1, 0.3), grain(4, 0.8, 2, 0.7)}, 4000,
        std::vector{make_smooth_constant(0.9), make_smooth_constant(0.8), make_smooth_constant(0.7)},
        EngineOptions{1.0, 1.0, 3, 1, 2, 2, 1}, 2);
}

TEST(EngineState, RefusesTheStateOfAnotherEngine) {
    const auto policy = std::vector{make_rough_constant(0.8, 0.3)};
    auto e = make_engine<RoughAoS, false>({grain()}, 2000, policy, EngineOptions{1.0, 1.0, 5, 0, 2, 1, 1}, 5);
    e.run_collisions(1000);
    const std::string saved = state_of(e);
    const auto load_into = [&](std::int64_t N, int groups, std::string_view bytes) {
        auto f = make_engine<RoughAoS, false>({grain()}, N, policy,
                                              EngineOptions{1.0, 1.0, 5, 0, 2, groups, 1}, 5);
        ByteReader r(bytes);
        f.load_state(r);
    };
    EXPECT_NO_THROW(load_into(2000, 1, saved));
    EXPECT_THROW(load_into(1000, 1, saved), std::runtime_error); // other particle count
    EXPECT_THROW(load_into(2000, 2, saved), std::runtime_error); // other groups
    EXPECT_THROW(load_into(2000, 1, std::string_view(saved).substr(0, saved.size() / 2)), std::runtime_error);
}

// ---- run_replica ----

using Rows = std::vector<std::vector<double>>;

struct Outcome {
    Rows rows;
    std::vector<HistogramSet> histograms;
    ReplicaEnd end = ReplicaEnd::finished;
};

// A checkpoint as the caller of run_replica stores it: the state with the rows and sets before it.
struct Saved {
    std::string state;
    Outcome before;
};

// Bitwise (NaN, as coll_rate at t = 0, equals itself).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}
bool same_bits(const Rows& a, const Rows& b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!same_bits(a[k], b[k]))
            return false;
    return true;
}
bool same_bits(const std::vector<HistogramSet>& a, const std::vector<HistogramSet>& b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (!same_bits(std::vector{a[k].t, a[k].coll_per_particle},
                       std::vector{b[k].t, b[k].coll_per_particle}) ||
            a[k].species.size() != b[k].species.size())
            return false;
        for (std::size_t s = 0; s < a[k].species.size(); ++s) {
            const SpeciesHistograms &x = a[k].species[s], &y = b[k].species[s];
            if (!same_bits(x.c, y.c) || !same_bits(x.w, y.w) || !same_bits(x.cw, y.cw))
                return false;
        }
    }
    return true;
}

// Runs replica 1 of `spec`, recording what a checkpointing caller would store.
Outcome run(const RunSpec& spec, ReplicaCheckpoints* ck = nullptr, std::vector<Saved>* saved = nullptr) {
    const auto tables = RestitutionTables::build(spec);
    Outcome o;
    if (ck && saved)
        ck->save = [&](std::string state) { saved->push_back({std::move(state), o}); };
    o.end = run_replica(
        spec, *tables, 1, [&](std::span<const double> r) { o.rows.emplace_back(r.begin(), r.end()); }, {},
        nullptr, [&](const HistogramSet& h) { o.histograms.push_back(h); }, ck);
    return o;
}

RunSpec cooling_spec() {
    RunSpec s;
    s.species = {SpeciesSpec{}};
    s.pairs = {ConstantRestitution{0.8, 0.4}};
    s.particles = 3000;
    s.end = 6;
    s.output_times = {1, 2, 3, 4, 5, 6};
    s.histogram_times = {2.5, 6};
    s.histogram_bins = 20;
    s.groups = 2;
    s.seed = 13;
    return s;
}

RunSpec shear_spec() {
    RunSpec s = cooling_spec();
    s.histogram_times = {3};
    s.shear = ShearSpec{0.7, 0.2};
    return s;
}

// The rows and sets of the run resumed from `c` follow its stored ones to give the whole run.
void expect_resumes_to(const RunSpec& spec, const Saved& c, const Outcome& whole) {
    ReplicaCheckpoints ck;
    ck.resume = c.state;
    RunSpec other_threads = spec;
    other_threads.threads = 2; // no influence on the results, resumed or not
    const Outcome rest = run(other_threads, &ck);
    Outcome joined = c.before;
    joined.rows.insert(joined.rows.end(), rest.rows.begin(), rest.rows.end());
    joined.histograms.insert(joined.histograms.end(), rest.histograms.begin(), rest.histograms.end());
    EXPECT_EQ(rest.end, ReplicaEnd::finished);
    EXPECT_TRUE(same_bits(joined.rows, whole.rows)) << "resumed after row " << c.before.rows.size();
    EXPECT_TRUE(same_bits(joined.histograms, whole.histograms))
        << "resumed after row " << c.before.rows.size();
}

void expect_checkpoints_are_exact(const RunSpec& spec, double every, std::size_t min_states) {
    const Outcome whole = run(spec);
    ReplicaCheckpoints ck;
    ck.every = every;
    std::vector<Saved> saved;
    const Outcome with = run(spec, &ck, &saved);
    EXPECT_TRUE(same_bits(with.rows, whole.rows)) << "taking checkpoints changed the rows";
    EXPECT_TRUE(same_bits(with.histograms, whole.histograms));
    EXPECT_GE(saved.size(), min_states);
    for (const Saved& c : saved)
        expect_resumes_to(spec, c, whole);
}

TEST(ReplicaCheckpoints, CoolingResumesFromEveryCheckpointBitForBit) {
    // Chunks of 65536 collisions are longer than an output interval (1500): a state at every row.
    expect_checkpoints_are_exact(cooling_spec(), 0.5, 6);
}

TEST(ReplicaCheckpoints, ShearResumesBetweenStrangStepsBitForBit) {
    // Strang steps of 0.2 mean free times (about 0.1 collisions per particle): states every
    // 0.35 collisions per particle fall between two steps of an interval, not at its rows.
    const RunSpec spec = shear_spec();
    expect_checkpoints_are_exact(spec, 0.35, 12);
}

TEST(ReplicaCheckpoints, HeatedBoxResumesBitForBit) {
    // A periodic box heated by white noise (exact energy, a share to the spins): its state holds the
    // time the kicks reached; states every 0.35 collisions per particle fall between the box's steps.
    RunSpec spec = cooling_spec();
    spec.histogram_times.clear();
    spec.density = 0.05;
    DomainSpec d;
    d.size = {30, 30, 30};
    d.cells = {4, 4, 4};
    spec.domain = d;
    ThermostatSpec th;
    th.kind = ThermostatKind::white_noise;
    th.exact_energy = true;
    SpeciesThermostat s;
    s.drive.value = {0.2};
    s.rotational_share = 0.2;
    th.species = {s};
    spec.thermostat = th;
    expect_checkpoints_are_exact(spec, 0.35, 12);
}

TEST(ReplicaCheckpoints, StopSavesTheStateAndReturnsStopped) {
    for (const RunSpec& spec : {cooling_spec(), shear_spec()}) {
        const Outcome whole = run(spec);
        ReplicaCheckpoints ck;
        int polls = 0;
        ck.stop = [&] { return ++polls == 9; };
        std::vector<Saved> saved;
        const Outcome stopped = run(spec, &ck, &saved);
        EXPECT_EQ(stopped.end, ReplicaEnd::stopped);
        ASSERT_EQ(saved.size(), 1u); // no interval: only the stop's
        EXPECT_EQ(polls, 9);
        EXPECT_LT(stopped.rows.size(), whole.rows.size());
        expect_resumes_to(spec, saved[0], whole);
    }
}

// A replica started from a saved state (RunSpec::initial_state): its row at t = 0 is the state's
// (the same grains, less a mean velocity of round-off); its checkpoints change no row; resumed from
// any of them it gives the uninterrupted rows bit for bit without reading the state again.
TEST(ReplicaCheckpoints, AStartFromASavedStateResumesWithoutReadingItAgain) {
    RunSpec first = cooling_spec();
    first.histogram_times.clear();
    GrainState saved_state;
    first.final_state = [&](int, const GrainState& g) { saved_state = g; };
    const Outcome before = run(first);
    ASSERT_EQ(saved_state.v.size(), 3000u);
    RunSpec spec = cooling_spec();
    spec.seed = 29;
    int reads = 0;
    spec.initial_state = [&](int replica) {
        EXPECT_EQ(replica, 1); // run() runs replica 1
        ++reads;
        return saved_state;
    };
    const Outcome whole = run(spec);
    EXPECT_EQ(reads, 1);
    // The same moments of the same grains.
    ASSERT_FALSE(whole.rows.empty());
    const std::vector<double>&start = whole.rows.front(), &end = before.rows.back();
    const std::vector<Column> columns = dsmc_columns(spec);
    ASSERT_EQ(start.size(), columns.size());
    EXPECT_EQ(start[0], 0.0); // t
    EXPECT_EQ(start[1], 0.0); // coll_per_particle
    int compared = 0;
    for (std::size_t k = 0; k < columns.size(); ++k)
        for (const char* name : {"T_tr", "T_rot", "theta", "a20", "a02", "a11"})
            if (columns[k].name == name) {
                ++compared;
                EXPECT_NEAR(start[k] / end[k], 1.0, 1e-12) << name;
            }
    EXPECT_EQ(compared, 6);
    ReplicaCheckpoints ck;
    ck.every = 1;
    std::vector<Saved> saved;
    reads = 0;
    const Outcome with = run(spec, &ck, &saved);
    EXPECT_EQ(reads, 1);
    EXPECT_TRUE(same_bits(with.rows, whole.rows)) << "taking checkpoints changed the rows";
    ASSERT_GE(saved.size(), 4u);
    reads = 0;
    for (const Saved& c : saved)
        expect_resumes_to(spec, c, whole);
    EXPECT_EQ(reads, 0);
}

TEST(ReplicaCheckpoints, ResumeRefusesAStateOfAnotherRun) {
    ReplicaCheckpoints ck;
    ck.every = 2;
    std::vector<Saved> saved;
    run(cooling_spec(), &ck, &saved);
    ASSERT_FALSE(saved.empty());
    RunSpec smooth = cooling_spec();
    smooth.pairs = {ConstantRestitution{0.8, -1.0}}; // another kernel: smooth spheres
    ReplicaCheckpoints resume;
    resume.resume = saved[0].state;
    EXPECT_THROW(run(smooth, &resume), ResumeError);
    RunSpec more = cooling_spec();
    more.particles = 4000;
    EXPECT_THROW(run(more, &resume), ResumeError);
    resume.resume = saved[0].state.substr(0, saved[0].state.size() - 1);
    EXPECT_THROW(run(cooling_spec(), &resume), ResumeError);
    resume.resume = "not a state";
    EXPECT_THROW(run(cooling_spec(), &resume), ResumeError);
}

} // namespace
} // namespace roughgas
