#pragma once
// A run too large for the machine is refused before any work (exit 2), with the estimate and what
// the machine offers, instead of failing in an allocation (or being killed) later.
#include "roughgas/dsmc/run_spec.hpp"

#include <string>

namespace roughgas::cli {

// `at_once`: the replicas (or sweep points) that run at the same time in this process. Throws
// InputError naming `case_file` and run.particles when N x memory_per_particle_bound x at_once
// exceeds available_memory(); does nothing when the machine's free memory cannot be read.
void refuse_if_too_large(const RunSpec& spec, int at_once, const std::string& case_file);

} // namespace roughgas::cli
