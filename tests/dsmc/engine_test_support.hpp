#pragma once
// The homogeneous engine as the engine tests build and read it (engine_test.cpp, thermostat_test.cpp):
// a Maxwellian start, the moments of its grains and their total kinetic energy.
#include "roughgas/dsmc/engine.hpp"
#include "roughgas/dsmc/init.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/moments.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace roughgas::test {

// N grains of `species` from their Maxwellian (streams of opt.seed and opt.replica).
template <class Store, bool Mixture = false, class Policy>
Engine<Store, Policy, Mixture> make_engine(const std::vector<SpeciesSpec>& species, std::int64_t N,
                                           std::vector<Policy> policies, EngineOptions opt) {
    const auto blocks = make_species_blocks(species, N);
    Store store(static_cast<std::size_t>(N));
    init_maxwellian(store, blocks, opt.seed, opt.replica);
    return Engine<Store, Policy, Mixture>(blocks, std::move(policies), std::move(store), opt);
}

template <class E> Moments moments_of(const E& e) {
    return compute_moments(e.store().velocities(), e.store().angular_velocities(), species_slices(e.species()));
}

// sum m v^2/2 + J omega^2/2 over the grains.
template <class E> double total_energy(const E& e) {
    double sum = 0;
    for (const auto& b : e.species())
        for (std::size_t i = b.offset; i < b.offset + b.count; ++i)
            sum += 0.5 * b.grain.mass * norm2(e.store().v(i)) + 0.5 * b.moment_of_inertia() * norm2(e.store().w(i));
    return sum;
}

} // namespace roughgas::test
