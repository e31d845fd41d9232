// The steady states of the driven two-temperature equations: observables/driven_steady_state.hpp.
#include "roughgas/observables/driven_steady_state.hpp"

#include "roughgas/observables/driven_theory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace roughgas {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

using Vector = std::vector<double>;

bool finite(const Vector& x) {
    return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

// The solution of J x = b (J n x n, row-major) by Gaussian elimination with partial pivoting;
// nullopt for a singular or non-finite J.
std::optional<Vector> solve(Vector J, Vector b) {
    const std::size_t n = b.size();
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t p = c;
        for (std::size_t r = c + 1; r < n; ++r)
            if (std::abs(J[r * n + c]) > std::abs(J[p * n + c]))
                p = r;
        if (!(std::abs(J[p * n + c]) > 0))
            return std::nullopt;
        for (std::size_t k = 0; k < n; ++k)
            std::swap(J[c * n + k], J[p * n + k]);
        std::swap(b[c], b[p]);
        for (std::size_t r = c + 1; r < n; ++r) {
            const double f = J[r * n + c] / J[c * n + c];
            for (std::size_t k = c; k < n; ++k)
                J[r * n + k] -= f * J[c * n + k];
            b[r] -= f * b[c];
        }
    }
    Vector x(n);
    for (std::size_t c = n; c-- > 0;) {
        double sum = b[c];
        for (std::size_t k = c + 1; k < n; ++k)
            sum -= J[c * n + k] * x[k];
        x[c] = sum / J[c * n + c];
    }
    if (!finite(x))
        return std::nullopt;
    return x;
}

// What the steady state of species s's spins is when no collision couples them to the translation
// (beta = -1 with every partner present): unknown == false means an ordinary unknown.
struct Spin {
    bool unknown = true;
    double value = 0; // otherwise: NaN (nothing sets it) or +infinity (white noise heats it for ever)
};

std::vector<Spin> spins(const HcsTheory& theory, const ThermostatSpec& th) {
    const std::size_t S = theory.species_count();
    std::vector<Spin> out(S);
    for (std::size_t a = 0; a < S; ++a) {
        bool coupled = false;
        for (std::size_t b = 0; b < S; ++b)
            if (theory.species()[b].fraction > 0 && theory.pairs()[pair_index(a, b, S)].beta > -1)
                coupled = true;
        if (coupled)
            continue;
        const SpeciesThermostat& s = th.species[a];
        const double fed = th.kind == ThermostatKind::white_noise ? s.rotational_share * s.drive.at(0)
                                                                   : s.rotational_friction;
        if (th.kind == ThermostatKind::langevin && fed > 0)
            continue; // the bath sets it: T_b
        out[a] = {false, fed > 0 ? inf : nan};
    }
    return out;
}

// The equations' relative rates (dT_k/dt)/T_k at T_k = exp(u_k) over the unknowns (T_tr of every
// species, then the T_rot that are unknowns; the others enter as 0: no collision sees them).
class Residual {
  public:
    Residual(const HcsTheory& theory, const ThermostatSpec& th, const std::vector<Spin>& spin)
        : theory_(theory), th_(th), spin_(spin), S_(theory.species_count()) {
        for (std::size_t s = 0; s < S_; ++s)
            if (spin_[s].unknown)
                rot_.push_back(s);
    }
    std::size_t size() const { return S_ + rot_.size(); }
    HcsTemperatures temperatures(const Vector& u) const {
        HcsTemperatures T{std::vector<double>(S_), std::vector<double>(S_, 0.0)};
        for (std::size_t s = 0; s < S_; ++s)
            T.T_tr[s] = std::exp(u[s]);
        for (std::size_t k = 0; k < rot_.size(); ++k)
            T.T_rot[rot_[k]] = std::exp(u[S_ + k]);
        return T;
    }
    Vector unknowns(const HcsTemperatures& T) const {
        Vector u(size());
        for (std::size_t s = 0; s < S_; ++s)
            u[s] = std::log(T.T_tr[s]);
        for (std::size_t k = 0; k < rot_.size(); ++k)
            u[S_ + k] = std::log(T.T_rot[rot_[k]]);
        return u;
    }
    Vector operator()(const Vector& u) const {
        const HcsTemperatures T = temperatures(u);
        std::vector<double> dT_tr(S_), dT_rot(S_);
        driven_rates(theory_, th_, 0.0, T.T_tr, T.T_rot, dT_tr, dT_rot);
        Vector r(size());
        for (std::size_t s = 0; s < S_; ++s)
            r[s] = dT_tr[s] / T.T_tr[s];
        for (std::size_t k = 0; k < rot_.size(); ++k)
            r[S_ + k] = dT_rot[rot_[k]] / T.T_rot[rot_[k]];
        return r;
    }

