#pragma once
// A thermostat's kicks over a stretch of time (run_spec.hpp ThermostatSpec; docs/model.md, "The DSMC"):
// what every grain's velocity and spin become, as the pure functions the engines call once per
// step in their pass over the grains.
//
// Per species s and component, over [t0, t1] (tau = t1 - t0):
//   white noise  v -> v + dv, dv of variance (1 - eps) int xi0^2 dt; omega -> omega + dw, dw of
//                variance eps (m/I) int xi0^2 dt. The kicks alone raise T_tr = m<c^2>/3 by
//                (1 - eps) m int xi0^2 dt and T_rot = I<w^2>/3 by eps m int xi0^2 dt: the injected power
//                (3/2) m xi0^2 per grain, split by eps (the "splitting" thermostat of Megias & Santos
//                2022; eps = 0 the plain white-noise thermostat of van Noije & Ernst 1998).
//   langevin     the Ornstein-Uhlenbeck process dv = -gamma v dt + sqrt(2 gamma T_b/m) dW solved
//                exactly over tau: v -> a v + dv, a = exp(-gamma tau), dv of variance
//                (2 gamma/m) int T_b(s) exp(-2 gamma (t1 - s)) ds (= (T_b/m)(1 - a^2) for a constant
//                bath); the spins the same with gamma_rot and I. Its only equilibrium with elastic
//                collisions is the Maxwellian at T_b (fluctuation-dissipation).
// Both kick variances integrate the drive's schedule exactly over the stretch.
//
// Zero momentum. The kicks of a species in one stretch are N_s independent Gaussian vectors
// conditioned on summing to zero. N iid N(0, s^2) numbers conditioned on their sum S have the
// sequential law x_1 ~ N(S/N, s^2 (N - 1)/N), then the remaining N - 1 conditioned on S - x_1, ...
// (a Gaussian bridge). The species' grains are split into the engine's fixed chunks: the chunk sums
// are drawn first by that law (chunk c of n_c grains: N(R n_c/M, s^2 n_c (M - n_c)/M) with R, M the
// sum and grains left), then each chunk's kicks as n_c iid Gaussians less their mean plus the chunk's
// sum over n_c (the same conditioned law, without a division or square root per grain), chunks in
// parallel, each from its own stream. Every kick then has the law of a kick minus the species' mean
// kick; s^2 = sigma^2 N_s/(N_s - 1) makes each grain's kick variance exactly the sigma^2 above (and
// the expected injected energy exactly the intended one).
//
// Exact energy (white noise, optional). The kicks are generated twice from the same streams: the
// first time to sum B = m sum v.dv and A = m sum dv^2/2 (likewise for the spins), the second to
// apply lambda dv with lambda > 0 the root of A lambda^2 + B lambda = Q, Q the intended energy
// N_s (3/2) m sigma^2: the step injects Q to round-off, still with zero momentum.
#include "roughgas/core/normal.hpp"
#include "roughgas/core/rng.hpp"
#include "roughgas/core/vec.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/dsmc/species.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace roughgas {

// What one stretch's kicks do to the grains of one species, per component: v -> decay_v v + dv with
// dv of variance var_v (each grain's, after the zero-sum conditioning), omega likewise.
struct SpeciesKick {
    double decay_v = 1, var_v = 0;
    double decay_w = 1, var_w = 0;
    bool moves() const { return var_v > 0 || var_w > 0 || decay_v != 1 || decay_w != 1; }
};

// The kicks of species `th` (mass m, moment of inertia I) over [t0, t1].
inline SpeciesKick species_kick(ThermostatKind kind, const SpeciesThermostat& th, double m, double I, double t0,
                                double t1) {
    SpeciesKick k;
    if (!(t1 > t0))
        return k;
    if (kind == ThermostatKind::white_noise) {
        const double xi2_dt = th.drive.integral(t0, t1);
        k.var_v = (1 - th.rotational_share) * xi2_dt;
        k.var_w = th.rotational_share * m / I * xi2_dt;
        return k;
    }
    const double tau = t1 - t0;
    k.decay_v = std::exp(-th.friction * tau);
    k.var_v = 2 * th.friction / m * th.drive.decaying_integral(t0, t1, 2 * th.friction);
    k.decay_w = std::exp(-th.rotational_friction * tau);
    k.var_w = 2 * th.rotational_friction / I * th.drive.decaying_integral(t0, t1, 2 * th.rotational_friction);
    return k;
}

// The stream of one species' kicks in one step: the chunk sums (chunk = -1) or chunk `chunk`'s bridge.
inline StreamKey kick_stream_key(std::uint64_t seed, std::uint64_t replica, std::uint64_t step, std::size_t species,
                                 long chunk) {
    return StreamKey{seed, Stream::thermostat, replica, step,
                     (static_cast<std::uint64_t>(species) << 32) | static_cast<std::uint64_t>(chunk + 1)};
}

