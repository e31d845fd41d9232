#pragma once
// Profiles of a spatially resolved gas (profiles.csv, docs/reference.md): the fields averaged over
// slabs normal to one axis (the bins: the collision cells along that axis), from the grains'
// positions, velocities and spins in the middle of a free flight, and the collisional part of the
// pressure tensor from the collisions of an interval.
//
// Why the middle of a flight: the grains' velocities are those the collisions left, but the grains
// in a slab change as they fly, and with them the slab's moments: in a Couette flow the slab's
// P_xy drifts linearly during a flight of length h, by -h p du/dy, and the momentum the flight
// carries through a plane is its average over the flight. Sampled right after the collisions, P_xy
// misses h/2 p du/dy (7 % of the viscosity at h = 0.2 mean free times); sampled at mid-flight, the
// kinetic fluxes agree with what the walls receive. Each grain is taken at x + v h/2 + g h^2/8
// with the velocity v + g h/2 (wrapped along a periodic axis; along a walled one, a grain that
// would pass the wall is reflected specularly; across Lees-Edwards boundaries it becomes the image's
// grain), h being the flight that follows.
//
// Per bin, with N_b grains of masses m and moments of inertia J,
// V_b the slab's volume and F the physical grains per simulated one:
//   n = F N_b / V_b;  u = sum m v / sum m;  c = v - u;
//   T_tr = sum m c^2 / (3 N_b),  T_rot = sum J omega^2 / (3 N_b),  theta = T_rot / T_tr;
//   P_ab (kinetic) = (F / V_b) sum m c_a c_b;
//   Pc_ab (collisional) = (F / (V_b dt)) sum over the interval's collisions in the slab of the
//     symmetrised (Delta p_i,a r_ij,b + Delta p_i,b r_ij,a)/2, Delta p_i the impulse on grain i and
//     r_ij = x_i - x_j (the momentum a collision carries across the distance between its grains: in
//     the DSMC the source of the cell-size error of the viscosity, zero on average in a uniform gas);
//   q_a = (F / V_b) sum (m c^2/2 + J omega^2/2) c_a (kinetic; the rotational energy only where
//     collisions or walls change the spins: smooth grains carry theirs unchanged, a noise of zero mean);
//   omega = sum omega / N_b.
// A bin without grains has n = 0 and every other field NaN.
#include "roughgas/core/vec.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/dsmc/output_columns.hpp"

#include <array>
#include <string>
#include <vector>

namespace roughgas {

class WorkerTeam; // core/worker_team.hpp

inline constexpr const char* profile_fields[] = {
    "n",     "u_x",   "u_y",   "u_z",   "T_tr",  "T_rot", "theta", "P_xx", "P_yy", "P_zz", "P_xy",
    "P_xz",  "P_yz",  "Pc_xx", "Pc_yy", "Pc_zz", "Pc_xy", "Pc_xz", "Pc_yz", "q_x", "q_y",  "q_z",
    "omega_x", "omega_y", "omega_z"};
inline constexpr std::size_t profile_field_count = std::size(profile_fields);
// Index of the first collisional field (Pc_xx), of T_tr and of theta in profile_fields.
inline constexpr std::size_t profile_collisional_first = 13, profile_T_tr = 4, profile_theta = 6;

// The unit of each field, in profile_fields order.
std::vector<Column> profile_field_columns();

// The symmetrised virial sums of one slab's collisions: xx, yy, zz, xy, xz, yz.
using Virial = std::array<double, 6>;

// How the grains are taken in the middle of a flight (the profiles and the cell fields alike).
struct FlightSampling {
    double weight = 1;       // F: physical grains per simulated one
    bool rotation = true;    // the spins take part in the energy exchange (rough grains or walls)
    double half_flight = 0;  // h/2: the grains are taken in the middle of a flight of length h
    Vec3 gravity{};
    // Lees-Edwards along y (a sheared box): a grain passing y = L_y or 0 in the half flight is
    // taken as the image's grain (v_x -/+ a L_y, x -/+ a L_y t at t = time + h/2).
    double shear_rate = 0, time = 0;
    std::array<double, 3> box{1, 1, 1};
};

struct ProfileGeometry : FlightSampling {
    int axis = 0;            // 0, 1, 2: x, y, z
    int bins = 1;
    double length = 1;       // of the box along the axis
    double bin_volume = 1;   // V_b (the case's volume unit)
    bool periodic = true;    // along the axis (else walls)
};

// The fields of every bin, bin after bin (profile_field_count each). `virial[b]` are bin b's sums
// over an interval of length `dt` (NaN: no interval, the collisional fields are NaN).
// With a team the pass over the grains runs on it (the same profiles on any team).
std::vector<double> compute_profiles(const ProfileGeometry& g, const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                     const std::vector<Vec3>& w, const std::vector<SpeciesBlock>& species,
                                     const std::vector<Virial>& virial, double dt, WorkerTeam* team = nullptr);

} // namespace roughgas
