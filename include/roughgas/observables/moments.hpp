#pragma once
// Temperatures and cumulants of docs/model.md §5, per species and over all particles (k_B = 1):
//
//   T_tr = (1/3) <m c^2>,  T_rot = (1/3) <J omega^2>,  theta = T_rot/T_tr,   c = v - u
//   a20 = (4/15) <c*^4> - 1,  a02 = (4/15) <w*^4> - 1,  a11 = (4/9) <c*^2 w*^2> - 1
//   A_cw = <(c . omega)^2>/(<c^2> <omega^2>) - 1/3
//
// with u the centre-of-mass (mass-weighted mean) velocity of all particles, and the reduced
// c* = c/sqrt(2 T_tr/m), w* = omega/sqrt(2 T_rot/J). Per species, T_tr and T_rot are the species'
// own; over all particles of a mixture, c* = c sqrt(m/(2 T_tr)) with each particle's mass and the
// mixture's T_tr (likewise w* with each J), and A_cw is taken over these reduced vectors:
// A_cw = <(c*.w*)^2>/(<c*^2><w*^2>) - 1/3. For one species the reduced form is A_cw of docs/model.md §5
// exactly (the constant factors cancel); for a mixture it is the form that vanishes when every
// species is Maxwellian at the mixture's temperatures, whatever their m and J (the raw c and omega
// of light and heavy grains are correlated in size, which gave A_cw = 0.25 for a Maxwellian mixture).
// The mixture-wide a20, a02, a11 are not 0 when the species' temperatures differ (a sum of
// Maxwellians of different widths is not one): read the per-species columns for each species' shape.
//
// Range: every fourth-order sum is accumulated on the reduced vectors c*, w* (O(1) whatever the
// temperature), so nothing like T^2 or v^4 is formed; a run can cool through 40 decades of T.
// Only c^2 and omega^2 themselves are formed: they underflow below |c| ~ 1e-154 (in the run's units).
// Undefined values are NaN: every cumulant of an empty species, and a02, a11, A_cw (and theta of an
// empty species) when T_rot = 0.
#include "roughgas/core/vec.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace roughgas {

class WorkerTeam;

// Species s occupies the index range [offset, offset + count) of the columns.
struct SpeciesSlice {
    std::size_t offset = 0, count = 0;
    double mass = 1;
    double moment_of_inertia = 0.1; // J = q m R^2
};

struct GroupMoments {
    std::size_t count = 0;
    double T_tr = 0, T_rot = 0, theta = 0;
    double a20 = 0, a02 = 0, a11 = 0, A_cw = 0;
};

struct Moments {
    GroupMoments all;
    std::vector<GroupMoments> species;
    Vec3 mean_velocity{}; // u
};

// The mean of x over all grains weighted by a per-species property (mass: the centre-of-mass velocity;
// moment_of_inertia: the mean spin); 0 when the weights sum to 0.
Vec3 weighted_mean(Vec3Column x, std::span<const SpeciesSlice> species, double SpeciesSlice::*weight);

// Two passes over the grains, in fixed chunks: with `threads` > 1 (or a team) the chunks are
// summed on that many threads; the result does not depend on it (bitwise).
Moments compute_moments(Vec3Column v, Vec3Column omega, std::span<const SpeciesSlice> species,
                        int threads = 1);
Moments compute_moments(Vec3Column v, Vec3Column omega, std::span<const SpeciesSlice> species, WorkerTeam& team);

} // namespace roughgas
