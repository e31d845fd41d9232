// The Maxwellian-approximation HCS theory: the derivation is in observables/theory.hpp.
#include "roughgas/observables/theory.hpp"

#include "roughgas/dsmc/pair_correlation.hpp"

#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/observables/driven_theory.hpp"

#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace roughgas {
namespace {

void require(bool ok, const std::string& what) {
    if (!ok)
        throw std::invalid_argument("HcsTheory: " + what);
}

// Integration round-off never makes a temperature negative.
double pos(double x) {
    return x > 0 ? x : 0.0;
}

// Error control of the scaled state (ln(E/E0), T_k/E): absolute on ln E (= relative on E), relative
// on every fraction T_k/E, so a temperature 40 decades below the others is still integrated to
// rel_tol (odeint's default_error_checker mixes one absolute and one relative tolerance over all
// components). A non-finite error estimate (a trial step that overflowed) rejects the step.
class ScaleFreeErrorChecker {
  public:
    using value_type = double;
    explicit ScaleFreeErrorChecker(double rel_tol = 1e-10) : rel_tol_(rel_tol) {}

    template <class Algebra, class State, class Deriv, class Err, class Time>
    double error(Algebra&, const State& x_old, const Deriv& dxdt_old, Err& x_err, Time dt) const {
        double worst = std::abs(x_err[0]) / rel_tol_;
        for (std::size_t k = 1; k < x_err.size(); ++k) {
            const double scale =
                rel_tol_ * (std::abs(x_old[k]) + std::abs(dt) * std::abs(dxdt_old[k])) + 1e-300;
            worst = std::max(worst, std::abs(x_err[k]) / scale);
        }
        return std::isfinite(worst) ? worst : 1e300;
    }
    template <class State, class Deriv, class Err, class Time>
    double error(const State& x_old, const Deriv& dxdt_old, Err& x_err, Time dt) const {
        int unused = 0;
        return error(unused, x_old, dxdt_old, x_err, dt);
    }

  private:
    double rel_tol_;
};

} // namespace

HcsTheory::HcsTheory(std::vector<HcsSpecies> species, std::vector<ConstantRestitution> pairs, double density)
    : species_(std::move(species)), pairs_(std::move(pairs)), density_(density) {
    const std::size_t S = species_.size();
    require(S > 0, "no species");
    require(pairs_.size() == S * (S + 1) / 2, "one (alpha, beta) per species pair needed");
    require(density_ > 0 && std::isfinite(density_), "density must be > 0");
    for (const HcsSpecies& s : species_) {
        require(s.mass > 0 && s.radius > 0 && s.inertia > 0, "mass, radius and inertia must be > 0");
        require(s.fraction >= 0, "fractions must be >= 0");
    }
    for (const ConstantRestitution& p : pairs_) {
        require(p.alpha >= 0 && p.alpha <= 1, "alpha must be in [0, 1]");
        require(p.beta >= -1 && p.beta <= 1, "beta must be in [-1, 1]");
    }
    chi_.assign(pairs_.size(), 1.0);
}

void HcsTheory::set_pair_correlations(std::vector<double> chi) {
    require(chi.size() == pairs_.size(), "one pair correlation per species pair needed");
    for (double x : chi)
        require(x > 0 && std::isfinite(x), "pair correlations must be > 0");
    chi_ = std::move(chi);
}

HcsTheory::HcsTheory(std::vector<HcsSpecies> species, std::vector<ConstantRestitution> pairs, double density,
                     std::vector<double> maxwell_T0_tr)
    : HcsTheory(std::move(species), std::move(pairs), density) {
    require(maxwell_T0_tr.size() == species_.size(), "one initial T_tr per species for the Maxwell kernel");
    for (double T : maxwell_T0_tr)
        require(T >= 0 && std::isfinite(T), "initial temperatures must be finite and >= 0");
    maxwell_T0_ = std::move(maxwell_T0_tr);
}

