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
    for (std::size_t k = 0; k < quantities.size(); ++k) {
        out.values[k].clear();
        out.values[k].reserve(sums.size() * static_cast<std::size_t>(field_components(quantities[k])));
    }
    for (const detail::BinSums& b : sums) {
        const bool empty = b.count == 0;
        const double T_tr = empty ? nan : (b.cc[0] + b.cc[1] + b.cc[2]) / (3 * b.count);
        const double T_rot = empty ? nan : b.rot / (3 * b.count);
        const Vec3 u = empty ? Vec3{nan, nan, nan} : b.flow();
        const Vec3 spin = empty ? Vec3{nan, nan, nan} : (1.0 / b.count) * b.spin;
        const Vec3 heat = empty ? Vec3{nan, nan, nan} : f * b.heat;
        for (std::size_t k = 0; k < quantities.size(); ++k) {
            std::vector<double>& values = out.values[k];
            switch (quantities[k]) {
            case FieldQuantity::n:
                values.push_back(f * b.count);
                break;
            case FieldQuantity::u:
                values.insert(values.end(), {u.x, u.y, u.z});
                break;
            case FieldQuantity::T_tr:
                values.push_back(T_tr);
                break;
            case FieldQuantity::T_rot:
                values.push_back(T_rot);
                break;
            case FieldQuantity::theta:
                values.push_back(T_tr > 0 ? T_rot / T_tr : nan);
                break;
            case FieldQuantity::omega:
                values.insert(values.end(), {spin.x, spin.y, spin.z});
                break;
            case FieldQuantity::P: // Tensor6: xx, xy, xz, yy, yz, zz from cc's xx, yy, zz, xy, xz, yz
                for (int c : {0, 3, 4, 1, 5, 2})
                    values.push_back(empty ? nan : f * b.cc[c]);
                break;
            case FieldQuantity::q:
                values.insert(values.end(), {heat.x, heat.y, heat.z});
                break;
            }
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
