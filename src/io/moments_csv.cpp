#include "roughgas/io/moments_csv.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"
#include "roughgas/dsmc/run.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/io/replica_mean.hpp"
#include "roughgas/observables/longitudinal_modes.hpp"
#include "roughgas/observables/profiles.hpp"
#include "roughgas/observables/shear_mode.hpp"
#include "roughgas/observables/driven_steady_state.hpp"
#include "roughgas/observables/enskog_pressure.hpp"
#include "roughgas/observables/enskog_usf_theory.hpp"
#include "roughgas/observables/sonine_cooling_state.hpp"
#include "roughgas/observables/white_noise_sonine.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>

namespace roughgas {
namespace {

// "a02.ice" -> {"a02", ".ice"}; "T_tr.a/T_tr.b" stays whole.
std::pair<std::string, std::string> split(const std::string& name) {
    const std::size_t dot = name.find('.');
    if (dot == std::string::npos || name.find('/') != std::string::npos)
        return {name, ""};
    return {name.substr(0, dot), name.substr(dot)};
}

} // namespace

MomentsTable::MomentsTable(const RunSpec& spec)
    : solver_(dsmc_columns(spec)), wall_solver_(wall_columns(spec)), profile_solver_(profile_columns(spec)),
      spectra_solver_(spectra_columns(spec)), replicas_(spec.replicas) {
    if (replicas_ < 1)
        throw std::invalid_argument("MomentsTable: replicas must be >= 1");
    profile_start_ = solver_.size() + wall_solver_.size();
    spectra_start_ = profile_start_ + profile_solver_.size();
    if (spec.domain && spec.domain->spectra) {
        const SpectraGeometry g = spectra_geometry(*spec.domain);
        spectrum_bins_ = spectrum_bins(g);
        modes_ = mode_indices(g);
        spectra_columns_ = {solver_[0], solver_[1], {"axis", "-"}, {"n", "-"}, {"k", "1/length"}, {"n_modes", "-"}};
        if (!modes_.empty()) // spectra.modes = 0 (or no axis long enough): no modes.csv
            modes_columns_ = {solver_[0], solver_[1], {"axis", "-"}, {"n", "-"}, {"k", "1/length"}};
        for (auto [fields, table] : {std::pair{spectrum_field_columns(), &spectra_columns_},
                                     std::pair{mode_field_columns(), &modes_columns_}})
            for (const Column& f : table->empty() ? std::vector<Column>{} : fields) {
                table->push_back(f);
                if (replicas_ > 1)
                    table->push_back({f.name + "_err", f.unit});
            }
        // The Navier-Stokes rates of each mode where the theory applies: the transverse wave's
        // (observables/shear_mode.hpp), the heat and sound modes' (observables/longitudinal_modes.hpp);
        // per wave number, the same in every block.
        if (const std::optional<ShearModeTheory> t = shear_mode_theory(spec); t && !modes_.empty()) {
            const double lambda = mean_free_path(spec.density, 2 * spec.species[0].radius);
            const std::optional<LongitudinalModeTheory> lt = longitudinal_mode_theory(spec);
            for (const ModeIndex& m : modes_) {
                std::vector<double>& v = mode_theory_.emplace_back();
                v.push_back(shear_mode_rate(*t, m.k * lambda));
                if (lt) {
                    const LongitudinalModeRates r = longitudinal_mode_rates(*lt, m.k * lambda);
                    v.insert(v.end(), {r.heat.real(), r.sound[0].real(), std::abs(r.sound[0].imag())});
                }
            }
            modes_columns_.push_back({"gamma_perp_theory", "-"});
            if (lt)
                for (const char* name : {"gamma_heat_theory", "gamma_sound_theory", "omega_sound_theory"})
                    modes_columns_.push_back({name, "-"});
        }
    }
    if (spec.domain) {
        const int a = spec.domain->profile_axis;
        const int bins = spec.domain->cells[static_cast<std::size_t>(a)];
        const double L = spec.domain->size[static_cast<std::size_t>(a)];
        for (int b = 0; b < bins; ++b)
            bin_centres_.push_back((b + 0.5) * L / bins);
        profile_columns_ = {solver_[0], solver_[1], {"bin", "-"}, {std::string(1, "xyz"[a]), "length"}};
        for (const Column& c : profile_field_columns()) {
            profile_columns_.push_back(c);
            if (replicas_ > 1)
                profile_columns_.push_back({c.name + "_err", c.unit});
        }
    }
    if (!wall_solver_.empty()) {
        wall_columns_ = {solver_[0], solver_[1]}; // t, coll_per_particle
        for (const Column& c : wall_solver_) {
            wall_columns_.push_back(c);
            if (replicas_ > 1)
                wall_columns_.push_back({c.name + "_err", c.unit});
        }
    }
    for (const Column& c : solver_) {
        columns_.push_back(c);
        if (replicas_ > 1)
            columns_.push_back({c.name + "_err", c.unit});
    }
    enskog_ = spec.enskog.has_value();
    zeta_ = !spec.shear;
    if (zeta_) {
        columns_.push_back({"zeta_star", "-"});
        if (replicas_ > 1)
            columns_.push_back({"zeta_star_err", "-"});
        prev_T_tr_.assign(static_cast<std::size_t>(replicas_), std::numeric_limits<double>::quiet_NaN());
        prev_cpp_ = prev_T_tr_;
    }
    // The theory columns describe the homogeneous gas, freely cooling or driven by a thermostat
    // (observables/driven_theory.hpp): not written for shear runs, nor for a driven gas that starts
    // without energy (its scaled variables need some).
    std::optional<HcsTheory> th = spec.shear ? std::nullopt : hcs_theory(spec);
    const HcsTemperatures T0 = initial_temperatures(spec);
    if (th && spec.thermostat) {
        double E0 = 0;
        for (std::size_t s = 0; s < T0.T_tr.size(); ++s)
            E0 += T0.T_tr[s] + T0.T_rot[s];
        if (E0 > 0)
            trajectory_.emplace(std::move(*th), T0, *spec.thermostat);
    } else if (th) {
        trajectory_.emplace(std::move(*th), T0);
    }
    if (trajectory_) {
        columns_.push_back({"T_tr_theory", "energy"});
        columns_.push_back({"T_rot_theory", "energy"});
        columns_.push_back({"theta_theory", "-"});
        if (spec.species.size() > 1) {
            for (const SpeciesSpec& s : spec.species) {
                columns_.push_back({"T_tr_theory." + s.name, "energy"});
                columns_.push_back({"T_rot_theory." + s.name, "energy"});
                columns_.push_back({"theta_theory." + s.name, "-"});
            }
            // Beside the measured ratios: every species pair A before B, as in the solver's columns.
            for (std::size_t a = 0; a < spec.species.size(); ++a)
                for (std::size_t b = a + 1; b < spec.species.size(); ++b) {
                    const std::string& A = spec.species[a].name;
                    const std::string& B = spec.species[b].name;
                    columns_.push_back({"T_tr." + A + "/T_tr." + B + "_theory", "-"});
                    columns_.push_back({"T_rot." + A + "/T_rot." + B + "_theory", "-"});
                }
        }
        columns_.push_back({"zeta_star_theory", "-"});
        // The Enskog equation's pressure (observables/enskog_pressure.hpp), as the solver's p: the kinetic
        // part at t, the collisional part averaged over the interval since the previous row.
        if (enskog_)
            columns_.push_back({"p_theory", "energy/volume"});
        // The scaled cooling state in the first Sonine approximation, the same in every row, where
        // it applies (observables/sonine_cooling_state.hpp): one species, whose restitution is
        // constant, with the hard-sphere kernel. NaN where it has no value: theta, a02 and a11 of
        // smooth grains, everything where the approximation has no cooling state. Cooling runs only.
        if (spec.species.size() == 1 && !trajectory_->theory().maxwell() && !spec.thermostat) {
            const ConstantRestitution& r = trajectory_->theory().pairs()[0];
            const std::optional<SonineCoolingState> s = sonine_cooling_state(r.alpha, r.beta, spec.species[0].inertia);
            const auto value = [&](double SonineCoolingState::*field) {
                return s && std::isfinite((*s).*field) ? (*s).*field : std::numeric_limits<double>::quiet_NaN();
            };
            for (double SonineCoolingState::*field : {&SonineCoolingState::theta, &SonineCoolingState::zeta_star,
                                                      &SonineCoolingState::a20, &SonineCoolingState::a02,
                                                      &SonineCoolingState::a11})
                sonine_.push_back(value(field));
            for (const char* name : {"theta_sonine", "zeta_star_sonine", "a20_sonine", "a02_sonine", "a11_sonine"})
                columns_.push_back({name, "-"});
        }
        // A driven gas: its steady state in the Maxwellian approximation under the thermostat's final
        // drives (observables/driven_steady_state.hpp; NaN where there is none), and for one species of
        // smooth grains under plain white noise the first Sonine approximation's steady T_tr and a2
        // (van Noije & Ernst 1998; observables/white_noise_sonine.hpp): the same in every row.
        if (spec.thermostat) {
            const std::optional<DrivenSteadyState> st = driven_steady_state(trajectory_->theory(), *spec.thermostat);
            const double nan = std::numeric_limits<double>::quiet_NaN();
            constant_theory_.push_back(st ? st->T_tr : nan);
            constant_theory_.push_back(st ? st->T_rot : nan);
            constant_theory_.push_back(st ? st->theta : nan);
            for (const char* name : {"T_tr_steady_theory", "T_rot_steady_theory", "theta_steady_theory"})
                columns_.push_back({name, std::string_view(name).starts_with("theta") ? "-" : "energy"});
            const HcsTheory& th = trajectory_->theory();
            const SpeciesThermostat& drive = spec.thermostat->species[0];
            if (th.species_count() == 1 && !th.maxwell() && th.pairs()[0].beta == -1 &&
                spec.thermostat->kind == ThermostatKind::white_noise && drive.rotational_share == 0) {
                const HcsSpecies& g = th.species()[0];
                const WhiteNoiseSonineState s = white_noise_sonine_state(
                    th.pairs()[0].alpha, g.mass, 2 * g.radius, th.density() * th.pair_correlation(0, 0),
                    drive.drive.value.back());
                constant_theory_.push_back(s.T_tr);
                constant_theory_.push_back(s.a2);
                columns_.push_back({"T_tr_sonine", "energy"});
                columns_.push_back({"a20_sonine", "-"});
            }
        }
    }
    // Uniform shear flow of one species of smooth grains with a constant alpha < 1 (hard spheres): the
    // steady state in Grad's approximation (observables/enskog_usf_theory.hpp), of the Enskog equation
    // at the run's phi and chi, or at phi = 0 the Boltzmann equation's; the same in every row.
    if (spec.shear && spec.species.size() == 1 && spec.kernel == CollisionKernel::hard_sphere) {
        const auto* r = std::get_if<ConstantRestitution>(&spec.pairs[0]);
        if (r && r->beta == -1 && r->alpha >= 0 && r->alpha < 1) {
            const double phi = spec.enskog ? solid_fraction(spec.density, spec.species) : 0.0;
            const double chi = spec.enskog ? pair_correlations(spec)[0] : 1.0;
            if (phi < 1 && chi > 0) {
                const EnskogUsfState g = enskog_usf_grad(r->alpha, phi, chi);
                for (double x : {g.a_star, g.eta_star, g.total.xx, g.total.yy, g.total.zz, g.N1, g.N2})
                    shear_theory_.push_back(x);
                for (const char* name : {"a_star_grad", "eta_star_grad", "P_xx_star_grad", "P_yy_star_grad",
                                         "P_zz_star_grad", "N1_star_grad", "N2_star_grad"})
                    columns_.push_back({name, "-"});
            }
        }
    }
}

const Column& MomentsTable::row_column(std::size_t j) const {
    return j < solver_.size()         ? solver_[j]
           : j < profile_start_       ? wall_solver_[j - solver_.size()]
           : j < spectra_start_       ? profile_solver_[j - profile_start_]
                                      : spectra_solver_[j - spectra_start_];
}

void MomentsTable::check(std::span<const double> row) const {
    if (row.size() != spectra_start_ + spectra_solver_.size())
        throw std::invalid_argument(fmt::format("replica row has {} values for {} columns", row.size(),
                                                spectra_start_ + spectra_solver_.size()));
    std::map<std::string, double> value; // by name: the moments and walls (profiles go by index)
    for (std::size_t j = 0; j < profile_start_; ++j)
        value[row_column(j).name] = row[j];
    const auto zero = [&](const std::string& name) {
        const auto it = value.find(name);
        return it != value.end() && it->second == 0;
    };
    const double t = row[0];
    const bool first = value.count("coll_per_particle") && value["coll_per_particle"] == 0;
    for (std::size_t j = 0; j < row.size(); ++j) {
        if (std::isfinite(row[j]))
            continue;
        const std::string& name = row_column(j).name;
        const auto [base, suffix] = split(name);
        bool undefined = j >= solver_.size() && j < profile_start_ && first; // walls.csv: no interval yet
        if (j >= spectra_start_) { // spectra: S_T and the temperature amplitudes divide by T_tr
            const std::string field = name.substr(name.rfind('.') + 1);
            if ((field == "S_T" || field == "T_re" || field == "T_im") && zero("T_tr"))
                continue;
            throw NonFiniteValue(name, t, row[j], fmt::format("spectra field {} is {} at t = {}", name, row[j], t));
        }
        if (j >= profile_start_) { // a profile bin's field
            const std::size_t f = (j - profile_start_) % profile_field_count, bin = j - profile_start_ - f;
            const double n = row[profile_start_ + bin], T_tr = row[profile_start_ + bin + profile_T_tr];
            undefined = f > 0 && (n == 0 || (f >= profile_collisional_first && f < profile_collisional_first + 6 && first) ||
                                  (f == profile_theta && T_tr == 0));
            if (!undefined)
                throw NonFiniteValue(name, t, row[j],
                                     fmt::format("profile field {} is {} at t = {}", name, row[j], t));
            continue;
        }
        if (base == "coll_rate" || base == "E_diss_rate" || base == "p_coll" || base == "p" ||
            base.starts_with("P_coll_"))
            undefined = first;
        // A sheared Enskog gas's reduced stresses hold the collisional part, an interval's mean.
        if (enskog_ && (base == "eta_star" || base == "N1_star" || base == "N2_star" ||
                        (base.starts_with("P_") && base.ends_with("_star"))))
            undefined |= first;
        if (base == "theta" || base == "a20" || base == "a11")
            undefined |= zero("T_tr" + suffix);
        if (base == "a02" || base == "a11" || base == "A_cw")
            undefined |= zero("T_rot" + suffix);
        if (const std::size_t slash = name.find('/'); slash != std::string::npos)
            undefined = zero(name.substr(slash + 1)); // T_tr.A/T_tr.B with T_tr.B = 0
        if (!undefined) {
            throw NonFiniteValue(
                name, t, row[j],
                fmt::format("column {} is {} at t = {} (coll_per_particle = {})", name, row[j], t,
                            value.count("coll_per_particle") ? value["coll_per_particle"] : 0.0));
        }
    }
}

void MomentsTable::require_replicas(std::size_t rows) const {
    if (rows != static_cast<std::size_t>(replicas_))
        throw std::invalid_argument(fmt::format("MomentsTable: {} replica rows for {} replicas", rows, replicas_));
}

std::vector<double> MomentsTable::combine_walls(std::span<const std::span<const double>> rows) const {
    require_replicas(rows.size());
    std::vector<double> out;
    std::vector<double> x(rows.size());
    const std::size_t n = solver_.size();
    for (std::size_t j = 0; j < 2 + wall_solver_.size(); ++j) {
        const std::size_t k = j < 2 ? j : n + j - 2;
        for (std::size_t r = 0; r < rows.size(); ++r)
            x[r] = rows[r][k];
        const ReplicaMean m = replica_mean(x);
        out.push_back(m.mean);
        if (replicas_ > 1 && j >= 2)
            out.push_back(m.error);
    }
    return out;
}

std::vector<std::vector<double>>
MomentsTable::combine_entries(std::span<const std::span<const double>> rows, std::size_t entries,
                              const std::function<std::vector<double>(std::size_t)>& head, std::size_t first,
                              std::size_t count) const {
    require_replicas(rows.size());
    std::vector<std::vector<double>> out;
    std::vector<double> x(rows.size());
    for (std::size_t e = 0; e < entries; ++e) {
        std::vector<double> row;
        for (std::size_t j = 0; j < 2; ++j) { // t, coll_per_particle: the replicas' mean (t: exact when shared)
            for (std::size_t r = 0; r < rows.size(); ++r)
                x[r] = rows[r][j];
            row.push_back(j == 0 ? replica_mean_of_shared(x).mean : replica_mean(x).mean);
        }
        for (double h : head(e))
            row.push_back(h);
        for (std::size_t f = 0; f < count; ++f) {
            for (std::size_t r = 0; r < rows.size(); ++r)
                x[r] = rows[r][first + e * count + f];
            const ReplicaMean m = replica_mean(x);
            row.push_back(m.mean);
            if (replicas_ > 1)
                row.push_back(m.error);
        }
        out.push_back(std::move(row));
    }
    return out;
}

std::vector<std::vector<double>>
MomentsTable::combine_profiles(std::span<const std::span<const double>> rows) const {
    return combine_entries(
        rows, bin_centres_.size(),
        [&](std::size_t b) { return std::vector<double>{static_cast<double>(b), bin_centres_[b]}; }, profile_start_,
        profile_field_count);
}

std::vector<std::vector<double>>
MomentsTable::combine_spectra(std::span<const std::span<const double>> rows) const {
    return combine_entries(
        rows, spectrum_bins_.size(),
        [&](std::size_t e) {
            const SpectrumBin& b = spectrum_bins_[e];
            return std::vector<double>{static_cast<double>(b.axis), static_cast<double>(b.n), b.k,
                                       static_cast<double>(b.modes)};
        },
        spectra_start_, spectrum_field_count);
}

std::vector<std::vector<double>> MomentsTable::combine_modes(std::span<const std::span<const double>> rows) const {
    std::vector<std::vector<double>> out = combine_entries(
        rows, modes_.size(),
        [&](std::size_t e) {
            const ModeIndex& m = modes_[e];
            return std::vector<double>{static_cast<double>(m.axis), static_cast<double>(m.n), m.k};
        },
        spectra_start_ + spectrum_bins_.size() * spectrum_field_count, mode_field_count);
    for (std::size_t e = 0; e < mode_theory_.size(); ++e)
        out[e].insert(out[e].end(), mode_theory_[e].begin(), mode_theory_[e].end());
    return out;
}

std::vector<double> MomentsTable::combine(std::span<const std::span<const double>> rows) {
    require_replicas(rows.size());
    const std::size_t n = solver_.size();
    std::vector<double> out;
    out.reserve(columns_.size());
    std::vector<double> x(rows.size());
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t r = 0; r < rows.size(); ++r)
            x[r] = rows[r][j];
        // Column 0, t: the time clock's rows at the same t in every replica keep it exactly (and the
        // theory columns below are taken at it). coll_per_particle, shared by the collision clock's
        // replicas, keeps its mean as it always has.
        const ReplicaMean m = j == 0 ? replica_mean_of_shared(x) : replica_mean(x);
        out.push_back(m.mean);
        if (replicas_ > 1)
            out.push_back(m.error);
    }
    if (zeta_) { // solver columns 1 and 2: coll_per_particle, T_tr (dsmc_columns)
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const double cpp = rows[r][1], T = rows[r][2];
            // Undefined (NaN) in the first row, and where either temperature is 0 or no collision
            // separates the rows.
            x[r] = T > 0 && prev_T_tr_[r] > 0 && cpp > prev_cpp_[r]
                       ? -std::log(T / prev_T_tr_[r]) / (cpp - prev_cpp_[r])
                       : std::numeric_limits<double>::quiet_NaN();
            prev_T_tr_[r] = T;
            prev_cpp_[r] = cpp;
        }
        const ReplicaMean m = replica_mean(x);
        out.push_back(m.mean);
        if (replicas_ > 1)
            out.push_back(m.error);
    }
    if (trajectory_) {
        const double t = out[0];
        // p_theory's midpoint of the interval since the previous row, before the trajectory moves on to
        // t (it only moves forward).
        double p_coll_mid = std::numeric_limits<double>::quiet_NaN();
        if (enskog_ && std::isfinite(p_coll_prev_) && t > t_prev_)
            p_coll_mid = enskog_collisional_pressure(trajectory_->theory(), trajectory_->at(0.5 * (t_prev_ + t)));
        const HcsTemperatures T = trajectory_->at(t);
        const HcsTheory& th = trajectory_->theory();
        const double tr = th.mixture_T_tr(T), rot = th.mixture_T_rot(T);
        out.push_back(tr);
        out.push_back(rot);
        out.push_back(rot / tr);
        if (th.species_count() > 1) {
            for (std::size_t s = 0; s < th.species_count(); ++s) {
                out.push_back(T.T_tr[s]);
                out.push_back(T.T_rot[s]);
                out.push_back(T.T_rot[s] / T.T_tr[s]);
            }
            for (std::size_t a = 0; a < th.species_count(); ++a)
                for (std::size_t b = a + 1; b < th.species_count(); ++b) {
                    out.push_back(T.T_tr[a] / T.T_tr[b]);
                    out.push_back(T.T_rot[a] / T.T_rot[b]);
                }
        }
        out.push_back(reduced_cooling_rate(th, T));
        if (enskog_)
            out.push_back(pressure_theory(t, T, p_coll_mid));
        out.insert(out.end(), sonine_.begin(), sonine_.end());
        out.insert(out.end(), constant_theory_.begin(), constant_theory_.end());
    }
    out.insert(out.end(), shear_theory_.begin(), shear_theory_.end());
    return out;
}

