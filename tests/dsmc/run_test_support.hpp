#pragma once
// Shared by the tests that read run_replica's rows (tests/dsmc, tests/stress).
#include "roughgas/dsmc/run.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

namespace roughgas::test {

// Index of the column `name` in the rows of `spec` (dsmc_columns); a test failure if there is none.
inline std::size_t column(const RunSpec& spec, const std::string& name) {
    const auto cols = dsmc_columns(spec);
    for (std::size_t k = 0; k < cols.size(); ++k)
        if (cols[k].name == name)
            return k;
    ADD_FAILURE() << "no column " << name;
    return 0;
}

// Index of the column `name` in a replica's whole row (replica_row_columns: the dsmc columns, then
// the walls', profiles' and spectra's, e.g. "mode1.1.u_y_re"); a test failure if there is none.
inline std::size_t row_column(const RunSpec& spec, const std::string& name) {
    const auto cols = replica_row_columns(spec);
    for (std::size_t k = 0; k < cols.size(); ++k)
        if (cols[k].name == name)
            return k;
    ADD_FAILURE() << "no column " << name;
    return 0;
}

} // namespace roughgas::test
