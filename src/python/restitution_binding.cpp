// eps_N(g_N) and eps_T(g_N, g_T) of a case's contact model over NumPy arrays, for the pair
// `roughgas restitution` tabulates (the first two species, or the only one with itself): directly
// integrated (contact_integrator.hpp), or from the tables a DSMC run of the case uses
// (restitution_tables.hpp). The GIL is released while they compute, over OpenMP's threads.
#include "bindings.hpp"
#include "case_source.hpp"

#include "parallel_for.hpp"
#include "restitution_tables.hpp"

#include "roughgas/contact/contact_integrator.hpp"

#include <pybind11/numpy.h>

#include <omp.h>

#include <cmath>
#include <optional>
#include <string>

namespace py = pybind11;

namespace roughgas::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

class ContactFunctions {
  public:
    ContactFunctions(const CaseSource& c, bool tabulated) : cfg_(c.parse(c.sets, CaseUse::restitution)) {
        const auto [i, j] = restitution_species(cfg_);
        pair_ = contact_pair(cfg_, i, j);
        if (tabulated) {
            py::gil_scoped_release release;
            tables_.emplace(cli::load_or_build_tables(cfg_, pair_));
        }
    }

    Array eps_n(const Array& g_n) const {
        require(g_n, "g_n", false);
        Array out(g_n.size());
        const double* g = g_n.data();
        double* e = out.mutable_data();
        parallel(g_n.size(), [&](std::size_t k) {
            e[k] = tables_ ? tables_->normal.eps_n(pair_.w(g[k])) : integrate_normal_contact(pair_, g[k], tol()).eps_n;
        });
        return out;
    }

    Array eps_t(const Array& g_n, const Array& g_t) const {
        require(g_n, "g_n", false);
        require(g_t, "g_t", true);
        if (g_t.size() != g_n.size())
            throw py::value_error("eps_t: g_n and g_t differ in size (" + std::to_string(g_n.size()) + " and " +
                                  std::to_string(g_t.size()) + ")");
        Array out(g_n.size());
        const double* gn = g_n.data();
        const double* gt = g_t.data();
        double* e = out.mutable_data();
        parallel(g_n.size(), [&](std::size_t k) {
            e[k] = tables_ ? tables_->tangential.eps_t(gn[k], gt[k]) : integrate_contact(pair_, gn[k], gt[k], tol()).eps_t;
        });
        return out;
    }

    bool tabulated() const { return tables_.has_value(); }

  private:
    Tolerance tol() const { return cfg_.contact.tolerance; }

    // Speeds must be finite, g_n > 0 and g_t >= 0 (m/s): the integrator's domain.
    static void require(const Array& a, const char* name, bool zero_allowed) {
        if (a.ndim() != 1)
            throw py::value_error(std::string(name) + ": a 1-d array expected, got " + std::to_string(a.ndim()) + "-d");
        const double* v = a.data();
        for (py::ssize_t k = 0; k < a.size(); ++k)
            if (!std::isfinite(v[k]) || v[k] < 0 || (!zero_allowed && v[k] == 0))
                throw py::value_error(std::string(name) + "[" + std::to_string(k) + "] = " + std::to_string(v[k]) +
                                      ": must be finite and " + (zero_allowed ? ">= 0" : "> 0") + " (m/s)");
    }

    // f(k) for k in [0, n) over OpenMP's threads without the GIL: a table's value costs nanoseconds
    // (chunks of 1024 points), a direct integration up to milliseconds (one point at a time).
    template <class F> void parallel(py::ssize_t n, F&& f) const {
        py::gil_scoped_release release;
        cli::parallel_for(static_cast<std::size_t>(n), omp_get_max_threads(), f, tables_ ? 1024 : 1);
    }

    CaseConfig cfg_;
    ContactPair pair_{};
    std::optional<cli::CachedTables> tables_;
};

} // namespace

void bind_restitution(py::module_& m) {
    py::class_<ContactFunctions>(m, "ContactFunctions",
                                 "eps_N and eps_T of a case's contact model (the pair roughgas restitution tabulates)")
        .def(py::init<const CaseSource&, bool>(), py::arg("case"), py::arg("tabulated"))
        .def("eps_n", &ContactFunctions::eps_n, py::arg("g_n"))
        .def("eps_t", &ContactFunctions::eps_t, py::arg("g_n"), py::arg("g_t"))
        .def_property_readonly("tabulated", &ContactFunctions::tabulated);
}

} // namespace roughgas::python