double MomentsTable::pressure_theory(double t, const HcsTemperatures& T, double p_coll_mid) {
    // The collisional part's mean over [t_prev, t] by Simpson's rule on the trajectory.
    const HcsTheory& th = trajectory_->theory();
    const double end = enskog_collisional_pressure(th, T);
    const double coll = std::isfinite(p_coll_mid) ? (p_coll_prev_ + 4 * p_coll_mid + end) / 6 : end;
    p_coll_prev_ = end;
    t_prev_ = t;
    return enskog_kinetic_pressure(th, T) + coll;
}

namespace {

const std::map<std::string, std::string>& meanings() {
    static const std::map<std::string, std::string> m = {
        {"t", "time since the start (the case's time unit: the density n and the species set it)"},
        {"coll_per_particle", "collisions per particle so far, 2 x collisions / N"},
        {"T_tr", "translational temperature (1/3)<m c^2>, c = v - u (docs/model.md §5)"},
        {"T_rot", "rotational temperature (1/3)<J omega^2>"},
        {"theta", "T_rot/T_tr"},
        {"a20", "(4/15)<c*^4> - 1, c* = c/sqrt(2 T_tr/m): 0 for a Maxwellian"},
        {"a02", "(4/15)<w*^4> - 1, w* = omega/sqrt(2 T_rot/J)"},
        {"a11", "(4/9)<c*^2 w*^2> - 1"},
        {"A_cw", "<(c.omega)^2>/(<c^2><omega^2>) - 1/3: translation-rotation alignment"},
        {"coll_rate", "collisions per particle per unit time since the previous row (NaN at t = 0)"},
        {"E_diss_rate", "energy dissipated per unit volume and time since the previous row (NaN at t = 0)"},
        {"p_kin", "run.equation = enskog: the kinetic pressure n T_tr, the trace of the kinetic pressure tensor over 3"},
        {"p_coll", "run.equation = enskog: the collisional transfer part of the pressure, (1/3) sum sigma_ab J_n over "
                   "the collisions since the previous row, over the volume and the interval's length (J_n = m_ab "
                   "(1 + alpha) g_n the normal impulse a collision moves across the grains' distance sigma_ab: the "
                   "virial of hard spheres; in a box the trace over 3 of the collisions' impulse times the grains' actual "
                   "separation, through the periodic images); NaN at t = 0"},
        {"p", "run.equation = enskog: p_kin + p_coll, the pressure (NaN at t = 0)"},
        {"a_star_grad", "shear runs of one species of smooth grains with constant alpha < 1: the steady a* of "
                        "Grad's approximation (of the Enskog equation at the run's phi and chi; of the Boltzmann "
                        "equation, phi = 0, without run.equation = enskog), the same in every row; a few per cent "
                        "from the DSMC's (docs/validation.md)"},
        {"eta_star_grad", "the steady eta* of the same state (as a_star_grad)"},
        {"P_xx_star_grad", "the steady P_xx_star of the same state (as a_star_grad)"},
        {"P_yy_star_grad", "the steady P_yy_star of the same state (as a_star_grad)"},
        {"P_zz_star_grad", "the steady P_zz_star of the same state (as a_star_grad; = P_yy_star_grad at phi = 0)"},
        {"N1_star_grad", "P_xx_star_grad - P_yy_star_grad"},
        {"N2_star_grad", "P_yy_star_grad - P_zz_star_grad"},
        {"P_coll_xx", "sheared Enskog gas: the collisional transfer part of the pressure tensor, the flux along x of "
                      "x-momentum, sum of sigma n_x J_x over the collisions since the previous row per volume and "
                      "time (J the impulse on the grain at r_j + sigma n); NaN at t = 0"},
        {"P_coll_yy", "as P_coll_xx, along y of y-momentum"},
        {"P_coll_zz", "as P_coll_xx, along z of z-momentum"},
        {"P_coll_xy", "as P_coll_xx, along y of x-momentum: the collisional shear stress of u = a y x"},
        {"P_coll_xz", "as P_coll_xx, along z of x-momentum"},
        {"P_coll_yz", "as P_coll_xx, along z of y-momentum"},
        {"p_theory", "run.equation = enskog: the Enskog pressure of the Maxwellian approximation's temperatures, its "
                     "kinetic part n T_tr at t plus its collisional part (pi/3) sum_ab n_a n_b chi_ab sigma_ab^3 m_ab "
                     "(1 + alpha_ab) (T_a/m_a + T_b/m_b) averaged over the interval since the previous row, as p "
                     "(one species: n T [1 + 2 (1 + alpha) phi chi]; exact for any distribution given the "
                     "temperatures)"},
        {"beta_clamped",
         "collisions so far whose brilliantov beta left [-1, 1] and was clamped (brilliantov runs)"},
        {"cell_over_lambda", "box runs: the largest cell edge over the local mean free path "
                             "1/(sqrt(2) pi n_b sigma^2) among the profile slabs (n_b the slab's density, sigma the "
                             "largest diameter); run warns once it exceeds 0.5 and 1"},
        {"cell_over_lambda_cells",
         "box runs: the same at the density of the cell holding the most grains, N_c, counted 8 Poisson "
         "standard deviations of the mean count m = N/C and 8 grains low: (N_c - 8 sqrt(m) - 8)/m times the "
         "mean density, at least the mean (a uniform gas's noisiest cell reads as the mean, a cluster as "
         "nearly itself); with run.kernel = maxwell both paths are <v>/nu at the kernel's constant rate; run "
         "warns once it exceeds 0.5 and 1 where it exceeds cell_over_lambda by 5 %"},
        {"T_th",
         "box runs: the translational temperature about the local flow, each grain's velocity taken about its "
         "collision cell's mass-weighted mean velocity U_c: sum over cells and their grains of m (v - U_c)^2 over "
         "3 sum_c (N_c - 1) (cells of fewer than two grains count nothing; the N_c - 1 makes it unbiased at any "
         "number of grains per cell). T_tr, about the box's mean velocity u, holds the flows the cells resolve (a "
         "wave, a shear flow, vortices) besides: 3 N T_tr = 3 (N - C) T_th + sum_c M_c (U_c - u)^2 exactly, C the "
         "occupied cells, M_c a cell's mass (a sheared box's T_tr is about the images' flow a (y - L_y/2) "
         "instead). A flow varying within a cell stays in T_th (a shear rate a across cells of edge h adds "
         "m a^2 h^2/36). Taken after the step's collisions, from the cells' sums; NaN when no cell holds two "
         "grains"},
        {"u_wave", "box runs with an [initial] wave: its velocity amplitude, (2/N) sum of v.e sin(k.x) over the "
                   "grains (e: the transverse direction of a transverse wave, k/|k| for the other waves)"},
        {"n_wave", "box runs with an [initial] wave: the relative amplitude of the density wave, (2/N) sum of "
                   "sin(k.x)"},
        {"e_wave", "box runs with an [initial] wave: the relative amplitude of the wave of translational energy "
                   "density, (2/N) sum of (m v^2/2) sin(k.x) over the mean of m v^2/2"},
        {"T_tr_theory",
         "T_tr of the Maxwellian approximation at t (constant alpha, beta; Haff's law when smooth); with "
         "run.kernel = maxwell the exact solution of its linear ODEs; with a thermostat the same equations "
         "with its sources added (the driven gas, docs/model.md), integrated through the drive's schedule"},
        {"T_rot_theory", "T_rot of the Maxwellian approximation at t (constant alpha, beta; driven with a "
                         "thermostat, as T_tr_theory)"},
        {"theta_theory", "T_rot_theory/T_tr_theory"},
        {"zeta_star", "reduced cooling rate -ln(T_tr/T_tr,p)/(coll_per_particle - coll_per_particle,p), p "
                      "the previous row: the translational temperature's decay per collision per particle (cooling "
                      "runs; NaN at t = 0 and where either T_tr is 0; constant in the scaled homogeneous cooling state; "
                      "with a thermostat the net decay, the thermostat's heating included: 0 in the steady state)"},
        {"zeta_star_theory", "-(dT_tr/dt)/(T_tr nu_c) of the Maxwellian approximation at t, nu_c its collisions "
                             "per particle and unit time (constant alpha, beta; (1 - alpha^2)/3 for smooth "
                             "spheres); with a thermostat the collisions' part of dT_tr/dt alone, without the "
                             "thermostat's sources: the collisional cooling per collision, > 0 in the steady "
                             "state"},
        {"theta_sonine",
         "theta of the scaled homogeneous cooling state in the first Sonine approximation, its cumulants "
         "linearised, theta solved on the branch of the Maxwellian one (Santos, Kremer & dos Santos 2011; "
         "docs/model.md): the same in every row; one species with constant alpha, beta and the hard-sphere "
         "kernel, cooling runs (no thermostat); NaN for smooth grains (no scaled theta) and where the approximation has no cooling state"},
        {"zeta_star_sonine", "zeta_star of the same state, (2/3) R_c2/(1 - a20/16) with its cumulants (as "
                             "theta_sonine; for smooth grains with van Noije & Ernst's a2)"},
        {"a20_sonine", "a20 of the same state (as theta_sonine; van Noije & Ernst's a2 for smooth grains); with a "
                       "thermostat (one species of smooth grains, white noise without rotational share, hard-sphere "
                       "kernel) van Noije & Ernst's steady a2 under white noise"},
        {"T_tr_sonine", "the steady T_tr of smooth grains under white noise in the first Sonine approximation, "
                        "(m xi0^2/(G A (1 + 3 a2/16)))^(2/3) at the final strength (as a20_sonine with a thermostat): "
                        "the same in every row"},
        {"T_tr_steady_theory", "the steady T_tr of the Maxwellian approximation under the thermostat's final drives "
                               "(driven runs with constant alpha, beta; NaN where there is none): the same in every row"},
        {"T_rot_steady_theory", "the steady T_rot of the same state (as T_tr_steady_theory)"},
        {"theta_steady_theory", "T_rot_steady_theory/T_tr_steady_theory"},
        {"a02_sonine", "a02 of the same state (as theta_sonine; NaN for smooth grains, whose spins keep their "
                       "initial distribution)"},
        {"a11_sonine", "a11 of the same state (as a02_sonine)"},
        // uniform shear flow (run.kind = shear; observables/pressure.hpp)
        {"P_xx", "kinetic pressure tensor (1/V) sum m V_x V_x, V the peculiar velocity (shear runs)"},
        {"P_yy", "(1/V) sum m V_y V_y (shear runs)"},
        {"P_zz", "(1/V) sum m V_z V_z (shear runs)"},
        {"P_xy", "(1/V) sum m V_x V_y: the shear stress, < 0 (shear runs; with run.equation = enskog its kinetic part, P_coll_xy the collisional one)"},
        {"P_xz", "(1/V) sum m V_x V_z: 0 by symmetry (shear runs)"},
        {"P_yz", "(1/V) sum m V_y V_z: 0 by symmetry (shear runs)"},
        {"omega_x", "mean spin Omega_x = sum J omega_x/sum J (shear runs; T_rot is about Omega)"},
        {"omega_y", "mean spin Omega_y (shear runs)"},
        {"omega_z", "mean spin Omega_z (shear runs)"},
        {"a_star", "reduced shear rate a/nu, nu = p/eta_0 = (16/5) n sigma^2 sqrt(pi T_tr/m) (shear runs)"},
        {"eta_star", "reduced shear viscosity -P_xy_star/a_star (shear runs; the whole stress: in a sheared Enskog gas kinetic and collisional)"},
        {"P_xx_star", "P_xx/(n T_tr) (shear runs; a sheared Enskog gas: (P_xx + P_coll_xx)/(n T_tr), the whole tensor, NaN at t = 0, as every reduced stress below)"},
        {"P_yy_star", "P_yy/(n T_tr) (shear runs)"},
        {"P_zz_star", "P_zz/(n T_tr) (shear runs)"},
        {"P_xy_star", "P_xy/(n T_tr) (shear runs)"},
        {"P_xz_star", "P_xz/(n T_tr) (shear runs)"},
        {"P_yz_star", "P_yz/(n T_tr) (shear runs)"},
        {"N1_star", "first normal stress difference P_xx_star - P_yy_star (shear runs)"},
        {"N2_star", "second normal stress difference P_yy_star - P_zz_star (shear runs)"},
    };
    return m;
}

} // namespace

