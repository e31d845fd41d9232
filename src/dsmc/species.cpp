#include "roughgas/dsmc/species.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace roughgas {

std::vector<SpeciesBlock> make_species_blocks(const std::vector<SpeciesSpec>& species,
                                              std::int64_t particles) {
    if (species.empty())
        throw std::invalid_argument("no species");
    if (particles < 0)
        throw std::invalid_argument("negative particle number");
    double total = 0;
    for (const auto& s : species) {
        if (!(s.fraction >= 0))
            throw std::invalid_argument("species " + s.name + ": negative fraction");
        total += s.fraction;
    }
    if (!(total > 0))
        throw std::invalid_argument("species fractions sum to zero");
    const auto N = static_cast<std::size_t>(particles);
    std::vector<SpeciesBlock> out(species.size());
    std::vector<double> rest(species.size());
    std::size_t assigned = 0;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const double exact = static_cast<double>(N) * species[s].fraction / total;
        out[s].count = static_cast<std::size_t>(std::floor(exact));
        rest[s] = exact - std::floor(exact);
        assigned += out[s].count;
    }
    std::vector<std::size_t> order(species.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return rest[a] > rest[b]; });
    for (std::size_t k = 0; assigned < N; ++k, ++assigned)
        out[order[k % order.size()]].count += 1;
    std::size_t offset = 0;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSpec& sp = species[s];
        out[s].name = sp.name;
        out[s].grain = {sp.mass, sp.radius, sp.inertia};
        out[s].temperature = sp.temperature;
        out[s].rotational_temperature = sp.rotational_temperature;
        out[s].offset = offset;
        offset += out[s].count;
    }
    return out;
}

std::vector<PairType> make_pair_types(const std::vector<SpeciesBlock>& species, const std::vector<double>& chi) {
    if (!chi.empty() && chi.size() != species.size() * (species.size() + 1) / 2)
        throw std::invalid_argument("make_pair_types: one chi per species pair");
    const std::size_t n = species.size();
    std::vector<PairType> out(n * (n + 1) / 2);
    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t b = a; b < n; ++b) {
            PairType& p = out[pair_index(a, b, n)];
            p.a = a;
            p.b = b;
            p.pc = make_pair_constants(species[a].grain, species[b].grain);
            const double Na = static_cast<double>(species[a].count),
                         Nb = static_cast<double>(species[b].count);
            p.pairs = a == b ? 0.5 * Na * (Na - 1.0) : Na * Nb;
            if (!chi.empty())
                p.chi = chi[pair_index(a, b, n)];
        }
    }
    return out;
}

} // namespace roughgas
