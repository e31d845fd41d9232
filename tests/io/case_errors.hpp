#pragma once
// What parsing a case text refuses: shared by the tests of the case-file tables.
#include "roughgas/io/case_file.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace roughgas::test {

// The message of the InputError that parsing `text` (as case.toml, with the --set overrides `sets`)
// throws; "" if it does not throw.
inline std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
    try {
        (void)parse_case(text, "case.toml", sets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Whether parsing `text` with `sets` is refused with a message that holds `part`.
inline ::testing::AssertionResult refused(const std::string& text, const std::vector<std::string>& sets,
                                          const std::string& part) {
    const std::string e = error_of(text, sets);
    if (!e.empty() && e.find(part) != std::string::npos)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "expected \"" << part << "\" in:\n" << e;
}

} // namespace roughgas::test
