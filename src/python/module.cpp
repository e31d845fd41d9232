// The extension module roughgas._roughgas (docs/python.md).
#include "bindings.hpp"

#include "roughgas/io/csv_writer.hpp"

PYBIND11_MODULE(_roughgas, m) {
    m.doc() = "roughgas: the compiled part of the Python module (use the package roughgas)";
    m.attr("__version__") = roughgas::roughgas_version();
    roughgas::python::bind_input_error(m);
    roughgas::python::bind_case(m);
    roughgas::python::bind_run(m);
    roughgas::python::bind_csv(m);
    roughgas::python::bind_fields(m);
    roughgas::python::bind_restitution(m);
    roughgas::python::bind_collision(m);
}
