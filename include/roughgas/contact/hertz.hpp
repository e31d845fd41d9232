#pragma once
// Closed forms of the elastic (Hertz) contact, used by checks and tests (docs/model.md §6).
#include <boost/math/special_functions/beta.hpp>
#include <cmath>

namespace roughgas::hertz {

// I = int_0^1 (1 - x^{5/2})^{-1/2} dx = (2/5) B(2/5, 1/2).
inline double integral_I() { return 0.4 * boost::math::beta(0.4, 0.5); }

// Contact duration in Hertz units S_c = 2 I (5/4)^{2/5} = 3.21806546...; t_c = S_c rho^{-2/5} g_N^{-1/5}.
inline double scaled_duration() { return 2.0 * integral_I() * std::pow(1.25, 0.4); }

// Maximum compression in Hertz units: X_max = (5/4)^{2/5} (energy: X'^2/2 + (2/5) X^{5/2} = 1/2).
inline double scaled_max_compression() { return std::pow(1.25, 0.4); }

} // namespace roughgas::hertz