PairExchange HcsTheory::exchange(std::size_t a, std::size_t b, std::span<const double> T_tr,
                                 std::span<const double> T_rot) const {
    const HcsSpecies& A = species_[a];
    const HcsSpecies& B = species_[b];
    const ConstantRestitution& r = pairs_[pair_index(a, b, species_.size())];
    const PairConstants pc =
        make_pair_constants({A.mass, A.radius, A.inertia}, {B.mass, B.radius, B.inertia});
    const double Ta = pos(T_tr[a]), Tb = pos(T_tr[b]);
    const double s = Ta / A.mass + Tb / B.mass; // variance of v_ij
    const double s_w =
        pos(T_rot[a]) / (A.inertia * A.mass) + pos(T_rot[b]) / (B.inertia * B.mass); // of Omega
    const double a_n = pc.m_eff * (1 + r.alpha);
    const double a_t = pc.kappa * pc.m_eff * (1 + r.beta);
    PairExchange x;
    if (maxwell()) { // the Maxwell kernel (theory.hpp): constant frequency, exact averages
        const double s0 = maxwell_T0_[a] / A.mass + maxwell_T0_[b] / B.mass;
        x.frequency = pair_correlation(a, b) * density_ * B.fraction * pc.sigma * pc.sigma *
                      std::sqrt(8 * std::numbers::pi * s0);
        x.dE_tr = -(Ta / A.mass) * (a_n + 2 * a_t) + (0.5 * a_n * a_n * s + a_t * a_t * (s + s_w)) / A.mass;
        x.dE_rot = (-2 * a_t * pos(T_rot[a]) + a_t * a_t * (s + s_w)) / (A.inertia * A.mass);
        return x;
    }
    x.frequency =
        pair_correlation(a, b) * density_ * B.fraction * pc.sigma * pc.sigma * std::sqrt(8 * std::numbers::pi * s);
    const double p2 = a_n * a_n * s + a_t * a_t * (s + s_w); // <|P|^2>/2
    x.dE_tr = -2 * (Ta / A.mass) * (a_n + a_t) + p2 / A.mass;
    x.dE_rot = (-2 * a_t * pos(T_rot[a]) + a_t * a_t * (s + s_w)) / (A.inertia * A.mass);
    return x;
}

void HcsTheory::rates(std::span<const double> T_tr, std::span<const double> T_rot, std::span<double> dT_tr,
                      std::span<double> dT_rot) const {
    const std::size_t S = species_.size();
    for (std::size_t a = 0; a < S; ++a) {
        double tr = 0, rot = 0;
        for (std::size_t b = 0; b < S; ++b) {
            if (species_[b].fraction == 0)
                continue;
            const PairExchange x = exchange(a, b, T_tr, T_rot);
            tr += x.frequency * x.dE_tr;
            rot += x.frequency * x.dE_rot;
        }
        dT_tr[a] = (2.0 / 3.0) * tr; // (3/2) dT/dt = energy change per grain and unit time
        dT_rot[a] = (2.0 / 3.0) * rot;
    }
}

// sum_s x_s T_s / sum_s x_s: the temperature of the mixture (docs/model.md §5 over all grains).
double HcsTheory::fraction_weighted(std::span<const double> T) const {
    double sum = 0, x = 0;
    for (std::size_t s = 0; s < species_.size(); ++s) {
        sum += species_[s].fraction * T[s];
        x += species_[s].fraction;
    }
    return sum / x;
}

double HcsTheory::mixture_T_tr(const HcsTemperatures& T) const {
    return fraction_weighted(T.T_tr);
}

double HcsTheory::mixture_T_rot(const HcsTemperatures& T) const {
    return fraction_weighted(T.T_rot);
}

