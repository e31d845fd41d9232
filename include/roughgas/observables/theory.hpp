#pragma once
// Homogeneous cooling with CONSTANT alpha, beta in the Maxwellian approximation:
// each species s has a Maxwellian velocity distribution at T_tr,s and an independent Maxwellian
// spin distribution at T_rot,s (zero mean velocity); the Boltzmann collision integral (docs/model.md §4)
// with the collision rule of docs/model.md §3 then closes into 2S ODEs for the temperatures.
//
// Derivation (k_B = 1; 3-D; grains i of species a, j of species b). Let sigma = R_a + R_b,
// m_eff = m_a m_b/(m_a + m_b), kappa of docs/model.md §1, n the unit normal, w = -(v_i - v_j).n > 0,
// V = the part of v_i - v_j normal to n, S = (R_a w_i + R_b w_j) x n. Then g^N = -w n,
// g^T = V - S and the impulse on i is P = a_N w n - a_T g^T, a_N = m_eff (1 + alpha),
// a_T = kappa m_eff (1 + beta). The energies of i change by
//   dE_tr,i  = v_i.P + |P|^2/(2 m_a),           |P|^2 = a_N^2 w^2 + a_T^2 |g^T|^2,
//   dE_rot,i = -R_a P.(w_i x n) + |P^T|^2/(2 q_a m_a),   P^T = -a_T g^T.
// Averages. v_i, v_j are Gaussian with variances T_a/m_a, T_b/m_b per component, so
// v_ij = v_i - v_j has s = T_a/m_a + T_b/m_b, and E[v_i | v_ij] = (T_a/m_a)/s v_ij; the spins are
// independent of v, with Omega = R_a w_i + R_b w_j of variance s_W = T_rot,a/(q_a m_a) +
// T_rot,b/(q_b m_b) per component, so <|S|^2> = 2 s_W, <S.(w_i x n)> = 2 R_a T_rot,a/J_a.
// Weighting the pairs by |v_ij.n| on the approaching hemisphere (the Boltzmann kernel) gives the
// collision frequency of one a grain with the b grains
//   nu_ab = n_b sigma^2 (4 pi) <w; w > 0> = n_b sigma^2 sqrt(8 pi s)
// (equal spheres: 4 n sigma^2 sqrt(pi T/m), as it must), and per collision <w^2> = 2 s,
// <|V|^2> = 2 s, <V.g^T> = 2 s, <|g^T|^2> = 2 (s + s_W). Hence, per collision,
//   <dE_tr,i>  = -2 (T_a/m_a)(a_N + a_T) + [a_N^2 s + a_T^2 (s + s_W)]/m_a
//   <dE_rot,i> = [-2 a_T T_rot,a + a_T^2 (s + s_W)]/(q_a m_a)
// (their sum over i and j is (m_eff/2)(alpha^2 - 1) 2s + (kappa m_eff/2)(beta^2 - 1) 2(s + s_W),
// docs/model.md §3's Delta E averaged, which a test checks) and, with 3 degrees of freedom each,
//   (3/2) dT_tr,a/dt = sum_b nu_ab <dE_tr,i>,   (3/2) dT_rot,a/dt = sum_b nu_ab <dE_rot,i>.
//
// Equal spheres (m, sigma = 2R, q; eta = q(1 + beta)/(2(1 + q)), so a_N = m(1 + alpha)/2,
// a_T = m eta, s = 2T/m, s_W = 2 T_rot/(q m)) this reduces to
//   dT_tr/dt  = G [-A T_tr^{3/2} + B T_tr^{1/2} T_rot]
//   dT_rot/dt = G [ B T_tr^{3/2} - C T_tr^{1/2} T_rot]
//   A = (1 - alpha^2)/4 + eta (1 - eta),  B = eta^2/q,  C = (eta/q)(1 - eta/q),
//   G = (16/3) n sigma^2 sqrt(pi/m),
// i.e. A, B, C and G of Huthmann & Zippelius, PRE 56, R6275 (1997) and Luding, Huthmann,
// McNamara & Zippelius, PRE 58, 3416 (1998), checked against the derivation above. The factor 2
// those papers print in front of the T_rot equation belongs to disks (one rotational against two
// translational degrees of freedom); in 3-D both have three, and only the factor 1 conserves
// T_tr + T_rot at alpha = beta = 1 (where A = B = C), as tests/observables/theory_test.cpp checks.
// Smooth spheres (beta = -1): eta = 0, B = C = 0, T_rot stays constant and T_tr follows Haff's law
// T(t) = T0/(1 + t/t0)^2 with t0 = 2/(G A sqrt(T0)). The ratio theta = T_rot/T_tr obeys
// dtheta/dt = G T_tr^{1/2} [B - (C - A) theta - B theta^2], so for beta > -1 it tends to the
// positive root theta* = [A - C + sqrt((A - C)^2 + 4 B^2)]/(2B).
//
// Mixtures: the equations above, per species pair, with n_b = n x fraction_b (the continuum limit;
// a simulation of N grains has n_a (N_a - 1)/N_a for the like pairs, a relative 1/N_a).
//
// The Maxwell kernel (run.kernel = "maxwell", dsmc/run_spec.hpp): every pair of species (a, b)
// collides at the constant rate pi sigma^2 u_ab/V, u_ab = sqrt((8/pi) s_0), s_0 = s at the initial
// temperatures (so nu_ab = n_b sigma^2 sqrt(8 pi s_0): the hard-sphere frequency of the initial
// Maxwellian, constant in time), with n uniform on the approaching hemisphere. Then no Maxwellian
// assumption is needed: with p = P/m_eff = -b g - (A - b)(g.n) n (A = 1 + alpha, b = kappa(1 + beta)),
// g = v_ij - Omega x n, the averages over n (uniform; every term odd in n or in Omega averages to
// zero, so the hemisphere does not matter and v-omega correlations drop out) are
//   <(g.n)^2> = |v_ij|^2/3,  <|g|^2> = |v_ij|^2 + (2/3)|Omega|^2,  <|g^T|^2> = (2/3)(|v_ij|^2 + |Omega|^2),
//   <v_i.p> = -(A + 2b)|v_i|^2/3 (with <v_i.v_j> = 0),  <|p|^2> = (A^2 + 2b^2)|v_ij|^2/3 + (2/3) b^2 |Omega|^2,
//   <omega_i.(n x P)> = (2/3) m_eff b R_a |omega_i|^2,  <|n x P|^2> = m_eff^2 b^2 <|g^T|^2>,
// and with <|v_ij|^2> = 3 s, <|Omega|^2> = 3 s_W over the grains (any distribution with these
// second moments and uncorrelated grains), per collision
//   <dE_tr,i>  = -(T_a/m_a)(a_N + 2 a_T) + [a_N^2 s/2 + a_T^2 (s + s_W)]/m_a
//   <dE_rot,i> = [-2 a_T T_rot,a + a_T^2 (s + s_W)]/(q_a m_a)        (the same as for hard spheres)
// Both are linear in the temperatures and nu_ab is constant: (3/2) dT/dt = sum_b nu_ab <dE> is a
// closed linear system, exact for the Maxwell gas up to O(1/N) pair correlations of the finite
// system. Checks: alpha = beta = 1 conserves T_tr + T_rot (kappa = q/(1 + q) for equal spheres);
// beta = -1 gives dT_tr/dt = -nu (1 - alpha^2) T_tr/6 (tests/observables/theory_test.cpp), and the
// DSMC with the Maxwell kernel follows the system (tests/dsmc/maxwell_test.cpp).
//
// A driven gas: these rates plus a thermostat's sources (observables/driven_theory.hpp), integrated by
// HcsTrajectory's thermostat constructor; its steady states in observables/driven_steady_state.hpp.
#include "roughgas/dsmc/run_spec.hpp"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace roughgas {

