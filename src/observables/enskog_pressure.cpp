#include "roughgas/observables/enskog_pressure.hpp"

#include "roughgas/collision/pair_constants.hpp"

#include <numbers>

namespace roughgas {

double enskog_kinetic_pressure(const HcsTheory& theory, const HcsTemperatures& T) {
    double p = 0;
    for (std::size_t s = 0; s < theory.species_count(); ++s)
        p += theory.species()[s].fraction * theory.density() * T.T_tr[s];
    return p;
}

double enskog_collisional_pressure(const HcsTheory& theory, const HcsTemperatures& T) {
    const std::vector<HcsSpecies>& sp = theory.species();
    const std::size_t S = sp.size();
    const double n = theory.density();
    double p = 0;
    for (std::size_t a = 0; a < S; ++a)
        for (std::size_t b = 0; b < S; ++b) {
            const PairConstants pc =
                make_pair_constants({sp[a].mass, sp[a].radius, sp[a].inertia}, {sp[b].mass, sp[b].radius, sp[b].inertia});
            const double alpha = theory.pairs()[pair_index(a, b, S)].alpha;
            p += sp[a].fraction * n * sp[b].fraction * n * theory.pair_correlation(a, b) * pc.sigma * pc.sigma *
                 pc.sigma * pc.m_eff * (1 + alpha) * (T.T_tr[a] / sp[a].mass + T.T_tr[b] / sp[b].mass);
        }
    return std::numbers::pi / 3 * p;
}

} // namespace roughgas
