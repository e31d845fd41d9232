#pragma once
// The quantities a box's cell fields hold (observables/cell_fields.hpp, the [fields] table).
#include <array>
#include <string_view>

namespace roughgas {

enum class FieldQuantity { n, u, T_tr, T_rot, theta, omega, P, q };
inline constexpr std::array<std::string_view, 8> field_quantity_names = {"n",     "u",     "T_tr", "T_rot",
                                                                        "theta", "omega", "P",    "q"};
// Values per cell: 1 (scalars), 3 (vectors: x, y, z), 6 (P: xx, xy, xz, yy, yz, zz, the order of
// XDMF's Tensor6).
constexpr int field_components(FieldQuantity q) {
    return q == FieldQuantity::u || q == FieldQuantity::omega || q == FieldQuantity::q ? 3
           : q == FieldQuantity::P                                                     ? 6
                                                                                       : 1;
}

} // namespace roughgas
