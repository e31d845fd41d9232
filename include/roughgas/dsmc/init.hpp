#pragma once
// Initial state: Maxwellian v and omega per species at its temperatures (k_B = 1), then the
// mass-weighted mean velocity removed, so the total momentum is zero to round-off.
#include "roughgas/core/rng.hpp"
#include "roughgas/core/vec.hpp"
#include "roughgas/dsmc/grain_state.hpp"
#include "roughgas/dsmc/species.hpp"

#include <boost/random/normal_distribution.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace roughgas {

// Subtracts the mass-weighted mean velocity (the centre-of-mass velocity); returns it.
template <class Store> Vec3 remove_mean_velocity(Store& store, const std::vector<SpeciesBlock>& species) {
    Vec3 p{};
    double M = 0;
    for (const SpeciesBlock& sp : species) {
        Vec3 ps{};
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i)
            ps += store.v(i);
        p += sp.grain.mass * ps;
        M += sp.grain.mass * static_cast<double>(sp.count);
    }
    if (!(M > 0))
        return {};
    const Vec3 u = (1.0 / M) * p;
    for (const SpeciesBlock& sp : species)
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i)
            store.v(i) -= u;
    return u;
}

// Each component of v of species s is N(0, T_s/m_s), each of omega N(0, T_rot,s/J_s), from the
// streams (seed, initial_velocity | initial_rotation, replica, unit = s): a species' state does not
// depend on the other species or on the particle number of the others.
template <class Store>
void init_maxwellian(Store& store, const std::vector<SpeciesBlock>& species, std::uint64_t seed,
                     std::uint64_t replica) {
    boost::random::normal_distribution<double> normal(0.0, 1.0);
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesBlock& sp = species[s];
        Rng rv = make_stream(StreamKey{seed, Stream::initial_velocity, replica, 0, s});
        Rng rw = make_stream(StreamKey{seed, Stream::initial_rotation, replica, 0, s});
        const double sv = std::sqrt(sp.temperature / sp.grain.mass);
        const double sw = std::sqrt(sp.rotational_temperature / sp.moment_of_inertia());
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            Vec3& v = store.v(i);
            v.x = sv * normal(rv);
            v.y = sv * normal(rv);
            v.z = sv * normal(rv);
            Vec3& w = store.w(i);
            w.x = sw * normal(rw);
            w.y = sw * normal(rw);
            w.z = sw * normal(rw);
        }
    }
    remove_mean_velocity(store, species);
}

// The homogeneous gas's start from a saved state (RunSpec::initial_state): every grain's velocity
// and spin as the state holds them, in the same species-block order (its positions, from a box,
// are not used), then the mass-weighted mean velocity removed as after a Maxwellian start. The state
// of a homogeneous run or a periodic box carries none beyond round-off, but a box with walls or
// gravity can end with a net flow. The rows do not see it (c = v - u) and neither do the
// collisions, but the engine works in the centre-of-mass frame: it removes a drift only at a step's
// start, reports the largest as round-off's (max_mean_drift, dsmc/engine.hpp), and its speed bounds
// would carry the flow until then. Removed here, the start is at rest as a Maxwellian one.
template <class Store>
void init_from_state(Store& store, const std::vector<SpeciesBlock>& species, const GrainState& state) {
    std::size_t n = 0;
    for (const SpeciesBlock& sp : species)
        n = std::max(n, sp.offset + sp.count);
    if (state.v.size() != n || state.w.size() != n)
        throw std::invalid_argument("init_from_state: the state has another number of grains");
    for (std::size_t i = 0; i < n; ++i) {
        store.v(i) = state.v[i];
        store.w(i) = state.w[i];
    }
    remove_mean_velocity(store, species);
}

} // namespace roughgas