namespace {
// Collisions per particle and unit time at T, each grain's weighted by its fraction: the sum of
// x_a nu_a and the sum of x_a (nu_c is their ratio).
std::pair<double, double> weighted_frequency(const HcsTheory& theory, const HcsTemperatures& T) {
    const std::size_t S = theory.species_count();
    double nu = 0, x = 0;
    for (std::size_t a = 0; a < S; ++a) {
        const double xa = theory.species()[a].fraction;
        for (std::size_t b = 0; b < S; ++b)
            nu += xa * theory.exchange(a, b, T.T_tr, T.T_rot).frequency;
        x += xa;
    }
    return {nu, x};
}
} // namespace

double collision_frequency(const HcsTheory& theory, const HcsTemperatures& T) {
    const auto [nu, x] = weighted_frequency(theory, T);
    return nu / x;
}

double reduced_cooling_rate(const HcsTheory& theory, const HcsTemperatures& T) {
    const std::size_t S = theory.species_count();
    std::vector<double> dT_tr(S), dT_rot(S);
    theory.rates(T.T_tr, T.T_rot, dT_tr, dT_rot);
    const auto [nu, x] = weighted_frequency(theory, T);
    const HcsTemperatures rate{dT_tr, dT_rot};
    return -theory.mixture_T_tr(rate) / (theory.mixture_T_tr(T) * nu / x);
}

namespace {

// The trajectory from `initial` until its reduced cooling rate zeta* settles (the cooling state's
// ratios of the temperatures): where and when it is then, the collisions per particle on the way
// (the fall of ln T_tr over zeta*), and the settled zeta*.
struct SettledCooling {
    HcsTemperatures T;
    double t = 0, collisions = 0, zeta = 0;
};

SettledCooling settle_cooling(const HcsTheory& theory, const HcsTemperatures& initial) {
    // Steps of about 5 collisions per particle at the current frequency (the gas's own clock: an
    // elastic gas keeps it, a cooling one slows it), until zeta* settles to 1e-9 (or 1e-15 absolute:
    // an elastic gas's tends to 0), or 4000 steps.
    HcsTrajectory trajectory(theory, initial);
    SettledCooling s{initial, 0.0, 0.0, reduced_cooling_rate(theory, initial)};
    for (int k = 0; k < 4000; ++k) {
        const double t = s.t + 5.0 / collision_frequency(theory, s.T);
        const HcsTemperatures next = trajectory.at(t);
        const double z = reduced_cooling_rate(theory, next);
        const double mean = 0.5 * (s.zeta + z); // -d ln T_tr/ds, nearly constant over the step
        if (mean > 0)
            s.collisions += std::log(theory.mixture_T_tr(s.T) / theory.mixture_T_tr(next)) / mean;
        const bool settled = std::abs(z - s.zeta) <= std::max(1e-9 * std::abs(z), 1e-15);
        s.t = t;
        s.T = next;
        s.zeta = z;
        if (settled)
            break;
    }
    return s;
}

// The smallest T_tr,s/m_s over `floor`: the factor the settled gas still cools by.
double fall_to_floor(const HcsTheory& theory, const HcsTemperatures& T, double floor) {
    double least = HUGE_VAL;
    for (std::size_t s = 0; s < theory.species_count(); ++s)
        least = std::min(least, T.T_tr[s] / theory.species()[s].mass);
    return least / floor;
}

// The settled cooling both reaches start from; none when the gas does not cool (no collisions, no
// floor, or a cooling rate that vanishes: it never reaches the floor).
std::optional<SettledCooling> settled_towards(const HcsTheory& theory, const HcsTemperatures& initial, double floor) {
    if (!(collision_frequency(theory, initial) > 0) || !(floor > 0))
        return std::nullopt;
    const SettledCooling s = settle_cooling(theory, initial);
    if (!(s.zeta > 1e-12))
        return std::nullopt;
    return s;
}

} // namespace

double cooling_reach(const HcsTheory& theory, const HcsTemperatures& initial, double floor) {
    const std::optional<SettledCooling> settled = settled_towards(theory, initial, floor);
    if (!settled)
        return HUGE_VAL;
    const SettledCooling& s = *settled;
    return s.collisions + std::log(fall_to_floor(theory, s.T, floor)) / s.zeta;
}

