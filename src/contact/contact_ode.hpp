#pragma once
// The contact ODE of docs/model.md §6-7 in Hertz units, written for three independent variables
// ("clocks") so that the right-hand side is analytic on every piece that is integrated.
//
// Why: in Hertz time S the eq. 24 force X^{1/2}(X + uV) is not smooth at X = 0. The solution
// starts as X = S - (4/15) u S^{5/2} + ..., a series in S^{1/2}, and (separation end) returns to
// X = 0 the same way; eq. 25 at u = 0 (X^{3/2}) has the same defect one order higher. An
// error-controlled Runge-Kutta step then loses its order there. Away from the turning point V = 0,
// X is monotone, so vs = sqrt(X) can be the independent variable: dS/dvs = 2 vs / V, every
// derivative becomes (2 vs / V) d/dS, X = vs^2 is a polynomial and no square root of the state
// is left. So a contact is integrated in three pieces (contact_driver.hpp):
//   loading   t = vs, from 0 up to a vs_1 where V >= 1/2 is guaranteed (loading_end_root),
//   turning   t = S, through the maximum compression V = 0 (where vs cannot be a clock),
//   unloading t = vs_s - vs, from the switch point down to vs = 0 (X = 0), once V is safely < 0.
//
// State layout: loading/unloading (S, V[, e, p]); turning (X, V[, e, p]).
// N = 2: normal motion only; N = 4: with the tangential pair of tangential_integrator.hpp in the
// scaled form e' = k_e p, p' = k_p X'' e (see tangential_integrator.cpp for k_e, k_p).
#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/normal_model.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace roughgas::detail {

template <std::size_t N> using OdeState = std::array<double, N>;

enum class Clock { loading, time, unloading };

// Physical state at one instant, whatever the clock.
struct ContactPoint {
    double S = 0; // Hertz time
    double X = 0; // compression
    double V = 1; // compression rate X'
    double e = 0; // asperity strain (scaled), N = 4 only
    double p = 0; // tangential velocity (scaled), N = 4 only
};

struct OdeCoefficients {
    NormalForm form = NormalForm::eq24;
    double u = 0;   // w^{1/5}
    double k_e = 0; // e' = k_e p
    double k_p = 0; // p' = k_p X'' e
};

// X'' (normal_model.hpp). Eq. 24 is continued by 0 for X < 0 (no contact, no force): only stages
// beyond a separation event in the `time` clock can see X < 0, where sqrt would give NaN.
inline double acceleration(const OdeCoefficients& c, double X, double V) {
    if (c.form == NormalForm::eq24 && X <= 0) {
        return 0.0;
    }
    return normal_acceleration(c.form, X, V, c.u);
}

// The normal acceleration that drives the asperity spring: only a compressive normal force
// (X'' < 0) presses the asperities together. Brilliantov et al. (1996) eqs. 28-29: the load-bearing
// tangential area is S^T = phi^T sigma^N S with f^T(0) = 0, an expansion about sigma^N = 0 from the
// compressive side; under tension (the attractive end of an eq. 24/25 `separation` contact,
// docs/model.md §6) no asperity carries shear. Taken literally, X'' > 0 would turn the spring into an
// anti-spring (p' = (mu/kappa) X'' e grows with e) and let |eps_t| grow far beyond 1.
inline double compressive(double a) {
    return a < 0 ? a : 0.0;
}

template <std::size_t N> struct ContactOde {
    static_assert(N == 2 || N == 4);
    OdeCoefficients c;
    Clock clock = Clock::time;
    double origin = 0; // unloading: vs at t = 0

    // vs = sqrt(X) as a function of t (loading and unloading clocks only).
    double root(double t) const { return clock == Clock::loading ? t : origin - t; }

    ContactPoint point(double t, const OdeState<N>& x) const {
        ContactPoint q;
        if (clock == Clock::time) {
            q.S = t;
            q.X = x[0];
        } else {
            const double vs = root(t);
            q.S = x[0];
            q.X = vs * vs;
        }
        q.V = x[1];
        if constexpr (N == 4) {
            q.e = x[2];
            q.p = x[3];
        }
        return q;
    }

    OdeState<N> state(const ContactPoint& q) const {
        OdeState<N> x{};
        x[0] = clock == Clock::time ? q.X : q.S;
        x[1] = q.V;
        if constexpr (N == 4) {
            x[2] = q.e;
            x[3] = q.p;
        }
        return x;
    }

    // dS/dt: 1 in the `time` clock; d vs / dt = +-1 and dS/d vs = 2 vs / V otherwise.
    double time_rate(double t, double V) const {
        if (clock == Clock::time) {
            return 1.0;
        }
        const double r = 2.0 * root(t) / V;
        return clock == Clock::loading ? r : -r;
    }

    // The odeint System: d/dt = (dS/dt) d/dS applied to (X or S, V, e, p).
    void operator()(const OdeState<N>& x, OdeState<N>& dxdt, double t) const {
        const ContactPoint q = point(t, x);
        const double a = acceleration(c, q.X, q.V);
        const double f = time_rate(t, q.V);
        dxdt[0] = clock == Clock::time ? q.V : f;
        dxdt[1] = f * a;
        if constexpr (N == 4) {
            dxdt[2] = f * c.k_e * q.p;
            dxdt[3] = f * c.k_p * compressive(a) * q.e;
        }
    }
};

} // namespace roughgas::detail
