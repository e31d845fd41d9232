// collide: the collision rule (collision/rule.hpp, docs/model.md §3) over arrays of pre-collision
// states of rough grains, each pair with its own alpha and beta (constant restitution: the
// library's RoughConstant policy), the GIL released. New arrays out; the inputs stay as they were.
#include "bindings.hpp"

#include "parallel_for.hpp"

#include "roughgas/collision/pair_constants.hpp"
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/collision/rule.hpp"

#include <pybind11/numpy.h>

#include <omp.h>

#include <cmath>
#include <string>

namespace py = pybind11;

namespace roughgas::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An (N, 3) array of finite numbers; returns N.
py::ssize_t vectors(const Array& a, const char* name, py::ssize_t n) {
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw py::value_error(std::string(name) + ": an array of shape (N, 3) expected");
    if (n >= 0 && a.shape(0) != n)
        throw py::value_error(std::string(name) + ": " + std::to_string(a.shape(0)) + " rows, expected " +
                              std::to_string(n));
    const double* v = a.data();
    for (py::ssize_t k = 0; k < a.size(); ++k)
        if (!std::isfinite(v[k]))
            throw py::value_error(std::string(name) + "[" + std::to_string(k / 3) + "]: not finite");
    return a.shape(0);
}

// alpha in [0, 1] and beta in [-1, 1] per pair (docs/model.md §3): the rule's domain.
void coefficients(const Array& a, const char* name, double lo, py::ssize_t n) {
    if (a.ndim() != 1 || a.shape(0) != n)
        throw py::value_error(std::string(name) + ": one value per pair expected (" + std::to_string(n) + ")");
    const double* v = a.data();
    for (py::ssize_t k = 0; k < n; ++k)
        if (!(v[k] >= lo && v[k] <= 1))
            throw py::value_error(std::string(name) + "[" + std::to_string(k) + "] = " + std::to_string(v[k]) +
                                  ": must be in [" + (lo < 0 ? "-1" : "0") + ", 1]");
}

GrainProperties grain(py::tuple t, const char* name) {
    if (t.size() != 3)
        throw py::value_error(std::string(name) + ": (mass, radius, inertia) expected");
    const GrainProperties g{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>()};
    if (!(g.mass > 0 && std::isfinite(g.mass)) || !(g.radius > 0 && std::isfinite(g.radius)) ||
        !(g.inertia > 0 && g.inertia <= 2.0 / 3.0))
        throw py::value_error(std::string(name) + ": mass and radius must be finite and > 0, inertia in (0, 2/3]");
    return g;
}

} // namespace

void bind_collision(py::module_& m) {
    m.def(
        "collide",
        [](const Array& v_i, const Array& w_i, const Array& v_j, const Array& w_j, const Array& n, const Array& alpha,
           const Array& beta, py::tuple grain_i, py::tuple grain_j) {
            const py::ssize_t count = vectors(v_i, "v_i", -1);
            vectors(w_i, "w_i", count);
            vectors(v_j, "v_j", count);
            vectors(w_j, "w_j", count);
            vectors(n, "n", count);
            for (py::ssize_t k = 0; k < count; ++k) {
                const double* u = n.data() + 3 * k;
                if (std::abs(u[0] * u[0] + u[1] * u[1] + u[2] * u[2] - 1) > 1e-9)
                    throw py::value_error("n[" + std::to_string(k) + "]: not a unit vector");
            }
            coefficients(alpha, "alpha", 0, count);
            coefficients(beta, "beta", -1, count);
            const GrainProperties gi = grain(grain_i, "grain_i"), gj = grain(grain_j, "grain_j");
            const PairConstants pc = make_pair_constants(gi, gj);
            Array vi(std::vector<py::ssize_t>{count, 3}), wi(std::vector<py::ssize_t>{count, 3});
            Array vj(std::vector<py::ssize_t>{count, 3}), wj(std::vector<py::ssize_t>{count, 3});
            const auto in = [](const Array& a, std::size_t k) {
                const double* p = a.data() + 3 * k;
                return Vec3{p[0], p[1], p[2]};
            };
            const auto out = [](Array& a, std::size_t k, const Vec3& v) {
                double* p = a.mutable_data() + 3 * k;
                p[0] = v.x;
                p[1] = v.y;
                p[2] = v.z;
            };
            {
                py::gil_scoped_release release;
                cli::parallel_for(
                    static_cast<std::size_t>(count), omp_get_max_threads(),
                    [&](std::size_t k) {
                        Vec3 a = in(v_i, k), b = in(w_i, k), c = in(v_j, k), d = in(w_j, k);
                        collide(pc, make_rough_constant(alpha.data()[k], beta.data()[k]), a, b, c, d, in(n, k));
                        out(vi, k, a);
                        out(wi, k, b);
                        out(vj, k, c);
                        out(wj, k, d);
                    },
                    4096);
            }
            return py::make_tuple(vi, wi, vj, wj);
        },
        py::arg("v_i"), py::arg("w_i"), py::arg("v_j"), py::arg("w_j"), py::arg("n"), py::arg("alpha"),
        py::arg("beta"), py::arg("grain_i"), py::arg("grain_j"),
        "(v_i', w_i', v_j', w_j'): the collision rule over N pairs, n the unit normal from j to i");
}

} // namespace roughgas::python