// A chunk's n zero-sum kicks of scale s with the vector sum `total`: out[i] + the returned shift,
// i < n. n iid Gaussians z_i (scale s per component) less their mean plus total/n: given their sum,
// iid Gaussians are z_i - mean(z) + sum/n (Gaussian conditioning), so this is the law of the
// sequential bridge without a division or a square root per grain. The kicks sum to `total` to
// round-off. The shift is returned rather than added, so that the pass applying the kicks adds it.
template <class Rng> Vec3 draw_zero_sum(std::size_t n, Vec3 total, double s, Rng& rng, std::vector<Vec3>& out) {
    const ZigguratNormal normal;
    out.resize(n);
    Vec3 sum{};
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 z{s * normal(rng), s * normal(rng), s * normal(rng)};
        out[i] = z;
        sum += z;
    }
    return n > 0 ? (1.0 / static_cast<double>(n)) * (total - sum) : Vec3{};
}

// The sums of `chunks` chunks of sizes sizes[c] (summing to n) of n zero-sum draws of scale s.
template <class Rng> std::vector<Vec3> chunk_sums(const std::vector<std::size_t>& sizes, double s, Rng& rng) {
    std::size_t left = 0;
    for (std::size_t n : sizes)
        left += n;
    const ZigguratNormal normal;
    std::vector<Vec3> sums;
    Vec3 rest{};
    for (std::size_t c = 0; c < sizes.size(); ++c) {
        const double M = static_cast<double>(left), nc = static_cast<double>(sizes[c]);
        if (c + 1 == sizes.size() || sizes[c] == left) {
            sums.push_back(rest);
            rest = Vec3{};
        } else {
            const double sd = s * std::sqrt(nc * (M - nc) / M);
            const Vec3 x = (nc / M) * rest + Vec3{sd * normal(rng), sd * normal(rng), sd * normal(rng)};
            sums.push_back(x);
            rest -= x;
        }
        left -= sizes[c];
    }
    return sums;
}

// The scale s of the bridge that gives each of n grains the kick variance `var`: var n/(n - 1)
// (no kick for a single grain: its zero-sum kick is zero).
inline double bridge_scale(double var, std::size_t n) {
    return n > 1 ? std::sqrt(var * static_cast<double>(n) / static_cast<double>(n - 1)) : 0.0;
}

// lambda > 0 with A lambda^2 + B lambda = Q (A > 0, Q >= 0): the factor on a step's kicks that makes
// them inject exactly Q. Written to avoid cancellation when B > 0.
inline double exact_energy_factor(double A, double B, double Q) {
    if (!(A > 0))
        return 1.0;
    const double d = std::sqrt(B * B + 4 * A * Q);
    return B >= 0 ? 2 * Q / (B + d) : (d - B) / (2 * A);
}

// Per species, one step's kicks as an engine applies them: what they do, the bridge's scales, the
// exact-energy factors, the chunks' sums.
struct StepKick {
    SpeciesKick kick;
    double scale_v = 0, scale_w = 0, lambda_v = 1, lambda_w = 1;
    std::vector<Vec3> sums_v, sums_w;
};
// What a step's kicks would inject into a chunk's grains: A = sum m dv^2/2, B = sum m v.dv (and the
// same for the spins with I).
struct KickEnergy {
    double A_v = 0, B_v = 0, A_w = 0, B_w = 0;
    KickEnergy& operator+=(const KickEnergy& o) {
        A_v += o.A_v, B_v += o.B_v, A_w += o.A_w, B_w += o.B_w;
        return *this;
    }
};

// Where one step's kicks of a species come from: the streams' key (seed, replica, step, species)
// and the species' grains (count n, mass m, moment of inertia I).
struct KickSource {
    std::uint64_t seed = 0, replica = 0, step = 0;
    std::size_t species = 0, n = 0;
    double m = 1, I = 1;
    static KickSource of(std::uint64_t seed, std::uint64_t replica, std::uint64_t step, std::size_t s,
                         const SpeciesBlock& b) {
        return {seed, replica, step, s, b.count, b.grain.mass, b.moment_of_inertia()};
    }
};

// Every species' kicks over [t_kick, t1] into kicks[s].kick, and t_kick moved on to t1; nothing
// when t1 is not later than t_kick. Returns whether any grain is kicked. How both engines plan a
// step's kicks (t1: the middle of the step).
inline bool plan_species_kicks(const ThermostatSpec& th, const std::vector<SpeciesBlock>& species, double t1,
                               double& t_kick, std::vector<StepKick>& kicks) {
    if (!(t1 > t_kick))
        return false;
    bool any = false;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesBlock& b = species[s];
        kicks[s].kick = species_kick(th.kind, th.species[s], b.grain.mass, b.moment_of_inertia(), t_kick, t1);
        any |= kicks[s].kick.moves();
    }
    t_kick = t1;
    return any;
}

