#pragma once
// Restitution policies: how (alpha, beta) follow from the impact (g_N, g_T) for one species pair.
// Each is a small value type with compile-time traits the collision step reads:
//   needs_rotation: false means beta = -1 always, so the step never loads, stores or updates omega;
//   needs_g_t:      beta depends on |g^T| (else the rule skips nothing but the look-up).
// A policy is a normal part (alpha) composed with a tangential part (beta); the run picks one per
// species pair from dsmc/run_spec.hpp's PairRestitution, once per run.
//
// Sign conventions: docs/model.md §2 (beta = -eps^T: -1 smooth, +1 perfectly rough).
#include "roughgas/collision/record.hpp"
#include "roughgas/contact/contact_integrator.hpp"
#include "roughgas/restitution/normal_table.hpp"
#include "roughgas/restitution/tangential_table.hpp"

#include <algorithm>
#include <string_view>

namespace roughgas {

// A model's beta outside [-1, 1] is clamped to it (and reported).
//
// Physics note: the asperity model (docs/model.md §7) can return |eps^T| slightly above 1 for nearly
// elastic normal motion: the tangential spring's stiffness grows with the normal force while it is
// strained, so the spring is not passive and can hand energy back to the tangential motion
// (tests/contact/tangential_integrator_test.cpp, StiffeningAsperitySpringCanExceedPerfectReversal:
// eps^T = -1.24). The collision rule's tangential energy change is (kappa m_eff/2)(beta^2 - 1) g_T^2
// (docs/model.md §3), which is positive for |beta| > 1: a collision would create energy. The rule
// therefore never applies |beta| > 1: it uses the nearest admissible value and counts the event,
// so a run reports how often the model left its physical range (column beta_clamped).
inline Coefficients clamp_beta(double alpha, double beta) {
    if (beta > 1.0)
        return {alpha, 1.0, true};
    if (beta < -1.0)
        return {alpha, -1.0, true};
    return {alpha, beta, false};
}

// ---- normal parts: alpha(g_N) ----

struct ConstantNormal {
    double alpha = 1;
    double operator()(double /*g_n*/) const { return alpha; }
};

// Viscoelastic eps^N from the universal table at w = g_N rho^2 tau^5 (docs/model.md §6).
struct TableNormal {
    const NormalTable* table = nullptr;
    double w_per_speed = 0; // ContactPair::w_per_speed() of the pair
    [[gnu::always_inline]] double operator()(double g_n) const { return table->eps_n(w_per_speed * g_n); }
};

// The same, integrating the contact at every collision (the reference for the table).
struct DirectNormalPart {
    DirectNormal direct{};
    double w_per_speed = 0;
    double operator()(double g_n) const { return direct.eps_n(w_per_speed * g_n); }
};

// ---- tangential parts: beta(g_N, g_T, alpha) ----

struct SmoothTangential {
    static constexpr bool needs_rotation = false;
    static constexpr bool needs_g_t = false;
    Coefficients operator()(double, double, double alpha) const { return {alpha, -1.0, false}; }
};

struct ConstantTangential {
    static constexpr bool needs_rotation = true;
    static constexpr bool needs_g_t = false;
    double beta = -1;
    Coefficients operator()(double, double, double alpha) const { return {alpha, beta, false}; }
};

// Walton's friction-limited rough model. The impulse of docs/model.md §3 has the normal magnitude
// P_N = m_eff (1 + alpha) g_N and the tangential magnitude P_T = kappa m_eff (1 + beta) g_T, with the
// pair's kappa (docs/model.md §1, any masses, radii and q). Sticking (beta = beta0) is possible while
// Coulomb's bound P_T <= mu P_N holds, i.e. kappa (1 + beta0) g_T <= mu (1 + alpha) g_N; otherwise the
// contact slides with P_T = mu P_N exactly, which m_eff cancels from:
//     beta = -1 + mu (1 + alpha) g_N / (kappa g_T)       (in [-1, beta0) on the sliding branch).
// So beta = min(beta0, -1 + mu (1 + alpha) g_N/(kappa g_T)) for unequal grains too; for equal uniform
// spheres kappa = 2/7 gives Walton's -1 + (7/2) mu (1 + alpha) g_N/g_T.
struct CoulombTangential {
    static constexpr bool needs_rotation = true;
    static constexpr bool needs_g_t = true;
    double beta0 = 1;
    double mu_over_kappa = 0; // mu/kappa of the pair
    Coefficients operator()(double g_n, double g_t, double alpha) const {
        const double limit = mu_over_kappa * (1.0 + alpha) * g_n; // (1 + beta) g_T may not exceed this
        if ((1.0 + beta0) * g_t <= limit)
            return {alpha, beta0, false};
        return {alpha, -1.0 + limit / g_t, false};
    }
};

// beta = -eps^T(g_N, g_T) of the asperity model (docs/model.md §7) from the pair's table.
struct TableTangential {
    static constexpr bool needs_rotation = true;
    static constexpr bool needs_g_t = true;
    const TangentialTable* table = nullptr;
    [[gnu::always_inline]] Coefficients operator()(double g_n, double g_t, double alpha) const {
        if (!(g_n > 0))
            return {alpha, -1.0, false}; // no normal force, no friction (probability 0)
        return clamp_beta(alpha, -table->eps_t(g_n, g_t));
    }
};

// ---- policies ----

template <class Normal, class Tangential> struct Restitution {
    static constexpr bool needs_rotation = Tangential::needs_rotation;
    static constexpr bool needs_g_t = Tangential::needs_g_t;
    Normal normal{};
    Tangential tangential{};
    [[gnu::always_inline]] Coefficients operator()(double g_n, double g_t) const { return tangential(g_n, g_t, normal(g_n)); }
};

struct SmoothConstant : Restitution<ConstantNormal, SmoothTangential> {
    static constexpr std::string_view name = "constant (smooth)";
};
struct RoughConstant : Restitution<ConstantNormal, ConstantTangential> {
    static constexpr std::string_view name = "constant";
};
struct Coulomb : Restitution<ConstantNormal, CoulombTangential> {
    static constexpr std::string_view name = "coulomb";
};
struct ViscoelasticSmooth : Restitution<TableNormal, SmoothTangential> {
    static constexpr std::string_view name = "viscoelastic (smooth)";
};
struct Viscoelastic : Restitution<TableNormal, ConstantTangential> {
    static constexpr std::string_view name = "viscoelastic";
};
struct ViscoelasticSmoothDirect : Restitution<DirectNormalPart, SmoothTangential> {
    static constexpr std::string_view name = "viscoelastic (smooth, direct)";
};
struct ViscoelasticDirect : Restitution<DirectNormalPart, ConstantTangential> {
    static constexpr std::string_view name = "viscoelastic (direct)";
};
struct Brilliantov : Restitution<TableNormal, TableTangential> {
    static constexpr std::string_view name = "brilliantov";
};

// Both coefficients from one integration of the contact of Brilliantov et al. (1996) per collision (the
// reference for the tables).
struct BrilliantovDirect {
    static constexpr std::string_view name = "brilliantov (direct)";
    static constexpr bool needs_rotation = true;
    static constexpr bool needs_g_t = true;
    ContactPair pair{};
    Tolerance tol{};
    Coefficients operator()(double g_n, double g_t) const {
        if (!(g_n > 0))
            return {1.0, -1.0, false};
        const ContactResult r = integrate_contact(pair, g_n, g_t, tol);
        return clamp_beta(r.eps_n, r.beta);
    }
};

// Smart constructors (the pair's constants in, the policy out).
inline SmoothConstant make_smooth_constant(double alpha) {
    return {{{alpha}, {}}};
}
inline RoughConstant make_rough_constant(double alpha, double beta) {
    return {{{alpha}, {beta}}};
}
inline Coulomb make_coulomb(double alpha, double beta0, double mu, double kappa) {
    return {{{alpha}, {beta0, mu / kappa}}};
}
inline ViscoelasticSmooth make_viscoelastic_smooth(const NormalTable& t, const ContactPair& p) {
    return {{{&t, p.w_per_speed()}, {}}};
}
inline Viscoelastic make_viscoelastic(const NormalTable& t, const ContactPair& p, double beta) {
    return {{{&t, p.w_per_speed()}, {beta}}};
}
inline ViscoelasticSmoothDirect make_viscoelastic_smooth_direct(const ContactPair& p, Tolerance tol) {
    return {{{DirectNormal{p.model, tol}, p.w_per_speed()}, {}}};
}
inline ViscoelasticDirect make_viscoelastic_direct(const ContactPair& p, double beta, Tolerance tol) {
    return {{{DirectNormal{p.model, tol}, p.w_per_speed()}, {beta}}};
}
inline Brilliantov make_brilliantov(const NormalTable& n, const TangentialTable& t, const ContactPair& p) {
    return {{{&n, p.w_per_speed()}, {&t}}};
}
inline BrilliantovDirect make_brilliantov_direct(const ContactPair& p, Tolerance tol) {
    return {p, tol};
}

} // namespace roughgas
