// read_fields_header and read_fields: a box run's cell-field snapshots (DIR/fields/replica_R/
// row_NNNNNN.h5, io/fields_file.hpp) through the library's own HDF5 reader; each dataset's buffer
// is moved into NumPy in the file's shape (cell (i, j, l) at [l, j, i]), never copied.
#include "bindings.hpp"

#include "roughgas/io/fields_file.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <vector>

namespace py = pybind11;

namespace roughgas::python {

void bind_fields(py::module_& m) {
    m.def(
        "read_fields_header",
        [](const std::string& path) {
            const FieldsFileHeader h = read_fields_header(path);
            py::dict d;
            d["t"] = h.t;
            d["coll_per_particle"] = h.coll_per_particle;
            d["row"] = h.row;
            d["replica"] = h.replica;
            d["box"] = py::make_tuple(h.box[0], h.box[1], h.box[2]);
            d["cells"] = py::make_tuple(h.cells[0], h.cells[1], h.cells[2]);
            return d;
        },
        py::arg("path"), "the root attributes of a fields file (t, coll_per_particle, row, replica, box, cells)");
    m.def(
        "read_fields",
        [](const std::string& path, const std::string& name) {
            auto d = std::make_unique<FieldsDataset>();
            {
                py::gil_scoped_release release;
                *d = read_fields_dataset(path, name);
            }
            std::vector<py::ssize_t> shape(d->shape.begin(), d->shape.end());
            std::vector<py::ssize_t> strides(shape.size());
            py::ssize_t stride = sizeof(double);
            for (std::size_t k = shape.size(); k-- > 0;) {
                strides[k] = stride;
                stride *= shape[k];
            }
            const std::string unit = d->unit;
            double* data = d->values.data();
            py::capsule owner(d.release(), [](void* p) { delete static_cast<FieldsDataset*>(p); });
            return py::make_tuple(py::array_t<double>(shape, strides, data, owner), unit);
        },
        py::arg("path"), py::arg("name"), "(values, unit) of one quantity of a fields file");
}

} // namespace roughgas::python
