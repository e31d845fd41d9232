// roughgas.InputError (a ValueError): what the command line reports with exit status 2, with the
// same message, and the keys it names (`key`: the first issue's, "" when not about a key; `issues`:
// every issue as (file, key, message)).
#include "bindings.hpp"

#include "roughgas/io/input_error.hpp"

#include <exception>

namespace py = pybind11;

namespace roughgas::python {

void bind_input_error(py::module_& m) {
    const auto type = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
        "roughgas.InputError",
        "Invalid input: a case's key out of its range, an unknown key, a wrong value; the message is the "
        "command line's (exit status 2). `key`: the first key named, `issues`: (file, key, message) each.",
        PyExc_ValueError, nullptr));
    if (!type)
        throw py::error_already_set();
    m.add_object("InputError", type);
    // The translator looks the type up in the module: no static copy of it outlives the module.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const InputError& e) {
            py::object type = py::module_::import("roughgas._roughgas").attr("InputError");
            py::object error = type(e.what());
            py::list issues;
            for (const InputIssue& i : e.issues())
                issues.append(py::make_tuple(i.file, i.key, i.message));
            error.attr("key") = e.key();
            error.attr("issues") = issues;
            PyErr_SetObject(type.ptr(), error.ptr());
        }
    });
}

} // namespace roughgas::python
