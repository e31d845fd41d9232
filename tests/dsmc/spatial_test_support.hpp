#pragma once
// What the box tests share: a two-species mixture, and what they sum over a SpatialEngine's grains
// (the total momentum and kinetic energy).
#include "roughgas/dsmc/spatial_engine.hpp"

namespace roughgas::test {

// Two species of different mass and size (30 % heavy ones), both rough.
inline std::vector<SpeciesBlock> two_species(std::int64_t n) {
    SpeciesSpec a, b;
    a.name = "light";
    a.fraction = 0.7;
    b.name = "heavy";
    b.mass = 3;
    b.radius = 0.8;
    b.fraction = 0.3;
    b.temperature = 2;
    return make_species_blocks({a, b}, n);
}


template <class P, bool G> Vec3 momentum(const SpatialEngine<P, G>& e) {
    Vec3 p{};
    for (const SpeciesBlock& b : e.species())
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i)
            p += b.grain.mass * e.velocities()[i];
    return p;
}

// Translational and rotational.
template <class P, bool G> double energy(SpatialEngine<P, G>& e) {
    double E = 0;
    for (const SpeciesBlock& b : e.species())
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i)
            E += 0.5 * b.grain.mass * norm2(e.velocities()[i]) +
                 0.5 * b.moment_of_inertia() * norm2(e.angular_velocities()[i]);
    return E;
}

} // namespace roughgas::test
