// moments_at_drive_time (dsmc/thermostat.hpp): a driven row's moments moved from the kicks' time to
// the row's, through the kick's exact map of the second and fourth moments.
#include "roughgas/dsmc/thermostat.hpp"

#include <cmath>

namespace roughgas {
namespace {

// One species' raw moments: <c^2>, <c^4>, <w^2>, <w^4>, <c^2 w^2>, <(c.w)^2> (docs/model.md §5 backwards).
struct Raw {
    double c2 = 0, c4 = 0, w2 = 0, w4 = 0, c2w2 = 0, cw2 = 0;
};

Raw raw_of(const GroupMoments& g, double m, double I) {
    Raw r;
    r.c2 = 3 * g.T_tr / m;
    r.c4 = (1 + g.a20) * 15 * g.T_tr * g.T_tr / (m * m);
    r.w2 = 3 * g.T_rot / I;
    r.w4 = (1 + g.a02) * 15 * g.T_rot * g.T_rot / (I * I);
    r.c2w2 = (1 + g.a11) * 9 * g.T_tr * g.T_rot / (m * I);
    r.cw2 = (g.A_cw + 1.0 / 3.0) * r.c2 * r.w2;
    if (!(g.T_rot > 0)) // spins at rest: their cumulants are undefined, their moments 0
        r.w2 = r.w4 = r.c2w2 = r.cw2 = 0;
    return r;
}

// c -> a c + g (variance s2 per component), omega -> b omega + h (variance r2).
Raw forward(const Raw& x, double a, double s2, double b, double r2) {
    const double a2 = a * a, b2 = b * b;
    Raw y;
    y.c2 = a2 * x.c2 + 3 * s2;
    y.c4 = a2 * a2 * x.c4 + 10 * a2 * s2 * x.c2 + 15 * s2 * s2;
    y.w2 = b2 * x.w2 + 3 * r2;
    y.w4 = b2 * b2 * x.w4 + 10 * b2 * r2 * x.w2 + 15 * r2 * r2;
    y.c2w2 = a2 * b2 * x.c2w2 + 3 * r2 * a2 * x.c2 + 3 * s2 * b2 * x.w2 + 9 * s2 * r2;
    y.cw2 = a2 * b2 * x.cw2 + r2 * a2 * x.c2 + s2 * b2 * x.w2 + 3 * s2 * r2;
    return y;
}

// The inverse of forward: x from y.
Raw inverse(const Raw& y, double a, double s2, double b, double r2) {
    const double a2 = a * a, b2 = b * b;
    Raw x;
    x.c2 = (y.c2 - 3 * s2) / a2;
    x.c4 = (y.c4 - 10 * a2 * s2 * x.c2 - 15 * s2 * s2) / (a2 * a2);
    x.w2 = (y.w2 - 3 * r2) / b2;
    x.w4 = (y.w4 - 10 * b2 * r2 * x.w2 - 15 * r2 * r2) / (b2 * b2);
    x.c2w2 = (y.c2w2 - 3 * r2 * a2 * x.c2 - 3 * s2 * b2 * x.w2 - 9 * s2 * r2) / (a2 * b2);
    x.cw2 = (y.cw2 - r2 * a2 * x.c2 - s2 * b2 * x.w2 - 3 * s2 * r2) / (a2 * b2);
    return x;
}

// The moments of a group from its grains' raw moments: fractions x_s, the reduced vectors scaled by
// the group's temperatures (T_tr = sum x_s m_s <c^2>_s/3).
void finish(GroupMoments& g, std::span<const Raw> raw, std::span<const double> x, std::span<const SpeciesSlice> sp) {
    double T = 0, Tr = 0;
    for (std::size_t s = 0; s < raw.size(); ++s) {
        T += x[s] * sp[s].mass * raw[s].c2 / 3;
        Tr += x[s] * sp[s].moment_of_inertia * raw[s].w2 / 3;
    }
    g.T_tr = T;
    g.T_rot = Tr;
    g.theta = Tr / T;
    double c4 = 0, w4 = 0, c2w2 = 0, cw2 = 0, c2 = 0, w2 = 0;
    for (std::size_t s = 0; s < raw.size(); ++s) {
        const double fc = sp[s].mass / (2 * T), fw = sp[s].moment_of_inertia / (2 * Tr);
        c2 += x[s] * fc * raw[s].c2;
        w2 += x[s] * fw * raw[s].w2;
        c4 += x[s] * fc * fc * raw[s].c4;
        w4 += x[s] * fw * fw * raw[s].w4;
        c2w2 += x[s] * fc * fw * raw[s].c2w2;
        cw2 += x[s] * fc * fw * raw[s].cw2;
    }
    g.a20 = (4.0 / 15.0) * c4 - 1;
    if (Tr > 0) {
        g.a02 = (4.0 / 15.0) * w4 - 1;
        g.a11 = (4.0 / 9.0) * c2w2 - 1;
        g.A_cw = cw2 / (c2 * w2) - 1.0 / 3.0;
    }
}

} // namespace

Moments moments_at_drive_time(const Moments& m, std::span<const SpeciesSlice> species,
                              const ThermostatSpec& thermostat, double t, double t_kick) {
    if (t_kick == t || !(m.all.T_tr > 0))
        return m;
    const bool ahead = t_kick > t;
    const double t0 = ahead ? t : t_kick, t1 = ahead ? t_kick : t;
    std::vector<Raw> raw(species.size());
    std::vector<double> x(species.size());
    double N = 0;
    for (const SpeciesSlice& s : species)
        N += static_cast<double>(s.count);
    Moments out = m;
    for (std::size_t s = 0; s < species.size(); ++s) {
        const SpeciesSlice& sp = species[s];
        const SpeciesKick k =
            species_kick(thermostat.kind, thermostat.species[s], sp.mass, sp.moment_of_inertia, t0, t1);
        const Raw r = raw_of(m.species[s], sp.mass, sp.moment_of_inertia);
        raw[s] = ahead ? inverse(r, k.decay_v, k.var_v, k.decay_w, k.var_w)
                       : forward(r, k.decay_v, k.var_v, k.decay_w, k.var_w);
        x[s] = static_cast<double>(sp.count) / N;
        const double one = 1.0;
        finish(out.species[s], std::span(&raw[s], 1), std::span(&one, 1), species.subspan(s, 1));
    }
    finish(out.all, raw, x, species);
    return out;
}

} // namespace roughgas
