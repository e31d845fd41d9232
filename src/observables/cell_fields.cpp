// The fields of a box's collision cells: observables/cell_fields.hpp.
#include "roughgas/observables/cell_fields.hpp"

#include "bin_sums.hpp"

#include <limits>
#include <stdexcept>

namespace roughgas {

std::string_view field_unit(FieldQuantity q) {
    switch (q) {
    case FieldQuantity::n:
        return "1/volume";
    case FieldQuantity::u:
        return "length/time";
    case FieldQuantity::T_tr:
    case FieldQuantity::T_rot:
        return "energy";
    case FieldQuantity::theta:
        return "-";
    case FieldQuantity::omega:
        return "1/time";
    case FieldQuantity::P:
        return "energy/volume";
    case FieldQuantity::q:
        return "energy/(length^2*time)";
    }
    return "?";
}

CellFieldsScratch::CellFieldsScratch() : buffers(std::make_unique<detail::BinSumsBuffers>()) {}
CellFieldsScratch::~CellFieldsScratch() = default;

CellFields compute_cell_fields(const FlightSampling& s, const std::array<int, 3>& cells,
                               const std::array<bool, 3>& walled, const std::vector<FieldQuantity>& quantities,
                               const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                               const std::vector<SpeciesBlock>& species) {
    CellFields out;
    CellFieldsScratch scratch;
    compute_cell_fields(s, cells, walled, quantities, x, v, w, species, out, scratch);
    return out;
}

namespace {

detail::BinGrid cell_grid(const FlightSampling& s, const std::array<int, 3>& cells, const std::array<bool, 3>& walled) {
    detail::BinGrid grid;
    grid.bins = cells;
    grid.length = s.box;
    grid.walled = walled;
    for (std::size_t a = 0; a < 3; ++a)
        if (cells[a] < 1 || !(s.box[a] > 0))
            throw std::invalid_argument("compute_cell_fields: cells and box must be positive");
    return grid;
}

void fields_from_sums(const FlightSampling& s, const detail::BinGrid& grid, const std::vector<detail::BinSums>& sums,
                      const std::vector<FieldQuantity>& quantities, CellFields& out) {
    const std::array<int, 3>& cells = grid.bins;
    const double f = s.weight * static_cast<double>(grid.size()) / (s.box[0] * s.box[1] * s.box[2]); // F / V_c
    const double nan = std::numeric_limits<double>::quiet_NaN();

    out.cells = cells;
    out.quantities = quantities;
    out.values.resize(quantities.size());
    // An empty cell's fields are NaN (n: 0).
    const auto T_tr = [&](const detail::BinSums& b) {
        return b.count == 0 ? nan : (b.cc[0] + b.cc[1] + b.cc[2]) / (3 * b.count);
    };
    const auto T_rot = [&](const detail::BinSums& b) { return b.count == 0 ? nan : b.rot / (3 * b.count); };
    const auto or_nan = [&](const detail::BinSums& b, Vec3 q) { return b.count == 0 ? Vec3{nan, nan, nan} : q; };
    // Quantity by quantity, cell by cell: each array written in order, no switch per value.
    for (std::size_t k = 0; k < quantities.size(); ++k) {
        std::vector<double>& values = out.values[k];
        const auto C = static_cast<std::size_t>(field_components(quantities[k]));
        values.resize(sums.size() * C);
        double* o = values.data();
        const auto put = [&](Vec3 q) {
            o[0] = q.x;
            o[1] = q.y;
            o[2] = q.z;
            o += 3;
        };
        switch (quantities[k]) {
        case FieldQuantity::n:
            for (const detail::BinSums& b : sums)
                *o++ = f * b.count;
            break;
        case FieldQuantity::u:
            for (const detail::BinSums& b : sums)
                put(or_nan(b, b.flow()));
            break;
        case FieldQuantity::T_tr:
            for (const detail::BinSums& b : sums)
                *o++ = T_tr(b);
            break;
        case FieldQuantity::T_rot:
            for (const detail::BinSums& b : sums)
                *o++ = T_rot(b);
            break;
        case FieldQuantity::theta:
            for (const detail::BinSums& b : sums) {
                const double t = T_tr(b);
                *o++ = t > 0 ? T_rot(b) / t : nan;
            }
            break;
        case FieldQuantity::omega:
            for (const detail::BinSums& b : sums)
                put(or_nan(b, (1.0 / b.count) * b.spin));
            break;
        case FieldQuantity::P: // Tensor6: xx, xy, xz, yy, yz, zz from cc's xx, yy, zz, xy, xz, yz
            for (const detail::BinSums& b : sums)
                for (int c : {0, 3, 4, 1, 5, 2})
                    *o++ = b.count == 0 ? nan : f * b.cc[c];
            break;
        case FieldQuantity::q:
            for (const detail::BinSums& b : sums)
                put(or_nan(b, f * b.heat));
            break;
        }
    }
}

} // namespace

void compute_cell_fields(const FlightSampling& s, const std::array<int, 3>& cells, const std::array<bool, 3>& walled,
                         const std::vector<FieldQuantity>& quantities, const std::vector<Vec3>& x,
                         const std::vector<Vec3>& v, const std::vector<Vec3>& w,
                         const std::vector<SpeciesBlock>& species, CellFields& out, CellFieldsScratch& scratch) {
    const detail::BinGrid grid = cell_grid(s, cells, walled);
    fields_from_sums(s, grid, detail::bin_sums(s, grid, x, v, w, species, *scratch.buffers), quantities, out);
}

std::vector<double> compute_cell_fields_and_profiles(const ProfileGeometry& g, const std::array<int, 3>& cells,
                                                     const std::array<bool, 3>& walled,
                                                     const std::vector<FieldQuantity>& quantities,
                                                     const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                                     const std::vector<Vec3>& w, const std::vector<SpeciesBlock>& species,
                                                     const std::vector<Virial>& virial, double dt, CellFields& out,
                                                     CellFieldsScratch& scratch) {
    const auto axis = static_cast<std::size_t>(g.axis);
    // The profile's own pass reflects the grains only at the walls across its axis.
    bool other_walls = false;
    for (std::size_t a = 0; a < 3; ++a)
        other_walls = other_walls || (a != axis && walled[a]);
    if (axis > 2 || g.bins != cells[axis] || g.length != g.box[axis] || walled[axis] == g.periodic || other_walls)
        throw std::invalid_argument(
            "compute_cell_fields_and_profiles: the profile bins must be layers of cells, walls only across them");
    const detail::BinGrid grid = cell_grid(g, cells, walled);
    const std::vector<detail::BinSums>& sums = detail::bin_sums(g, grid, x, v, w, species, *scratch.buffers);
    fields_from_sums(g, grid, sums, quantities, out);
    return detail::profiles_from_sums(g, detail::layer_sums(sums, grid, g.axis, g.rotation), virial, dt);
}

} // namespace roughgas
