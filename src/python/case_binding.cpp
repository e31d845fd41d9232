// CaseSource for Python: the package's roughgas.Case holds one. Construction and set() validate as
// `roughgas check` does the parse; check() is `roughgas check` itself (check_report.hpp).
#include "bindings.hpp"
#include "case_source.hpp"

#include "check_report.hpp"

#include <pybind11/stl.h>

#include <utility>

namespace py = pybind11;

namespace roughgas::python {

CaseConfig CaseSource::parse(const std::vector<std::string>& overrides, CaseUse use) const {
    try {
        return text ? parse_case(*text, name, overrides, use) : load_case(name, overrides, use);
    } catch (const InputError& e) {
        if (positions)
            throw;
        // Lines and columns of TOML made from a dict would point into text the user never saw.
        std::vector<InputIssue> issues = e.issues();
        for (InputIssue& i : issues)
            i.where.reset();
        throw InputError(std::move(issues));
    }
}

void bind_case(py::module_& m) {
    py::class_<CaseSource>(m, "CaseSource", "a validated case: a file or TOML text, with its --set overrides")
        .def_static(
            "from_file",
            [](const std::string& path) {
                CaseSource c;
                c.name = path;
                c.cfg = c.parse({});
                return c;
            },
            py::arg("path"))
        .def_static(
            "from_text",
            [](const std::string& text, const std::string& name, bool positions) {
                CaseSource c;
                c.name = name;
                c.text = text;
                c.positions = positions;
                c.cfg = c.parse({});
                return c;
            },
            py::arg("text"), py::arg("name"), py::arg("positions") = true)
        .def(
            "set",
            [](CaseSource& c, const std::string& key_value) {
                std::vector<std::string> sets = c.sets;
                sets.push_back(key_value);
                c.cfg = c.parse(sets); // unchanged when it throws
                c.sets = std::move(sets);
            },
            py::arg("key_value"), "add a --set KEY=VALUE (VALUE as TOML); InputError leaves the case as it was")
        .def(
            "check",
            [](const CaseSource& c, const std::string& use, bool print) {
                if (use != "run" && use != "restitution")
                    throw py::value_error("check(use=...): \"run\" or \"restitution\", got \"" + use + "\"");
                const CaseUse u = use == "run" ? CaseUse::run : CaseUse::restitution;
                const cli::CheckReport r = cli::check_case(c.parse(c.sets, u), c.name, u, print);
                return py::make_tuple(r.out, r.warnings);
            },
            py::arg("use") = "run", py::arg("print") = false)
        .def("copy", [](const CaseSource& c) { return c; })
        .def("resolved_toml", [](const CaseSource& c) { return emit_case(c.cfg); })
        .def_readonly("name", &CaseSource::name)
        .def_readonly("text", &CaseSource::text)
        .def_readonly("sets", &CaseSource::sets)
        .def_property_readonly("replicas", [](const CaseSource& c) { return c.cfg.run.replicas; })
        .def_property_readonly("is_box", [](const CaseSource& c) { return c.cfg.domain.has_value(); });
}

} // namespace roughgas::python
