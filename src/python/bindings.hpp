#pragma once
// The parts of the extension module _roughgas (module.cpp), one per concept; the package roughgas
// (roughgas/*.py) builds the Python interface on them.
#include <pybind11/pybind11.h>

namespace roughgas::python {

void bind_input_error(pybind11::module_& m);  // roughgas.InputError, from roughgas::InputError
void bind_case(pybind11::module_& m);         // CaseSource: a case file, text or dict, with its --set
void bind_run(pybind11::module_& m);          // run_case, resume_run: `roughgas run` in this process
void bind_csv(pybind11::module_& m);          // read_csv: a roughgas CSV as one NumPy buffer
void bind_fields(pybind11::module_& m);       // read_fields: a box run's cell fields (HDF5)
void bind_restitution(pybind11::module_& m);  // ContactFunctions: eps_N and eps_T over arrays
void bind_collision(pybind11::module_& m);    // collide: the collision rule over arrays of pairs

} // namespace roughgas::python
