#include "roughgas/io/restitution_csv.hpp"

#include <fmt/format.h>

namespace roughgas {
namespace {

template <std::size_t N>
std::string table(std::string_view file, const std::array<ColumnSpec, N>& cols, const ColumnSpec& cached) {
    std::string md =
        fmt::format("`DIR/{}`:\n\n| Column | Unit | Meaning |\n|--------|------|---------|\n", file);
    for (const ColumnSpec& c : cols) {
        md += fmt::format("| `{}` | {} | {} |\n", c.name, c.unit, c.description);
    }
    md += fmt::format("| `{}` | {} | {} |\n", cached.name, cached.unit, cached.description);
    return md;
}

} // namespace

std::string restitution_columns_markdown() {
    return table("normal.csv", normal_columns, normal_table_column) + "\n" +
           table("tangential.csv", tangential_columns, tangential_table_column);
}

} // namespace roughgas
