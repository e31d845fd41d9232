#pragma once
// The fields of every collision cell of a box (the fields files, docs/reference.md): per cell the
// quantities of profiles.csv (observables/profiles.hpp), from the grains in the cell in the middle
// of the flight that follows, as the profiles take them. With N_c grains in a cell of volume V_c
// and F physical grains per simulated one:
//   n = F N_c / V_c;  u = sum m v / sum m;  c = v - u;
//   T_tr = sum m c^2 / (3 N_c),  T_rot = sum J omega^2 / (3 N_c),  theta = T_rot / T_tr;
//   omega = sum omega / N_c (the mean spin);
//   P_ab = (F / V_c) sum m c_a c_b (the kinetic pressure tensor: the Boltzmann equation's whole
//     pressure; the collisional transfer across a cell is the DSMC's cell-size error, in profiles.csv);
//   q_a = (F / V_c) sum (m c^2/2 + J omega^2/2) c_a (the rotational energy only where the spins
//     take part in the energy exchange, as in the profiles).
// A cell without grains has n = 0 and every other field NaN. Averaged over the cells of a slab
// with their grains as weights (n for u's momentum, n T for the temperatures), the fields give
// the slab's profile.
#include "roughgas/core/vec.hpp"
#include "roughgas/dsmc/species.hpp"
#include "roughgas/observables/field_quantity.hpp"
#include "roughgas/observables/profiles.hpp"

#include <array>
#include <memory>
#include <string_view>
#include <vector>

namespace roughgas {

namespace detail {
struct BinSumsBuffers;
}

// What the pass behind the fields keeps from snapshot to snapshot: its per-cell sums (at every row,
// fresh arrays of them would be faulted in and cleared anew). One per run, used by one thread at a time.
struct CellFieldsScratch {
    CellFieldsScratch();
    ~CellFieldsScratch();
    CellFieldsScratch(const CellFieldsScratch&) = delete;
    CellFieldsScratch& operator=(const CellFieldsScratch&) = delete;
    std::unique_ptr<detail::BinSumsBuffers> buffers;
};

// The unit, as the CSV headers name them ("1/volume", "length/time", ...).
std::string_view field_unit(FieldQuantity q);

struct CellFields {
    std::array<int, 3> cells{1, 1, 1};  // G_x, G_y, G_z
    std::vector<FieldQuantity> quantities;
    // values[k]: quantity k, cell after cell, x fastest (cell (i, j, l) at i + G_x (j + G_y l)),
    // its components fastest of all.
    std::vector<std::vector<double>> values;
};

// The cells of a box: `cells` along each axis, `walled` axes have walls at 0 and L (else periodic).
// `s` gives the box, the weight F and the flight the grains are taken in the middle of.
CellFields compute_cell_fields(const FlightSampling& s, const std::array<int, 3>& cells,
                               const std::array<bool, 3>& walled, const std::vector<FieldQuantity>& quantities,
                               const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                               const std::vector<SpeciesBlock>& species);
// The same into `out`, reusing its arrays' memory and those of `scratch` (a snapshot every row need
// not fault in fresh pages).
void compute_cell_fields(const FlightSampling& s, const std::array<int, 3>& cells, const std::array<bool, 3>& walled,
                         const std::vector<FieldQuantity>& quantities, const std::vector<Vec3>& x,
                         const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                         const std::vector<SpeciesBlock>& species, CellFields& out, CellFieldsScratch& scratch);

// At a row that writes fields: the cell fields into `out` and, from the same pass over the grains,
// the profiles of `g` (compute_profiles' result to round-off: each profile bin is a layer of cells,
// g.bins = cells[g.axis], summed with the identities of moments about two means; walls only across
// that axis, the only ones the profiles' own pass reflects grains at). `virial` and `dt` as for
// compute_profiles.
std::vector<double> compute_cell_fields_and_profiles(const ProfileGeometry& g, const std::array<int, 3>& cells,
                                                     const std::array<bool, 3>& walled,
                                                     const std::vector<FieldQuantity>& quantities,
                                                     const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                                     const std::vector<Vec3>& w, const std::vector<SpeciesBlock>& species,
                                                     const std::vector<Virial>& virial, double dt, CellFields& out,
                                                     CellFieldsScratch& scratch);

} // namespace roughgas
