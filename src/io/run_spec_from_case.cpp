#include "roughgas/io/run_spec_from_case.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace roughgas {

std::vector<double> output_times(double every, double end, OutputSpacing spacing) {
    if (!(every > 0) || !(end > 0) || !std::isfinite(every) || !std::isfinite(end))
        throw std::invalid_argument("output_times: every and end must be positive and finite");
    std::vector<double> t;
    const double merge = end * (1.0 - 1e-9);
    for (long k = 0;; ++k) {
        const double x = spacing == OutputSpacing::linear
                             ? static_cast<double>(k + 1) * every
                             : every * std::pow(10.0, static_cast<double>(k) / 10.0);
        if (!(x < merge))
            break;
        t.push_back(x);
    }
    t.push_back(end);
    return t;
}

std::vector<double> rows_apart(const std::vector<double>& times, std::int64_t particles) {
    // The collision count a row is taken at (dsmc/drive_impl.hpp): round(x N / 2).
    const auto count = [&](double x) { return std::llround(x * static_cast<double>(particles) / 2.0); };
    std::vector<double> kept;
    long long last = 0; // the row at t = 0
    for (std::size_t k = 0; k < times.size(); ++k) {
        const long long c = count(times[k]);
        if (c > last) {
            kept.push_back(times[k]);
            last = c;
        } else if (k + 1 == times.size() && !kept.empty()) {
            kept.back() = times[k]; // the last row stays at the end
        }
    }
    if (kept.empty())
        kept.push_back(times.back());
    return kept;
}

namespace {

// One SpeciesThermostat per species, in the order of cfg.species: the species' values over
// [thermostat]'s; a constant drive is a schedule of one value from t = 0.
ThermostatSpec thermostat_spec(const CaseConfig& cfg) {
    const ThermostatConfig& t = cfg.thermostat.value();
    ThermostatSpec spec;
    spec.kind = t.kind;
    spec.exact_energy = t.exact_energy;
    for (std::size_t i = 0; i < cfg.species.size(); ++i) {
        const ThermostatValues v = thermostat_for(cfg, i);
        SpeciesThermostat s;
        if (t.schedule.empty()) {
            const std::optional<double> x = t.kind == ThermostatKind::white_noise ? v.strength : v.bath_temperature;
            if (!x)
                throw std::invalid_argument("[thermostat] without a drive for species \"" + cfg.species[i].name + "\"");
            s.drive = DriveSchedule{{0.0}, {*x}};
        } else {
            s.drive.t.clear();
            s.drive.value.clear();
            for (const std::array<double, 2>& p : t.schedule) {
                s.drive.t.push_back(p[0]);
                s.drive.value.push_back(p[1]);
            }
        }
        s.rotational_share = v.rotational_share.value_or(0.0);
        s.friction = v.friction.value_or(0.0);
        s.rotational_friction = v.rotational_friction.value_or(0.0);
        spec.species.push_back(s);
    }
    return spec;
}

} // namespace

