#pragma once
// The DSMC collision engine of the homogeneous gas: the hard-sphere kernel of physics.md §4
// sampled exactly, with the collision rule of physics.md §3, for a store layout `Store`, one
// restitution policy type `Policy` and, at compile time, one species or a mixture.
//
// Kernel. In a gas of number density n simulated by N particles (volume V = N/n), each unordered
// pair (i, j) of species (a, b) collides at the rate pi sigma_ab^2 |v_i - v_j| / V, the direction n
// having density proportional to |g^ . n| on the approaching hemisphere (physics.md §4).
//
// Exact majorant (sequential thinning). Per pair type (a, b), candidates form a Poisson process of
// rate Lambda_ab = P_ab pi sigma_ab^2 g_max,ab / V, P_ab the number of distinct pairs, with
// g_max,ab = vmax_a + vmax_b, vmax_s = max over species s of |v|: a true bound on |v_i - v_j|
// because |v_i - v_j| <= |v_i| + |v_j|. A candidate is a uniformly random pair of the type, accepted
// with probability |g_c|/g_max,ab. The superposition of the types is one Poisson clock of rate
// Lambda = sum Lambda_ab whose events pick a type with probability Lambda_ab/Lambda. Time advances
// by exponential increments of rate Lambda; when a collision makes a grain faster than vmax, vmax,
// g_max and Lambda grow at once and the next increment is drawn at the new rate (memoryless, so
// exact: the majorant bounds the true rate at every instant and is never exceeded). A particle may
// collide any number of times per step.
//
// Steps. A step lasts `step` mean free times (at the step's start, Maxwellian estimate), and only
// refreshes the bound: vmax is recomputed exactly (it can then shrink as the gas cools) and the
// residual mean velocity is removed (a Galilean shift, exact for a homogeneous gas). The candidate
// that would fall after the step's end is discarded (memoryless again), so the statistics do not
// depend on the step length (tests/dsmc/engine_test.cpp). Each step draws from its own stream
// (seed, collisions, replica, step, unit): the unit for a later per-step random partition of the
// particles into groups, each with its own stream and candidate process (rate scaled by the
// fraction of pairs inside groups), is one call of the step loop on a set of species ranges.
//
// Pauses. run() stops after a given collision count or before a given time, keeping the pending
// candidate: stopping and resuming never changes the trajectory, so the output schedule does not
// influence the results.
//
// Latency. Candidate pairs do not depend on the state, so they are drawn `ring_size` candidates
// ahead and their grains prefetched: the random loads of several candidates are in flight at once.
#include "roughgas/collision/rule.hpp"
#include "roughgas/collision/sampling.hpp"
#include "roughgas/core/rng.hpp"
#include "roughgas/dsmc/species.hpp"

#include <boost/random/exponential_distribution.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace roughgas {

struct EngineOptions {
    double density = 1;         // number density n of the gas
    double step = 0.5;          // step length in mean free times (no influence on the statistics)
    std::uint64_t seed = 1;
    std::uint64_t replica = 0;
};

enum class StopReason { collisions, time, stalled };

// Counts of what the engine did.
struct EngineCounters {
    std::int64_t collisions = 0;
    std::int64_t candidates = 0;
    std::int64_t steps = 0;
    std::int64_t bound_raises = 0; // collisions after which vmax (and the candidate rate) grew
    double max_mean_drift = 0;     // largest residual |u| found at a step start, over the rms speed
};

// An observer that ignores every collision.
struct IgnoreCollisions {
    void operator()(const CollisionRecord&, std::size_t /*pair type*/) const {}
};

template <class Store, class Policy, bool Mixture>
class Engine {
    static_assert(!Policy::needs_rotation || Store::rotation_hot, "a rough policy needs a store with omega");

public:
    static constexpr unsigned ring_size = 16; // candidates drawn (and prefetched) ahead

    // `policies[k]` is the restitution of pair type k (species.hpp); one entry without Mixture.
    Engine(std::vector<SpeciesBlock> species, std::vector<Policy> policies, Store store, EngineOptions opt)
        : species_(std::move(species)), types_(make_pair_types(species_)), policies_(std::move(policies)),
          store_(std::move(store)), opt_(opt) {
        if (!Mixture && species_.size() != 1) throw std::invalid_argument("Engine: one-species engine given a mixture");
        if (policies_.size() != types_.size()) throw std::invalid_argument("Engine: one policy per species pair");
        std::size_t n = 0;
        for (const auto& s : species_) n += s.count;
        if (n != store_.size()) throw std::invalid_argument("Engine: store size differs from the species counts");
        if (n > std::numeric_limits<std::uint32_t>::max()) throw std::invalid_argument("Engine: too many particles");
        volume_ = static_cast<double>(n) / opt_.density;
        const std::size_t S = species_.size(), K = types_.size();
        vmax2_.assign(S, 0.0);
        vmax_.assign(S, 0.0);
        gmax_.assign(K, 0.0);
        cumulative_.assign(K, 0.0);
        rings_.resize(K);
    }

