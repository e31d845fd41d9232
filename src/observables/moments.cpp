#include "roughgas/observables/moments.hpp"

#include "roughgas/core/worker_team.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace roughgas {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

struct Sums { // over reduced vectors
    double c2 = 0, w2 = 0, c4 = 0, w4 = 0, c2w2 = 0, cw2 = 0;
    Sums& operator+=(const Sums& o) {
        c2 += o.c2;
        w2 += o.w2;
        c4 += o.c4;
        w4 += o.w4;
        c2w2 += o.c2w2;
        cw2 += o.cw2;
        return *this;
    }
};

// The grains in chunks of at most `chunk_grains` (none straddling two species), fixed by the
// species' ranges alone: each pass sums within a chunk and then adds the chunks' sums in chunk
// order, so the result is the same for any thread count. 8192 grains (256-384 KiB of v and omega)
// stay in a core's L2 between pass 1's two loops over them.
constexpr std::size_t chunk_grains = 8192;
struct Chunk {
    std::size_t species, begin, end;
};
std::vector<Chunk> chunks_of(std::span<const SpeciesSlice> species) {
    std::vector<Chunk> chunks;
    for (std::size_t s = 0; s < species.size(); ++s)
        for (std::size_t b = species[s].offset; b < species[s].offset + species[s].count; b += chunk_grains)
            chunks.push_back({s, b, std::min(b + chunk_grains, species[s].offset + species[s].count)});
    return chunks;
}

struct FirstSums {
    Vec3 sum{};    // of v
    double m2 = 0; // of |v - mean|^2, mean = sum / n
    double w2 = 0; // of |omega|^2
};

void finish(GroupMoments& g, const Sums& s, double n, bool has_rotation) {
    if (!(n > 0)) {
        g.T_tr = g.T_rot = g.theta = g.a20 = g.a02 = g.a11 = g.A_cw = nan;
        return;
    }
    g.a20 = (4.0 / 15.0) * s.c4 / n - 1.0;
    if (has_rotation) {
        g.a02 = (4.0 / 15.0) * s.w4 / n - 1.0;
        g.a11 = (4.0 / 9.0) * s.c2w2 / n - 1.0;
        g.A_cw = (s.cw2 / n) / ((s.c2 / n) * (s.w2 / n)) - 1.0 / 3.0;
    } else {
        g.a02 = g.a11 = g.A_cw = nan;
    }
}

void add(Sums& s, const Vec3& c, const Vec3& w) {
    const double c2 = norm2(c), w2 = norm2(w), cw = dot(c, w);
    s.c2 += c2;
    s.w2 += w2;
    s.c4 += c2 * c2;
    s.w4 += w2 * w2;
    s.c2w2 += c2 * w2;
    s.cw2 += cw * cw;
}

} // namespace

Vec3 weighted_mean(Vec3Column x, std::span<const SpeciesSlice> species, double SpeciesSlice::*weight) {
    Vec3 sum{};
    double total = 0;
    for (const SpeciesSlice& sp : species) {
        Vec3 s{};
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i)
            s += x[i];
        sum += sp.*weight * s;
        total += sp.*weight * static_cast<double>(sp.count);
    }
    return total > 0 ? (1.0 / total) * sum : Vec3{};
}

Moments compute_moments(Vec3Column v, Vec3Column omega, std::span<const SpeciesSlice> species, int threads) {
    WorkerTeam team(threads); // no thread started for threads <= 1
    return compute_moments(v, omega, species, team);
}

