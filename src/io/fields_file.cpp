// One snapshot of the cell fields as an HDF5 file: io/fields_file.hpp.
#include "roughgas/io/fields_file.hpp"

#include "roughgas/io/atomic_file.hpp"

#include <hdf5.h>

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace roughgas {
namespace {

// The library is not thread-safe as packaged (fields_file.hpp): one lock for every call. Its error
// stack is not printed (each failure here becomes an exception naming the file).
std::mutex& hdf5_mutex() {
    static std::mutex m;
    return m;
}
std::unique_lock<std::mutex> lock_hdf5() {
    std::unique_lock<std::mutex> lock(hdf5_mutex());
    // HDF5 prints its error stack unless told not to, per thread where it is built thread-safe;
    // its failures reach the user as exceptions naming the file instead.
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return lock;
}

// An identifier closed when it goes out of scope.
class Handle {
  public:
    Handle(hid_t id, herr_t (*close)(hid_t), const std::filesystem::path& path, const char* what)
        : id_(id), close_(close) {
        if (id_ < 0)
            throw std::runtime_error("HDF5: cannot " + std::string(what) + " in " + path.string());
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { close_(id_); }
    operator hid_t() const { return id_; }

  private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::filesystem::path& path, const char* what) {
    if (status < 0)
        throw std::runtime_error("HDF5: cannot " + std::string(what) + " in " + path.string());
}

template <class T>
void put_attribute(hid_t where, const char* name, hid_t file_type, hid_t memory_type, const T* values, hsize_t count,
                   const std::filesystem::path& path) {
    const Handle space(count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose, path,
                       "make a dataspace");
    const Handle a(H5Acreate2(where, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, path,
                   "create an attribute");
    check(H5Awrite(a, memory_type, values), path, "write an attribute");
}

// A variable-length UTF-8 string: Python's h5py reads it as str.
hid_t string_type(const std::filesystem::path& path) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    if (type < 0 || H5Tset_size(type, H5T_VARIABLE) < 0 || H5Tset_cset(type, H5T_CSET_UTF8) < 0)
        throw std::runtime_error("HDF5: cannot make a string type in " + path.string());
    return type;
}

void put_string_attribute(hid_t where, const char* name, const std::string& text, const std::filesystem::path& path) {
    const Handle type(string_type(path), H5Tclose, path, "make a string type");
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose, path, "make a dataspace");
    const Handle a(H5Acreate2(where, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, path,
                   "create an attribute");
    const char* c = text.c_str();
    check(H5Awrite(a, type, &c), path, "write an attribute");
}

template <class T> void get_attribute(hid_t where, const char* name, hid_t memory_type, T* values,
                                      const std::filesystem::path& path) {
    const Handle a(H5Aopen(where, name, H5P_DEFAULT), H5Aclose, path, (std::string("open attribute ") + name).c_str());
    check(H5Aread(a, memory_type, values), path, "read an attribute");
}

// A file's bytes, not zeroed before HDF5 writes them.
// Writes the file at `file` (a temporary name) with HDF5's own POSIX driver: the datasets go from
// the fields' arrays to the file without a copy in between. `path` names the file in messages.
void write_hdf5(const std::filesystem::path& file, const std::filesystem::path& path, const FieldsFileHeader& h,
                const CellFields& f) {
    const Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose, path, "make file properties");
    const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, path, "make dataset properties");
    check(H5Pset_obj_track_times(fcpl, 0), path, "leave out the times");
    check(H5Pset_obj_track_times(dcpl, 0), path, "leave out the times");
    const Handle out(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT), H5Fclose, path, "create the file");
    put_attribute(out, "t", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &h.t, 1, path);
    put_attribute(out, "coll_per_particle", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &h.coll_per_particle, 1, path);
    put_attribute(out, "row", H5T_STD_U64LE, H5T_NATIVE_UINT64, &h.row, 1, path);
    put_attribute(out, "replica", H5T_STD_I64LE, H5T_NATIVE_INT64, &h.replica, 1, path);
    put_attribute(out, "box", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, h.box.data(), 3, path);
    put_attribute(out, "cells", H5T_STD_I64LE, H5T_NATIVE_INT64, h.cells.data(), 3, path);
    for (std::size_t k = 0; k < f.quantities.size(); ++k) {
        const int C = field_components(f.quantities[k]);
        const hsize_t dims[4] = {static_cast<hsize_t>(f.cells[2]), static_cast<hsize_t>(f.cells[1]),
                                 static_cast<hsize_t>(f.cells[0]), static_cast<hsize_t>(C)};
        if (f.values[k].size() != dims[0] * dims[1] * dims[2] * dims[3])
            throw std::logic_error("write_fields_file: a quantity has the wrong number of values");
        const Handle space(H5Screate_simple(C == 1 ? 3 : 4, dims, nullptr), H5Sclose, path, "make a dataspace");
        const std::string name(field_quantity_names[static_cast<std::size_t>(f.quantities[k])]);
        const Handle set(H5Dcreate2(out, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                         H5Dclose, path, "create a dataset");
        check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.values[k].data()), path,
              "write a dataset");
        put_string_attribute(set, "unit", std::string(field_unit(f.quantities[k])), path);
    }
}

} // namespace

void write_fields_file(const std::filesystem::path& path, const FieldsFileHeader& header, const CellFields& fields) {
    const std::filesystem::path tmp = temporary_path(path);
    try {
        const auto lock = lock_hdf5();
        write_hdf5(tmp, path, header, fields);
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw;
    }
    publish_file_atomically(tmp, path);
}

FieldsFileHeader read_fields_header(const std::filesystem::path& path) {
    const auto lock = lock_hdf5();
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path, "open the file");
    FieldsFileHeader h;
    get_attribute(file, "t", H5T_NATIVE_DOUBLE, &h.t, path);
    get_attribute(file, "coll_per_particle", H5T_NATIVE_DOUBLE, &h.coll_per_particle, path);
    get_attribute(file, "row", H5T_NATIVE_UINT64, &h.row, path);
    get_attribute(file, "replica", H5T_NATIVE_INT64, &h.replica, path);
    get_attribute(file, "box", H5T_NATIVE_DOUBLE, h.box.data(), path);
    get_attribute(file, "cells", H5T_NATIVE_INT64, h.cells.data(), path);
    return h;
}

FieldsDataset read_fields_dataset(const std::filesystem::path& path, const std::string& name) {
    const auto lock = lock_hdf5();
    const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path, "open the file");
    const Handle set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, path, ("open dataset " + name).c_str());
    const Handle space(H5Dget_space(set), H5Sclose, path, "read a dataspace");
    const int rank = H5Sget_simple_extent_ndims(space);
    if (rank < 1 || rank > 8)
        throw std::runtime_error("HDF5: dataset " + name + " has an unexpected rank in " + path.string());
    hsize_t dims[8];
    H5Sget_simple_extent_dims(space, dims, nullptr);
    FieldsDataset d;
    std::size_t count = 1;
    for (int a = 0; a < rank; ++a) {
        d.shape.push_back(static_cast<std::size_t>(dims[a]));
        count *= d.shape.back();
    }
    d.values.resize(count);
    check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data()), path, "read a dataset");
    const Handle a(H5Aopen(set, "unit", H5P_DEFAULT), H5Aclose, path, "open attribute unit");
    const Handle type(string_type(path), H5Tclose, path, "make a string type");
    char* unit = nullptr;
    check(H5Aread(a, type, &unit), path, "read an attribute");
    d.unit = unit ? unit : "";
    H5free_memory(unit);
    return d;
}

} // namespace roughgas
