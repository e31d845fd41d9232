#pragma once
// Uniform shear flow u = a y x^ of the homogeneous gas, in the frame that moves with the
// flow: the state is the peculiar velocities V = v - u(r). Between collisions each grain moves on
// a straight line, so its peculiar velocity obeys dV_x/dt = -a V_y (the flow under it changes),
// V_y, V_z and omega unchanged: the exact solution over a time s is V_x -> V_x - a s V_y
// (stream_shear). Collisions act on V as in the homogeneous gas: in the dilute (Boltzmann) limit
// the relative velocity of the colliding centres, V_i - V_j + a (y_i - y_j) x^ with
// y_i - y_j = sigma n_y, is taken as V_i - V_j: the a sigma offset is neglected (it is of the
// order a sigma/sqrt(T/m), the collisional transfer of a dense gas; docs/model.md).
//
// Splitting (Strang). One step of length h is: stream h/2, collide over h, stream h/2. Consecutive
// half-streams merge into one stream of h (exact: the streams form a one-parameter group), so a
// run of n steps streams h/2, then (collide h, stream h) n - 1 times, then collides h and streams
// h/2: the state is synchronised (full steps of both operators) only at the end, which is where
// outputs are taken. The splitting error of the symmetric form is O(h^2) in the stationary state
// (the first-order Lie form would be O(h)); tests/validation/usf_test.cpp measures the order.
//
// The streaming keeps sum m V = 0 when sum m V_y = 0, which collisions and the engine's recentring
// (dsmc/engine.hpp, a Galilean shift of V) preserve: the mean peculiar velocity stays 0.
#include "roughgas/core/vec.hpp"
#include "roughgas/observables/moments.hpp"
#include "roughgas/observables/pressure.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>

namespace roughgas {

// The exact free streaming of the peculiar velocities over a time s (s may be negative): every
// grain's V_x -= a s V_y. Returns sum m V_i V_j over the grains of `species` after the stream (the
// pressure tensor times the volume), gathered in the same pass: what the next step's length is
// predicted from (strang_step_length).
template <class Store>
PressureTensor stream_shear(Store& store, double a, double s, std::span<const SpeciesSlice> species) {
    const double k = a * s;
    PressureTensor sums;
    for (const SpeciesSlice& sp : species) {
        PressureTensor p;
        for (std::size_t i = sp.offset; i < sp.offset + sp.count; ++i) {
            Vec3& v = store.v(i);
            v.x -= k * v.y;
            p.add_dyad(v);
        }
        sums.add_scaled(sp.mass, p);
    }
    return sums;
}

// T'/T of the state with pressure tensor P (any normalisation, tr P > 0) after a stream of s: the
// stream is exact on P, P_xx -> P_xx - 2 a s P_xy + a^2 s^2 P_yy, and T ~ tr P.
double streamed_temperature_ratio(const PressureTensor& P, double a, double s);

// The length h of the next Strang step, in time: h nu = tau with nu the Maxwellian hard-sphere
// collision frequency of the state the step's collisions start from, i.e. after the stream of
// s = (h_prev + h)/2 that precedes them (s = h/2 for the first step: h_prev = 0). Predicted from a
// state with pressure tensor P (any normalisation) and collision frequency nu_ref: the stream is
// exact on P, P_xx -> P_xx - 2 a s P_xy + a^2 s^2 P_yy, and nu scales as sqrt(T), T ~ tr P.
// Without the prediction a step set from the state before its stream can be off by orders of
// magnitude when a/nu is large: a gas at a/nu = 1e6 heats by ~1e10 in its first half-stream, and a
// step of tau/nu(before) would then hold ~1e4 collisions per grain (tests/stress).
// Throws std::runtime_error when nu_ref or tr P is not positive (no collision can happen).
double strang_step_length(double tau, double nu_ref, const PressureTensor& P, double a, double h_prev);

// Runs Strang steps until done() holds after a step (at least one step), with the merged
// half-streams described above: step() gives the length h_k of the next step (called once before
// each step, so steps may follow the state), stream(s) streams by s, collide(h) advances the
// collisions by h and returns the time it advanced: h, or less when it stopped early at a collision
// cap. Consecutive full steps h_k, h_{k+1} share one stream of (h_k + h_{k+1})/2. A step cut to
// h' < h ends with a stream of h' - h/2 instead of h/2 (possibly negative: streams are a group), so
// that streams and collisions always cover the same time; such a step is asymmetric (first order
// locally), which the caller keeps rare. Returns the number of steps. The state is synchronised on
// return.
// Checkpoints (dsmc/run.cpp): done may take the stream still owed by the step just finished,
// done(pending) (h/2 for a full step); a caller that saves the state at a done() returning false
// passes that `pending` as `resume` to a later call, which goes on from there bit for bit as the
// first would have (the step after it and its merged stream, pending + h/2, not a new half-stream).
// A step() that takes `double& pending` may do that owed stream itself (and set pending to 0)
// before it decides the next step's length, so that it decides from the state after it; the
// next stream is then only the new step's h/2.
template <class Step, class Stream, class Collide, class Done>
std::int64_t strang_steps(Step&& step, Stream&& stream, Collide&& collide, Done&& done,
                          std::optional<double> resume = std::nullopt) {
    const auto next_step = [&](double& pending) {
        if constexpr (std::is_invocable_v<Step&, double&>)
            return step(pending);
        else
            return step();
    };
    std::int64_t steps = 0;
    double owed = resume.value_or(0.0);
    double h = next_step(owed);
    stream(owed + 0.5 * h);
    for (;;) {
        double pending = collide(h) - 0.5 * h; // h/2 for a full step
        ++steps;
        bool finished;
        if constexpr (std::is_invocable_v<Done&, double>)
            finished = done(pending);
        else
            finished = done();
        if (finished) {
            stream(pending);
            break;
        }
        h = next_step(pending);
        stream(pending + 0.5 * h);
    }
    return steps;
}

} // namespace roughgas
