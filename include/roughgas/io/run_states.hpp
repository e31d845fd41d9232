#pragma once
// A case's run.save_state and initial.from, connected to the solver (dsmc/grain_state.hpp) through
// the state files (io/state_file.hpp).
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/io/case_config.hpp"

#include <filesystem>
#include <string>

namespace roughgas {

// initial.from: checks the earlier run's files against the case before any work (the directory,
// replica 0's file whole, its species, their grains and the box of its positions; InputError naming
// `case_file` and the key, exit 2; with a cooling gas, the end against the state's own reach of
// T_tr/m = 1e-300) and sets spec.initial_state to read replica r's grains from the file of replica r
// modulo the files there: a box's or the homogeneous gas's start (dsmc/run_spec.hpp). Returns what
// the run starts from, for the CSV header and stderr ("" without initial.from).
std::string attach_initial_state(RunSpec& spec, const CaseConfig& cfg, const std::string& case_file);

// run.save_state: spec.final_state writes each finished replica's grains to
// state_file_path(out, replica), atomically; creates the directory.
void attach_final_state(RunSpec& spec, const CaseConfig& cfg, const std::filesystem::path& out);

} // namespace roughgas
