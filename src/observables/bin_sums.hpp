#pragma once
// The sums over the grains of each bin of a grid, taken in the middle of a flight
// (observables/profiles.hpp): what the profiles (slabs along one axis) and the cell fields (every
// collision cell) are computed from, with the same sampling.
#include "roughgas/core/worker_team.hpp"
#include "roughgas/observables/profiles.hpp"

#include <array>
#include <vector>

namespace roughgas::detail {

// bins[a] bins of length[a] / bins[a] along axis a; walled[a]: walls at 0 and length[a] (else periodic).
struct BinGrid {
    std::array<int, 3> bins{1, 1, 1};
    std::array<double, 3> length{1, 1, 1};
    std::array<bool, 3> walled{false, false, false};
    std::size_t size() const {
        return static_cast<std::size_t>(bins[0]) * static_cast<std::size_t>(bins[1]) * static_cast<std::size_t>(bins[2]);
    }
};

// Per bin, with c = v - u (u the bin's mass-weighted mean velocity).
struct BinSums {
    double count = 0, mass = 0, rot = 0; // grains, sum m, sum J omega^2
    Vec3 momentum{}, spin{};             // sum m v, sum omega
    double cc[6] = {};                   // sum m c_a c_b: xx, yy, zz, xy, xz, yz
    Vec3 heat{};                         // sum (m c^2/2 + J omega^2/2) c (J omega^2/2 with s.rotation)
    Vec3 flow() const { return mass > 0 ? (1.0 / mass) * momentum : Vec3{}; }
};

// A bin's running sums in bin_sums' pass: its moments about a velocity of its own (`ref`, its first
// grain's), turned into BinSums about its flow at the end.
struct BinMoments {
    double count = 0, mass = 0, rot = 0;
    Vec3 momentum{}, spin{}, ref{}, md{}, q{}, r{};
    double a[6] = {};
};

// The arrays of bin_sums' pass, kept from call to call: a grid of every collision cell at N = 10^6
// needs 17 MB of them, and fresh arrays at every output row would be faulted in and cleared anew (a
// few per cent of a run writing cell fields at every row). `moments` is all zeros between calls.
struct BinSumsBuffers {
    std::vector<BinMoments> moments;
    std::vector<BinSums> sums;
};

// Bin i_x + B_x (i_y + B_y i_z) of each grain in the middle of its flight; grain order within a bin
// (a deterministic sum). The result lives in `buffers.sums`, valid until the next call with them.
// With a team, a grid of a few bins (the profiles' slabs) is summed in parallel: in fixed units of
// grains, each unit's sums about its own flows, added in unit order with the parallel-axis
// identities of layer_sums (the same result on any team, to round-off the serial one's).
const std::vector<BinSums>& bin_sums(const FlightSampling& s, const BinGrid& g, const std::vector<Vec3>& x,
                                     const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                                     const std::vector<SpeciesBlock>& species, BinSumsBuffers& buffers,
                                     WorkerTeam* team = nullptr);
// The same with buffers of its own (a few bins: the profiles' slabs).
std::vector<BinSums> bin_sums(const FlightSampling& s, const BinGrid& g, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                              const std::vector<SpeciesBlock>& species, WorkerTeam* team = nullptr);

// The sums of the layers of cells along `axis` (cells: bin_sums over a grid of every cell; the
// layers: what bin_sums over that axis's bins alone would give, to round-off): the counts, masses,
// momenta, spins and rotational energies add, the moments about each layer's flow U follow from
// those about the cells' flows U_c with d = U_c - U (the parallel-axis identities):
//   sum m c_a c_b = sum_cells [C_ab + M_c d_a d_b],
//   sum (m c^2/2) c = sum_cells [Q + C.d + (tr C/2) d + (M_c d^2/2) d] (+ (rot_c/2) d with `rotation`).
std::vector<BinSums> layer_sums(const std::vector<BinSums>& cells, const BinGrid& g, int axis, bool rotation);

// The profiles (compute_profiles' layout) from the sums of their bins.
std::vector<double> profiles_from_sums(const ProfileGeometry& g, const std::vector<BinSums>& sums,
                                       const std::vector<Virial>& virial, double dt);

} // namespace roughgas::detail