Moments compute_moments(Vec3Column v, Vec3Column omega, std::span<const SpeciesSlice> species, WorkerTeam& team) {
    Moments m;
    m.species.resize(species.size());
    const std::vector<Chunk> chunks = chunks_of(species);
    const std::size_t K = chunks.size();
    // Each chunk writes its own sums, combined in chunk order: the same bits on any team.
    const auto for_chunks = [&](auto&& f) { team.for_each(K, f); };

    // Pass 1, per chunk: its sum of v, its sum of |v - mean|^2 about its own mean (a second loop
    // over the chunk, in cache) and its sum of |omega|^2.
    std::vector<FirstSums> first(chunks.size());
    for_chunks([&](std::size_t k) {
        const Chunk& ch = chunks[k];
        FirstSums f;
        for (std::size_t i = ch.begin; i < ch.end; ++i) {
            f.sum += v[i];
            f.w2 += norm2(omega[i]);
        }
        const Vec3 mean = (1.0 / static_cast<double>(ch.end - ch.begin)) * f.sum;
        for (std::size_t i = ch.begin; i < ch.end; ++i)
            f.m2 += norm2(v[i] - mean);
        first[k] = f;
    });

    // The centre-of-mass velocity u (mass-weighted), then each species' sum of |v - u|^2 from its
    // chunks' (Chan, Golub & LeVeque 1979): sum over a chunk of |v - u|^2 = m2 + n |mean - u|^2.
    std::vector<Vec3> sum_v(species.size());
    for (std::size_t k = 0; k < chunks.size(); ++k)
        sum_v[chunks[k].species] += first[k].sum;
    std::size_t n_all = 0;
    Vec3 momentum{};
    double mass = 0;
    for (std::size_t s = 0; s < species.size(); ++s) {
        n_all += species[s].count;
        momentum += species[s].mass * sum_v[s];
        mass += species[s].mass * static_cast<double>(species[s].count);
    }
    const Vec3 u = mass > 0 ? (1.0 / mass) * momentum : Vec3{};
    m.mean_velocity = u;
    std::vector<double> c2(species.size(), 0.0), w2(species.size(), 0.0);
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        const double n = static_cast<double>(chunks[k].end - chunks[k].begin);
        const FirstSums& f = first[k];
        c2[chunks[k].species] += f.m2 + n * norm2((1.0 / n) * f.sum - u);
        w2[chunks[k].species] += f.w2;
    }

    // Temperatures.
    double mc2_all = 0, Jw2_all = 0;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSlice& sp = species[s];
        const double n = static_cast<double>(sp.count);
        GroupMoments& g = m.species[s];
        g.count = sp.count;
        g.T_tr = sp.mass * c2[s] / (3.0 * n);
        g.T_rot = sp.moment_of_inertia * w2[s] / (3.0 * n);
        g.theta = g.T_rot / g.T_tr;
        mc2_all += sp.mass * c2[s];
        Jw2_all += sp.moment_of_inertia * w2[s];
    }
    const double N = static_cast<double>(n_all);
    m.all.count = n_all;
    m.all.T_tr = mc2_all / (3.0 * N);
    m.all.T_rot = Jw2_all / (3.0 * N);
    m.all.theta = m.all.T_rot / m.all.T_tr;
    const bool rot_all = m.all.T_rot > 0;

    // Pass 2: fourth moments on reduced vectors. Per species: c* = c sqrt(m/(2 T_tr,s)); over all,
    // the same with the mixture's temperatures, so that every grain's c* and w* have the unit
    // Maxwellian's law when each species is Maxwellian at the mixture's temperatures (the cumulants
    // and A_cw then vanish, whatever the species' m and J).
    struct Scales {
        double sc, sw, sc_all, sw_all;
    };
    std::vector<Scales> scales(species.size());
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSlice& sp = species[s];
        const GroupMoments& g = m.species[s];
        scales[s] = {std::sqrt(sp.mass / (2.0 * g.T_tr)),
                     g.T_rot > 0 ? std::sqrt(sp.moment_of_inertia / (2.0 * g.T_rot)) : 0.0,
                     std::sqrt(sp.mass / (2.0 * m.all.T_tr)),
                     rot_all ? std::sqrt(sp.moment_of_inertia / (2.0 * m.all.T_rot)) : 0.0};
    }
    std::vector<Sums> own_of(chunks.size()), all_of(chunks.size());
    for_chunks([&](std::size_t k) {
        const Chunk& ch = chunks[k];
        const Scales& f = scales[ch.species];
        Sums own, all;
        for (std::size_t i = ch.begin; i < ch.end; ++i) {
            const Vec3 c = v[i] - u;
            const Vec3& w = omega[i];
            add(own, f.sc * c, f.sw * w);
            add(all, f.sc_all * c, f.sw_all * w);
        }
        own_of[k] = own;
        all_of[k] = all;
    });
    std::vector<Sums> own(species.size());
    Sums all;
    for (std::size_t k = 0; k < chunks.size(); ++k) {
        own[chunks[k].species] += own_of[k];
        all += all_of[k];
    }
    for (std::size_t s = 0; s < species.size(); ++s)
        finish(m.species[s], own[s], static_cast<double>(species[s].count), m.species[s].T_rot > 0);
    finish(m.all, all, N, rot_all);
    return m;
}

} // namespace roughgas
