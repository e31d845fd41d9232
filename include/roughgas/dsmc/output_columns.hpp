#pragma once
// The contract between the solver and the writers: an ordered list of named columns with units
// (docs/reference.md "Output"), and one row of values per output time and replica.
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace roughgas {

struct Column {
    std::string name; // e.g. "T_tr", "T_tr.ice", "T_tr.a/T_tr.b"
    std::string unit; // e.g. "energy", "1/time", "-"
};

inline std::vector<std::string> column_names(const std::vector<Column>& columns) {
    std::vector<std::string> v;
    for (const Column& c : columns)
        v.push_back(c.name);
    return v;
}

inline std::vector<std::string> column_units(const std::vector<Column>& columns) {
    std::vector<std::string> v;
    for (const Column& c : columns)
        v.push_back(c.unit);
    return v;
}

// Called once per output time with the values of the columns, in order.
using RowSink = std::function<void(std::span<const double> row)>;

} // namespace roughgas