std::string moments_column_meaning(const std::string& name) {
    if (name.size() > 4 && name.ends_with("_err")) {
        const std::string x = name.substr(0, name.size() - 4);
        return moments_column_meaning(x).empty()
                   ? ""
                   : "standard error of the mean of " + x + " over the replicas";
    }
    if (name.ends_with("_theory") && name.find('/') != std::string::npos) {
        const std::string m = moments_column_meaning(name.substr(0, name.size() - 7));
        return m.empty() ? "" : m + ", in the Maxwellian approximation at t (constant alpha, beta)";
    }
    if (const std::size_t slash = name.find('/'); slash != std::string::npos) {
        const auto [num, a] = split(name.substr(0, slash));
        const auto [den, b] = split(name.substr(slash + 1));
        if (num != den || a.empty() || b.empty() || !meanings().count(num))
            return "";
        return "ratio of " + num + " of species " + a.substr(1) + " to that of species " + b.substr(1);
    }
    const auto [base, suffix] = split(name);
    const auto it = meanings().find(base);
    if (it == meanings().end())
        return "";
    if (suffix.empty())
        return it->second;
    if (base == "coll_rate")
        return "collisions of a " + suffix.substr(1) + " grain per " + suffix.substr(1) +
               " grain and unit time since the previous row";
    return "as " + base + ", over the grains of species " + suffix.substr(1);
}