RunSpec run_spec_from_case(const CaseConfig& cfg) {
    RunSpec spec;
    if (cfg.run.kind == RunKind::shear) {
        if (!cfg.shear)
            throw std::invalid_argument("run.kind = \"shear\" without [shear]");
        spec.shear = ShearSpec{cfg.shear->rate, cfg.shear->time_step};
    }
    if (cfg.thermostat)
        spec.thermostat = thermostat_spec(cfg);
    if (cfg.domain) {
        DomainSpec d;
        d.size = cfg.domain->size;
        for (std::size_t i = 0; i < 3; ++i)
            d.cells[i] = static_cast<int>(cfg.domain->cells[i]);
        d.time_step = cfg.domain->time_step;
        d.partners = cfg.domain->partners;
        d.chi_cells = static_cast<int>(cfg.domain->chi_cells);
        d.boundary = cfg.domain->boundary;
        d.gravity = cfg.domain->gravity;
        d.profile_axis = cfg.domain->profile_axis;
        if (spec.shear)
            d.shear_rate = spec.shear->rate; // Lees-Edwards along y
        const auto wall = [](const std::optional<WallConfig>& w) {
            WallSpec s;
            if (w) {
                s.kind = w->kind;
                s.temperature = w->temperature.value_or(1.0);
                s.velocity = w->velocity;
                s.alpha = w->alpha.value_or(1.0);
                s.beta = w->beta.value_or(-1.0);
            }
            return s;
        };
        d.wall_lower = wall(cfg.wall_lower);
        d.wall_upper = wall(cfg.wall_upper);
        for (std::size_t a = 0; a < 3; ++a) {
            if (cfg.axis_wall_lower[a])
                d.axis_lower[a] = wall(cfg.axis_wall_lower[a]);
            if (cfg.axis_wall_upper[a])
                d.axis_upper[a] = wall(cfg.axis_wall_upper[a]);
        }
        if (cfg.initial) {
            d.initial.mode = cfg.initial->mode;
            d.initial.amplitude = cfg.initial->amplitude;
            for (std::size_t i = 0; i < 3; ++i)
                d.initial.wave[i] = static_cast<int>(cfg.initial->wave[i]);
        }
        if (cfg.spectra)
            d.spectra = SpectraSpec{static_cast<int>(cfg.spectra->modes)};
        if (cfg.fields)
            d.fields = FieldsSpec{cfg.fields->quantities, static_cast<int>(cfg.fields->every),
                                  static_cast<int>(cfg.fields->replicas)};
        spec.domain = d;
    }
    for (const SpeciesConfig& s : cfg.species) {
        SpeciesSpec sp;
        sp.name = s.name;
        sp.mass = s.mass;
        sp.radius = s.radius;
        sp.inertia = s.inertia;
        sp.fraction = s.fraction;
        sp.temperature = s.temperature;
        sp.rotational_temperature = s.rotational_temperature;
        spec.species.push_back(sp);
    }
    const std::size_t n = cfg.species.size();
    spec.pairs.resize(n * (n + 1) / 2);
    for (std::size_t a = 0; a < n; ++a) {
        for (std::size_t b = a; b < n; ++b) {
            const CollisionConfig& c = collision_for(cfg, a, b);
            PairRestitution& r = spec.pairs[pair_index(a, b, n)];
            switch (c.model) {
            case CollisionModel::constant:
                r = ConstantRestitution{c.alpha.value(), c.beta.value_or(-1.0)};
                break;
            case CollisionModel::coulomb:
                r = CoulombRestitution{c.alpha.value(), c.beta0.value(), c.friction.value()};
                break;
            case CollisionModel::viscoelastic:
                r = ViscoelasticRestitution{contact_pair(cfg, a, b), c.beta.value_or(-1.0), c.direct};
                break;
            case CollisionModel::brilliantov:
                r = BrilliantovRestitution{contact_pair(cfg, a, b), c.direct};
                break;
            }
        }
    }
    spec.particles = cfg.run.particles;
    spec.density = cfg.run.density;
    spec.seed = cfg.run.seed;
    spec.replicas = static_cast<int>(cfg.run.replicas);
    spec.groups = static_cast<int>(cfg.run.groups);
    spec.kernel = cfg.run.kernel;
    if (cfg.run.equation == KineticEquation::enskog)
        spec.enskog = EnskogSpec{cfg.run.pair_correlation, cfg.run.chi.value_or(1.0)};
    if (cfg.run.time_clock()) {
        // Times, each a row of its own (two rows may hold the same collision count: no collision between).
        spec.clock = Clock::time;
        spec.end = *cfg.run.end_time;
        spec.output_times = output_times(cfg.run.output_every_time.value(), spec.end, cfg.run.output_spacing);
        if (cfg.run.histogram_every_time > 0)
            spec.histogram_times = output_times(cfg.run.histogram_every_time, spec.end, cfg.run.histogram_spacing);
    } else {
        spec.end = cfg.run.end;
        spec.output_times = rows_apart(output_times(cfg.run.output_every, cfg.run.end, cfg.run.output_spacing),
                                       cfg.run.particles);
        if (cfg.run.histogram_every > 0)
            spec.histogram_times = output_times(cfg.run.histogram_every, cfg.run.end, cfg.run.histogram_spacing);
    }
    spec.histogram_bins = static_cast<int>(cfg.run.histogram_bins);
    spec.histogram_max = cfg.run.histogram_max;
    spec.contact_tolerance = cfg.contact.tolerance;
    spec.cache_file = cfg.contact.cache_file;
    spec.use_cache = cfg.contact.cache;
    return spec;
}

} // namespace roughgas