double cooling_reach_time(const HcsTheory& theory, const HcsTemperatures& initial, double floor) {
    const std::optional<SettledCooling> settled = settled_towards(theory, initial, floor);
    if (!settled)
        return HUGE_VAL;
    const SettledCooling& s = *settled;
    const double nu = collision_frequency(theory, s.T);
    const double fall = fall_to_floor(theory, s.T, floor);
    if (theory.maxwell()) // a constant frequency: T_tr = T_1 exp(-zeta* nu (t - t_1))
        return s.t + std::log(fall) / (s.zeta * nu);
    // Hard spheres: nu = nu_1 sqrt(T/T_1), so d ln T/dt = -zeta* nu gives Haff's law
    // sqrt(T_1/T) = 1 + zeta* nu_1 (t - t_1)/2.
    return s.t + 2.0 * (std::sqrt(fall) - 1.0) / (s.zeta * nu);
}

// --- the trajectory ---

HcsTrajectory::HcsTrajectory(HcsTheory theory, HcsTemperatures initial, double rel_tol, bool closed_form)
    : theory_(std::move(theory)), initial_(std::move(initial)), rel_tol_(rel_tol) {
    const std::size_t S = theory_.species_count();
    require(initial_.T_tr.size() == S && initial_.T_rot.size() == S,
            "one initial T_tr and T_rot per species");
    require(rel_tol_ > 0, "rel_tol must be > 0");
    for (std::size_t s = 0; s < S; ++s)
        require(initial_.T_tr[s] >= 0 && initial_.T_rot[s] >= 0 && std::isfinite(initial_.T_tr[s]) &&
                    std::isfinite(initial_.T_rot[s]),
                "initial temperatures must be finite and >= 0");
    // Haff's law only where nothing else moves: one species, beta = -1.
    haff_ = closed_form && S == 1 && theory_.pairs()[0].beta == -1 && !theory_.maxwell();
    for (std::size_t s = 0; s < S; ++s)
        E0_ += initial_.T_tr[s] + initial_.T_rot[s];
    y_.assign(1 + 2 * S, 0.0);
    if (E0_ > 0)
        for (std::size_t s = 0; s < S; ++s) {
            y_[1 + s] = initial_.T_tr[s] / E0_;
            y_[1 + S + s] = initial_.T_rot[s] / E0_;
        }
}

HcsTrajectory::HcsTrajectory(HcsTheory theory, HcsTemperatures initial, ThermostatSpec thermostat, double rel_tol)
    : HcsTrajectory(std::move(theory), std::move(initial), rel_tol, /*closed_form=*/false) {
    check_thermostat(thermostat, theory_.species_count());
    require(E0_ > 0, "a driven trajectory needs an initial temperature > 0");
    switches_ = drive_switch_times(thermostat);
    thermostat_ = std::move(thermostat);
}

HcsTemperatures HcsTrajectory::current() const {
    const std::size_t S = theory_.species_count();
    HcsTemperatures T{std::vector<double>(S), std::vector<double>(S)};
    double norm = 0;
    for (std::size_t k = 1; k < y_.size(); ++k)
        norm += pos(y_[k]);
    const double E = norm > 0 ? E0_ * std::exp(y_[0]) / norm : 0.0;
    for (std::size_t s = 0; s < S; ++s) {
        T.T_tr[s] = E * pos(y_[1 + s]);
        T.T_rot[s] = E * pos(y_[1 + S + s]);
    }
    return T;
}