std::string moments_columns_markdown() {
    // Columns of representative runs: one species with constant restitution and replicas (every
    // base column, X_err, theory), and a brilliantov mixture of species A and B (the per-species
    // columns and ratios); per-species columns are shown once, for NAME.
    RunSpec one;
    one.species = {SpeciesSpec{}};
    one.pairs = {ConstantRestitution{0.9, 0.0}};
    one.replicas = 2;
    RunSpec mix;
    mix.species = {SpeciesSpec{}, SpeciesSpec{}};
    mix.species[0].name = "A";
    mix.species[1].name = "B";
    mix.pairs = {BrilliantovRestitution{}, BrilliantovRestitution{}, BrilliantovRestitution{}};
    RunSpec mix_constant = mix;
    mix_constant.pairs = {ConstantRestitution{}, ConstantRestitution{}, ConstantRestitution{}};
    std::vector<Column> rows;
    const auto add = [&](const Column& c) {
        for (const Column& r : rows)
            if (r.name == c.name)
                return;
        rows.push_back(c);
    };
    const MomentsTable t1(one);
    for (const Column& c : t1.columns())
        if (!c.name.ends_with("_err") || c.name == "t_err")
            add(c);
    RunSpec dense = one; // the Enskog equation: the pressure columns
    dense.enskog = EnskogSpec{};
    const MomentsTable t7(dense);
    for (const Column& c : t7.columns())
        if (!c.name.ends_with("_err"))
            add(c);
    RunSpec dense_shear = dense; // the sheared Enskog gas: the collisional stresses after the shear columns
    dense_shear.shear = ShearSpec{};
    const MomentsTable t8(dense_shear);
    for (const Column& c : t8.columns())
        if (!c.name.ends_with("_err"))
            add(c);
    RunSpec driven = one; // a driven gas of smooth grains: its steady-state columns after the cooling ones
    driven.pairs = {ConstantRestitution{0.9, -1.0}};
    driven.thermostat = ThermostatSpec{};
    driven.thermostat->species.resize(1);
    driven.thermostat->species[0].drive.value = {1.0};
    const MomentsTable t6(driven);
    for (const Column& c : t6.columns())
        if (!c.name.ends_with("_err"))
            add(c);
    RunSpec shear = one; // the shear columns come after the base columns; smooth grains: Grad's steady state
    shear.shear = ShearSpec{};
    shear.pairs = {ConstantRestitution{0.9, -1.0}};
    const MomentsTable t4(shear);
    for (const Column& c : t4.columns())
        if (!c.name.ends_with("_err"))
            add(c);
    const MomentsTable t2(mix), t3(mix_constant);
    for (const Column& c : t2.columns())
        add(c);
    for (const Column& c : t3.columns())
        add(c);
    RunSpec wave = one; // a box with an initial wave: its amplitudes come last
    wave.domain = DomainSpec{};
    wave.domain->initial.mode = Perturbation::transverse;
    const MomentsTable t5(wave);
    for (const Column& c : t5.columns())
        if (!c.name.ends_with("_err"))
            add(c);
    std::string out = "`DIR/moments.csv` (one row per output time, the first at t = 0):\n\n"
                      "| Column | Unit | Meaning |\n|--------|------|---------|\n";
    for (Column c : rows) {
        if (c.name == "t_err") {
            out += "| `X_err` | as X | standard error of the mean of X over the replicas (replicas > 1): one "
                   "after "
                   "every column X of the solver, sqrt(sum (X_r - X)^2/(K (K - 1))) |\n";
            continue;
        }
        std::string meaning = moments_column_meaning(c.name);
        std::string name = c.name;
        if (name.find('/') == std::string::npos) { // per-species: A stands for every NAME; B is left out
            const auto [base, suffix] = split(name);
            if (suffix == ".B")
                continue;
            if (suffix == ".A") {
                name = base + ".NAME";
                meaning = moments_column_meaning(base + ".NAME");
            }
        }
        out += "| `" + name + "` | " + c.unit + " | " + meaning + " |\n";
    }
    return out;
}

} // namespace roughgas
