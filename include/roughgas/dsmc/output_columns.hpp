#pragma once
// The contract between the solver and the writers: an ordered list of named columns with units
// (interface.md "Output"), and one row of values per output time and replica.
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace roughgas {

struct Column {
    std::string name; // e.g. "T_tr", "T_tr.ice", "T_tr.a/T_tr.b"
    std::string unit; // e.g. "energy", "1/time", "-"
};

// Called once per output time with the values of the columns, in order.
using RowSink = std::function<void(std::span<const double> row)>;

} // namespace roughgas
