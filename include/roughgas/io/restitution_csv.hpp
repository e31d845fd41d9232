#pragma once
// The columns of `roughgas restitution`'s DIR/normal.csv and DIR/tangential.csv (docs/reference.md:
// extend, never rename). docs/reference.md's column tables are generated from these lists.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace roughgas {

struct ColumnSpec {
    std::string_view name;
    std::string_view unit; // "-" for dimensionless
    std::string_view description;
};

inline constexpr std::array<ColumnSpec, 5> normal_columns{{
    {"g_N", "m/s", "normal impact speed"},
    {"w", "-", "the scaled impact speed w = g_N rho^2 tau^5 that eps_N depends on (docs/model.md §6)"},
    {"eps_N", "-", "normal restitution coefficient, (g^N)' = -eps_N g^N"},
    {"duration", "s", "contact duration t_c"},
    {"max_compression", "m", "largest compression xi during the contact"},
}};

inline constexpr std::array<ColumnSpec, 5> tangential_columns{{
    {"g_N", "m/s", "normal impact speed"},
    {"g_T", "m/s", "tangential speed of the contact point before the collision"},
    {"eps_T", "-", "tangential restitution coefficient of Brilliantov et al. 1996, (g^T)' = eps_T g^T"},
    {"beta", "-", "beta = -eps_T (the case file's convention: -1 smooth, +1 perfectly rough)"},
    {"breaks", "-", "number of asperities broken during the contact (docs/model.md §7)"},
}};

// Appended when contact.cache = true: the cached tables' value at the same point, so the table error
// (the difference to the direct value) is in the file.
inline constexpr ColumnSpec normal_table_column{
    "eps_N_table", "-", "eps_N from the cached table (only with contact.cache = true): minus eps_N, the table's error"};
inline constexpr ColumnSpec tangential_table_column{
    "eps_T_table", "-", "eps_T from the cached table (only with contact.cache = true): minus eps_T, the table's error"};

template <std::size_t N> std::vector<std::string> column_names(const std::array<ColumnSpec, N>& cols) {
    std::vector<std::string> names;
    for (const ColumnSpec& c : cols)
        names.emplace_back(c.name);
    return names;
}

// Markdown tables of both files for docs/reference.md.
std::string restitution_columns_markdown();

} // namespace roughgas