struct HcsSpecies {
    double mass = 1, radius = 0.5, inertia = 0.4; // m, R, q
    double fraction = 1;                          // number fraction x_s (n_s = x_s n)
};

// Per-species temperatures (k_B = 1).
struct HcsTemperatures {
    std::vector<double> T_tr, T_rot;
};

// One grain of species a colliding with grains of species b: how often, and the mean changes of its
// energies per collision (the averages of the derivation above).
struct PairExchange {
    double frequency = 0; // nu_ab, collisions per unit time of one a grain with b grains
    double dE_tr = 0;     // <dE_tr,i> per collision
    double dE_rot = 0;    // <dE_rot,i> per collision
};

class HcsTheory {
  public:
    // `pairs`: (alpha, beta) of species pair (a, b) at pair_index(a, b, species.size()) (run_spec.hpp).
    // Throws std::invalid_argument for empty species, a wrong number of pairs, non-positive mass,
    // radius, inertia or density, a negative fraction, alpha outside [0, 1] or beta outside [-1, 1].
    HcsTheory(std::vector<HcsSpecies> species, std::vector<ConstantRestitution> pairs, double density);
    // The Maxwell kernel: constant frequencies from the initial translational temperatures T0_tr
    // (one per species), the exchange averages above.
    HcsTheory(std::vector<HcsSpecies> species, std::vector<ConstantRestitution> pairs, double density,
              std::vector<double> maxwell_T0_tr);
    bool maxwell() const { return !maxwell_T0_.empty(); }
    // The Enskog equation of a uniform gas (dsmc/pair_correlation.hpp): every frequency nu_ab times the
    // pair correlation at contact chi_ab (pair_index order, each > 0; the default is 1 for every pair,
    // the Boltzmann equation). The averages per collision do not change.
    void set_pair_correlations(std::vector<double> chi);
    double pair_correlation(std::size_t a, std::size_t b) const { return chi_[pair_index(a, b, species_.size())]; }

