#pragma once

namespace roughgas {

// Error control of the adaptive contact integration (absolute and relative, on the Hertz-scaled state).
struct Tolerance {
    double rel = 1e-12;
    double abs = 1e-14;
    friend bool operator==(const Tolerance&, const Tolerance&) = default;
};

} // namespace roughgas
