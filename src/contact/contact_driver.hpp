#pragma once
// Integrates one contact (contact_ode.hpp) piece by piece with Boost.Odeint's dense-output
// Dormand-Prince 5(4) stepper, and locates every event on the dense output: odeint has no events,
// so, as in odeint's examples/find_crossing.cpp, an event is bracketed between previous_time() and
// current_time() and refined with Boost.Math toms748_solve on calc_state.
//
// Events (docs/model.md §6-7):
//   max compression   V: + -> 0            records max X
//   force end         X + uV: + -> 0       terminal (`force` end)
//   separation end    X: + -> 0            terminal (`separation` end)
//   capture           V: - -> 0 after max compression, `separation` end: eps_n = 0 (a safety
//                                          net: in exact arithmetic the force turns repulsive at
//                                          V = -X/u before V can reach 0, so X creeps to 0 instead)
//   asperity break    |e| -> threshold     e -> 0 and the stepper restarts (never step across it:
//                                          the right-hand side jumps there)
//   turning point     p: sign change        counted; |e| there is a local maximum of the strain
// A terminal event is "landed": the step is redone from previous_time() so that it ends exactly
// at the event, which gives the end state from the 5th-order solution rather than from the
// 4th-order interpolant (and, for eq. 25, never evaluates the force beyond its zero).
//
// Cost: about one accepted step (6 force evaluations, FSAL) per step of the smooth motion, plus,
// per asperity break, one restart (1 evaluation), one step capped to end just past the next
// break, and a toms748 refinement on the interpolant (3-6 cheap polynomial evaluations). So
// the time is ~ (smooth steps + breaks) * 1 us; the number of breaks of a sliding contact is
// about |p(0)| S_c / z (tangential_integrator.cpp).
#include "contact_ode.hpp"
#include "contact_phases.hpp"

#include "roughgas/contact/contact_model.hpp"
#include "roughgas/contact/contact_result.hpp"
#include "roughgas/contact/tolerance.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace roughgas::detail {

struct DriverSetup {
    OdeCoefficients coefficients;
    ContactEnd end = ContactEnd::force;                         // resolved: u = 0 always ends at separation
    double threshold = std::numeric_limits<double>::infinity(); // |e| that breaks an asperity
    double p0 = 0;                                              // p(0), N = 4
    Tolerance tol;
};

struct DriverResult {
    NormalResult normal;
    double p_end = 0;       // p(S_c)
    int breaks = 0;         // asperity breaks
    int turning_points = 0; // sign changes of p
    double max_abs_e = 0;   // max |e| over the contact (the threshold once an asperity broke)
};

// Bounded work: the smooth motion takes a few hundred steps even at rel = 1e-14; each break
// adds about one; an unbroken asperity spring oscillates with angular frequency
// sqrt(k_e k_p |X''|) (e'' = k_e k_p X'' e), |X''| = O(1) in Hertz units over a contact of duration
// O(3), and dopri5 needs about 30 steps per period at rel = 1e-12: max_steps_per_stiffness
// sqrt(k_e k_p) covers ~10x that (huge mu/kappa over tiny zeta_0: tests/stress). More than the sum
// means the step size collapsed.
inline constexpr long max_smooth_steps = 100000;
inline constexpr long max_steps_per_break = 16;
inline constexpr double max_steps_per_stiffness = 1000;