    // Advances until `collision_target` collisions in all (returns `collisions` right after that
    // collision, time() being its time) or until the next candidate would come at or after
    // `t_stop` (returns `time`, time() = t_stop if t_stop is finite). `stalled`: no collision can
    // ever happen (every grain at rest in the centre-of-mass frame).
    // `obs(const CollisionRecord&, std::size_t pair_type)` sees every collision.
    template <class Observer>
    StopReason run(std::int64_t collision_target, double t_stop, Observer&& obs) {
        if (c_.collisions >= collision_target) return StopReason::collisions;
        for (;;) {
            if (t_next_ >= t_step_end_) {
                if (stalled_) {
                    if (std::isfinite(t_stop)) t_ = std::max(t_, t_stop);
                    return std::isfinite(t_stop) ? StopReason::time : StopReason::stalled;
                }
                begin_step();
                continue;
            }
            if (t_next_ >= t_stop) {
                t_ = t_stop;
                return StopReason::time;
            }
            t_ = t_next_;
            ++c_.candidates;
            std::size_t k = 0;
            if constexpr (Mixture) k = choose_type();
            const Candidate cand = next_candidate(k);
            Vec3& v_i = store_.v(cand.i);
            Vec3& v_j = store_.v(cand.j);
            const Vec3 g_c = v_i - v_j;
            const double g2 = norm2(g_c);
            const double x = uniform01(rng_) * gmax_[k];
            if (x * x < g2) { // accepted with probability |g_c|/g_max
                const Vec3 n = sample_impact_normal(rng_, g_c, std::sqrt(g2));
                const PairConstants& pc = types_[k].pc;
                const Policy& policy = policies_[k];
                CollisionRecord rec;
                if constexpr (Policy::needs_rotation) {
                    rec = collide(pc, policy, v_i, store_.w(cand.i), v_j, store_.w(cand.j), n);
                } else {
                    rec = collide(pc, policy, v_i, v_j, n);
                }
                ++c_.collisions;
                obs(rec, k);
                const std::size_t a = Mixture ? types_[k].a : 0, b = Mixture ? types_[k].b : 0;
                const double vi2 = norm2(v_i), vj2 = norm2(v_j);
                if (vi2 > vmax2_[a] || vj2 > vmax2_[b]) [[unlikely]] {
                    vmax2_[a] = std::max(vmax2_[a], vi2);
                    vmax2_[b] = std::max(vmax2_[b], vj2);
                    ++c_.bound_raises;
                    update_rates();
                }
                t_next_ = t_ + exponential_(rng_) * inv_rate_;
                if (c_.collisions >= collision_target) return StopReason::collisions;
            } else {
                t_next_ = t_ + exponential_(rng_) * inv_rate_;
            }
        }
    }
    StopReason run_collisions(std::int64_t collision_target) {
        return run(collision_target, std::numeric_limits<double>::infinity(), IgnoreCollisions{});
    }

    double time() const { return t_; }
    std::int64_t collisions() const { return c_.collisions; }
    const EngineCounters& counters() const { return c_; }
    const Store& store() const { return store_; }
    Store& store() { return store_; }
    const std::vector<SpeciesBlock>& species() const { return species_; }
    const std::vector<PairType>& pair_types() const { return types_; }
    const std::vector<Policy>& policies() const { return policies_; }
    double volume() const { return volume_; }
    std::size_t particles() const { return store_.size(); }
    // Length and end of the current step, and the current majorant (for tests and diagnostics).
    double step_length() const { return step_length_; }
    double candidate_rate() const { return rate_; }
    double vmax(std::size_t s) const { return vmax_[s]; }

private:
    struct Candidate {
        std::uint32_t i, j;
    };
    struct Ring {
        std::array<Candidate, ring_size> c{};
        unsigned head = 0;
    };

    Candidate draw_candidate(std::size_t k) {
        const PairType& t = types_[k];
        const SpeciesBlock& A = species_[t.a];
        Candidate c;
        if (Mixture && t.a != t.b) {
            const SpeciesBlock& B = species_[t.b];
            c.i = static_cast<std::uint32_t>(A.offset + uniform_index(rng_, A.count));
            c.j = static_cast<std::uint32_t>(B.offset + uniform_index(rng_, B.count));
        } else { // a distinct pair of one species: j uniform among the others
            const std::uint64_t i = uniform_index(rng_, A.count);
            std::uint64_t j = uniform_index(rng_, A.count - 1);
            j += j >= i;
            c.i = static_cast<std::uint32_t>(A.offset + i);
            c.j = static_cast<std::uint32_t>(A.offset + j);
        }
        store_.prefetch(c.i);
        store_.prefetch(c.j);
        return c;
    }

