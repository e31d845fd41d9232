#pragma once
// The Mpemba crossing of the driven two-temperature equations (observables/driven_theory.hpp): two
// samples of the same gas under the same thermostat, started from states A and B with
// T_tr,A(0) != T_tr,B(0), and the first time their translational temperatures (the mixture's,
// HcsTheory::mixture_T_tr) are equal again. A sample whose spins hold much energy (high theta) keeps
// its T_tr up while the collisions hand that energy to the translation (the B T_tr^{1/2} T_rot term of
// observables/theory.hpp), so a hotter sample with low theta can overtake a colder one with high
// theta on the way to the common steady state: the Mpemba effect of rough spheres (Torrente,
// Lopez-Castano, Lasanta, Vega Reyes, Prados & Santos 2019; for smooth spheres through a2, Lasanta,
// Vega Reyes, Prados & Santos 2017).
//
// Both trajectories are followed on a grid of a twentieth of the shorter collision time of the two
// (HcsTrajectory, relative tolerance rel_tol) until the difference changes sign; the crossing is then
// located by bisection between the two grid times, each probe integrating a copy of the trajectories
// from the earlier grid time, to 1e-12 relative in t (well inside the trajectories' own accuracy).
// Both samples tend to the same steady state, where their difference decays to the integration
// error: a change of sign counts only where the difference on one side of it exceeds 1e4 rel_tol
// times T_tr (1e-6 at the default), and the search ends at the first change of sign that does not.
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/observables/theory.hpp"

#include <optional>

namespace roughgas {

// The first t in (0, t_max] with T_tr,A(t) = T_tr,B(t) (a change of sign of their difference), or
// nullopt if there is none by t_max. Throws std::invalid_argument if the two T_tr are equal at
// t = 0, t_max is not > 0, or for a thermostat check_thermostat refuses.
std::optional<double> mpemba_crossing_time(const HcsTheory& theory, const ThermostatSpec& thermostat,
                                           const HcsTemperatures& A, const HcsTemperatures& B, double t_max,
                                           double rel_tol = 1e-10);

} // namespace roughgas
