#pragma once
// What the box tests sum over a SpatialEngine's grains: the total momentum and kinetic energy.
#include "roughgas/dsmc/spatial_engine.hpp"

namespace roughgas::test {

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