template <std::size_t N> class ContactRun {
  public:
    using State = OdeState<N>;
    using Stepper = typename boost::numeric::odeint::result_of::make_dense_output<
        boost::numeric::odeint::runge_kutta_dopri5<State>>::type;

    explicit ContactRun(const DriverSetup& setup)
        : setup_(setup),
          stepper_(boost::numeric::odeint::make_dense_output(
              setup.tol.abs, setup.tol.rel, boost::numeric::odeint::runge_kutta_dopri5<State>())) {}

    DriverResult run() {
        const OdeCoefficients& c = setup_.coefficients;
        ContactPoint q;
        q.p = setup_.p0;

        // Loading: vs from 0 to vs_1 (contact_phases.hpp). The first step is small because
        // the step-size controller has no history; it grows by up to 5x per step.
        ode_ = ContactOde<N>{c, Clock::loading, 0.0};
        const double vs1 = loading_end_root(c.form, c.u);
        if (run_piece(q, 0.0, vs1, 0.02 * vs1 * std::pow(setup_.tol.rel / 1e-12, 0.2))) {
            return result_;
        }
        // Turning: S through the maximum compression; dS = (2 vs / V) dvs converts the step.
        q = exit_point_;
        double dt = exit_step_ * ode_.time_rate(vs1, q.V);
        ode_ = ContactOde<N>{c, Clock::time, 0.0};
        if (run_piece(q, q.S, std::numeric_limits<double>::infinity(), dt)) {
            return result_;
        }
        // Unloading: vs = vs_s - t from vs_s = sqrt(X) down to 0 (or the force zero before).
        // Never step past vs = 0: beyond it X = vs^2 grows again and a step could jump over the
        // force zero (X + uV: + -> - -> +) unseen; at vs = 0 itself X + uV = uV < 0.
        q = exit_point_;
        const double vs_s = std::sqrt(q.X);
        dt = exit_step_ * std::abs(q.V) / (2.0 * vs_s);
        ode_ = ContactOde<N>{c, Clock::unloading, vs_s};
        if (run_piece(q, 0.0, vs_s, dt)) {
            return result_;
        }
        throw std::logic_error("roughgas: contact integration left the unloading piece without an end event");
    }

  private:
    enum class Stop { none, force, separation, capture, asperity_break, force_kink };

    DriverSetup setup_;
    Stepper stepper_;
    ContactOde<N> ode_;
    DriverResult result_;
    bool compressed_ = false; // the maximum compression has been passed
    bool kinked_ = false;     // separation end: the force zero has been landed on
    long steps_ = 0;
    ContactPoint exit_point_;
    double exit_step_ = 0;

    ContactPoint at(double t) const {
        State x;
        stepper_.calc_state(t, x);
        return ode_.point(t, x);
    }

    long step_budget() const {
        const OdeCoefficients& c = setup_.coefficients;
        const double stiffness = std::sqrt(std::abs(c.k_e * c.k_p));
        return max_smooth_steps + max_steps_per_break * static_cast<long>(result_.breaks) +
               static_cast<long>(std::min(max_steps_per_stiffness * stiffness, 1e12));
    }

    void count_step() {
        if (++steps_ > step_budget()) {
            std::ostringstream msg;
            msg << "roughgas: contact integration exceeded " << steps_ - 1
                << " steps (u = " << setup_.coefficients.u << ", form " << name(setup_.coefficients.form)
                << ", end " << name(setup_.end) << ", k_e = " << setup_.coefficients.k_e
                << ", k_p = " << setup_.coefficients.k_p << ", breaks so far " << result_.breaks
                << ", t = " << stepper_.current_time()
                << "). For u >~ 1e3 (w >~ 1e15) the damping makes the contact ODE stiff for this explicit "
                   "integrator; otherwise check the tolerance and the parameters";
            throw std::runtime_error(msg.str());
        }
    }

    // Root of f(point(t)) in [ta, tb] given fa = f(ta), fb = f(tb) of opposite signs (or zero).
    template <class F> double locate(double ta, double tb, double fa, double fb, F f) const {
        if (fa == 0) {
            return ta;
        }
        if (fb == 0) {
            return tb;
        }
        const double width = tb - ta;
        const auto close = [width](double a, double b) {
            return std::abs(b - a) <= 1e-14 * width + 4.0 * DBL_EPSILON * std::abs(b);
        };
        std::uintmax_t iterations = 100;
        const auto g = [&](double t) { return f(at(t)); };
        const auto r = boost::math::tools::toms748_solve(g, ta, tb, fa, fb, close, iterations);
        return 0.5 * (r.first + r.second);
    }

    // Integrates one piece from q0 (clock value t0) until the contact ends (true), or until
    // t_end (loading) or the unloading switch point (turning) is reached (false; exit_point_).
    bool run_piece(const ContactPoint& q0, double t0, double t_end, double dt0) {
        stepper_.initialize(ode_.state(q0), t0, dt0);
        for (;;) {
            const double t = stepper_.current_time();
            if (stepper_.current_time_step() >= t_end - t) {
                const State x = stepper_.current_state(); // land exactly on the end of the piece
                stepper_.initialize(x, t, t_end - t);
            }
            count_step();
            stepper_.do_step(ode_);
            const double ta = stepper_.previous_time();
            const double tb = stepper_.current_time();
            const Stop stop = process_step(ta, tb);
            if (stop == Stop::asperity_break || stop == Stop::force_kink) {
                continue;
            }
            if (stop != Stop::none) {
                return true;
            }
            const ContactPoint qb = ode_.point(tb, stepper_.current_state());
            const bool at_end = tb >= t_end - 4.0 * DBL_EPSILON * std::abs(t_end);
            const bool may_unload =
                ode_.clock == Clock::time && compressed_ &&
                unloading_is_safe(setup_.coefficients.form, setup_.end, setup_.coefficients.u, qb.X, qb.V);
            if (at_end || may_unload) {
                exit_point_ = qb;
                exit_step_ = stepper_.current_time_step();
                return false;
            }
        }
    }

    // The events inside the accepted step [ta, tb]; handles the earliest one that stops the step.
    Stop process_step(double ta, double tb) {
        const OdeCoefficients& c = setup_.coefficients;
        const ContactPoint qa = ode_.point(ta, stepper_.previous_state());
        const ContactPoint qb = ode_.point(tb, stepper_.current_state());
        double t_stop = tb;
        Stop stop = Stop::none;
        const auto consider = [&](double t, Stop s) {
            if (stop == Stop::none || t < t_stop) {
                t_stop = t;
                stop = s;
            }
        };

        // 1. The end of the contact.
        if (setup_.end == ContactEnd::force) {
            const auto g = [&c](const ContactPoint& q) {
                return normal_force_sign_function(c.form, q.X, q.V, c.u);
            };
            const double ga = g(qa), gb = g(qb);
            if (ga > 0 && gb <= 0) {
                consider(locate(ta, tb, ga, gb, g), Stop::force);
            }
        } else {
            // vs = 0 is X = 0 exactly; the last unloading step is clamped to end there, up to
            // the rounding of t + (vs_s - t).
            if (ode_.clock == Clock::unloading && tb >= ode_.origin * (1.0 - 4.0 * DBL_EPSILON)) {
                consider(ode_.origin, Stop::separation);
            } else if (ode_.clock == Clock::time && qa.X > 0 && qb.X <= 0) {
                consider(locate(ta, tb, qa.X, qb.X, [](const ContactPoint& q) { return q.X; }),
                         Stop::separation);
            }
            if (compressed_ && ode_.clock == Clock::time && qa.V < 0 && qb.V >= 0) {
                consider(locate(ta, tb, qa.V, qb.V, [](const ContactPoint& q) { return q.V; }),
                         Stop::capture);
            }
            // Eq. 25's force -y|y|^{1/2} is only C^1 at y = X + uV = 0, and the asperity spring
            // (N = 4) is switched off there (contact_ode.hpp, compressive): a step across it
            // loses its order and the error estimate misjudges it, so land on the zero and restart.
            if ((c.form == NormalForm::eq25 || N == 4) && !kinked_) {
                const auto g = [&c](const ContactPoint& q) {
                    return normal_force_sign_function(c.form, q.X, q.V, c.u);
                };
                const double ga = g(qa), gb = g(qb);
                if (ga > 0 && gb <= 0) {
                    consider(locate(ta, tb, ga, gb, g), Stop::force_kink);
                }
            }
        }

        // 2. Turning point of p and asperity breaks before the end.
        double t_turn = std::numeric_limits<double>::infinity();
        ContactPoint q_turn;
        if constexpr (N == 4) {
            if ((qa.p > 0 && qb.p <= 0) || (qa.p < 0 && qb.p >= 0)) {
                t_turn = locate(ta, tb, qa.p, qb.p, [](const ContactPoint& q) { return q.p; });
                q_turn = at(t_turn);
            }
            const double theta = setup_.threshold;
            if (std::isfinite(theta)) {
                // |e| is monotone between turning points (e' = k_e p): look at the segment ends.
                const auto find_break = [&](double x, const ContactPoint& qx, double y,
                                            const ContactPoint& qy) {
                    if (std::abs(qy.e) < theta) {
                        return false;
                    }
                    const double sign = qy.e > 0 ? 1.0 : -1.0;
                    const auto h = [theta, sign](const ContactPoint& q) { return theta - sign * q.e; };
                    t_stop = locate(x, y, h(qx), h(qy), h);
                    stop = Stop::asperity_break;
                    return true;
                };
                const double y1 = std::min(t_turn, t_stop);
                const ContactPoint qy1 = y1 == tb ? qb : at(y1);
                if (!find_break(ta, qa, y1, qy1) && t_turn < t_stop) {
                    find_break(t_turn, q_turn, t_stop, t_stop == tb ? qb : at(t_stop));
                }
            }
        }

        // 3. Bookkeeping of what happened before t_stop.
        if (!compressed_ && qa.V > 0 && qb.V <= 0) {
            const double t_max = locate(ta, tb, qa.V, qb.V, [](const ContactPoint& q) { return q.V; });
            if (t_max <= t_stop) {
                compressed_ = true;
                result_.normal.max_compression = at(t_max).X;
            }
        }
        if (t_turn < t_stop || (t_turn == t_stop && stop != Stop::asperity_break)) {
            ++result_.turning_points;
            result_.max_abs_e = std::max(result_.max_abs_e, std::abs(q_turn.e));
        }

        switch (stop) {
        case Stop::none:
            result_.max_abs_e = std::max(result_.max_abs_e, std::abs(qb.e));
            break;
        case Stop::asperity_break:
            restart_after_break(t_stop);
            break;
        case Stop::force_kink:
            land(ta, t_stop);
            kinked_ = true;
            break;
        default:
            finish(ta, t_stop, stop);
        }
        return stop;
    }

    // e -> 0 at the break (docs/model.md §7) and a fresh start of the stepper: the right-hand side
    // jumps here. The first step is capped to end just past the next break, predicted from
    // de/dt at the restart, so that a many-break contact costs about one step per break.
    void restart_after_break(double t_break) {
        if constexpr (N == 4) {
            State x;
            stepper_.calc_state(t_break, x);
            x[2] = 0.0;
            ++result_.breaks;
            result_.max_abs_e = std::max(result_.max_abs_e, setup_.threshold);
            double dt = stepper_.current_time_step();
            const ContactPoint q = ode_.point(t_break, x);
            const double rate = std::abs(ode_.time_rate(t_break, q.V) * setup_.coefficients.k_e * q.p);
            if (rate * dt > 0.8 * setup_.threshold) {
                dt = 1.2 * setup_.threshold / rate;
            }
            stepper_.initialize(x, t_break, dt);
        }
    }

    // Redo the last step from ta so that it ends exactly at the event t_end (see top).
    void land(double ta, double t_end) {
        const State xa = stepper_.previous_state();
        stepper_.initialize(xa, ta, t_end - ta);
        while (stepper_.current_time() < t_end) {
            const double t = stepper_.current_time();
            if (stepper_.current_time_step() >= t_end - t) {
                const State x = stepper_.current_state();
                stepper_.initialize(x, t, t_end - t);
            }
            count_step();
            stepper_.do_step(ode_);
            if (stepper_.current_time() >= t_end - 4.0 * DBL_EPSILON * std::abs(t_end)) {
                break;
            }
        }
    }

    void finish(double ta, double t_end, Stop stop) {
        land(ta, t_end);
        ContactPoint q = ode_.point(t_end, stepper_.current_state());
        if (stop == Stop::separation) {
            q.X = 0.0;
        }
        NormalResult& n = result_.normal;
        n.duration = q.S;
        n.captured = stop == Stop::capture;
        n.eps_n = n.captured ? 0.0 : std::clamp(-q.V, 0.0, 1.0);
        result_.p_end = q.p;
        result_.max_abs_e = std::max(result_.max_abs_e, std::abs(q.e));
    }
};

// Arguments every contact integration needs; `where` names the caller in the message.
inline void check_contact_arguments(const char* where, double u, Tolerance tol) {
    if (!(std::isfinite(u) && u >= 0)) {
        std::ostringstream msg;
        msg << where << ": u = " << u << ", need a finite u >= 0";
        throw std::invalid_argument(msg.str());
    }
    // Both must be positive: at S = 0 some state components are exactly 0 and odeint's error
    // norm divides by abs + rel |x|.
    if (!(tol.rel > 0 && tol.abs > 0)) {
        std::ostringstream msg;
        msg << where << ": tolerance rel = " << tol.rel << ", abs = " << tol.abs << ", need both > 0";
        throw std::invalid_argument(msg.str());
    }
}

// The resolved end: at u = 0 the force X + uV = X vanishes exactly at separation.
inline ContactEnd resolved_end(ContactEnd end, double u) {
    return u == 0 ? ContactEnd::separation : end;
}

template <std::size_t N> DriverResult integrate_contact_ode(const DriverSetup& setup) {
    return ContactRun<N>(setup).run();
}

} // namespace roughgas::detail