// Chunk ch's kicks (its grains, in order, are v(0 .. count - 1) and w(..)), from the chunk's own
// stream: applied (energy == nullptr) or only summed into *energy. The engines call it from a
// function of theirs that is never inlined (see Engine::kick_chunk).
template <class V, class W>
void kick_grains(const KickSource& src, std::size_t ch, std::size_t count, const StepKick& k, V&& v_of, W&& w_of,
                 KickEnergy* energy) {
    CollisionRng rng =
        make_collision_stream(kick_stream_key(src.seed, src.replica, src.step, src.species, static_cast<long>(ch)));
    // The chunk's kicks into this thread's buffers (reused from chunk to chunk: no allocation per step).
    thread_local std::vector<Vec3> dv, dw;
    const Vec3 shift_v = draw_zero_sum(count, k.sums_v[ch], k.scale_v, rng, dv);
    const bool spins = k.kick.var_w > 0 || k.kick.decay_w != 1;
    const Vec3 shift_w = spins ? draw_zero_sum(count, k.sums_w[ch], k.scale_w, rng, dw) : Vec3{};
    const double m = src.m, I = src.I;
    for (std::size_t q = 0; q < count; ++q) {
        const Vec3 kv = dv[q] + shift_v;
        Vec3& v = v_of(q);
        if (energy) {
            energy->A_v += 0.5 * m * norm2(kv);
            energy->B_v += m * dot(v, kv);
        } else {
            v = k.kick.decay_v * v + k.lambda_v * kv;
        }
        if (!spins)
            continue;
        const Vec3 kw = dw[q] + shift_w;
        Vec3& w = w_of(q);
        if (energy) {
            energy->A_w += 0.5 * I * norm2(kw);
            energy->B_w += I * dot(w, kw);
        } else {
            w = k.kick.decay_w * w + k.lambda_w * kw;
        }
    }
}

// A species' kicks of one step over its chunks of sizes[ch] grains: the bridge's scales, the chunks'
// sums and, with `exact_energy`, the factors on the kicks. `sum_chunk(ch, energy)` sums chunk ch's
// kicks (kick_grains with energy set) and `for_chunks(C, f)` runs f over the chunks, on any threads:
// the chunks' sums are combined in chunk order, so the factors do not depend on the threads.
template <class ForChunks, class SumChunk>
void prepare_step_kick(const KickSource& src, const std::vector<std::size_t>& sizes, bool exact_energy, StepKick& k,
                       ForChunks&& for_chunks, SumChunk&& sum_chunk) {
    k.scale_v = bridge_scale(k.kick.var_v, src.n);
    k.scale_w = bridge_scale(k.kick.var_w, src.n);
    k.lambda_v = k.lambda_w = 1;
    CollisionRng rng = make_collision_stream(kick_stream_key(src.seed, src.replica, src.step, src.species, -1));
    k.sums_v = chunk_sums(sizes, k.scale_v, rng);
    k.sums_w = chunk_sums(sizes, k.scale_w, rng);
    if (!exact_energy)
        return;
    const std::size_t C = sizes.size();
    std::vector<KickEnergy> parts(C);
    for_chunks(C, [&](std::size_t ch) { sum_chunk(ch, &parts[ch]); });
    KickEnergy e;
    for (const KickEnergy& p : parts) // in chunk order: independent of the threads
        e += p;
    const double N = static_cast<double>(src.n);
    k.lambda_v = exact_energy_factor(e.A_v, e.B_v, 1.5 * N * src.m * k.kick.var_v);
    k.lambda_w = exact_energy_factor(e.A_w, e.B_w, 1.5 * N * src.I * k.kick.var_w);
}

} // namespace roughgas

namespace roughgas {

// The moments a row reports for a driven gas at time t whose kicks reached t_kick (Engine::kicked_until):
// the moments of the gas at t as the continuous drive has it, to the splitting's O(L^2). The kicks of
// a step are given at its start and lead the time by up to half a step there (lag by up to half a
// step at its end): left alone, a row's T_tr would carry a sawtooth of +-(1/2) x (the drive's power
// over T) x (step length), +-8 % for smooth grains at alpha = 0.7 under white noise with steps of one
// mean free time. A kick over [t_a, t_b] maps c -> a c + g, g Gaussian of variance s^2 per component
// independent of c (and omega -> b omega + h, variance r^2), so that
//   <c^2> -> a^2 <c^2> + 3 s^2,   <c^4> -> a^4 <c^4> + 10 a^2 s^2 <c^2> + 15 s^4,
//   <c^2 w^2> -> a^2 b^2 <c^2 w^2> + 3 r^2 a^2 <c^2> + 3 s^2 b^2 <w^2> + 9 s^2 r^2,
//   <(c.w)^2> -> a^2 b^2 <(c.w)^2> + r^2 a^2 <c^2> + s^2 b^2 <w^2> + 3 s^2 r^2
// (exact in expectation). A gas behind its drive (t_kick < t) gets the kick over [t_kick, t] this way;
// one ahead of it (t_kick > t) has the kick over [t, t_kick] undone by the inverse map. The mixture's
// moments are rebuilt from the species' (docs/model.md §5). The grains themselves are not changed:
// histograms, fields and saved states are the grains as they are.
Moments moments_at_drive_time(const Moments& m, std::span<const SpeciesSlice> species,
                              const ThermostatSpec& thermostat, double t, double t_kick);

} // namespace roughgas