    std::size_t species_count() const { return species_.size(); }
    const std::vector<HcsSpecies>& species() const { return species_; }
    const std::vector<ConstantRestitution>& pairs() const { return pairs_; }
    double density() const { return density_; }

    PairExchange exchange(std::size_t a, std::size_t b, std::span<const double> T_tr,
                          std::span<const double> T_rot) const;
    // d T_tr,s/dt and d T_rot,s/dt at the given temperatures.
    void rates(std::span<const double> T_tr, std::span<const double> T_rot, std::span<double> dT_tr,
               std::span<double> dT_rot) const;

    // Mixture temperatures: T_tr = sum_s x_s T_tr,s (docs/model.md §5 over all grains), likewise T_rot.
    double mixture_T_tr(const HcsTemperatures& T) const;
    double mixture_T_rot(const HcsTemperatures& T) const;

  private:
    double fraction_weighted(std::span<const double> T) const;
    std::vector<HcsSpecies> species_;
    std::vector<ConstantRestitution> pairs_;
    double density_;
    std::vector<double> chi_;        // chi_ab, pair_index order
    std::vector<double> maxwell_T0_; // Maxwell kernel: initial T_tr per species (empty: hard spheres)
};

// The reduced cooling rate zeta* = -(dT_tr/dt)/(T_tr nu_c) at the temperatures T, with T_tr and its
// rate the fraction-weighted sums over the species and nu_c = sum_a x_a sum_b nu_ab the collisions per
// particle and unit time (each collision counted for both grains): the translational temperature's
// decay per collision per particle. Equal smooth spheres: G A sqrt(T)/(4 n sigma^2 sqrt(pi T/m)) =
// (1 - alpha^2)/3, for any T.
double reduced_cooling_rate(const HcsTheory& theory, const HcsTemperatures& T);
// nu_c above: collisions per particle and unit time at T (equal spheres: 4 n sigma^2 sqrt(pi T_tr/m)).
double collision_frequency(const HcsTheory& theory, const HcsTemperatures& T);