    Candidate next_candidate(std::size_t k) {
        Ring& r = rings_[k];
        const Candidate c = r.c[r.head];
        r.c[r.head] = draw_candidate(k);
        r.head = (r.head + 1) % ring_size;
        return c;
    }

    std::size_t choose_type() {
        const double x = uniform01(rng_) * rate_;
        std::size_t k = 0;
        while (k + 1 < cumulative_.size() && !(x < cumulative_[k])) ++k;
        return k;
    }

    void update_rates() {
        for (std::size_t s = 0; s < species_.size(); ++s) vmax_[s] = std::sqrt(vmax2_[s]);
        double total = 0;
        for (std::size_t k = 0; k < types_.size(); ++k) {
            const PairType& t = types_[k];
            // (1 + 1e-12): the computed |g_c| of the two fastest grains head-on may round above the
            // computed vmax_a + vmax_b; the inflation keeps the acceptance probability below 1.
            gmax_[k] = (vmax_[t.a] + vmax_[t.b]) * (1.0 + 1e-12);
            total += t.pairs * t.pc.cross_section * gmax_[k] / volume_;
            cumulative_[k] = total;
        }
        rate_ = total;
        inv_rate_ = 1.0 / total;
    }

    // Refreshes the bound and the frame, sets the step length, and starts the step's stream.
    void begin_step() {
        const std::size_t S = species_.size();
        const Vec3 u = mean_;
        Vec3 momentum{};
        double mass = 0, mv2_all = 0;
        std::vector<double> mv2(S, 0.0);
        for (std::size_t s = 0; s < S; ++s) {
            const SpeciesBlock& sp = species_[s];
            double m2 = 0, sum2 = 0;
            Vec3 ps{};
            for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
                Vec3& v = store_.v(i);
                v -= u;
                const double v2 = norm2(v);
                m2 = std::max(m2, v2);
                sum2 += v2;
                ps += v;
            }
            vmax2_[s] = m2;
            mv2[s] = sp.grain.mass * sum2;
            mv2_all += mv2[s];
            momentum += sp.grain.mass * ps;
            mass += sp.grain.mass * static_cast<double>(sp.count);
        }
        // The residual mean (round-off of momentum conservation) is removed at the next step start.
        mean_ = (1.0 / mass) * momentum;
        if (mv2_all > 0) c_.max_mean_drift = std::max(c_.max_mean_drift, norm(mean_) / std::sqrt(mv2_all / mass));

        // Mean free time from the Maxwellian collision frequency at the species' temperatures:
        // nu = (2/N) sum_ab P_ab pi sigma^2 <g_ab>/V, <g_ab> = sqrt((8/pi)(T_a/m_a + T_b/m_b)).
        double nu = 0;
        for (const PairType& t : types_) {
            const auto T_over_m = [&](std::size_t s) {
                const double N = static_cast<double>(species_[s].count);
                return N > 0 ? mv2[s] / (3.0 * N * species_[s].grain.mass * species_[s].grain.mass) : 0.0;
            };
            const double mean_g = std::sqrt(8.0 / std::numbers::pi * (T_over_m(t.a) + T_over_m(t.b)));
            nu += 2.0 * t.pairs * t.pc.cross_section * mean_g / volume_ / static_cast<double>(store_.size());
        }
        update_rates();
        rng_ = make_stream(StreamKey{opt_.seed, Stream::collisions, opt_.replica, static_cast<std::uint64_t>(c_.steps), 0});
        ++c_.steps;
        const double t0 = t_step_end_;
        if (!(rate_ > 0) || !(nu > 0)) { // nothing moves: no collision can ever happen
            stalled_ = true;
            step_length_ = std::numeric_limits<double>::infinity();
            t_step_end_ = t_next_ = std::numeric_limits<double>::infinity();
            return;
        }
        step_length_ = opt_.step / nu;
        t_step_end_ = t0 + step_length_;
        for (std::size_t k = 0; k < types_.size(); ++k) {
            Ring& r = rings_[k];
            r.head = 0;
            if (types_[k].pairs > 0)
                for (auto& c : r.c) c = draw_candidate(k);
        }
        t_next_ = t0 + exponential_(rng_) * inv_rate_;
    }

    std::vector<SpeciesBlock> species_;
    std::vector<PairType> types_;
    std::vector<Policy> policies_;
    Store store_;
    EngineOptions opt_;
    double volume_ = 0;

    Rng rng_{};
    boost::random::exponential_distribution<double> exponential_{1.0};
    std::vector<double> vmax2_, vmax_, gmax_, cumulative_;
    std::vector<Ring> rings_;
    Vec3 mean_{}; // residual mean velocity found at the last step start
    double rate_ = 0, inv_rate_ = 0;
    double t_ = 0, t_next_ = 0, t_step_end_ = 0, step_length_ = 0;
    bool stalled_ = false;
    EngineCounters c_{};
};

} // namespace roughgas
