#pragma once
// Uniform shear flow u = a y x^ of the homogeneous gas (issue 4), in the frame that moves with the
// flow: the state is the peculiar velocities V = v - u(r). Between collisions each grain moves on
// a straight line, so its peculiar velocity obeys dV_x/dt = -a V_y (the flow under it changes),
// V_y, V_z and omega unchanged: the exact solution over a time s is V_x -> V_x - a s V_y
// (stream_shear). Collisions act on V as in the homogeneous gas: in the dilute (Boltzmann) limit
// the relative velocity of the colliding centres, V_i - V_j + a (y_i - y_j) x^ with
// y_i - y_j = sigma n_y, is taken as V_i - V_j: the a sigma offset is neglected (it is of the
// order a sigma/sqrt(T/m), the collisional transfer of a dense gas; README "Uniform shear flow").
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

#include <cstddef>
#include <cstdint>

namespace roughgas {

// The exact free streaming of the peculiar velocities over a time s (s may be negative): every
// grain's V_x -= a s V_y.
template <class Store> void stream_shear(Store& store, double a, double s) {
    const double k = a * s;
    const std::size_t n = store.size();
    for (std::size_t i = 0; i < n; ++i) {
        Vec3& v = store.v(i);
        v.x -= k * v.y;
    }
}

// Runs Strang steps of length h until done() holds after a step (at least one step), with the
// merged half-streams described above: stream(s) streams by s, collide(h) advances the collisions
// by h. Returns the number of steps. The state is synchronised on return.
// `resumed`: the state is that of an earlier call at a done() that returned false (a checkpoint,
// dsmc/run.cpp), half a stream from synchronised; the steps go on from there, bit for bit as that
// call would have (the merged stream of h first, not a new half-stream).
template <class Stream, class Collide, class Done>
std::int64_t strang_steps(double h, Stream&& stream, Collide&& collide, Done&& done, bool resumed = false) {
    std::int64_t steps = 0;
    stream(resumed ? h : 0.5 * h);
    for (;;) {
        collide(h);
        ++steps;
        if (done())
            break;
        stream(h);
    }
    stream(0.5 * h);
    return steps;
}

} // namespace roughgas
