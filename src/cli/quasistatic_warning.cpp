#include "quasistatic_warning.hpp"

#include "roughgas/contact/quasistatic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <ostream>

namespace roughgas::cli {

bool warn_if_not_quasistatic(const CaseConfig& cfg, std::size_t i, std::size_t j, std::span<const double> g_n,
                             const std::string& where, std::ostream& err) {
    if (!cfg.material)
        return false;
    const ContactPair pc = contact_pair(cfg, i, j);
    const Material mat = cfg.material->material();
    // The slower sound speed of the two grains' densities (uniform spheres).
    const double rho_m = std::max(sphere_density(cfg.species[i].mass, cfg.species[i].radius),
                                  sphere_density(cfg.species[j].mass, cfg.species[j].radius));
    const double c_t = transverse_sound_speed(mat, rho_m);
    double lo = 0, hi = 0;
    QuasistaticRatios worst;
    for (double g : g_n) {
        if (!(g > 0))
            continue;
        const QuasistaticRatios q = quasistatic_ratios(pc, c_t, g);
        if (q.holds())
            continue;
        lo = lo == 0 ? g : std::min(lo, g);
        if (g >= hi) {
            hi = g;
            worst = q;
        }
    }
    if (hi == 0)
        return false;
    err << fmt::format("roughgas: warning: {}: impact speeds {:.3g} .. {:.3g} m/s of species \"{}\" with \"{}\" are "
                       "outside the quasistatic range of the contact model (Brilliantov et al. 1996, "
                       "appendix B: at {:.3g} m/s, g/c_t = {:.3g} (must be <= 0.1) and A/t_c = {:.3g} "
                       "(<= 1); c_t = {:.4g} m/s): the restitution there is computed but is not physics\n",
                       where, lo, hi, cfg.species[i].name, cfg.species[j].name, hi, worst.speed, worst.time, c_t);
    return true;
}

} // namespace roughgas::cli