HcsTemperatures HcsTrajectory::at(double t) {
    require(std::isfinite(t) && t >= t_, "times must be finite and non-decreasing from 0");
    if (haff_) {
        const HcsSpecies& sp = theory_.species()[0];
        t_ = t;
        return {{haff_temperature(t, initial_.T_tr[0], theory_.pairs()[0].alpha, sp.mass, 2 * sp.radius,
                                  theory_.density() * sp.fraction)},
                {initial_.T_rot[0]}};
    }
    if (E0_ == 0 || t == t_) {
        t_ = t;
        return current();
    }
    // Piece by piece between the drive's switch times (none without a thermostat).
    for (double s : switches_)
        if (s > t_ && s < t)
            advance(s);
    advance(t);
    return current();
}

void HcsTrajectory::advance(double t) {
    if (!(t > t_))
        return;
    const std::size_t S = theory_.species_count();
    // The drive over this piece: constant, its value at the piece's start (DriveSchedule::at is
    // right-continuous), so the right-hand side never sees the next piece's value at t itself.
    const double drive_time = t_;
    using State = std::vector<double>;
    std::vector<double> p_tr(S), p_rot(S), f_tr(S), f_rot(S), T_tr(S), T_rot(S), src_tr(S), src_rot(S);
    // In E0 units (the rates are homogeneous of degree 3/2; degree 1 for the Maxwell kernel, below):
    // dT_k/dt = E^{3/2} F_k(p), so
    // d ln E/dt = E^{1/2} sum F(p), dp_k/dt = E^{1/2} (F_k(p) - p_k sum F(p)). Written that way,
    // sum p = 1 would be an unstable invariant (a deviation grows like 1/E as the gas cools); with
    // the normalised p^ = p/sum p on the right-hand side, d(sum p)/dt = 0 and the drift is neutral.
    const double scale = std::sqrt(E0_);
    const auto system = [&](const State& y, State& dydt, double) {
        double norm = 0;
        for (std::size_t k = 1; k < y.size(); ++k)
            norm += pos(y[k]);
        const double inv = norm > 0 ? 1.0 / norm : 0.0;
        for (std::size_t s = 0; s < S; ++s) {
            p_tr[s] = pos(y[1 + s]) * inv;
            p_rot[s] = pos(y[1 + S + s]) * inv;
        }
        theory_.rates(p_tr, p_rot, f_tr, f_rot);
        // The Maxwell kernel's rates are linear in the temperatures (degree 1): no E^{1/2} factor.
        const double root_E = theory_.maxwell() ? 1.0 : scale * std::exp(0.5 * y[0]);
        // g = (dT_k/dt)/E: the collisions' E^{1/2} F_k(p), and the thermostat's sources at T = E p over E
        // (not homogeneous in E; they vanish for a cooling gas).
        for (std::size_t s = 0; s < S; ++s) {
            f_tr[s] *= root_E;
            f_rot[s] *= root_E;
        }
        if (thermostat_) {
            const double E = E0_ * std::exp(y[0]);
            for (std::size_t s = 0; s < S; ++s) {
                T_tr[s] = E * p_tr[s];
                T_rot[s] = E * p_rot[s];
                src_tr[s] = src_rot[s] = 0;
            }
            add_thermostat_sources(*thermostat_, theory_.species(), drive_time, T_tr, T_rot, src_tr, src_rot);
            for (std::size_t s = 0; s < S; ++s) {
                f_tr[s] += src_tr[s] / E;
                f_rot[s] += src_rot[s] / E;
            }
        }
        double sum = 0;
        for (std::size_t s = 0; s < S; ++s)
            sum += f_tr[s] + f_rot[s];
        dydt[0] = sum;
        for (std::size_t s = 0; s < S; ++s) {
            dydt[1 + s] = f_tr[s] - p_tr[s] * sum;
            dydt[1 + S + s] = f_rot[s] - p_rot[s] * sum;
        }
    };
    namespace odeint = boost::numeric::odeint;
    if (dt_ <= 0) {
        // First step: a small fraction of the initial relaxation time 1/|d ln E/dt|.
        State d(y_.size());
        system(y_, d, 0.0);
        double rate = std::abs(d[0]);
        for (std::size_t k = 1; k < d.size(); ++k)
            rate = std::max(rate, std::abs(d[k]));
        dt_ = rate > 0 ? 1e-3 / rate : t - t_;
    }
    const double dt = std::min(dt_, t - t_);
    using Dopri5 = odeint::runge_kutta_dopri5<State>;
    odeint::controlled_runge_kutta<Dopri5, ScaleFreeErrorChecker> stepper{ScaleFreeErrorChecker(rel_tol_)};
    // integrate_adaptive ends exactly at t; the observer records the last step size taken.
    double last_t = t_;
    double last_dt = dt;
    steps_ += odeint::integrate_adaptive(stepper, system, y_, t_, t, dt, [&](const State&, double tt) {
        if (tt > last_t)
            last_dt = tt - last_t;
        last_t = tt;
    });
    dt_ = std::max(dt_, last_dt);
    t_ = t;
}

