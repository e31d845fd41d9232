#pragma once
// The validated case (io/case_config.hpp) as what the DSMC needs (dsmc/run_spec.hpp).
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/io/case_config.hpp"

#include <vector>

namespace roughgas {

// Output times in collisions per particle, increasing, the last one == end:
//   linear: every, 2 every, ... below end, then end;
//   log:    every x 10^(k/10), k = 0, 1, ... below end, then end (ten per decade).
// every > 0 and end > 0 (validated by the case file reader); an output closer than 1e-9 relative
// to end merges with end.
std::vector<double> output_times(double every, double end, OutputSpacing spacing);

// `times` without those that fall on the collision count of the row before (round(x N/2) for N
// `particles`; the row at t = 0 has 0): a few grains with dense rows would otherwise give rows
// with no collision between them, whose rates are 0/0. The last time (the end) is kept.
std::vector<double> rows_apart(const std::vector<double>& times, std::int64_t particles);

// Species, the model of every species pair (its [[pair]] table, else [collision]), particles,
// density, seed, replicas, end and output times, the contact settings, and for run.kind = "shear"
// the shear rate and time step (std::invalid_argument without [shear]; the parser rejects that
// case first).
RunSpec run_spec_from_case(const CaseConfig& cfg);

} // namespace roughgas