  private:
    const HcsTheory& theory_;
    const ThermostatSpec& th_;
    const std::vector<Spin>& spin_;
    std::size_t S_;
    std::vector<std::size_t> rot_;
};

// Newton's method in u = ln T from u: the root, or nullopt if it does not converge to 1e-13 in u
// within 40 iterations (steps limited to a factor e in each temperature).
std::optional<Vector> newton(const Residual& F, Vector u) {
    const std::size_t n = u.size();
    for (int it = 0; it < 40; ++it) {
        Vector r = F(u);
        if (!finite(r))
            return std::nullopt;
        Vector J(n * n);
        for (std::size_t k = 0; k < n; ++k) { // central differences: O(h^2) = 1e-12 relative
            const double h = 1e-6;
            Vector up = u, dn = u;
            up[k] += h;
            dn[k] -= h;
            const Vector fp = F(up), fm = F(dn);
            for (std::size_t i = 0; i < n; ++i)
                J[i * n + k] = (fp[i] - fm[i]) / (2 * h);
        }
        for (double& x : r)
            x = -x;
        std::optional<Vector> du = solve(std::move(J), std::move(r));
        if (!du)
            return std::nullopt;
        double big = 0;
        for (double x : *du)
            big = std::max(big, std::abs(x));
        const double scale = big > 1 ? 1 / big : 1.0;
        for (std::size_t i = 0; i < n; ++i)
            u[i] += scale * (*du)[i];
        if (big < 1e-13)
            return u;
    }
    return std::nullopt;
}

// Collisions per unit time of the most colliding grain, plus twice the largest friction: the
// fastest rate of the equations, whose inverse sets the relaxation's steps.
double fastest_rate(const HcsTheory& theory, const ThermostatSpec& th, const HcsTemperatures& T) {
    double nu = 0;
    for (std::size_t a = 0; a < theory.species_count(); ++a) {
        double na = 0;
        for (std::size_t b = 0; b < theory.species_count(); ++b)
            na += theory.exchange(a, b, T.T_tr, T.T_rot).frequency;
        nu = std::max(nu, na);
    }
    if (th.kind == ThermostatKind::langevin)
        for (const SpeciesThermostat& s : th.species)
            nu = std::max(nu, 2 * std::max(s.friction, s.rotational_friction));
    return nu;
}

// A first guess: per species, the closed form of equal spheres with its own pair's (alpha, beta) at
// the full density (exact for one species); the bath's temperature for Langevin; 1 where neither applies.
HcsTemperatures guess(const HcsTheory& theory, const ThermostatSpec& th) {
    const std::size_t S = theory.species_count();
    HcsTemperatures T{std::vector<double>(S, 1.0), std::vector<double>(S, 1.0)};
    for (std::size_t s = 0; s < S; ++s) {
        const HcsSpecies& sp = theory.species()[s];
        const double drive = th.species[s].drive.at(0);
        double x = th.kind == ThermostatKind::langevin ? drive : nan;
        if (th.kind == ThermostatKind::white_noise) {
            const ConstantRestitution& r = theory.pairs()[pair_index(s, s, S)];
            x = white_noise_steady_state(r.alpha, r.beta, sp.inertia, sp.mass, 2 * sp.radius, theory.density(), drive,
                                         th.species[s].rotational_share)
                    .T_tr;
        }
        if (std::isfinite(x) && x > 0)
            T.T_tr[s] = T.T_rot[s] = x;
    }
    return T;
}

// No steady state is possible: no energy fed (nothing to balance a cooling gas but T = 0), or
// energy fed to a gas that does not dissipate.
bool hopeless(const HcsTheory& theory, const ThermostatSpec& th) {
    bool fed = false;
    for (const SpeciesThermostat& s : th.species) {
        const double d = s.drive.at(0);
        fed |= th.kind == ThermostatKind::white_noise ? d > 0 : d > 0 && (s.friction > 0 || s.rotational_friction > 0);
    }
    if (!fed)
        return true;
    if (th.kind == ThermostatKind::langevin)
        return false;
    for (const ConstantRestitution& p : theory.pairs())
        if (p.alpha < 1 || (p.beta > -1 && p.beta < 1))
            return false;
    return true; // elastic under white noise
}

} // namespace

