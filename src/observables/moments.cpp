#include "roughgas/observables/moments.hpp"

#include <cmath>
#include <limits>

namespace roughgas {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

struct Sums { // over reduced vectors
    double c2 = 0, w2 = 0, c4 = 0, w4 = 0, c2w2 = 0, cw2 = 0;
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

Moments compute_moments(Vec3Column v, Vec3Column omega, std::span<const SpeciesSlice> species) {
    Moments m;
    m.species.resize(species.size());

    // Pass 1: centre-of-mass velocity.
    std::size_t n_all = 0;
    for (const SpeciesSlice& sp : species)
        n_all += sp.count;
    const Vec3 u = weighted_mean(v, species, &SpeciesSlice::mass);
    m.mean_velocity = u;

    // Pass 2: second moments -> temperatures.
    std::vector<double> c2(species.size(), 0.0), w2(species.size(), 0.0);
    double mc2_all = 0, Jw2_all = 0;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSlice& sp = species[s];
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            c2[s] += norm2(v[i] - u);
            w2[s] += norm2(omega[i]);
        }
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

    // Pass 3: fourth moments on reduced vectors. Per species: c* = c sqrt(m/(2 T_tr,s)); over all,
    // the same with the mixture's temperatures, so that every grain's c* and w* have the unit
    // Maxwellian's law when each species is Maxwellian at the mixture's temperatures (the cumulants
    // and A_cw then vanish, whatever the species' m and J).
    Sums all;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSlice& sp = species[s];
        GroupMoments& g = m.species[s];
        const bool rot = g.T_rot > 0;
        const double sc = std::sqrt(sp.mass / (2.0 * g.T_tr));
        const double sw = rot ? std::sqrt(sp.moment_of_inertia / (2.0 * g.T_rot)) : 0.0;
        const double sc_all = std::sqrt(sp.mass / (2.0 * m.all.T_tr));
        const double sw_all = rot_all ? std::sqrt(sp.moment_of_inertia / (2.0 * m.all.T_rot)) : 0.0;
        Sums own;
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            const Vec3 c = v[i] - u;
            const Vec3& w = omega[i];
            add(own, sc * c, sw * w);
            add(all, sc_all * c, sw_all * w);
        }
        finish(g, own, static_cast<double>(sp.count), rot);
    }
    finish(m.all, all, N, rot_all);
    return m;
}

} // namespace roughgas