// --- from a run ---

std::optional<HcsTheory> hcs_theory(const RunSpec& spec) {
    std::vector<ConstantRestitution> pairs;
    for (const PairRestitution& p : spec.pairs) {
        const auto* c = std::get_if<ConstantRestitution>(&p);
        if (!c)
            return std::nullopt;
        pairs.push_back(*c);
    }
    std::vector<HcsSpecies> species;
    double total = 0;
    for (const SpeciesSpec& s : spec.species)
        total += s.fraction;
    for (const SpeciesSpec& s : spec.species)
        species.push_back({s.mass, s.radius, s.inertia, total > 0 ? s.fraction / total : s.fraction});
    std::vector<double> T0;
    if (spec.kernel == CollisionKernel::maxwell)
        for (const SpeciesSpec& s : spec.species)
            T0.push_back(s.temperature);
    HcsTheory theory = T0.empty() ? HcsTheory(std::move(species), std::move(pairs), spec.density)
                                  : HcsTheory(std::move(species), std::move(pairs), spec.density, std::move(T0));
    theory.set_pair_correlations(pair_correlations(spec));
    return theory;
}

HcsTemperatures initial_temperatures(const RunSpec& spec) {
    HcsTemperatures T;
    for (const SpeciesSpec& s : spec.species) {
        T.T_tr.push_back(s.temperature);
        T.T_rot.push_back(s.rotational_temperature);
    }
    return T;
}

// --- equal spheres ---

EqualSphereCoefficients equal_sphere_coefficients(double alpha, double beta, double q, double mass,
                                                  double sigma, double density) {
    EqualSphereCoefficients c;
    c.eta = q * (1 + beta) / (2 * (1 + q));
    c.A = (1 - alpha * alpha) / 4 + c.eta * (1 - c.eta);
    c.B = c.eta * c.eta / q;
    c.C = (c.eta / q) * (1 - c.eta / q);
    c.G = (16.0 / 3.0) * density * sigma * sigma * std::sqrt(std::numbers::pi / mass);
    return c;
}

double haff_time(double T0, double alpha, double mass, double sigma, double density) {
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, -1.0, 0.4, mass, sigma, density);
    const double k = c.G * c.A; // dT/dt = -k T^{3/2}; A does not depend on q for beta = -1
    return k > 0 && T0 > 0 ? 2.0 / (k * std::sqrt(T0)) : std::numeric_limits<double>::infinity();
}

double haff_temperature(double t, double T0, double alpha, double mass, double sigma, double density) {
    const double t0 = haff_time(T0, alpha, mass, sigma, density);
    const double x = 1 + t / t0;
    return T0 / (x * x);
}

double theta_fixed_point(double alpha, double beta, double q) {
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, 1.0, 1.0, 1.0);
    if (c.B == 0)
        return c.A > 0 ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
    const double d = c.A - c.C;
    // The positive root of B theta^2 - d theta - B = 0, written without cancellation for d < 0.
    const double r = std::sqrt(d * d + 4 * c.B * c.B);
    return d >= 0 ? (d + r) / (2 * c.B) : 2 * c.B / (r - d);
}

} // namespace roughgas