std::optional<DrivenSteadyState> driven_steady_state(const HcsTheory& theory, const ThermostatSpec& thermostat) {
    const std::size_t S = theory.species_count();
    check_thermostat(thermostat, S);
    const ThermostatSpec th = final_drive(thermostat);
    if (hopeless(theory, th))
        return std::nullopt;
    const std::vector<Spin> spin = spins(theory, th);
    const Residual F(theory, th, spin);
    // Relax in time, then try Newton's method; again after more relaxation if it fails.
    HcsTemperatures T = guess(theory, th);
    HcsTrajectory trajectory(theory, T, th);
    std::optional<Vector> root;
    double t = 0;
    for (int round = 0; round < 200 && !root; ++round) {
        HcsTemperatures probe = T;
        for (std::size_t s = 0; s < S; ++s)
            if (!spin[s].unknown)
                probe.T_rot[s] = 0;
        bool positive = true;
        for (std::size_t s = 0; s < S; ++s)
            positive &= probe.T_tr[s] > 0 && (!spin[s].unknown || probe.T_rot[s] > 0);
        if (positive)
            root = newton(F, F.unknowns(probe));
        if (!root) {
            t += 20 / fastest_rate(theory, th, T); // some 20 collision (or friction) times
            T = trajectory.at(t);
        }
    }
    if (!root)
        return std::nullopt;
    DrivenSteadyState out;
    out.T = F.temperatures(*root);
    out.zeta_star = reduced_cooling_rate(theory, out.T);
    for (std::size_t s = 0; s < S; ++s)
        if (!spin[s].unknown)
            out.T.T_rot[s] = spin[s].value;
    out.T_tr = theory.mixture_T_tr(out.T);
    out.T_rot = theory.mixture_T_rot(out.T);
    out.theta = out.T_rot / out.T_tr;
    for (std::size_t s = 0; s < S; ++s) {
        out.theta_s.push_back(out.T.T_rot[s] / out.T.T_tr[s]);
        out.T_tr_ratio.push_back(out.T.T_tr[s] / out.T_tr);
        const double bath = th.kind == ThermostatKind::langevin ? th.species[s].drive.at(0) : nan;
        out.T_tr_over_bath.push_back(out.T.T_tr[s] / bath);
        out.T_rot_over_bath.push_back(out.T.T_rot[s] / bath);
    }
    return out;
}

// --- equal spheres ---

double white_noise_steady_theta(double alpha, double beta, double q, double rotational_share) {
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, 1.0, 1.0, 1.0);
    const double eps = rotational_share;
    if (c.B == 0) // smooth: nothing couples the spins
        return eps > 0 ? inf : nan;
    if (eps == 0)
        return q * (1 + beta) / (1 + 2 * q - beta); // = B/C, written without cancellation
    return ((1 - eps) * c.B + eps * c.A) / ((1 - eps) * c.C + eps * c.B);
}

EqualSphereSteadyState white_noise_steady_state(double alpha, double beta, double q, double mass, double sigma,
                                                double density, double strength, double rotational_share) {
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, mass, sigma, density);
    EqualSphereSteadyState s;
    s.theta = white_noise_steady_theta(alpha, beta, q, rotational_share);
    // The power fed to T_tr + T_rot (to T_tr alone when the spins are uncoupled) over G times the
    // collisional loss per T_tr^{3/2}.
    const double loss = c.B == 0 ? c.A : c.A - c.B + (c.C - c.B) * s.theta;
    const double power = (c.B == 0 ? 1 - rotational_share : 1.0) * mass * strength;
    s.T_tr = loss > 0 ? std::pow(power / (c.G * loss), 2.0 / 3.0) : inf;
    s.T_rot = s.theta * s.T_tr;
    return s;
}

EqualSphereSteadyState langevin_steady_state(double alpha, double beta, double q, double mass, double sigma,
                                             double density, double bath, double friction, double rotational_friction) {
    const EqualSphereCoefficients c = equal_sphere_coefficients(alpha, beta, q, mass, sigma, density);
    const double g = 2 * friction, gr = 2 * rotational_friction, Tb = bath;
    const auto T_rot = [&](double T) {
        const double den = c.G * c.C * std::sqrt(T) + gr;
        return den > 0 ? (c.G * c.B * T * std::sqrt(T) + gr * Tb) / den : nan;
    };
    const auto f = [&](double T) {
        const double Tr = c.B == 0 ? 0.0 : T_rot(T); // smooth: no coupling (B T_rot = 0 even if T_rot is unset)
        return c.G * std::sqrt(T) * (-c.A * T + c.B * Tr) + g * (Tb - T);
    };
    EqualSphereSteadyState s;
    if (!(Tb > 0) || (g == 0 && gr == 0))
        return {0.0, 0.0, nan};
    // Bisection in ln T on (T_b e^{-700}, T_b]: f(T_b) <= 0 < f(0+) (see the header).
    double lo = std::log(Tb) - 700, hi = std::log(Tb);
    if (f(Tb) >= 0) {
        lo = hi;
    } else {
        for (int k = 0; k < 200 && hi - lo > 1e-16; ++k) {
            const double mid = 0.5 * (lo + hi);
            (f(std::exp(mid)) > 0 ? lo : hi) = mid;
        }
    }
    s.T_tr = std::exp(0.5 * (lo + hi));
    s.T_rot = c.B == 0 && gr == 0 ? nan : c.B == 0 ? Tb : T_rot(s.T_tr);
    s.theta = s.T_rot / s.T_tr;
    return s;
}

} // namespace roughgas