// The solution from `initial` at t = 0, evaluated at non-decreasing times: each call integrates on
// from the previous one (Dormand-Prince 5(4), adaptive, relative tolerance `rel_tol`). The state is
// integrated as (ln E, T_k/E) with E the sum of all temperatures, so it is scale-free: a gas that
// cools through 40 decades is integrated as accurately as one that cools through one.
// With `closed_form` (default) a one-species smooth gas (beta = -1) uses Haff's law instead.
// Driven (the constructor with a thermostat, observables/driven_theory.hpp): the same variables with
// the thermostat's sources S_k added, d ln E/dt = sum_k dT_k/dt / E and d(T_k/E)/dt =
// (dT_k/dt - (T_k/E) sum dT/dt)/E; E then tends to the steady state's instead of 0, which the error
// control (relative in E and in each T_k/E) follows as well. The drive is piecewise constant: each
// call integrates piece by piece between the drive's switch times, so no step straddles a jump of
// the right-hand side.
class HcsTrajectory {
  public:
    HcsTrajectory(HcsTheory theory, HcsTemperatures initial, double rel_tol = 1e-10, bool closed_form = true);
    // Throws std::invalid_argument for a thermostat check_thermostat refuses, and for initial
    // temperatures that are all 0 (the scaled variables need E > 0).
    HcsTrajectory(HcsTheory theory, HcsTemperatures initial, ThermostatSpec thermostat, double rel_tol = 1e-10);
    // Throws std::invalid_argument if t is earlier than the previous call's t (or < 0).
    HcsTemperatures at(double t);
    const HcsTheory& theory() const { return theory_; }
    const std::optional<ThermostatSpec>& thermostat() const { return thermostat_; }
    std::size_t steps() const { return steps_; } // integration steps so far

  private:
    HcsTemperatures current() const;
    void advance(double t); // integrates to t within one piece of the drive
    HcsTheory theory_;
    HcsTemperatures initial_;
    double rel_tol_;
    bool haff_ = false;
    double t_ = 0, dt_ = 0;
    double E0_ = 0;
    std::vector<double> y_; // ln(E/E0), then T_tr,s/E, T_rot,s/E
    std::size_t steps_ = 0;
    std::optional<ThermostatSpec> thermostat_;
    std::vector<double> switches_; // the drive's switch times (drive_switch_times)
};

// How many collisions per particle the gas of `theory`, started at `initial`, cools until the smallest
// T_tr,s/m_s reaches `floor`: the trajectory followed in steps of a few collisions per particle until
// its reduced cooling rate zeta* settles (the cooling state's ratios of the temperatures), the
// collisions on the way counted as the fall of ln T_tr over zeta*; then ln(min T_tr,s/m_s / floor)/zeta*
// more. +infinity if the settled zeta* is not > 0 (an elastic gas).
double cooling_reach(const HcsTheory& theory, const HcsTemperatures& initial, double floor);
// The same as a time (the case's time unit): the time the trajectory took to settle, then the time
// the settled gas takes to cool by the rest, by Haff's law T_tr ~ (1 + zeta* nu t/2)^-2 (hard
// spheres: nu ~ sqrt(T_tr)) or exponentially (the Maxwell kernel's constant nu). Finite wherever
// cooling_reach is: in a finite time a cooling gas collides finitely often (~ ln t per particle).
double cooling_reach_time(const HcsTheory& theory, const HcsTemperatures& initial, double floor);
// The floor a run checks its reach against: below T_tr,s/m_s = 1e-300 (in the case's units) the
// squares of the velocities underflow.
inline constexpr double underflow_temperature_per_mass = 1e-300;

// The theory of a run if every species pair has constant restitution, else nullopt.
std::optional<HcsTheory> hcs_theory(const RunSpec& spec);
HcsTemperatures initial_temperatures(const RunSpec& spec);

// --- equal spheres: the literature form (see the derivation above) ---
struct EqualSphereCoefficients {
    double eta = 0, A = 0, B = 0, C = 0;
    double G = 0; // (16/3) n sigma^2 sqrt(pi/m)
};
EqualSphereCoefficients equal_sphere_coefficients(double alpha, double beta, double q, double mass,
                                                  double sigma, double density);

// Haff's law: T0/(1 + t/t0)^2 with t0 = 2/(G A sqrt(T0)), A = (1 - alpha^2)/4 (smooth spheres).
// alpha = 1: t0 = infinity, T = T0.
double haff_time(double T0, double alpha, double mass, double sigma, double density);
double haff_temperature(double t, double T0, double alpha, double mass, double sigma, double density);

// The long-time theta = T_rot/T_tr of equal spheres (root of B theta^2 + (C - A) theta - B = 0);
// +infinity for beta = -1 with alpha < 1 (T_rot frozen while T_tr decays), 0/0 undefined for
// alpha = 1, beta = -1 (NaN).
double theta_fixed_point(double alpha, double beta, double q);

} // namespace roughgas
